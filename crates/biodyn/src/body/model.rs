//! The lumped-parameter body: rigid segments joined by Kelvin–Voigt links.
//!
//! A link joins two segments, or one segment and the seat (the prescribed
//! motion x0). Nothing here assumes a chain: branched models (a viscera mass
//! hanging off the torso, say) are as valid as the paper's serial 4-DOF model.

pub use super::limits::{
    MAX_C, MAX_K, MAX_LINK_NAME, MAX_MASS, MAX_NAME, MIN_MASS, mass_in_range, name_problem,
};
use crate::io::excerpt::{num, quote};
use serde::{Deserialize, Serialize};
use std::fmt;

/// Validation failures; each names the offending field and value.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ModelError {
    #[error("the model has no segments: give at least one [[segment]]")]
    NoSegments,
    #[error("segment {index} has an empty name: every segment needs a unique name")]
    EmptyName { index: usize },
    #[error("segment name '{0}' is used twice: segment names must be unique")]
    DuplicateSegment(String),
    #[error("link name '{0}' is used twice: link names must be unique")]
    DuplicateLink(String),
    #[error(
        "mass of segment '{segment}' is {} kg: a segment mass must be > 0: a number from {} to {} kg",
        num(*.value), num(MIN_MASS), num(MAX_MASS)
    )]
    BadMass { segment: String, value: f64 },
    #[error(
        "share of segment '{segment}' is {}: a share of body mass must be finite and > 0",
        num(*.value)
    )]
    BadShare { segment: String, value: f64 },
    #[error(
        "body mass is {} kg: it must be > 0: a number from {} to {} kg",
        num(*.0), num(MIN_MASS), num(MAX_MASS)
    )]
    BadBodyMass(f64),
    #[error(
        "body mass {} kg makes segment '{segment}' {} kg (share {} of it): a segment mass must be from {} to {} kg",
        num(*.body_mass), num(*.mass), num(*.share), num(MIN_MASS), num(MAX_MASS)
    )]
    BodyMassMakesBadSegment {
        body_mass: f64,
        segment: String,
        share: f64,
        mass: f64,
    },
    #[error("{what} name \"{name}\" {why}")]
    BadName {
        /// "segment" or "link".
        what: &'static str,
        /// The name, escaped and cut short for printing.
        name: String,
        why: &'static str,
    },
    #[error(
        "{field} of link '{link}' is {}: stiffness must be in [0, 1e12] N/m and damping in [0, 1e10] N·s/m",
        num(*.value)
    )]
    BadLinkValue {
        link: String,
        field: &'static str,
        value: f64,
    },
    #[error("link '{link}' refers to segment index {index}, but the model has {count} segments")]
    BadLinkEnd {
        link: String,
        index: usize,
        count: usize,
    },
    #[error("link '{0}' joins a segment to itself: a link needs two different ends")]
    SelfLink(String),
    #[error("no link reaches the seat: add a link with lower = \"seat\"")]
    NoSeatLink,
    #[error(
        "segment '{0}' is not tied to the seat through any chain of links: its motion would be undetermined"
    )]
    Floating(String),
    #[error("head index {index} is out of range: the model has {count} segments")]
    BadHead { index: usize, count: usize },
    #[error(
        "segment '{0}' has no share of body mass, so a body mass cannot set it: give every segment a share, or set masses directly"
    )]
    NoShare(String),
    #[error(
        "unknown parameter '{0}': use m1..mN, k1..kN, c1..cN, body_mass, a segment name, or <link>.k / <link>.c"
    )]
    UnknownParam(String),
}

/// One rigid mass of the body.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Segment {
    pub name: String,
    /// Mass in kg.
    pub mass: f64,
    /// Anthropometric share of total body mass, when the model is built the
    /// paper's way (segment mass = share × body mass).
    pub share: Option<f64>,
}

impl Segment {
    /// A segment with a mass set directly (no share of body mass).
    pub fn new(name: &str, mass: f64) -> Segment {
        Segment {
            name: name.to_string(),
            mass,
            share: None,
        }
    }
}

impl Link {
    pub fn new(name: &str, upper: usize, lower: End, k: f64, c: f64) -> Link {
        Link {
            name: name.to_string(),
            upper,
            lower,
            k,
            c,
        }
    }
}

