//! The one set of limits every body is held to, and the rules for names.
//! [`Body::validate`](crate::body::model::Body::validate) applies them, and every way of
//! building or changing a body (preset, a body mass, a set parameter, a TUI edit,
//! `predict`) goes through it.

use crate::io::excerpt::is_invisible;

/// Masses (segments and body mass) lie in [`MIN_MASS`, `MAX_MASS`], 1 g to
/// 1000 t. Why a lower bound: the lightest body part anyone models (an eye,
/// a finger phalanx) weighs several grams, and with k ≤ [`MAX_K`] a gram
/// keeps k/m ≤ 1e15 s⁻² (natural frequencies below 5 MHz) and the masses of
/// one model within a ratio of 1e9, a spread an f64 solve and a balanced
/// eigenproblem still resolve. Far below it they do not: a 1e-6 kg head on
/// a 1e12 N/m link gave modes wrong in the first digit, and 1e-300 kg gave
/// frequencies of 1e296 Hz.
///
/// The upper limits are far beyond any body (a rigid joint is well modelled
/// by 1e9 N/m): past them the solve would lose every digit to cancellation
/// against the other terms, so such values are refused rather than answered.
pub const MIN_MASS: f64 = 1e-3;
pub const MAX_MASS: f64 = 1e6;
pub const MAX_K: f64 = 1e12;
pub const MAX_C: f64 = 1e10;
/// Longest seat suspension travel, m: far beyond any seat (50–150 mm).
pub const MAX_STROKE_M: f64 = 1.0;

/// Longest segment name in characters (a link's default name joins two).
pub const MAX_NAME: usize = 64;
/// Longest link name in characters: two segment names and a dash.
pub const MAX_LINK_NAME: usize = 2 * MAX_NAME + 1;

/// Whether `v` is an allowed mass (segment or body), in kg.
pub fn mass_in_range(v: f64) -> bool {
    v.is_finite() && (MIN_MASS..=MAX_MASS).contains(&v)
}

/// What an out-of-range mass `v` must be, for its error message: it says
/// "> 0" only for a value that is not (so 1e30 kg is not told so), and
/// "finite and > 0" for inf and NaN (as a share's message); always the
/// range.
pub fn mass_rule(v: f64) -> String {
    let range = format!(
        "a number from {} to {} kg",
        crate::io::excerpt::num(MIN_MASS),
        crate::io::excerpt::num(MAX_MASS)
    );
    if !v.is_finite() {
        format!("finite and > 0: {range}")
    } else if v <= 0.0 {
        format!("> 0: {range}")
    } else {
        range
    }
}

/// Why `name` cannot name a segment or link, if it cannot: it must be
/// printable on one line, reachable by a setting `NAME=VALUE` (no outer
/// spaces) and must not read as a parameter (`m2`, `K3`, `body_mass`,
/// `LINK.k`), which would make `NAME=` mean two things.
pub fn name_problem(name: &str, max_chars: usize) -> Option<&'static str> {
    if name.trim().is_empty() {
        return Some("is empty: give it a name");
    }
    if name.chars().any(|c| c.is_control() || is_invisible(c)) {
        return Some(
            "contains a control or invisible character: names must be printable text on one line",
        );
    }
    if name.chars().count() > max_chars {
        return Some("is too long: a segment name has at most 64 characters, a link name 129");
    }
    if name.contains('=') {
        return Some("contains '=': a setting NAME=VALUE could not reach it; remove the '='");
    }
    if name.trim() != name {
        return Some(
            "starts or ends with a space: a setting by name could not reach it; remove the space",
        );
    }
    let lower = name.to_ascii_lowercase();
    if is_param_word(&lower) {
        return Some(
            "reads as a parameter (mN, kN, cN, body_mass, LINK.k, LINK.c): a setting by name would be ambiguous; rename it",
        );
    }
    None
}

