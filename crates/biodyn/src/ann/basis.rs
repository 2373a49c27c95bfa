//! The body a case's networks train on: the paper's (no base, the default)
//! or any model the user chooses (`Settings::base`). From the case and the
//! base come the body at each training value, the network's inputs and
//! their names, and the default training and hold-out values, scaled from
//! the paper's by the base's own body mass or k4.
//!
//! ```
//! use biodyn::ann::Case;
//! use biodyn::Body;
//! let base = Body::paper(85.0).unwrap();
//! // Mass cases: every segment mass and f; 85 kg × 65/75, × 75/75, × 85/75.
//! assert_eq!(Case::MassApms.input_count(Some(&base)), 5);
//! assert_eq!(Case::MassApms.train_values_on(Some(&base))[1], 85.0);
//! // The paper's own body gives the paper's numbers exactly.
//! let paper = Body::paper(75.0).unwrap();
//! assert_eq!(Case::K4Stht.train_values_on(Some(&paper)), Case::K4Stht.train_values());
//! ```

use super::case::{Case, Group, K4_BODY_MASS};
use super::error::AnnError;
use crate::body::model::{Body, PAPER_K, Param};

/// Most segments a mass case takes (one input per segment mass): a model
/// of thousands of segments would make a network of thousands of inputs.
pub const MAX_SEGMENTS: usize = 64;

/// Link 4, the one k4 cases vary (0-based).
const K4_LINK: usize = 3;

impl Case {
    /// Checks that the case can train on `base` (None: the paper's body,
    /// always fine): a valid body, at most `MAX_SEGMENTS` segments for a
    /// mass case, a 4th link for a k4 case.
    pub fn check_base(self, base: Option<&Body>) -> Result<(), AnnError> {
        let Some(b) = base else {
            return Ok(());
        };
        b.validate().map_err(AnnError::BadBase)?;
        self.check_body(b)
    }

    /// The shape checks of `check_base`, for any body the case reads inputs from.
    fn check_body(self, b: &Body) -> Result<(), AnnError> {
        match self.group() {
            Group::Mass if b.n() > MAX_SEGMENTS => Err(AnnError::TooManySegments {
                n: b.n(),
                max: MAX_SEGMENTS,
            }),
            Group::K4 if b.links.len() <= K4_LINK => Err(AnnError::NoK4Link(b.links.len())),
            _ => Ok(()),
        }
    }

    /// Number of network inputs on `base`: every segment mass and f, or k4
    /// and f (the paper's 5 and 2 without a base).
    pub fn input_count(self, base: Option<&Body>) -> usize {
        match (self.group(), base) {
            (Group::Mass, Some(b)) => b.n() + 1,
            _ => self.inputs(),
        }
    }

    /// The inputs' names: m1..mn and f, or k4 and f.
    pub fn input_names_on(self, base: Option<&Body>) -> Vec<String> {
        match (self.group(), base) {
            (Group::Mass, Some(b)) => (1..=b.n())
                .map(|i| format!("m{i}"))
                .chain(std::iter::once("f".to_string()))
                .collect(),
            _ => self.input_names().iter().map(|s| s.to_string()).collect(),
        }
    }

    /// The base's own value of the case's parameter: its body mass or its
    /// k4 (the paper's 75 kg and 90000 N/m without a base).
    pub fn base_value(self, base: Option<&Body>) -> f64 {
        match (self.group(), base) {
            (Group::Mass, None) => K4_BODY_MASS,
            (Group::K4, None) => PAPER_K[K4_LINK],
            (_, Some(b)) if self.group() == Group::K4 && b.links.len() <= K4_LINK => f64::NAN,
            (_, Some(b)) => self.value_of(b),
        }
    }

    /// Default training values on `base`: the paper's three scaled by the
    /// base's value (computed as v·65/75 so that the paper's body gives
    /// exactly 65, 75, 85 kg or 54000, 90000, 126000 N/m).
    pub fn train_values_on(self, base: Option<&Body>) -> Vec<f64> {
        let Some(_) = base else {
            return self.train_values();
        };
        let v = self.base_value(base);
        match self.group() {
            Group::Mass => [65.0, 75.0, 85.0].iter().map(|x| (v * x) / 75.0).collect(),
            Group::K4 => [54_000.0, 90_000.0, 126_000.0]
                .iter()
                .map(|x| (v * x) / 90_000.0)
                .collect(),
        }
    }

    /// Default hold-out values on `base`: body mass × 60/70/80/90 ÷ 75, or
    /// k4 × 0.4/0.8/1.2/1.6.
    pub fn holdout_values_on(self, base: Option<&Body>) -> Vec<f64> {
        let Some(_) = base else {
            return self.holdout_values();
        };
        let v = self.base_value(base);
        match self.group() {
            Group::Mass => [60.0, 70.0, 80.0, 90.0]
                .iter()
                .map(|x| (v * x) / 75.0)
                .collect(),
            Group::K4 => [0.4, 0.8, 1.2, 1.6].iter().map(|x| x * v).collect(),
        }
    }

    /// The body a curve at `value` is computed on. Mass cases: the base at
    /// that body mass (by its shares when every segment has one, else every
    /// segment scaled in proportion); k4 cases: the base with k4 = value.
    /// Without a base, the paper's body (at 75 kg for k4 cases).
    pub fn body_on(self, base: Option<&Body>, value: f64) -> Result<Body, AnnError> {
        let Some(base) = base else {
            return self.body_at(value);
        };
        self.check_base(Some(base))?;
        let mut b = base.clone();
        match self.group() {
            Group::Mass => b = at_body_mass(base, value)?,
            Group::K4 => b.set(Param::Stiffness(K4_LINK), value)?,
        }
        Ok(b)
    }

