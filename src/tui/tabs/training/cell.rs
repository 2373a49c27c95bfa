//! A setting's value in its column: whole when it fits, else cut at a
//! separator with "…" (`54000,9e4,…`) or, for one number, fewer digits
//! after "≈" — never inside a number. The status line shows it whole.

use crate::view::format::{clip, clip_start, fit};
use biodyn::ann::SettingKind;

/// `text` (a setting of `kind`) in at most `width` characters.
pub fn fit_value(text: &str, kind: Option<SettingKind>, width: usize) -> String {
    let len = |s: &str| s.chars().count();
    if len(text) <= width {
        return text.to_string();
    }
    let sep = match kind {
        Some(SettingKind::Values) => Some(','),
        Some(SettingKind::Layers) => Some('-'),
        Some(SettingKind::Band) => Some(':'),
        _ => None,
    };
    let Some(sep) = sep else {
        return approx(text, width).unwrap_or_else(|| clip(text, width));
    };
    // Whole parts while they and the closing ",…" fit.
    let mut out = String::new();
    for part in text.split(sep) {
        let grown = if out.is_empty() {
            len(part)
        } else {
            len(&out) + 1 + len(part)
        };
        if grown + 2 > width {
            break;
        }
        if !out.is_empty() {
            out.push(sep);
        }
        out.push_str(part);
    }
    if out.is_empty() {
        // Not even the first part fits whole: it, rounded.
        let first = text.split(sep).next().unwrap_or_default();
        match approx(first, width.saturating_sub(2)) {
            Some(a) => out = a,
            None => return "…".chars().take(width).collect(),
        }
    }
    out.push(sep);
    out.push('…');
    out
}

/// A number too long for `width`, rounded to fewer digits after "≈".
fn approx(text: &str, width: usize) -> Option<String> {
    let v: f64 = text.trim().parse().ok()?;
    if width < 2 || !v.is_finite() {
        return None;
    }
    let s = fit(v, 17, width - 1);
    (s.chars().count() < width).then(|| format!("≈{s}"))
}

/// The last part of `path`, at most `width` characters: a longer name
/// keeps its end (where `.json` is) after "…".
pub fn file_name(path: &str, width: usize) -> String {
    let name = std::path::Path::new(path)
        .file_name()
        .map_or(path.into(), |n| n.to_string_lossy().into_owned());
    clip_start(&name, width)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_file_name_keeps_its_end() {
        assert_eq!(file_name("/tmp/.tmpAbC/mass.json", 24), "mass.json");
        assert_eq!(file_name("a-very-long-network-name.json", 12), "…k-name.json");
        assert_eq!(file_name("x.json", 24), "x.json");
    }

    #[test]
    fn lists_are_cut_between_numbers_and_numbers_are_rounded_not_cut() {
        let k = Some(SettingKind::Values);
        assert_eq!(fit_value("54000,9e4,126000", k, 16), "54000,9e4,126000");
        assert_eq!(fit_value("54000,9e4,126000", k, 15), "54000,9e4,…");
        assert_eq!(fit_value("54000,9e4,126000", k, 8), "54000,…");
        assert_eq!(fit_value("0.30000000000000004,1", k, 10), "≈0.3,…");
        assert_eq!(fit_value("5-60-40-30-1", Some(SettingKind::Layers), 9), "5-60-40-…");
        assert_eq!(fit_value("0.30000000000000004", Some(SettingKind::Real), 15), "≈0.3");
        let seed = fit_value("18446744073709551615", Some(SettingKind::Whole), 15);
        assert!(seed.starts_with("≈1.8") && seed.chars().count() <= 15, "{seed}");
        for w in 0..25 {
            for (t, k) in [
                ("54000,9e4,126000", k),
                ("0.1:20:0.125", Some(SettingKind::Band)),
                ("1.2345678901234567e-300", Some(SettingKind::Real)),
            ] {
                assert!(fit_value(t, k, w).chars().count() <= w.max(1), "{t} {w}");
            }
        }
    }
}
