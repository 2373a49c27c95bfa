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
pub mod generate;
mod kernel;
pub mod record;
pub mod signal;
pub mod simulate;

pub use discrete::{Discrete, MAX_FS, SimError};
pub use generate::Generator;
pub use record::{Record, RecordError, RecordOptions};
pub use signal::{Component, Signal, SignalError};
pub use simulate::{Layout, Simulator, record_columns};

/// Most samples in one record, read or generated: 10^8 (27.8 h at 1 kHz,
/// 8 h at 3.4 kHz). Memory stays bounded either way; this caps the time a
/// typo (a duration of 3600000 s) can cost.
pub const MAX_SAMPLES: usize = 100_000_000;

/// Largest seat acceleration a signal or record may hold, m/s² (≈ 1000 g):
/// far beyond any seat vibration or shock a body survives, so a larger value
/// is a unit slip; it also keeps every sum and the simulator finite.
pub const MAX_ACC: f64 = 1e4;

/// Every way a time-domain run can be refused.
#[derive(Debug, thiserror::Error)]
pub enum TimeError {
    #[error(transparent)]
    Signal(#[from] SignalError),
    #[error(transparent)]
    Record(#[from] RecordError),
    #[error(transparent)]
    Sim(#[from] SimError),
    #[error("duration {0:?} s: it must be a finite number > 0")]
    BadDuration(f64),
    #[error("sampling rate {0:?} Hz: it must be a finite number > 0 and at most 1e6")]
    BadFs(f64),
    #[error(
        "{} samples (duration × fs) is over the cap of {cap}: shorten the duration or lower the sampling rate",
        crate::io::excerpt::num(*.samples)
    )]
    TooLong { samples: f64, cap: usize },
    #[error(
        "{} s at {} Hz is fewer than two samples: lengthen the duration or raise the sampling rate",
        crate::io::excerpt::num(*.duration),
        crate::io::excerpt::num(*.fs)
    )]
    TooShort { duration: f64, fs: f64 },
}
