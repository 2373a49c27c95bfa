//! The paper's trainer: online error back-propagation with momentum,
//! Δw(t) = LR·δ_j·X_i + M·Δw(t−1), one pattern at a time, in an order
//! shuffled each epoch from the seeded generator.
//!
//! The epoch's RMS, MPRE and share right are taken from each pattern's
//! output just before its own update, as online trainers traditionally
//! report them: it costs no extra pass. The final report recomputes them
//! with a clean pass over the finished network.

use super::metrics::EpochStats;
use super::network::Network;
use super::rng::Rng;
use super::settings::Settings;
use super::stop::{Flow, StopReason, divergence};
use super::train::Encoded;
use std::time::Instant;

/// Trains `net` in place; returns why it stopped and the epochs done.
pub fn run(
    net: &mut Network,
    data: &Encoded,
    settings: &Settings,
    rng: &mut Rng,
    member: usize,
    deadline: Option<Instant>,
    observe: &mut dyn FnMut(&EpochStats) -> Flow,
) -> (StopReason, u64) {
    let n = data.x.len();
    let np = net.params.len();
    let mut order: Vec<usize> = (0..n).collect();
    let mut dprev = vec![0.0; np];
    let mut s = net.scratch();
    let mut noisy = vec![0.0; net.inputs()];
    let (lr, m, tol) = (
        settings.learning_rate,
        settings.momentum,
        settings.train_tolerance,
    );
    for epoch in 1..=settings.epochs {
        rng.shuffle(&mut order);
        let (mut se, mut mpre, mut right) = (0.0, 0.0f64, 0usize);
        for &p in &order {
            let x: &[f64] = if settings.input_noise > 0.0 {
                for (o, xi) in noisy.iter_mut().zip(&data.x[p]) {
                    *o = xi + rng.symmetric(settings.input_noise);
                }
                &noisy
            } else {
                &data.x[p]
            };
            let y = net.forward(x, &mut s)[0];
            let e = data.d[p] - y;
            se += e * e;
            if e.abs() <= tol {
                right += 1;
            }
            let rel = data.pct_error(y, p);
            // NaN-safe max: a NaN error must survive to the divergence check.
            if rel > mpre || rel.is_nan() {
                mpre = rel;
            }
            net.backprop_step(&mut s, e, lr, m, &mut dprev);
        }
        let stats = EpochStats {
            member,
            epoch,
            rms: (se / n as f64).sqrt(),
            mpre_pct: mpre,
            share_right: right as f64 / n as f64,
        };
        if let Some(d) = divergence(stats.rms, stats.mpre_pct, &net.params) {
            return (d, epoch);
        }
        if observe(&stats) == Flow::Cancel {
            return (StopReason::Cancelled, epoch);
        }
        if let Some(stop) = data.target_reached(settings, &stats) {
            return (stop, epoch);
        }
        if deadline.is_some_and(|d| Instant::now() >= d) {
            return (StopReason::TimeLimit, epoch);
        }
    }
    (StopReason::EpochLimit, settings.epochs)
}
