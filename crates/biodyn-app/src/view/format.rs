//! Number and label formatting for eyes, shared by both fronts: tables round;
//! files and edit fields keep every digit.

/// `v` with `sig` significant digits, trailing zeros trimmed; thousands
/// stay whole (310000, not 3.1e5) because that is how Table 1 reads.
pub fn num(v: f64, sig: usize) -> String {
    if !v.is_finite() {
        return format!("{v}");
    }
    if v == 0.0 {
        return "0".into();
    }
    let mag = v.abs().log10().floor() as i32;
    let decimals = (sig as i32 - 1 - mag).max(0) as usize;
    let s = format!("{v:.decimals$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// Unit of a function's magnitude for labels; STHT is a plain ratio.
pub fn unit(f: biodyn::Function) -> &'static str {
    f.unit_label()
}

/// The short y-axis title of a magnitude chart whose title already names
/// the function: the unit, or |STHT| for the dimensionless transmissibility.
/// (The TUI's; `axis_title` is the full form.)
pub fn magnitude_axis(f: biodyn::Function) -> String {
    match unit(f) {
        "" => format!("|{}|", f.name()),
        u => u.to_string(),
    }
}

/// A chart's y-axis title: `|STHT|`, `|DPMI| (N·s/m)`, or `STHT phase (deg)`.
pub fn axis_title(f: biodyn::Function, phase: bool) -> String {
    if phase {
        format!("{} phase (deg)", f.name())
    } else {
        match unit(f) {
            "" => format!("|{}|", f.name()),
            u => format!("|{}| ({u})", f.name()),
        }
    }
}

/// The exact value for an edit field: Rust's shortest round-trip form.
pub fn exact(v: f64) -> String {
    format!("{v}")
}

/// A model value for its edit field: 12 significant digits, so that
/// 0.402 × 75 reads 30.15, not 30.150000000000002. Committing the
/// pre-filled text unchanged leaves the exact value alone.
pub fn for_edit(v: f64) -> String {
    num(v, 12)
}

/// `s` cut to `w` characters, with an ellipsis when anything was cut.
pub fn clip(s: &str, w: usize) -> String {
    if s.chars().count() <= w {
        s.to_string()
    } else {
        let mut t: String = s.chars().take(w.saturating_sub(1)).collect();
        t.push('…');
        t
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounding_for_tables() {
        assert_eq!(num(5.625, 4), "5.625");
        assert_eq!(num(310_000.0, 4), "310000");
        assert_eq!(num(0.123456, 3), "0.123");
        assert_eq!(num(30.15, 3), "30.1");
        assert_eq!(num(0.0, 3), "0");
        assert_eq!(exact(0.1 + 0.2), "0.30000000000000004");
        assert_eq!(for_edit(0.402 * 75.0), "30.15");
        assert_eq!(for_edit(310_000.0), "310000");
        assert_eq!(for_edit(1.5e-7), "0.00000015");
    }
}
