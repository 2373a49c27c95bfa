//! Validation: a body is checked whole (names, masses, links, every
//! segment held), and every failure names the field and the value.

use super::body::{Body, End};
use super::error::ModelError;
use crate::body::limits::{MAX_C, MAX_K, MAX_LINK_NAME, MAX_NAME, mass_in_range, name_problem};
use crate::io::excerpt::quote;

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
        self.validate_seat()
    }
}
