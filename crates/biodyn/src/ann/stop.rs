//! Why a training run ended, and how an observer steers it.

use crate::clock::Clock;
use serde::{Serialize, Serializer};
use std::fmt;
use std::time::Instant;

/// The reason a run stopped; the report always says which.
#[derive(Debug, Clone, PartialEq)]
pub enum StopReason {
    /// Every training output within the training tolerance.
    AllRight,
    RmsTarget,
    MpreTarget,
    EpochLimit,
    TimeLimit,
    Cancelled,
    /// LM: no step reduces the loss any more (μ ran away).
    Converged,
    /// NaN, infinity or an exploding error; the text says what was seen.
    Diverged(String),
}

impl StopReason {
    pub fn key(&self) -> &'static str {
        match self {
            StopReason::AllRight => "all-right",
            StopReason::RmsTarget => "rms-target",
            StopReason::MpreTarget => "mpre-target",
            StopReason::EpochLimit => "epoch-limit",
            StopReason::TimeLimit => "time-limit",
            StopReason::Cancelled => "cancelled",
            StopReason::Converged => "converged",
            StopReason::Diverged(_) => "diverged",
        }
    }

    pub fn is_diverged(&self) -> bool {
        matches!(self, StopReason::Diverged(_))
    }
}

impl fmt::Display for StopReason {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            StopReason::Diverged(why) => write!(f, "diverged ({why})"),
            other => f.write_str(other.key()),
        }
    }
}

impl Serialize for StopReason {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.key())
    }
}

/// What an observer tells the trainer after each epoch.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Flow {
    Continue,
    Cancel,
    /// The observer's own clock ran out (the worker's, which leaves paused
    /// time out of the time limit).
    TimeUp,
}

/// When a run stops inside an epoch (or one LM iteration), where the work
/// is: the run's deadline on its clock and the caller's own poll (the
/// worker's cancel flag and its clock, which leaves paused time out).
/// Checked every few milliseconds of work, so a time limit or a cancel is
/// honoured however large one epoch is.
#[derive(Clone, Copy)]
pub struct Halt<'a> {
    pub deadline: Option<Instant>,
    pub poll: Option<&'a dyn Fn() -> Flow>,
    /// The clock the deadline is read on.
    pub clock: &'a Clock,
}

/// The clock of a [`Halt`] that names none.
static REAL: Clock = Clock::Real;

impl Default for Halt<'_> {
    fn default() -> Self {
        Halt::at(None)
    }
}

impl Halt<'_> {
    /// Only a deadline on the real clock (None: never).
    pub fn at(deadline: Option<Instant>) -> Halt<'static> {
        Halt {
            deadline,
            poll: None,
            clock: &REAL,
        }
    }

    /// True once the deadline has passed on the run's clock.
    pub fn past_deadline(&self) -> bool {
        self.deadline.is_some_and(|d| self.clock.now() >= d)
    }

    /// Why the run must stop now, if it must.
    pub fn check(&self) -> Option<StopReason> {
        match self.poll.map(|p| p()) {
            Some(Flow::Cancel) => return Some(StopReason::Cancelled),
            Some(Flow::TimeUp) => return Some(StopReason::TimeLimit),
            _ => {}
        }
        if self.past_deadline() {
            return Some(StopReason::TimeLimit);
        }
        None
    }
}

/// Weight updates between two [`Halt::check`]s inside an epoch (≈ 0.1 ms).
pub const POLL_WORK: usize = 1 << 16;

/// Error level above which a run counts as exploded: on the scaled scale a
/// bounded activation cannot reach it, so only a broken run gets there.
pub const EXPLODED_RMS: f64 = 1e6;
/// Weight magnitude beyond which the network has left any sensible region.
pub const EXPLODED_WEIGHT: f64 = 1e8;

/// Checks one epoch's numbers for divergence.
pub fn divergence(rms: f64, mpre_pct: f64, params: &[f64]) -> Option<StopReason> {
    if !rms.is_finite() || !mpre_pct.is_finite() {
        return Some(StopReason::Diverged(
            "the error became NaN or infinite".into(),
        ));
    }
    if rms > EXPLODED_RMS {
        return Some(StopReason::Diverged(format!(
            "the RMS error exploded past {EXPLODED_RMS:e}"
        )));
    }
    if let Some(w) = params.iter().find(|w| !w.is_finite()) {
        return Some(StopReason::Diverged(format!("a weight became {w}")));
    }
    if params.iter().any(|w| w.abs() > EXPLODED_WEIGHT) {
        return Some(StopReason::Diverged(format!(
            "a weight grew past {EXPLODED_WEIGHT:e}"
        )));
    }
    None
}
