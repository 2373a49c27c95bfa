//! The multi-start fit: Levenberg–Marquardt from the start model and from
//! seeded points around it, keeping the best.

use super::data::Measured;
use super::error::FitError;
use super::free::FreeParam;
use super::lm::{self, Residuals, Workspace};
use super::report::{self, Fit};
use super::residual::Engine;
use crate::ann::Rng;
use crate::body::model::Body;
use std::time::Instant;

/// Most starts a fit takes.
pub const MAX_STARTS: usize = 1000;
/// Starts after the first are drawn uniformly in ln p within this factor of
/// the start model (then put inside the bounds).
pub const SPREAD: f64 = 3.0;
/// A start "reached the best cost" when its cost is within this fraction of
/// the best (plus 1e-12 per value, for data a model fits exactly).
pub const SAME_COST: f64 = 1e-6;

/// Settings of a fit besides the model, data and free parameters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    pub starts: usize,
    pub seed: u64,
}

impl Default for Settings {
    fn default() -> Self {
        Settings { starts: 8, seed: 1 }
    }
}

/// Reported after each start: start `done` of `starts` finished.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Progress {
    pub done: usize,
    pub starts: usize,
    pub best_cost: f64,
}

impl Residuals for Engine {
    fn m(&self) -> usize {
        Engine::m(self)
    }
    fn p(&self) -> usize {
        Engine::p(self)
    }
    fn eval(&mut self, theta: &[f64], r: &mut [f64], jac: Option<&mut [f64]>) -> f64 {
        Engine::eval(self, theta, r, jac)
    }
}

/// Fits `free` parameters of `body` to `data`.
pub fn fit(
    body: &Body,
    data: &Measured,
    free: &[FreeParam],
    settings: Settings,
) -> Result<Fit, FitError> {
    fit_with(body, data, free, settings, &mut |_| true)
}

/// As [`fit`], calling `progress` after every start; when it returns false
/// the fit stops with [`FitError::Cancelled`]. Same seed, same bits.
pub fn fit_with(
    body: &Body,
    data: &Measured,
    free: &[FreeParam],
    settings: Settings,
    progress: &mut dyn FnMut(Progress) -> bool,
) -> Result<Fit, FitError> {
    let clock = Instant::now();
    if settings.starts == 0 || settings.starts > MAX_STARTS {
        return Err(FitError::BadStarts(settings.starts));
    }
    if free.is_empty() {
        return Err(FitError::EmptyFree);
    }
    let params: Vec<_> = free.iter().map(|f| f.param).collect();
    let mut engine = Engine::new(body, data, &params)?;
    let (m, p) = (engine.m(), engine.p());
    if m <= p {
        return Err(FitError::TooFewValues {
            path: data.path.clone(),
            values: m,
            params: p,
        });
    }
    let lo: Vec<f64> = free.iter().map(|f| f.lo.ln()).collect();
    let hi: Vec<f64> = free.iter().map(|f| f.hi.ln()).collect();
    let centre: Vec<f64> = free.iter().map(|f| f.start.ln()).collect();
    let mut ws = Workspace::new(m, p);
    let mut theta = vec![0.0; p];
    let mut best = vec![0.0; p];
    let mut best_cost = f64::INFINITY;
    let mut costs = Vec::with_capacity(settings.starts);
    let mut ends = Vec::with_capacity(settings.starts);
    for s in 0..settings.starts {
        theta.copy_from_slice(&centre);
        if s > 0 {
            let mut rng = Rng::derived(settings.seed, s as u64);
            for t in &mut theta {
                *t += rng.symmetric(SPREAD.ln());
            }
        }
        let out = lm::minimise(&mut engine, &mut theta, &lo, &hi, &mut ws);
        costs.push(out.cost);
        ends.push(theta.clone());
        if out.cost < best_cost {
            best_cost = out.cost;
            best.copy_from_slice(&theta);
        }
        let go = progress(Progress {
            done: s + 1,
            starts: settings.starts,
            best_cost,
        });
        if !go {
            return Err(FitError::Cancelled);
        }
    }
    if !best_cost.is_finite() {
        return Err(FitError::Unsolvable {
            path: data.path.clone(),
        });
    }
    let tol = SAME_COST * best_cost + 1e-12 * m as f64;
    let converged = costs.iter().filter(|&&c| c - best_cost <= tol).count();
    report::build(
        body,
        data,
        free,
        &mut engine,
        &best,
        costs,
        &ends,
        converged,
        settings,
        clock,
    )
}
