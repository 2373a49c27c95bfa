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
    #[error(
        "segment '{0}' is a seat part (seat = true) but the model has no [seat] table: add [seat] with pan, suspension and stroke_m, or drop seat = true"
    )]
    SeatPartsWithoutSeat(String),
    #[error(
        "seat pan '{0}' is not a seat segment: the pan is the seat part the body rests on (give it seat = true)"
    )]
    PanNotSeat(String),
    #[error("seat pan index {index} is out of range: the model has {count} segments")]
    BadPan { index: usize, count: usize },
    #[error("the head '{0}' is a seat segment: the head is a part of the body")]
    HeadOnSeat(String),
    #[error("seat suspension link index {index} is out of range: the model has {count} links")]
    BadSuspension { index: usize, count: usize },
    #[error(
        "seat suspension '{0}' does not reach the floor from a seat segment: the suspension is the link from the seat's frame (a seat segment) to the floor"
    )]
    SuspensionNotToFloor(String),
    #[error(
        "seat stroke is {} m: the travel end-stop to end-stop must be finite, > 0 and at most {} m",
        num(*.0), num(crate::body::limits::MAX_STROKE_M)
    )]
    BadStroke(f64),
    #[error(
        "link '{link}' joins the body's segment '{segment}' to the floor: with a seat the body rests on the pan only, or the pan's force would miss that link"
    )]
    BodyOnFloor { link: String, segment: String },
    /// A link from the body to a seat segment that is not the pan: the
    /// link's name, then (body segment, seat segment, pan) in one box.
    #[error(
        "link '{link}' joins the body's segment '{}' to the seat segment '{}', not to the pan '{}': the pan's force would miss it",
        .ends.0, .ends.1, .ends.2
    )]
    BodyOffPan {
        link: String,
        ends: Box<(String, String, String)>,
    },
    #[error("no link joins the body to the seat pan '{0}': the body must rest on the pan")]
    PanCarriesNothing(String),
}