/// `body_mass` and its spellings, `m3`/`k3`/`c3` (as `param` parses them),
/// or anything ending in `.k` / `.c`.
fn is_param_word(lower: &str) -> bool {
    if matches!(lower, "body_mass" | "body-mass" | "mass" | "bodymass") {
        return true;
    }
    if lower.ends_with(".k") || lower.ends_with(".c") {
        return true;
    }
    let mut chars = lower.chars();
    matches!(chars.next(), Some('m' | 'k' | 'c')) && chars.as_str().parse::<usize>().is_ok()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::body::model::{Body, ModelError, Param};

    #[test]
    fn a_mass_refusal_never_contradicts_the_value() {
        let mut b = Body::paper(75.0).unwrap();
        let e = b.set(Param::BodyMass, 1e30).unwrap_err().to_string();
        assert_eq!(
            e,
            "body mass is 1e30 kg: it must be a number from 1e-3 to 1e6 kg"
        );
        let e = b.set(Param::BodyMass, -3.0).unwrap_err().to_string();
        assert!(e.contains("> 0: a number from 1e-3"), "{e}");
        let e = b.set(Param::Mass(0), 1e-6).unwrap_err().to_string();
        assert!(
            e.ends_with("a segment mass must be a number from 1e-3 to 1e6 kg"),
            "{e}"
        );
        assert!(mass_rule(f64::INFINITY).starts_with("finite"));
        assert!(mass_rule(f64::NAN).starts_with("finite"));
    }

    #[test]
    fn names_that_mislead_are_refused() {
        for bad in [
            "head\nneck",
            "a\u{1b}[31m",
            "x\u{202e}y",
            "m2",
            "K3",
            "c10",
            "k+3",
            "a=b",
            "pelvis-seat.k",
            "x.C",
            "body_mass",
            "Body-Mass",
            "mass",
            " chest",
            "chest ",
            "",
            "   ",
        ] {
            assert!(name_problem(bad, MAX_NAME).is_some(), "{bad:?} passed");
        }
        for good in [
            "head-neck",
            "m",
            "k",
            "mk2",
            "m2a",
            "chest.kk",
            "tête",
            "c-1",
        ] {
            assert_eq!(name_problem(good, MAX_NAME), None, "{good:?}");
        }
        assert!(name_problem(&"n".repeat(65), MAX_NAME).is_some());
        assert!(name_problem(&"n".repeat(65), MAX_LINK_NAME).is_none());
        let mut b = Body::paper(75.0).unwrap();
        b.segments[1].name = "m1".into();
        let e = b.validate().unwrap_err();
        assert!(
            matches!(
                e,
                ModelError::BadName {
                    what: "segment",
                    ..
                }
            ),
            "{e}"
        );
        let mut b = Body::paper(75.0).unwrap();
        b.links[2].name = "a\u{1b}b".into();
        let e = b.validate().unwrap_err().to_string();
        assert!(e.contains("a\\u{1b}b") && !e.contains('\u{1b}'), "{e}");
    }

    #[test]
    fn body_mass_limits_name_the_body_mass() {
        let mut b = Body::paper(75.0).unwrap();
        let before = b.clone();
        for bad in [1e7, 1e-300, 0.0, -1.0, f64::NAN] {
            assert!(matches!(
                b.set_body_mass(bad),
                Err(ModelError::BadBodyMass(_))
            ));
            assert!(Body::paper(bad).is_err());
        }
        // In range itself, but the head (7.5 % of it) is under a gram.
        let e = b.set_body_mass(0.01).unwrap_err();
        assert!(
            matches!(e, ModelError::BodyMassMakesBadSegment { ref segment, .. } if segment == "head-neck"),
            "{e}"
        );
        assert!(e.to_string().contains("body mass 0.01 kg"), "{e}");
        assert_eq!(b, before);
        let e = Body::paper(0.01).unwrap_err();
        assert!(
            matches!(e, ModelError::BodyMassMakesBadSegment { .. }),
            "{e}"
        );
        // A mass set by hand is named as such, not as the body mass's doing.
        let e = b.set(Param::Mass(0), 1e-9).unwrap_err();
        assert!(matches!(e, ModelError::BadMass { .. }), "{e}");
        assert!(e.to_string().contains("1e-9"), "{e}");
        // The lower limit itself is allowed.
        b.set(Param::Mass(0), MIN_MASS).unwrap();
        b.set(Param::Mass(0), MAX_MASS).unwrap();
        assert!(b.set(Param::Mass(9), 1.0).is_err());
        assert!(b.set(Param::Stiffness(9), 1.0).is_err());
    }
}
