//! The time domain (SPEC §6): the body under any seat acceleration.
//!
//! In coordinates relative to the seat, z = x − x0, the body obeys
//! M z'' + C z' + K z = −M·1·a_s; with q = [z, z'] that is q' = A q + B a_s,
//! and for a seat acceleration linear between samples the step
//! `q[k+1] = Φ q[k] + Γ0 a[k] + Γ1 a[k+1]` is exact ([`Discrete`]).
//!
//! - [`InputClass`], [`CLASSES`]: the seat-testing standards' input spectral
//!   classes (floor PSDs of machine groups).
//! - [`Signal`], [`Component`]: sine, sweep, random, shock, class and their sums,
//!   and the signal grammar; [`Generator`] samples them, seeded and
//!   reproducible ([`sample_count`] says how many samples).
//! - [`Record`], [`RecordOptions`]: seat-acceleration records from CSV, streamed;
//!   [`Point`], [`PointAxis`]: the other measuring points' channels beside
//!   the seat's ([`Record::frames`]).
//! - [`Discrete`] and [`Simulator`]: the exact first-order-hold
//!   discretisation and the streaming simulator (every segment's
//!   acceleration, the seat force, every link's deflection; [`Layout`] and
//!   [`record_columns`] name the columns).
//! - [`Biquad`], [`Cascade`]: second-order sections shared with the ISO 2631-1
//!   filters.

mod axis;
pub(crate) mod biquad;
mod class;
mod discrete;
mod error;
pub(crate) mod foh;
mod generate;
mod kernel;
pub(crate) mod lanes;
mod limits;
mod point;
mod record;
mod signal;
mod simulate;
mod unit;

pub use axis::{Axis, PerAxis, Row};
pub use biquad::{Biquad, Cascade};
pub use class::{CLASS_MIN_FS, CLASS_TOLERANCE, CLASSES, InputClass, LowPass};
pub use discrete::{Discrete, MAX_FS, SimError, stiffness_damping};
pub use error::TimeError;
pub use generate::{Generator, sample_count};
pub use limits::{MAX_ACC, MAX_SAMPLES, MAX_SEGMENTS, MIN_FS};
pub use point::{Channel, Frame, PerPoint, Point, PointAxis, PointRow};
pub use record::{
    AxisColumn, Columns, Given, NamedBy, PointColumn, Record, RecordError, RecordOptions, TimeName,
    TimeUnit, UnitBy, axis_of, channel_of, parse_axes, parse_channels, time_name,
};
pub use signal::{Component, Signal, SignalError};
pub use simulate::{Layout, Simulator, record_columns};
pub use unit::{G_N, HeaderUnit, Unit, bracketed, split_unit};
