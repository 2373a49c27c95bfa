//! The seat between floor and body (SPEC §11, ISO 10326-1): its figures in
//! the frequency domain for a floor PSD, and the search for a suspension.
//!
//! - [`FloorPsd`]: the floor's acceleration PSD, from a file
//!   (`f_hz,psd_m2_s4_hz`) or an input spectral class ([`crate::time::CLASSES`]).
//! - [`SeatGrid`], [`SeatFigures`]: SEAT % = 100·√(∫G|T|²|W_k|²df / ∫G|W_k|²df),
//!   the pan's and the floor's a_w, and the suspension's r.m.s. travel
//!   √∫G·|X_rel/A_floor|²df, for any model with a seat.
//! - [`design`] ([`design_with`]: with progress), [`Vary`], [`Design`]: the
//!   box of one or two parameters searched for the lowest SEAT whose r.m.s.
//!   travel keeps a limit, with the map around it; [`suspension_box`]: the
//!   box around a suspension's own k and c when none is given.

mod design;
#[cfg(test)]
mod design_tests;
mod error;
mod figures;
#[cfg(test)]
mod figures_tests;
mod psd;
mod quadrature;
mod suspension_box;

pub use design::{
    Design, DesignMap, DesignPoint, MAP_POINTS, MAX_VARIED, Vary, design, design_with,
};
pub use error::SeatError;
pub use figures::{MAX_HZ, MIN_HZ, SeatFigures, SeatGrid, TOLERANCE, integrated_range};
pub use psd::FloorPsd;
pub use suspension_box::{LIMIT_SHARE, SPAN, default_limit, suspension, suspension_box};