/// The lower end of a link: another segment, or the seat.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum End {
    Segment(usize),
    Seat,
}

/// A spring k (N/m) in parallel with a damper c (N·s/m).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Link {
    pub name: String,
    /// Index of the upper segment.
    pub upper: usize,
    pub lower: End,
    pub k: f64,
    pub c: f64,
}

/// A seated body: segments, links, and which segment is the head (for STHT).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Body {
    pub segments: Vec<Segment>,
    pub links: Vec<Link>,
    pub head: usize,
    /// Total body mass in kg when the masses came from shares.
    pub body_mass: Option<f64>,
}

/// A scalar parameter of a body that studies and `--set` can change.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Param {
    /// Total body mass: rescales every segment by its share.
    BodyMass,
    /// Mass of segment i (0-based, top to bottom).
    Mass(usize),
    /// Stiffness of link i (0-based, in declaration order).
    Stiffness(usize),
    /// Damping of link i.
    Damping(usize),
}

/// The paper's anthropometric shares (SPEC §1), top to bottom.
pub const PAPER_SHARES: [f64; 4] = [0.075, 0.402, 0.122, 0.182];
/// Table 1 stiffnesses k1..k4 in N/m.
pub const PAPER_K: [f64; 4] = [310_000.0, 183_000.0, 162_800.0, 90_000.0];
/// Table 1 dampings c1..c4 in N·s/m.
pub const PAPER_C: [f64; 4] = [400.0, 4_750.0, 4_585.0, 2_064.0];
/// Segment names of the paper's model, top to bottom.
pub const PAPER_SEGMENTS: [&str; 4] = ["head-neck", "chest", "lower-torso", "pelvis"];

impl Body {
    /// The Boileau & Rakheja serial chain with the paper's shares × `body_mass`.
    pub fn paper(body_mass: f64) -> Result<Body, ModelError> {
        let segments = PAPER_SEGMENTS
            .iter()
            .zip(PAPER_SHARES)
            .map(|(name, share)| Segment {
                name: (*name).to_string(),
                mass: share * body_mass,
                share: Some(share),
            })
            .collect();
        let mut body = Body::chain(segments, &PAPER_K, &PAPER_C);
        body.body_mass = Some(body_mass);
        body.validate()?;
        Ok(body)
    }

    /// A serial chain: link i joins segment i to i+1, the last one to the seat.
    /// Link names are "`upper`-`lower`" (e.g. "pelvis-seat"). `k` and `c` must have one entry per segment.
    pub fn chain(segments: Vec<Segment>, k: &[f64], c: &[f64]) -> Body {
        let n = segments.len();
        let links = (0..n)
            .map(|i| {
                let lower = if i + 1 < n {
                    End::Segment(i + 1)
                } else {
                    End::Seat
                };
                let lower_name = match lower {
                    End::Segment(j) => segments[j].name.as_str(),
                    End::Seat => "seat",
                };
                Link {
                    name: format!("{}-{}", segments[i].name, lower_name),
                    upper: i,
                    lower,
                    k: k.get(i).copied().unwrap_or(0.0),
                    c: c.get(i).copied().unwrap_or(0.0),
                }
            })
            .collect();
        Body {
            segments,
            links,
            head: 0,
            body_mass: None,
        }
    }

    pub fn n(&self) -> usize {
        self.segments.len()
    }

    /// Σ m_i: the mass the seat carries, the low-frequency limit of APMS.
    pub fn seated_mass(&self) -> f64 {
        self.segments.iter().map(|s| s.mass).sum()
    }