    /// The network's physical inputs for `body` at `f_hz`: every segment
    /// mass and f (mass cases), or k4 and f.
    pub fn inputs_of(self, body: &Body, f_hz: f64) -> Result<Vec<f64>, AnnError> {
        self.check_body(body)?;
        Ok(match self.group() {
            Group::Mass => body
                .segments
                .iter()
                .map(|s| s.mass)
                .chain(std::iter::once(f_hz))
                .collect(),
            Group::K4 => vec![body.get(Param::Stiffness(K4_LINK)), f_hz],
        })
    }
}

/// `base` at body mass `kg`, as the mass cases build it: by the shares
/// when every segment has one, else every segment × kg / the base's body
/// mass (proportions kept; a body mass stored on the base follows).
pub fn at_body_mass(base: &Body, kg: f64) -> Result<Body, AnnError> {
    let mut b = base.clone();
    if b.segments.iter().all(|s| s.share.is_some()) {
        b.set_body_mass(kg)?;
        return Ok(b);
    }
    if !(kg.is_finite() && kg > 0.0) {
        return Err(AnnError::BadTrainValue {
            param: "body_mass",
            value: kg,
        });
    }
    let from = base.get(Param::BodyMass);
    for s in &mut b.segments {
        s.mass = s.mass * kg / from;
    }
    if b.body_mass.is_some() {
        b.body_mass = Some(kg);
    }
    b.validate()?;
    Ok(b)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::body::model::{End, Link, Segment};

    fn five() -> Body {
        let segs = ["a", "b", "c", "d", "e"]
            .iter()
            .zip([4.0, 20.0, 8.0, 10.0, 6.0])
            .map(|(n, m)| Segment::new(n, m))
            .collect();
        Body::chain(
            segs,
            &[3e5, 2e5, 1.6e5, 9e4, 5e4],
            &[400.0, 4000.0, 4000.0, 2000.0, 1000.0],
        )
    }

    #[test]
    fn the_paper_body_gives_the_paper_numbers_exactly() {
        let paper = Body::paper(75.0).unwrap();
        for c in Case::ALL {
            assert_eq!(c.train_values_on(Some(&paper)), c.train_values(), "{c}");
            assert_eq!(c.holdout_values_on(Some(&paper)), c.holdout_values(), "{c}");
            assert_eq!(c.input_count(Some(&paper)), c.inputs());
            assert_eq!(c.input_names_on(Some(&paper)), c.input_names_on(None));
            for v in c.train_values() {
                assert_eq!(c.body_on(Some(&paper), v).unwrap(), c.body_at(v).unwrap());
            }
        }
    }

    #[test]
    fn a_body_without_shares_scales_in_proportion() {
        let b = five();
        let c = Case::MassDpmi;
        assert_eq!(c.input_count(Some(&b)), 6);
        assert_eq!(
            c.input_names_on(Some(&b)),
            ["m1", "m2", "m3", "m4", "m5", "f"]
        );
        assert_eq!(c.base_value(Some(&b)), 48.0);
        assert_eq!(c.train_values_on(Some(&b)), [41.6, 48.0, 54.4]);
        let at = c.body_on(Some(&b), 96.0).unwrap();
        assert_eq!(at.segments[1].mass, 40.0);
        assert_eq!(at.seated_mass(), 96.0);
        assert_eq!(at.links, b.links);
        assert_eq!(c.inputs_of(&at, 3.0).unwrap().len(), 6);
    }

    #[test]
    fn k4_needs_a_fourth_link_and_mass_a_bounded_model() {
        let mut b = five();
        b.segments.truncate(3);
        b.links.truncate(3);
        b.links[2].lower = End::Seat;
        b.validate().unwrap();
        let e = Case::K4Apms.check_base(Some(&b)).unwrap_err().to_string();
        assert!(e.contains("3 links") && e.contains("mass case"), "{e}");
        assert!(Case::K4Apms.body_on(Some(&b), 5e4).is_err());
        assert!(Case::MassApms.check_base(Some(&b)).is_ok());
        let segs = (0..65)
            .map(|i| Segment::new(&format!("s{i}"), 1.0))
            .collect();
        let big = Body::chain(segs, &[1e5; 65], &[1e3; 65]);
        let e = Case::MassStht
            .check_base(Some(&big))
            .unwrap_err()
            .to_string();
        assert!(e.contains("65 segments") && e.contains("64"), "{e}");
        let mut bad = five();
        bad.links.push(Link::new("x", 0, End::Segment(9), 1.0, 1.0));
        let e = Case::MassStht
            .check_base(Some(&bad))
            .unwrap_err()
            .to_string();
        assert!(e.contains("model"), "{e}");
    }

    #[test]
    fn k4_on_a_base_keeps_its_masses() {
        let b = Body::paper(85.0).unwrap();
        let at = Case::K4Dpmi.body_on(Some(&b), 1e5).unwrap();
        assert_eq!(at.links[3].k, 1e5);
        assert_eq!(at.segments, b.segments);
        assert_eq!(
            Case::K4Dpmi.train_values_on(Some(&b)),
            [54_000.0, 90_000.0, 126_000.0]
        );
    }
}
