//! The time a run reads: the real monotonic clock, or a hand-moved one for
//! tests. Time limits, paused time and message-rate throttles read a
//! [`Clock`] passed in, as randomness comes from a seeded [`crate::Rng`]
//! passed in, so a test can move time itself and wait on the worker's own
//! reports instead of sleeping and asserting on wall-clock bounds.
//!
//! Both kinds give real [`Instant`]s: a manual clock is a fixed origin plus
//! the time its [`ManualClock`] has been moved on, so code that adds a
//! `Duration` to a reading or subtracts two readings works on either.

use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::{Duration, Instant};

/// A clock to read: [`Clock::Real`] (the default) or a manual one.
#[derive(Debug, Clone, Default)]
pub enum Clock {
    /// `Instant::now()`.
    #[default]
    Real,
    /// Stands still until its [`ManualClock`] moves it.
    Manual(ManualClock),
}

impl Clock {
    /// The time now.
    pub fn now(&self) -> Instant {
        match self {
            Clock::Real => Instant::now(),
            Clock::Manual(m) => m.now(),
        }
    }

    /// Time since `t` (zero if `t` is later, as a reading from before a
    /// clock was swapped could be).
    pub fn since(&self, t: Instant) -> Duration {
        self.now().saturating_duration_since(t)
    }
}

/// The hand of a manual clock: clones share one time, which only
/// [`ManualClock::advance`] moves.
#[derive(Debug, Clone)]
pub struct ManualClock {
    origin: Instant,
    /// Nanoseconds moved on since `origin`.
    nanos: Arc<AtomicU64>,
}

impl Default for ManualClock {
    fn default() -> ManualClock {
        ManualClock::new()
    }
}

impl ManualClock {
    /// A clock standing at its origin.
    pub fn new() -> ManualClock {
        ManualClock {
            origin: Instant::now(),
            nanos: Arc::new(AtomicU64::new(0)),
        }
    }

    /// The [`Clock`] that reads this hand.
    pub fn clock(&self) -> Clock {
        Clock::Manual(self.clone())
    }

    /// Moves the time on by `d` (for every clone and every reader).
    pub fn advance(&self, d: Duration) {
        let n = u64::try_from(d.as_nanos()).unwrap_or(u64::MAX);
        self.nanos.fetch_add(n, Ordering::SeqCst);
    }

    /// Time moved on since the origin.
    pub fn elapsed(&self) -> Duration {
        Duration::from_nanos(self.nanos.load(Ordering::SeqCst))
    }

    pub fn now(&self) -> Instant {
        self.origin + self.elapsed()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_manual_clock_moves_only_when_advanced_and_clones_share_it() {
        let hand = ManualClock::new();
        let c = hand.clock();
        let t0 = c.now();
        std::hint::black_box(0..1000).for_each(drop);
        assert_eq!(c.now(), t0);
        hand.clone().advance(Duration::from_millis(33));
        assert_eq!(c.since(t0), Duration::from_millis(33));
        assert_eq!(c.clone().now(), t0 + Duration::from_millis(33));
        assert_eq!(c.since(t0 + Duration::from_secs(1)), Duration::ZERO);
    }
}
