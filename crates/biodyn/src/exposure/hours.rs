//! Hours as people write them, read and printed once for every front:
//! `assess`'s exposure, a day file's `hours`, the day's sheet.
//!
//! The forms read (spaces anywhere are ignored, so `6 h 30` is `6h30`):
//!
//! | form | example | hours |
//! |---|---|---|
//! | decimal hours | `6.5`, `8` | 6.5, 8 |
//! | h:mm (two digits of minutes, 00–59) | `6:30`, `0:45` | 6.5, 0.75 |
//! | `h` and minutes (0–59), `min` optional | `6h30`, `6h05`, `6h30min` | 6.5, 6.083…, 6.5 |
//! | whole hours | `6h` | 6 |
//! | minutes alone | `45min`, `90min` | 0.75, 1.5 |
//!
//! Every form must give more than 0 h and at most a day (24 h).
//! [`hours_text`] prints hours back the way they are said: `6 h 45 min`.

use crate::io::excerpt::{num, quote};

/// The most hours a value here may hold: a day.
pub const MAX_HOURS: f64 = 24.0;

/// The forms, for messages.
pub const HOURS_FORMS: &str = "6.5, 6:30, 6h30, 6h or 45min";

/// A sum of hours within this of a bound is at the bound: 0.1 + 16.1 + 7.8
/// is 24.000000000000004 in binary floating point, and 24 h of a day.
pub const HOURS_TOLERANCE: f64 = 1e-9;

/// What is wrong with a text of hours.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum HoursError {
    #[error("'{}' is not hours: write {HOURS_FORMS}", quote(.0))]
    Form(String),
    #[error("'{}' has {minutes} minutes past the hour: minutes are 0 to 59 (write {example})", quote(.text))]
    Minutes {
        text: String,
        minutes: u64,
        example: String,
    },
    #[error("'{}' is {}: hours must be over 0 and at most 24 h", quote(.text), hours_text(*.hours))]
    Range { text: String, hours: f64 },
}

/// Reads `text` in one of the forms above; over 0 and at most 24 h.
pub fn parse_hours(text: &str) -> Result<f64, HoursError> {
    let s: String = text.chars().filter(|c| !c.is_whitespace()).collect();
    let form = || HoursError::Form(text.trim().to_string());
    let hours = if let Some((h, m)) = s.split_once(':') {
        if m.len() != 2 {
            return Err(form());
        }
        whole(h).ok_or_else(form)? as f64 + minutes(text, h, m, ':')? / 60.0
    } else if let Some(m) = s.strip_suffix("min") {
        match m.split_once('h') {
            Some((h, m)) if !m.is_empty() && m.len() <= 2 => {
                whole(h).ok_or_else(form)? as f64 + minutes(text, h, m, 'h')? / 60.0
            }
            Some(_) => return Err(form()),
            None => decimal(m).ok_or_else(form)? / 60.0,
        }
    } else if let Some((h, m)) = s.split_once('h') {
        if m.is_empty() {
            decimal(h).ok_or_else(form)?
        } else if m.len() <= 2 {
            whole(h).ok_or_else(form)? as f64 + minutes(text, h, m, 'h')? / 60.0
        } else {
            return Err(form());
        }
    } else {
        decimal(&s).ok_or_else(form)?
    };
    check_hours(text, hours)
}

/// `hours` over 0 and at most 24 h, or the error naming `text`.
pub fn check_hours(text: &str, hours: f64) -> Result<f64, HoursError> {
    if hours.is_finite() && hours > 0.0 && hours <= MAX_HOURS {
        Ok(hours)
    } else {
        Err(HoursError::Range {
            text: text.trim().to_string(),
            hours,
        })
    }
}

/// Digits only: the hours of `6:30`.
fn whole(s: &str) -> Option<u64> {
    if s.is_empty() || s.len() > 6 || !s.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    s.parse().ok()
}

/// A plain decimal: digits with at most one point, no sign, no exponent
/// (so `inf`, `-1` and `1e3` are not hours).
fn decimal(s: &str) -> Option<f64> {
    let ok = !s.is_empty()
        && s.bytes().any(|b| b.is_ascii_digit())
        && s.bytes().all(|b| b.is_ascii_digit() || b == b'.')
        && s.matches('.').count() <= 1;
    if ok { s.parse().ok() } else { None }
}

