//! Models learned from data: the fit of free parameters to measured
//! responses and the paper's networks. One test binary.

/// Fitting against data made by the response solver.
mod fit;
/// How often the fit's 95 % intervals hold the truth (the fast study).
mod fit_coverage;
/// Networks: determinism, metrics, divergence, stop reasons, files.
mod network;
/// Networks trained on a base body other than the paper's.
mod network_base;
/// The training thread on a manual clock: throttle, pause, resume, cancel.
mod worker;
