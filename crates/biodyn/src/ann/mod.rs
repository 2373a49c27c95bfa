//! The paper's six neural networks (SPEC §4): data from the analytic engine,
//! the paper's back-propagation trainer, a Levenberg–Marquardt trainer that
//! generalises, metrics, a worker thread for the TUI and network files.
//!
//! Each [`Network`] is fully connected and feed-forward with the paper's
//! neuron, U_j = Σ_i w_ij X_i, Y_j = F(U_j + t_j) ([`Activation`] F).
//! [`Trainer::Backprop`] is online back-propagation with momentum,
//! Δw(t) = LR·δ_j·X_i + M·Δw(t−1) ([`run_backprop`]); [`Trainer::Lm`]
//! minimises Σ(Y − d)² + λ·Σθ² by solving (JᵀJ + (λ + μ)I)·Δ = −(Jᵀr + λθ)
//! ([`run_lm`]).
//!
//! - [`Case`], [`Dataset`], [`holdouts`], [`at_body_mass`]: what a network
//!   learns, sampled from the analytic engine on the paper's body or a base
//!   the user chooses.
//! - [`Settings`], [`SETTINGS`]: every training setting, described once
//!   (key, range, kind, which trainers read it).
//! - [`train`], [`Outcome`], [`Worker`]: a training run, in the caller's thread
//!   or a worker's, with [`EpochStats`] and [`HoldoutResult`]s.
//! - [`save_network`], [`load_network`], [`TrainedNet`]: network files.
//! - [`Comparison`]: a trained network beside the analytic engine.
//!
//! Inside, imports run one way: `train` → `algorithm` (the trait) ← `backprop`,
//! `lm` → `encoded` (what trainers share) → `settings`.

mod algorithm;
mod backprop;
mod basis;
mod bounds;
mod case;
mod compare;
mod dataset;
mod encoded;
mod error;
mod exp;
mod lm;
mod metrics;
mod netfile;
mod network;
mod scaling;
mod schema;
mod settings;
mod stop;
mod train;
mod trained;
mod worker;

pub use algorithm::Algorithm;
pub use backprop::run_backprop;
pub use basis::at_body_mass;
pub use bounds::{LM_MAX_WEIGHTS, MAX_ENSEMBLE, MAX_SAMPLES, MEMORY_BUDGET, memory_bytes};
pub use case::{Case, Group, K4_BODY_MASS, PaperRow};
pub use compare::Comparison;
pub use dataset::{Curve, Dataset, Holdout, holdouts, holdouts_on};
pub use encoded::Encoded;
pub use error::AnnError;
pub use exp::logistic_lanes;
pub use lm::run_lm;
pub use metrics::{EpochStats, HoldoutResult, curve_error, worst_holdout};
pub use netfile::{
    load_network, load_network_expect, parse_network, save_network, save_network_guarded,
};
pub use network::{Activation, Network};
pub use scaling::Scaling;
pub use schema::{SETTINGS, Setting, SettingKind};
pub use settings::{Combine, Settings, TRAIN_GRID, Trainer};
pub use stop::{Flow, Halt, POLL_WORK, StopReason};
pub use train::{Outcome, Report, algorithm_for, evaluate_holdouts, train, train_with};
pub use trained::TrainedNet;
pub use worker::{Event, Finished, HistoryPoint, MIN_INTERVAL, Progress, Worker};
