//! The time domain (SPEC §6): the body under any seat acceleration.
//!
//! - [`signal`]: sine, sweep, random, shock and their sums, and the
//!   signal grammar; [`generate`] samples them, seeded and reproducible.
//! - [`record`]: seat-acceleration records from CSV, streamed.
//! - [`discrete`] and [`simulate`]: the exact first-order-hold discretisation
//!   and the streaming simulator (every segment's acceleration, the seat
//!   force, every link's deflection).
//! - [`biquad`]: second-order sections shared with the ISO 2631-1 filters.

pub mod biquad;
pub mod discrete;
mod error;
pub mod generate;
mod kernel;
mod limits;
pub mod record;
pub mod signal;
pub mod simulate;

pub use discrete::{Discrete, MAX_FS, SimError};
pub use error::TimeError;
pub use generate::Generator;
pub use limits::{MAX_ACC, MAX_SAMPLES};
pub use record::{Record, RecordError, RecordOptions};
pub use signal::{Component, Signal, SignalError};
pub use simulate::{Layout, Simulator, record_columns};
