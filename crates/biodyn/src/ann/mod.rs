//! The paper's six neural networks (SPEC §4): data from the analytic engine,
//! the paper's back-propagation trainer, a Levenberg–Marquardt trainer that
//! generalises, metrics, a worker thread for the TUI and network files.

pub mod backprop;
pub mod case;
pub mod dataset;
pub mod error;
pub mod exp;
pub mod lm;
pub mod metrics;
pub mod netfile;
pub mod network;
pub mod rng;
pub mod scaling;
pub mod settings;
pub mod stop;
pub mod train;
pub mod trained;
pub mod worker;

pub use case::{Case, Group, PaperRow};
pub use dataset::{Curve, Dataset, Holdout};
pub use error::AnnError;
pub use metrics::{EpochStats, HoldoutResult};
pub use network::{Activation, Network};
pub use rng::Rng;
pub use scaling::Scaling;
pub use settings::{Combine, Settings, Trainer};
pub use stop::{Flow, StopReason};
pub use train::{Outcome, Report, evaluate_holdouts, train};
pub use trained::TrainedNet;
pub use worker::{Event, Finished, HistoryPoint, Progress, Worker};
