//! Validation: a body is checked whole (names, masses, links, every
//! segment held), and every failure names the field and the value.

use super::{
    Body, End, MAX_C, MAX_K, MAX_LINK_NAME, MAX_MASS, MAX_NAME, MIN_MASS, mass_in_range, mass_rule,
    name_problem,
};
use crate::io::excerpt::{num, quote};

/// The allowed range of a link field, for its error message only.
fn link_range(field: &str) -> &'static str {
    if field.starts_with('k') {
        "stiffness must be in [0, 1e12] N/m"
    } else {
        "damping must be in [0, 1e10] N·s/m"
    }
}

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
        "mass of segment '{segment}' is {} kg: a segment mass must be {}",
        num(*.value), mass_rule(*.value)
    )]
    BadMass { segment: String, value: f64 },
    #[error(
        "share of segment '{segment}' is {}: a share of body mass must be finite and > 0",
        num(*.value)
    )]
    BadShare { segment: String, value: f64 },
    #[error(
        "body mass is {} kg: it must be {}",
        num(*.0), mass_rule(*.0)
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
        "{field} of link '{link}' is {}: {}",
        num(*.value),
        link_range(field)
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

impl Body {
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
            let ends = [Some(l.upper), l.lower.segment()];
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
}
