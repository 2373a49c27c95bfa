//! Why a body is not valid; each variant names the offending field and value.

use crate::body::limits::{MAX_MASS, MIN_MASS, mass_rule};
use crate::io::excerpt::num;

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
