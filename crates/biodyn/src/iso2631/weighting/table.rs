//! The weightings' definitions, one row each: the parameters of ISO 8041-1:2017
//! Table 3 (ISO 2631-1:1997 Table A.1, ISO 2631-2:2003 Annex A, ISO 2631-4:2001
//! Annex A), the band each is defined over, the quantity it weighs and what it
//! is for. A new weighting is one row here and one variant of `Weighting`.

/// Band limiting Q1 = Q2 = 1/√2 (second-order Butterworth), as ISO 8041-1
/// Table 3 gives for every weighting; ISO 2631-1 prints it rounded, 0.71,
/// and its Table 3 is computed with 1/√2.
const BUTTERWORTH: f64 = std::f64::consts::FRAC_1_SQRT_2;

/// The parameters of one weighting, ISO 8041-1 Formulae (1)–(5): frequencies
/// in Hz, `None` where the table says ∞ (the stage is then 1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Params {
    /// High-pass band limit, Hz, and its Q.
    pub f1: f64,
    pub q1: f64,
    /// Low-pass band limit, Hz, and its Q.
    pub f2: f64,
    pub q2: f64,
    /// Acceleration–velocity transition (1 + s/ω3)/(1 + s/(Q4 ω4) + (s/ω4)²):
    /// its zero (∞ for Wf: no zero) and its pole pair (∞ for Wj: no transition).
    pub f3: Option<f64>,
    pub f4: Option<f64>,
    pub q4: Option<f64>,
    /// Upward step, absent where the table gives none.
    pub step: Option<Step>,
    /// Overall gain K (1 but for Wb).
    pub k: f64,
}

/// The upward step (1 + s/(Q5 ω5) + (s/ω5)²)/(1 + s/(Q6 ω6) + (s/ω6)²)·(ω5/ω6)².
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Step {
    pub f5: f64,
    pub q5: f64,
    pub f6: f64,
    pub q6: f64,
}

/// What a weighting weighs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    /// Translational acceleration, m/s².
    Acceleration,
    /// Rotational acceleration, rad/s² (We).
    AngularAcceleration,
}

impl Quantity {
    /// The SI unit of the input (and of the weighted output).
    pub fn unit(self) -> &'static str {
        match self {
            Quantity::Acceleration => "m/s²",
            Quantity::AngularAcceleration => "rad/s²",
        }
    }
}

/// One weighting's row.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Definition {
    /// As ISO 8041-1 writes it (Wb … Wm).
    pub name: &'static str,
    pub params: Params,
    /// The nominal band it is defined over, Hz (ISO 8041-1 Table 1).
    pub band_hz: (f64, f64),
    pub quantity: Quantity,
    /// What it is for, one line.
    pub purpose: &'static str,
    /// Where the standard defines its use.
    pub standard: &'static str,
}

/// Without a transition or a step: the band limits only.
const BAND_LIMITS: Params = Params {
    f1: 0.4,
    q1: BUTTERWORTH,
    f2: 100.0,
    q2: BUTTERWORTH,
    f3: None,
    f4: None,
    q4: None,
    step: None,
    k: 1.0,
};

/// A transition with its zero and pole pair at one frequency `f`.
const fn transition(f: f64, q4: f64) -> Params {
    Params {
        f3: Some(f),
        f4: Some(f),
        q4: Some(q4),
        ..BAND_LIMITS
    }
}

const fn step(f5: f64, q5: f64, f6: f64, q6: f64) -> Option<Step> {
    Some(Step { f5, q5, f6, q6 })
}

/// The whole-body band of ISO 8041-1, Hz.
const WHOLE_BODY: (f64, f64) = (0.5, 80.0);

