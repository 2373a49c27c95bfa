//! The table writer: aligned columns for eyes, numbers rounded.

use biodyn::{Function, Response};

/// A plain table: a header row, a rule, then rows; columns right-aligned
/// except the first.
pub fn table(header: &[&str], rows: &[Vec<String>]) -> String {
    let n = header.len();
    let mut width: Vec<usize> = header.iter().map(|h| h.chars().count()).collect();
    for r in rows {
        for (i, c) in r.iter().enumerate().take(n) {
            width[i] = width[i].max(c.chars().count());
        }
    }
    let mut s = String::new();
    let line = |cells: Vec<&str>, s: &mut String| {
        let mut parts = Vec::with_capacity(n);
        for (i, c) in cells.iter().enumerate() {
            let pad = width
                .get(i)
                .map_or(0, |w| w.saturating_sub(c.chars().count()));
            if i == 0 {
                parts.push(format!("{c}{}", " ".repeat(pad)));
            } else {
                parts.push(format!("{}{c}", " ".repeat(pad)));
            }
        }
        s.push_str(parts.join("  ").trim_end());
        s.push('\n');
    };
    line(header.to_vec(), &mut s);
    let total: usize = width.iter().sum::<usize>() + 2 * (n.saturating_sub(1));
    s.push_str(&"-".repeat(total));
    s.push('\n');
    for r in rows {
        line(r.iter().map(String::as_str).collect(), &mut s);
    }
    s
}

/// Fixed decimals for tables.
/// Past ordinary sizes (≥ 1e7) the short scientific form (`1e300`, not 301
/// digits); a value that rounds to zero prints without a sign (`0.0`, not
/// `-0.0`).
pub fn fx(v: f64, decimals: usize) -> String {
    if v.is_finite() && v.abs() >= crate::view::format::PLAIN_BELOW {
        return crate::view::format::num(v, 4);
    }
    let s = format!("{v:.decimals$}");
    match s.strip_prefix('-') {
        Some(rest) if rest.bytes().all(|b| b == b'0' || b == b'.') => rest.to_string(),
        _ => s,
    }
}

/// `|STHT|`, `|DPMI| N·s/m`: a magnitude column's title.
pub fn mag_title(f: Function) -> String {
    match f.unit_label() {
        "" => format!("|{}|", f.name()),
        u => format!("|{}| {u}", f.name()),
    }
}

/// Decimals that print every frequency of a grid as it is: three, or as
/// many more (up to ten) as a fine step needs (0.0015 Hz is not "0.002").
pub fn freq_decimals(freqs: impl Iterator<Item = f64> + Clone) -> usize {
    (3..10)
        .find(|&d| {
            let k = 10f64.powi(d as i32);
            freqs
                .clone()
                .all(|f| ((f * k).round() / k - f).abs() <= 1e-9 * f.abs())
        })
        .unwrap_or(10)
}

/// A response curve as a table: frequency, then magnitude and phase of
/// each function.
pub fn curve(curve: &[Response]) -> String {
    curve_of(curve, &Function::ALL)
}

/// As `curve`, with the columns of `functions` (a seat model's five:
/// `Function::of(true)`).
pub fn curve_of(curve: &[Response], functions: &[Function]) -> String {
    let mut header = vec!["f Hz".to_string()];
    for &f in functions {
        header.push(mag_title(f));
        header.push(format!("{} deg", f.name()));
    }
    let d = freq_decimals(curve.iter().map(|r| r.f_hz));
    let rows: Vec<Vec<String>> = curve
        .iter()
        .map(|r| {
            let mut row = vec![fx(r.f_hz, d)];
            for &f in functions {
                row.push(fx(r.mag(f), f.mag_decimals()));
                row.push(fx(r.phase_deg(f), 1));
            }
            row
        })
        .collect();
    let h: Vec<&str> = header.iter().map(String::as_str).collect();
    table(&h, &rows)
}
