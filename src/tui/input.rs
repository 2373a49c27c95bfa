//! What the user types into a field, parsed: shared by the app and the
//! tabs (a band, a frequency inside it), so two tabs that ask for the same
//! thing accept and refuse the same text.

use crate::view::format::num;

/// "from to step" in Hz; spaces, commas, colons or semicolons between.
pub fn parse_band(text: &str) -> Result<(f64, f64, f64), String> {
    let parts: Vec<&str> = text
        .split(|c: char| c.is_whitespace() || matches!(c, ',' | ':' | ';'))
        .filter(|p| !p.is_empty())
        .collect();
    let [from, to, step] = parts.as_slice() else {
        return Err(format!(
            "give three numbers, from to step in Hz, e.g. 0.5 20 0.1 (got {})",
            parts.len()
        ));
    };
    let num = |name: &str, t: &str| -> Result<f64, String> {
        t.parse::<f64>()
            .map_err(|_| format!("{name} '{t}' is not a number (write e.g. 0.5 20 0.1)"))
    };
    Ok((num("from", from)?, num("to", to)?, num("step", step)?))
}

/// A typed frequency ("4.56", "4.56 Hz") inside `band`, or one line that
/// says what to type (the `g` fields of Responses and Study).
pub fn frequency_in_band(text: &str, b: &biodyn::Band) -> Result<f64, String> {
    let t = text.trim();
    let t = t
        .strip_suffix("Hz")
        .or_else(|| t.strip_suffix("hz"))
        .unwrap_or(t)
        .trim();
    let f: f64 = t.parse().map_err(|_| {
        format!(
            "'{}' is not a frequency: type a number of Hz, e.g. 4.56",
            text.trim()
        )
    })?;
    if !f.is_finite() || f < b.from || f > b.to {
        return Err(format!(
            "{} Hz is outside the band {}–{} Hz: type a frequency inside it (b changes the band)",
            num(f, 6),
            num(b.from, 6),
            num(b.to, 6)
        ));
    }
    Ok(f)
}