/// Every weighting, in the order of `Weighting::ALL` (ISO 8041-1 Table 3's):
/// `TABLE[w as usize]` is w's row.
pub const TABLE: [Definition; 8] = [
    Definition {
        name: "Wb",
        // K = 1.024: with (ω5/ω6)² = (2.5/4)² it gives BS 6841's gain 0.4.
        params: Params {
            step: step(2.5, 0.9, 4.0, 0.95),
            k: 1.024,
            ..transition(16.0, 0.55)
        },
        band_hz: WHOLE_BODY,
        quantity: Quantity::Acceleration,
        purpose: "vertical (z) on the seat in rail vehicles: ride comfort",
        standard: "ISO 2631-4",
    },
    Definition {
        name: "Wc",
        params: transition(8.0, 0.63),
        band_hz: WHOLE_BODY,
        quantity: Quantity::Acceleration,
        purpose: "backrest, fore-and-aft (x): health and comfort, seated",
        standard: "ISO 2631-1",
    },
    Definition {
        name: "Wd",
        params: transition(2.0, 0.63),
        band_hz: WHOLE_BODY,
        quantity: Quantity::Acceleration,
        purpose: "horizontal (x, y), seated, standing or recumbent: health, comfort, perception",
        standard: "ISO 2631-1",
    },
    Definition {
        name: "We",
        params: transition(1.0, 0.63),
        band_hz: WHOLE_BODY,
        quantity: Quantity::AngularAcceleration,
        purpose: "rotations of the seat (roll, pitch, yaw): comfort",
        standard: "ISO 2631-1",
    },
    Definition {
        name: "Wf",
        params: Params {
            f1: 0.08,
            f2: 0.63,
            f3: None,
            f4: Some(0.25),
            q4: Some(0.86),
            step: step(0.0625, 0.80, 0.1, 0.80),
            ..BAND_LIMITS
        },
        band_hz: (0.1, 0.5),
        quantity: Quantity::Acceleration,
        purpose: "vertical (z), motion sickness (MSDV)",
        standard: "ISO 2631-1 Annex D",
    },
    Definition {
        name: "Wj",
        // No acceleration–velocity transition: f3 = f4 = ∞.
        params: Params {
            step: step(3.75, 0.91, 5.32, 0.91),
            ..BAND_LIMITS
        },
        band_hz: WHOLE_BODY,
        quantity: Quantity::Acceleration,
        purpose: "under the head of a recumbent person, vertical (x): comfort",
        standard: "ISO 2631-1",
    },
    Definition {
        name: "Wk",
        params: Params {
            step: step(2.37, 0.91, 3.35, 0.91),
            ..transition(12.5, 0.63)
        },
        band_hz: WHOLE_BODY,
        quantity: Quantity::Acceleration,
        purpose: "vertical (z), seated, standing or recumbent: health, comfort, perception",
        standard: "ISO 2631-1",
    },
    Definition {
        name: "Wm",
        // f1 = 10^-0.1 Hz; f3 = f4 = 1/(2π·0.028 s) = 5.684 Hz with Q4 = 1/2:
        // a double real pole that the zero halves, 1/(1 + 0.028 s).
        params: Params {
            f1: 0.794_328_234_724_281_5,
            ..transition(1.0 / (0.028 * 2.0 * std::f64::consts::PI), 0.5)
        },
        band_hz: (1.0, 80.0),
        quantity: Quantity::Acceleration,
        purpose: "people in buildings, any direction: perception and comfort",
        standard: "ISO 2631-2",
    },
];

#[cfg(test)]
mod tests {
    use super::super::formula::Weighting;
    use super::*;

    /// Each weighting's purpose in the words of ISO 2631-1:1997 Tables 3
    /// and 4 (and 2631-2, 2631-4 for Wm and Wb), and what it weighs: We
    /// alone takes rotations (rad/s²).
    #[test]
    fn each_weighting_says_what_it_is_for_and_what_it_weighs() {
        let want = [
            (Weighting::Wb, "rail vehicles"),
            (Weighting::Wc, "backrest"),
            (Weighting::Wd, "horizontal (x, y)"),
            (Weighting::We, "rotations"),
            (Weighting::Wf, "motion sickness"),
            (Weighting::Wj, "head of a recumbent person"),
            (Weighting::Wk, "vertical (z), seated"),
            (Weighting::Wm, "buildings"),
        ];
        for (w, words) in want {
            assert!(w.purpose().contains(words), "{w:?}: {}", w.purpose());
            let unit = w.quantity().unit();
            if w == Weighting::We {
                assert_eq!(
                    (w.quantity(), unit),
                    (Quantity::AngularAcceleration, "rad/s²")
                );
            } else {
                assert_eq!(
                    (w.quantity(), unit),
                    (Quantity::Acceleration, "m/s²"),
                    "{w:?}"
                );
            }
        }
        assert_eq!(want.len(), Weighting::ALL.len());
    }
}