    /// Checks every rule that the physics needs; the first failure is returned.
    pub fn validate(&self) -> Result<(), ModelError> {
        let mut segment_names = std::collections::HashSet::new();
        let mut link_names = std::collections::HashSet::new();
        let n = self.n();
        if n == 0 {
            return Err(ModelError::NoSegments);
        }
        if let Some(bm) = self.body_mass
            && !mass_in_range(bm)
        {
            return Err(ModelError::BadBodyMass(bm));
        }
        for (i, s) in self.segments.iter().enumerate() {
            if s.name.trim().is_empty() {
                return Err(ModelError::EmptyName { index: i + 1 });
            }
            if let Some(why) = name_problem(&s.name, MAX_NAME) {
                return Err(ModelError::BadName {
                    what: "segment",
                    name: quote(&s.name),
                    why,
                });
            }
            if !segment_names.insert(s.name.as_str()) {
                return Err(ModelError::DuplicateSegment(quote(&s.name)));
            }
            if let Some(share) = s.share
                && !(share.is_finite() && share > 0.0)
            {
                return Err(ModelError::BadShare {
                    segment: quote(&s.name),
                    value: share,
                });
            }
            if !mass_in_range(s.mass) {
                // A mass that is share × body mass is the body mass's doing:
                // name what the user set.
                if let (Some(share), Some(bm)) = (s.share, self.body_mass)
                    && (share * bm).to_bits() == s.mass.to_bits()
                {
                    return Err(ModelError::BodyMassMakesBadSegment {
                        body_mass: bm,
                        segment: quote(&s.name),
                        share,
                        mass: s.mass,
                    });
                }
                return Err(ModelError::BadMass {
                    segment: quote(&s.name),
                    value: s.mass,
                });
            }
        }
        if self.head >= n {
            return Err(ModelError::BadHead {
                index: self.head,
                count: n,
            });
        }
        for l in &self.links {
            if let Some(why) = name_problem(&l.name, MAX_LINK_NAME) {
                return Err(ModelError::BadName {
                    what: "link",
                    name: quote(&l.name),
                    why,
                });
            }
            if !link_names.insert(l.name.as_str()) {
                return Err(ModelError::DuplicateLink(quote(&l.name)));
            }
            for (field, value, max) in [("k (stiffness)", l.k, MAX_K), ("c (damping)", l.c, MAX_C)]
            {
                if !(value.is_finite() && value >= 0.0 && value <= max) {
                    return Err(ModelError::BadLinkValue {
                        link: quote(&l.name),
                        field,
                        value,
                    });
                }
            }
            let ends = [Some(l.upper), self.lower_index(l)];
            for idx in ends.into_iter().flatten() {
                if idx >= n {
                    return Err(ModelError::BadLinkEnd {
                        link: quote(&l.name),
                        index: idx,
                        count: n,
                    });
                }
            }
            if l.lower == End::Segment(l.upper) {
                return Err(ModelError::SelfLink(quote(&l.name)));
            }
        }
        if !self.links.iter().any(|l| l.lower == End::Seat) {
            return Err(ModelError::NoSeatLink);
        }
        // Flood-fill from the seat through the links; any segment not reached
        // would make K singular at zero frequency. Linear in the model's
        // size: a 4 MB preset holds tens of thousands of segments.
        let mut reached = vec![false; n];
        let mut next_to: Vec<Vec<usize>> = vec![Vec::new(); n];
        let mut stack = Vec::new();
        // A link with k = c = 0 carries no force and ties nothing.
        for l in self.links.iter().filter(|l| l.k > 0.0 || l.c > 0.0) {
            match l.lower {
                End::Seat => stack.push(l.upper),
                End::Segment(j) => {
                    next_to[l.upper].push(j);
                    next_to[j].push(l.upper);
                }
            }
        }
        while let Some(i) = stack.pop() {
            if !std::mem::replace(&mut reached[i], true) {
                stack.extend(next_to[i].iter().copied().filter(|&j| !reached[j]));
            }
        }
        if let Some(i) = reached.iter().position(|r| !r) {
            return Err(ModelError::Floating(quote(&self.segments[i].name)));
        }
        Ok(())
    }

    fn lower_index(&self, l: &Link) -> Option<usize> {
        match l.lower {
            End::Segment(j) => Some(j),
            End::Seat => None,
        }
    }

    /// Rescales every segment to share × `kg`; needs a share on every segment.
    /// The body is re-validated; on error it is unchanged, and the error
    /// names the body mass (and the segment it pushed out of range).
    pub fn set_body_mass(&mut self, kg: f64) -> Result<(), ModelError> {
        if !mass_in_range(kg) {
            return Err(ModelError::BadBodyMass(kg));
        }
        if let Some(s) = self.segments.iter().find(|s| s.share.is_none()) {
            return Err(ModelError::NoShare(quote(&s.name)));
        }
        let mut next = self.clone();
        for s in &mut next.segments {
            s.mass = s.share.unwrap_or(0.0) * kg;
        }
        next.body_mass = Some(kg);
        next.validate()?;
        *self = next;
        Ok(())
    }

