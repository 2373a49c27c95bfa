//! The lumped-parameter body: rigid segments joined by Kelvin–Voigt links.
//!
//! A link joins two segments, or one segment and the seat (the prescribed
//! motion x0). Nothing here assumes a chain: branched models (a viscera mass
//! hanging off the torso, say) are as valid as the paper's serial 4-DOF model.

mod body;
mod error;
mod param;
mod seat;
mod validate;

pub use body::{Body, End, Link, PAPER_C, PAPER_K, PAPER_SEGMENTS, PAPER_SHARES, Seat, Segment};
pub use error::ModelError;
pub use param::Param;

#[cfg(test)]
mod tests;
