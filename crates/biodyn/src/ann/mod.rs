//! The paper's six neural networks (SPEC §4): data from the analytic engine,
//! the paper's back-propagation trainer, a Levenberg–Marquardt trainer that
//! generalises, metrics, a worker thread for the TUI and network files.
//!
//! `basis` builds the training bodies on the paper's body or a base the
//! user chooses. Imports run one way: `train` → `algorithm` (the trait) ← `backprop`, `lm`
//! → `encoded` (what trainers share) → `settings`; `schema` describes each
//! setting once and `compare` sets a trained net beside the analytic engine.

pub mod algorithm;
pub mod backprop;
pub mod basis;
pub mod case;
pub mod compare;
pub mod dataset;
pub mod encoded;
pub mod error;
pub mod exp;
pub mod lm;
pub mod metrics;
pub mod netfile;
pub mod network;
pub mod scaling;
pub mod schema;
pub mod settings;
pub mod stop;
pub mod train;
pub mod trained;
pub mod worker;

pub use algorithm::Algorithm;
pub use case::{Case, Group, PaperRow};
pub use compare::Comparison;
pub use dataset::{Curve, Dataset, Holdout};
pub use encoded::Encoded;
pub use error::AnnError;
pub use metrics::{EpochStats, HoldoutResult};
pub use network::{Activation, Network};
pub use scaling::Scaling;
pub use schema::{SETTINGS, Setting};
pub use settings::{Combine, Settings, Trainer};
pub use stop::{Flow, StopReason};
pub use train::{Outcome, Report, algorithm_for, evaluate_holdouts, train};
pub use trained::TrainedNet;
pub use worker::{Event, Finished, HistoryPoint, Progress, Worker};