/// The minutes of `h:mm` or `hhmm`, 0 to 59.
fn minutes(text: &str, h: &str, m: &str, sep: char) -> Result<f64, HoursError> {
    let v = whole(m).ok_or_else(|| HoursError::Form(text.trim().to_string()))?;
    if v > 59 {
        let total = whole(h).unwrap_or(0) * 60 + v;
        let example = if sep == ':' {
            format!("{}:{:02}", total / 60, total % 60)
        } else {
            format!("{}h{:02}", total / 60, total % 60)
        };
        return Err(HoursError::Minutes {
            text: text.trim().to_string(),
            minutes: v,
            example,
        });
    }
    Ok(v as f64)
}

/// Hours as people say them: `6 h 45 min`, `3 h`, `45 min`, when they are
/// whole minutes (to 1e-9 of them: 0.1 + 16.1 + 7.8 is `24 h`); else
/// decimal hours to four decimals, `0.1234 h`. Not a finite number ≥ 0:
/// its digits, `inf h`.
pub fn hours_text(hours: f64) -> String {
    if !(hours.is_finite() && hours >= 0.0) {
        return format!("{} h", num(hours));
    }
    let minutes = hours * 60.0;
    let whole = minutes.round();
    if (minutes - whole).abs() <= 1e-9 * whole.max(1.0) && whole < 1e12 {
        let whole = whole as u64;
        return match (whole / 60, whole % 60) {
            (0, 0) => "0 h".into(),
            (0, m) => format!("{m} min"),
            (h, 0) => format!("{h} h"),
            (h, m) => format!("{h} h {m} min"),
        };
    }
    let s = format!("{hours:.4}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    format!("{s} h")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_form_reads_as_its_hours() {
        for (text, h) in [
            ("6.5", 6.5),
            ("8", 8.0),
            (" 6:30 ", 6.5),
            ("0:45", 0.75),
            ("6h30", 6.5),
            ("6h05", 6.0 + 5.0 / 60.0),
            ("6h5", 6.0 + 5.0 / 60.0),
            ("6h30min", 6.5),
            ("6 h 30", 6.5),
            ("6h", 6.0),
            ("2.5h", 2.5),
            ("45min", 0.75),
            ("90 min", 1.5),
            ("24:00", 24.0),
            (".5", 0.5),
        ] {
            assert_eq!(parse_hours(text), Ok(h), "{text}");
        }
    }

    #[test]
    fn what_is_not_hours_is_refused_with_the_forms() {
        for text in [
            "", "abc", "-1", "1e3", "inf", "NaN", "6:3", "6:300", "6.5:30", "6h300", "6hh", "h30",
            ":30", "6:30:00", "min", "1.2.3", "6h30h", "6m",
        ] {
            let e = parse_hours(text).unwrap_err();
            assert!(matches!(e, HoursError::Form(_)), "{text}: {e}");
            assert!(e.to_string().contains(HOURS_FORMS), "{e}");
        }
    }

    #[test]
    fn minutes_past_59_name_the_hours_meant() {
        let e = parse_hours("6:75").unwrap_err();
        assert_eq!(
            e.to_string(),
            "'6:75' has 75 minutes past the hour: minutes are 0 to 59 (write 7:15)"
        );
        let e = parse_hours("1h90").unwrap_err();
        assert!(e.to_string().contains("(write 2h30)"), "{e}");
    }

    #[test]
    fn hours_past_a_day_or_none_are_refused() {
        for text in ["0", "0:00", "24:01", "25", "0min", "1441min", "24h01"] {
            let e = parse_hours(text).unwrap_err();
            assert!(matches!(e, HoursError::Range { .. }), "{text}: {e}");
        }
        assert_eq!(
            parse_hours("25h30").unwrap_err().to_string(),
            "'25h30' is 25 h 30 min: hours must be over 0 and at most 24 h"
        );
    }

    #[test]
    fn hours_print_as_said() {
        assert_eq!(hours_text(6.75), "6 h 45 min");
        assert_eq!(hours_text(3.0), "3 h");
        assert_eq!(hours_text(0.75), "45 min");
        assert_eq!(hours_text(0.0), "0 h");
        assert_eq!(hours_text(0.1 + 16.1 + 7.8), "24 h");
        assert_eq!(hours_text(1.0 / 3.0), "20 min");
        assert_eq!(hours_text(0.1234), "0.1234 h");
        assert_eq!(hours_text(2.0 + 1e-3), "2.001 h");
        assert_eq!(hours_text(f64::INFINITY), "inf h");
        // What prints reads back.
        for h in [6.75, 3.25, 0.5, 24.0, 13.0 + 59.0 / 60.0] {
            let t = hours_text(h).replace(' ', "");
            assert!((parse_hours(&t).unwrap() - h).abs() < 1e-12, "{t}");
        }
    }
}
