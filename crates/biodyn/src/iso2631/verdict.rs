//! Judging the numbers: the EU Directive 2002/44/EC action and limit values,
//! the comfort words of ISO 2631-1 Annex C, and the checks that call for the
//! additional methods.

use super::metrics::{Exposure, Metrics};

/// EU 2002/44/EC, whole body: action and limit values for A(8) (m/s²) and
/// VDV (m/s^1.75).
pub const A8_ACTION: f64 = 0.5;
pub const A8_LIMIT: f64 = 1.15;
pub const VDV_ACTION: f64 = 9.1;
pub const VDV_LIMIT: f64 = 21.0;

/// Where an exposure stands against the Directive. A value equal to a
/// threshold has not exceeded it (the Directive acts when a value is exceeded).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Verdict {
    BelowAction,
    AboveAction,
    AboveLimit,
}

impl Verdict {
    pub fn judge(value: f64, action: f64, limit: f64) -> Verdict {
        if value > limit {
            Verdict::AboveLimit
        } else if value > action {
            Verdict::AboveAction
        } else {
            Verdict::BelowAction
        }
    }

    pub fn words(self) -> &'static str {
        match self {
            Verdict::BelowAction => "below action value",
            Verdict::AboveAction => "above action value",
            Verdict::AboveLimit => "above limit value",
        }
    }
}

/// Both EU verdicts of one exposure.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Eu {
    pub a8: Verdict,
    pub vdv: Verdict,
}

impl Eu {
    pub fn of(e: &Exposure) -> Eu {
        Eu {
            a8: Verdict::judge(e.a8, A8_ACTION, A8_LIMIT),
            vdv: Verdict::judge(e.vdv, VDV_ACTION, VDV_LIMIT),
        }
    }
}

/// ISO 2631-1 Annex C: likely reactions on public transport, by a_w (m/s²).
/// The bands overlap on purpose; each is [from, to).
pub const COMFORT: [(f64, f64, &str); 6] = [
    (0.0, 0.315, "not uncomfortable"),
    (0.315, 0.63, "a little uncomfortable"),
    (0.5, 1.0, "fairly uncomfortable"),
    (0.8, 1.6, "uncomfortable"),
    (1.25, 2.5, "very uncomfortable"),
    (2.0, f64::INFINITY, "extremely uncomfortable"),
];

/// Every comfort word whose band holds `aw` (two where the bands overlap).
pub fn comfort(aw: f64) -> Vec<&'static str> {
    COMFORT
        .iter()
        .filter(|(lo, hi, _)| aw >= *lo && aw < *hi)
        .map(|(_, _, w)| *w)
        .collect()
}

/// `v` with `decimals`, or as many more (up to 6) as it takes to read above
/// `limit`: a crest factor of 9.04 is "9.04 > 9", not "9.0 > 9".
pub fn above(v: f64, limit: f64, decimals: usize) -> String {
    (decimals..=6)
        .map(|d| format!("{v:.d$}"))
        .find(|s| s.parse::<f64>().is_ok_and(|x| x > limit))
        .unwrap_or_else(|| format!("{v}"))
}

/// The checks of ISO 2631-1 §6.3 that call for the additional methods
/// (running r.m.s., VDV): one sentence per check that fires.
pub fn additional_methods(m: &Metrics) -> Vec<String> {
    let mut v = Vec::new();
    if m.crest > 9.0 {
        v.push(format!(
            "crest factor {} > 9: the basic r.m.s. method may underestimate; judge by MTVV and VDV too",
            above(m.crest, 9.0, 1)
        ));
    }
    if m.mtvv_ratio() > 1.5 {
        v.push(format!(
            "MTVV/a_w = {} > 1.5: occasional shocks; judge by MTVV and VDV too",
            above(m.mtvv_ratio(), 1.5, 2)
        ));
    }
    if m.vdv_ratio() > 1.75 {
        v.push(format!(
            "VDV/(a_w T^1/4) = {} > 1.75: occasional shocks; judge by VDV too",
            above(m.vdv_ratio(), 1.75, 2)
        ));
    }
    v
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A value just past a limit never prints as the limit: "9.0 > 9" read
    /// as a contradiction (issue 19 item 23).
    #[test]
    fn a_value_above_its_limit_prints_above_it() {
        assert_eq!(above(9.04, 9.0, 1), "9.04");
        assert_eq!(above(9.0004, 9.0, 1), "9.0004");
        assert_eq!(above(12.34, 9.0, 1), "12.3");
        assert_eq!(above(1.5001, 1.5, 2), "1.5001");
        assert_eq!(above(1.77, 1.75, 2), "1.77");
        let m = Metrics {
            aw: 1.0,
            peak: 9.04,
            crest: 9.04,
            mtvv: 1.0,
            vdv: 1.0,
            duration_s: 1.0,
        };
        let s = additional_methods(&m);
        assert!(s[0].starts_with("crest factor 9.04 > 9"), "{s:?}");
    }

    /// ISO 2631-1 §6.3.1: the additional methods are called for *above*
    /// a crest factor of 9, MTVV/a_w 1.5 and VDV/(a_w T^¼) 1.75; at the
    /// values themselves the basic method stands.
    #[test]
    fn the_checks_fire_above_their_values_not_at_them() {
        // a_w 2, T 16 s (T^¼ = 2): MTVV 3 is 1.5·a_w, VDV 7 is 1.75·a_w·T^¼.
        let at = Metrics {
            aw: 2.0,
            peak: 18.0,
            crest: 9.0,
            mtvv: 3.0,
            vdv: 7.0,
            duration_s: 16.0,
        };
        assert_eq!((at.mtvv_ratio(), at.vdv_ratio()), (1.5, 1.75));
        assert!(additional_methods(&at).is_empty());
        let up = |f: &dyn Fn(&mut Metrics)| {
            let mut m = at;
            f(&mut m);
            additional_methods(&m)
        };
        assert!(up(&|m| m.crest = 9.001)[0].starts_with("crest factor"));
        assert!(up(&|m| m.mtvv = 3.001)[0].starts_with("MTVV/a_w"));
        assert!(up(&|m| m.vdv = 7.001)[0].starts_with("VDV/(a_w"));
    }
}
