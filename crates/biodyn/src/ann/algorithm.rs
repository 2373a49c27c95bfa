//! The seam between a training run and a training algorithm: `train` builds
//! the data and the networks, an `Algorithm` fits one network to the data. A
//! new trainer is one file implementing this trait, one `Trainer` variant,
//! its rows in `schema::SETTINGS` (`trainers:`) and one line in `train::algorithm_for`.

use super::encoded::Encoded;
use super::metrics::EpochStats;
use super::network::Network;
use super::settings::{Settings, Trainer};
use super::stop::{Flow, Halt, StopReason};
use crate::rng::Rng;

/// One ensemble member's job: the data, the settings, its own seeded
/// generator, its index, and when it must stop early (the run's deadline
/// and the caller's poll).
pub struct Member<'a> {
    pub data: &'a Encoded,
    pub settings: &'a Settings,
    pub rng: &'a mut Rng,
    pub index: usize,
    pub halt: Halt<'a>,
}

/// A training algorithm.
pub trait Algorithm: Sync {
    fn trainer(&self) -> Trainer;

    /// Trains `net` in place; returns why it stopped and the epochs
    /// (iterations) done. `observe` sees every epoch and may cancel.
    fn run(
        &self,
        net: &mut Network,
        job: Member<'_>,
        observe: &mut dyn FnMut(&EpochStats) -> Flow,
    ) -> (StopReason, u64);
}