    /// Resolves a user-facing parameter name: `body_mass`, `m1`.., `k1`..,
    /// `c1`.. (numbered top to bottom), a segment name (its mass), or a link
    /// name with `.k` / `.c`.
    pub fn param(&self, name: &str) -> Result<Param, ModelError> {
        let unknown = || ModelError::UnknownParam(quote(name));
        let lower = name.trim().to_ascii_lowercase();
        if matches!(
            lower.as_str(),
            "body_mass" | "body-mass" | "mass" | "bodymass"
        ) {
            return Ok(Param::BodyMass);
        }
        if let Some(seg) = self.segments.iter().position(|s| s.name == name.trim()) {
            return Ok(Param::Mass(seg));
        }
        if let Some((link, what)) = name.trim().rsplit_once('.')
            && let Some(i) = self.links.iter().position(|l| l.name == link)
        {
            return match what {
                "k" => Ok(Param::Stiffness(i)),
                "c" => Ok(Param::Damping(i)),
                _ => Err(unknown()),
            };
        }
        // The first character may be more than one byte (`é1`): split on a char.
        let mut chars = lower.chars();
        let kind = chars.next().ok_or_else(unknown)?;
        let idx: usize = chars.as_str().parse().map_err(|_| unknown())?;
        if idx == 0 {
            return Err(unknown());
        }
        let i = idx - 1;
        match kind {
            'm' if i < self.n() => Ok(Param::Mass(i)),
            'k' if i < self.links.len() => Ok(Param::Stiffness(i)),
            'c' if i < self.links.len() => Ok(Param::Damping(i)),
            _ => Err(unknown()),
        }
    }

    /// Current value of a parameter. Body mass falls back to Σm / Σshare
    /// when it was never set explicitly, or to the seated mass without shares.
    pub fn get(&self, p: Param) -> f64 {
        match p {
            Param::BodyMass => self.body_mass.unwrap_or_else(|| self.seated_mass()),
            Param::Mass(i) => self.segments[i].mass,
            Param::Stiffness(i) => self.links[i].k,
            Param::Damping(i) => self.links[i].c,
        }
    }

    /// Sets a parameter and re-validates; on error the body is unchanged.
    pub fn set(&mut self, p: Param, value: f64) -> Result<(), ModelError> {
        let exists = match p {
            Param::BodyMass => true,
            Param::Mass(i) => i < self.n(),
            Param::Stiffness(i) | Param::Damping(i) => i < self.links.len(),
        };
        if !exists {
            return Err(ModelError::UnknownParam(self.label(p)));
        }
        let mut next = self.clone();
        match p {
            Param::BodyMass => next.set_body_mass(value)?,
            Param::Mass(i) => {
                // Checked here so the error names the mass typed, not a body mass.
                if !mass_in_range(value) {
                    return Err(ModelError::BadMass {
                        segment: quote(&next.segments[i].name),
                        value,
                    });
                }
                // Keep the share in step with a mass set by hand, so a later
                // body-mass change scales what the user sees, not the old share.
                let seg = &mut next.segments[i];
                seg.mass = value;
                if let (Some(_), Some(bm)) = (seg.share, next.body_mass) {
                    seg.share = Some(value / bm);
                }
            }
            Param::Stiffness(i) => next.links[i].k = value,
            Param::Damping(i) => next.links[i].c = value,
        }
        next.validate()?;
        *self = next;
        Ok(())
    }

    /// Short label of a parameter as the paper writes it (m1, k4, …) or "body mass".
    pub fn label(&self, p: Param) -> String {
        match p {
            Param::BodyMass => "body mass".into(),
            Param::Mass(i) => format!("m{}", i + 1),
            Param::Stiffness(i) => format!("k{}", i + 1),
            Param::Damping(i) => format!("c{}", i + 1),
        }
    }

    /// True when every link joins i to i+1 or i to the seat: then A(ω) is
    /// tridiagonal and the O(n) solve applies.
    pub fn is_tridiagonal(&self) -> bool {
        self.links.iter().all(|l| match l.lower {
            End::Segment(j) => j.abs_diff(l.upper) == 1,
            End::Seat => true,
        })
    }
}

impl Param {
    /// Unit of the parameter's value, for labels.
    pub fn unit(self) -> &'static str {
        match self {
            Param::BodyMass | Param::Mass(_) => "kg",
            Param::Stiffness(_) => "N/m",
            Param::Damping(_) => "N·s/m",
        }
    }
}

