//! Every way a time-domain run can be refused.

use super::discrete::SimError;
use super::record::RecordError;
use super::signal::SignalError;

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
