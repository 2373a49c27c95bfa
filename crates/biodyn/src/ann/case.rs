//! The paper's six networks (SPEC §4): which body parameter varies, which
//! response magnitude is the output, and the paper's architecture and results.

use super::error::AnnError;
use crate::body::model::{Body, PAPER_K, Param};
use crate::freq::function::Function;
use serde::{Deserialize, Serialize};
use std::fmt;

/// Which parameter a case's networks are trained over.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Group {
    /// Body mass 65/75/85 kg; inputs m1..m4 and f (every segment mass on another base).
    Mass,
    /// Pelvic stiffness k4 at 75 kg; inputs k4 and f.
    K4,
}

/// One of the six networks.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Case {
    MassStht,
    MassDpmi,
    MassApms,
    K4Stht,
    K4Dpmi,
    K4Apms,
}

/// What the paper reports for a case (Table 5 and SPEC §4).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PaperRow {
    pub epochs: u64,
    pub mpre_pct: f64,
    pub rms: f64,
}

/// Body mass at which the stiffness group is trained (SPEC §4).
pub const K4_BODY_MASS: f64 = 75.0;

impl Case {
    pub const ALL: [Case; 6] = [
        Case::MassStht,
        Case::MassDpmi,
        Case::MassApms,
        Case::K4Stht,
        Case::K4Dpmi,
        Case::K4Apms,
    ];

    pub fn key(self) -> &'static str {
        match self {
            Case::MassStht => "mass-stht",
            Case::MassDpmi => "mass-dpmi",
            Case::MassApms => "mass-apms",
            Case::K4Stht => "k4-stht",
            Case::K4Dpmi => "k4-dpmi",
            Case::K4Apms => "k4-apms",
        }
    }

    pub fn parse(s: &str) -> Result<Case, AnnError> {
        let k = s.trim().to_ascii_lowercase().replace('_', "-");
        Case::ALL
            .into_iter()
            .find(|c| c.key() == k)
            .ok_or_else(|| AnnError::UnknownCase(s.to_string()))
    }

    pub fn group(self) -> Group {
        match self {
            Case::MassStht | Case::MassDpmi | Case::MassApms => Group::Mass,
            _ => Group::K4,
        }
    }

    pub fn function(self) -> Function {
        match self {
            Case::MassStht | Case::K4Stht => Function::Stht,
            Case::MassDpmi | Case::K4Dpmi => Function::Dpmi,
            Case::MassApms | Case::K4Apms => Function::Apms,
        }
    }

    /// The paper's architecture, input layer first.
    pub fn paper_layers(self) -> &'static [usize] {
        match self {
            Case::MassStht => &[5, 6, 4, 2, 1],
            Case::MassDpmi | Case::MassApms => &[5, 6, 4, 1],
            _ => &[2, 5, 3, 1],
        }
    }

    pub fn paper(self) -> PaperRow {
        let (epochs, mpre_pct, rms) = match self {
            Case::MassStht => (45_931, 1.213, 0.0015),
            Case::MassDpmi => (7_560, 2.609, 0.0022),
            Case::MassApms => (7_174, 3.743, 0.0023),
            Case::K4Stht => (14_012, 3.449, 0.0014),
            Case::K4Dpmi => (100_185, 3.938, 0.0020),
            Case::K4Apms => (101_463, 1.644, 0.0012),
        };
        PaperRow {
            epochs,
            mpre_pct,
            rms,
        }
    }

    /// Number of network inputs on the paper's body: m1..m4 + f, or k4 + f
    /// (`input_count` gives them on any base).
    pub fn inputs(self) -> usize {
        match self.group() {
            Group::Mass => 5,
            Group::K4 => 2,
        }
    }

    pub fn input_names(self) -> &'static [&'static str] {
        match self.group() {
            Group::Mass => &["m1", "m2", "m3", "m4", "f"],
            Group::K4 => &["k4", "f"],
        }
    }

    /// Name and unit of the parameter that varies across training curves.
    pub fn param_name(self) -> &'static str {
        match self.group() {
            Group::Mass => "body_mass",
            Group::K4 => "k4",
        }
    }

    pub fn param_unit(self) -> &'static str {
        match self.group() {
            Group::Mass => "kg",
            Group::K4 => "N/m",
        }
    }

    /// The paper's three training values.
    pub fn train_values(self) -> Vec<f64> {
        match self.group() {
            Group::Mass => vec![65.0, 75.0, 85.0],
            Group::K4 => vec![54_000.0, 90_000.0, 126_000.0],
        }
    }

    /// Hold-out values for prediction (paper §7): 60/70/80/90 kg, or k4 at
    /// ×0.4/×0.8/×1.2/×1.6 of the base value.
    pub fn holdout_values(self) -> Vec<f64> {
        match self.group() {
            Group::Mass => vec![60.0, 70.0, 80.0, 90.0],
            Group::K4 => [0.4, 0.8, 1.2, 1.6]
                .iter()
                .map(|x| x * PAPER_K[3])
                .collect(),
        }
    }

    /// The paper's body a curve of this case is computed on (`body_on`
    /// builds it on any base).
    pub fn body_at(self, value: f64) -> Result<Body, AnnError> {
        match self.group() {
            Group::Mass => Ok(Body::paper(value)?),
            Group::K4 => {
                let mut b = Body::paper(K4_BODY_MASS)?;
                b.set(Param::Stiffness(3), value)?;
                Ok(b)
            }
        }
    }

    /// The value of the case's parameter in `body`: body mass or k4.
    pub fn value_of(self, body: &Body) -> f64 {
        match self.group() {
            Group::Mass => body.get(Param::BodyMass),
            // NaN on a body without a 4th link (which no k4 net takes).
            Group::K4 => body.links.get(3).map_or(f64::NAN, |l| l.k),
        }
    }

    /// Index of the frequency among the inputs (the last one).
    pub fn freq_input(self) -> usize {
        self.inputs() - 1
    }
}

impl fmt::Display for Case {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.key())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_round_trip_and_architectures_fit_inputs() {
        for c in Case::ALL {
            assert_eq!(Case::parse(c.key()).unwrap(), c);
            assert_eq!(c.paper_layers()[0], c.inputs());
            assert_eq!(*c.paper_layers().last().unwrap(), 1);
        }
        assert!(Case::parse("mass-xyz").is_err());
    }

    #[test]
    fn k4_body_has_the_value_and_mass_body_the_shares() {
        let b = Case::K4Stht.body_at(54_000.0).unwrap();
        assert_eq!(b.links[3].k, 54_000.0);
        let x = Case::MassStht.inputs_of(&Case::MassStht.body_at(65.0).unwrap(), 2.0);
        assert_eq!(
            x.unwrap(),
            vec![0.075 * 65.0, 0.402 * 65.0, 0.122 * 65.0, 0.182 * 65.0, 2.0]
        );
    }
}