impl fmt::Display for End {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            End::Segment(i) => write!(f, "segment {}", i + 1),
            End::Seat => f.write_str("seat"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paper_model_is_valid_chain() {
        let b = Body::paper(75.0).unwrap();
        assert_eq!(b.n(), 4);
        assert!(b.is_tridiagonal());
        assert!((b.seated_mass() - 0.781 * 75.0).abs() < 1e-12);
        assert_eq!(b.links[3].lower, End::Seat);
        assert_eq!(b.links[3].name, "pelvis-seat");
    }

    #[test]
    fn validation_names_the_field() {
        let mut b = Body::paper(75.0).unwrap();
        b.segments[2].mass = -1.0;
        let e = b.validate().unwrap_err().to_string();
        assert!(e.contains("lower-torso") && e.contains("-1"), "{e}");

        let mut b = Body::paper(75.0).unwrap();
        b.links[0].k = 1e50;
        assert!(matches!(b.validate(), Err(ModelError::BadLinkValue { .. })));

        let mut b = Body::paper(75.0).unwrap();
        b.links[1].c = f64::NAN;
        assert!(matches!(b.validate(), Err(ModelError::BadLinkValue { .. })));

        let mut b = Body::paper(75.0).unwrap();
        b.links[3].lower = End::Segment(0);
        assert_eq!(b.validate(), Err(ModelError::NoSeatLink));

        let mut b = Body::paper(75.0).unwrap();
        b.segments[1].name = "head-neck".into();
        assert!(matches!(b.validate(), Err(ModelError::DuplicateSegment(_))));
    }

    #[test]
    fn floating_segment_is_rejected() {
        let mut b = Body::paper(75.0).unwrap();
        // Cut the chest from the lower torso: head and chest float.
        b.links.remove(1);
        assert_eq!(
            b.validate(),
            Err(ModelError::Floating("head-neck".to_string()))
        );
    }

    #[test]
    fn a_link_with_nothing_in_it_ties_nothing() {
        let mut b = Body::paper(75.0).unwrap();
        b.links[0].k = 0.0;
        b.links[0].c = 0.0;
        assert_eq!(b.validate(), Err(ModelError::Floating("head-neck".into())));
        b.links[0].c = 1.0;
        assert!(b.validate().is_ok());
    }

    #[test]
    fn params_resolve_by_number_and_name() {
        let b = Body::paper(75.0).unwrap();
        assert_eq!(b.param("k4").unwrap(), Param::Stiffness(3));
        assert_eq!(b.param("m1").unwrap(), Param::Mass(0));
        assert_eq!(b.param("chest").unwrap(), Param::Mass(1));
        assert_eq!(b.param("pelvis-seat.c").unwrap(), Param::Damping(3));
        assert_eq!(b.param("body_mass").unwrap(), Param::BodyMass);
        assert!(b.param("k5").is_err());
        assert!(b.param("k0").is_err());
        assert!(b.param("x1").is_err());
        assert!(b.param("pelvis-seat.z").is_err());
    }

    #[test]
    fn set_rejects_bad_values_and_keeps_body() {
        let mut b = Body::paper(75.0).unwrap();
        let before = b.clone();
        assert!(b.set(Param::Mass(0), 0.0).is_err());
        assert!(b.set(Param::Stiffness(3), -5.0).is_err());
        assert!(b.set(Param::BodyMass, f64::INFINITY).is_err());
        assert_eq!(b, before);
        b.set(Param::BodyMass, 85.0).unwrap();
        assert!((b.segments[1].mass - 0.402 * 85.0).abs() < 1e-12);
        // A mass set by hand moves its share, so rescaling keeps it in proportion.
        b.set(Param::Mass(3), 20.0).unwrap();
        b.set(Param::BodyMass, 42.5).unwrap();
        assert!((b.segments[3].mass - 10.0).abs() < 1e-12);
    }

    #[test]
    fn a_non_ascii_parameter_name_is_unknown_not_a_panic() {
        let b = Body::paper(75.0).unwrap();
        for name in ["é", "é1", "€2", "ß", "\u{0}", ""] {
            assert!(
                matches!(b.param(name), Err(ModelError::UnknownParam(_))),
                "{name:?}"
            );
        }
    }
}
