//! The paper's trainer: online error back-propagation with momentum,
//! Δw(t) = LR·δ_j·X_i + M·Δw(t−1), one pattern at a time, in an order
//! shuffled each epoch from the seeded generator.
//!
//! The epoch's RMS, MPRE and share right are taken from each pattern's
//! output just before its own update, as online trainers traditionally
//! report them: it costs no extra pass. The final report recomputes them
//! with a clean pass over the finished network.

use super::metrics::EpochStats;
use super::network::{Activation, Network};
use super::rng::Rng;
use super::settings::Settings;
use super::stop::{Flow, StopReason, divergence};
use super::train::Encoded;
use std::time::Instant;

/// Trains `net` in place; returns why it stopped and the epochs done.
///
/// The paper's three architectures get their own copies of the loop with
/// the layer sizes as constants, so the compiler unrolls the tiny inner
/// loops; the arithmetic, and so every bit of the result, is the same as
/// for any other architecture.
pub fn run(
    net: &mut Network,
    data: &Encoded,
    settings: &Settings,
    rng: &mut Rng,
    member: usize,
    deadline: Option<Instant>,
    observe: &mut dyn FnMut(&EpochStats) -> Flow,
) -> (StopReason, u64) {
    let layers = net.layers.clone();
    let args = (data, settings, rng, member, deadline, observe);
    match layers.as_slice() {
        [2, 5, 3, 1] => run_shaped(&[2, 5, 3, 1], net, args),
        [5, 6, 4, 1] => run_shaped(&[5, 6, 4, 1], net, args),
        [5, 6, 4, 2, 1] => run_shaped(&[5, 6, 4, 2, 1], net, args),
        other => run_shaped(other, net, args),
    }
}

type Args<'a, 'b> = (
    &'a Encoded,
    &'a Settings,
    &'a mut Rng,
    usize,
    Option<Instant>,
    &'a mut (dyn FnMut(&EpochStats) -> Flow + 'b),
);

#[inline(always)]
fn run_shaped(layers: &[usize], net: &mut Network, args: Args) -> (StopReason, u64) {
    let (data, settings, rng, member, deadline, observe) = args;
    let n = data.x.len();
    let np = net.params.len();
    let total: usize = layers.iter().sum();
    let mut order: Vec<usize> = (0..n).collect();
    let mut dprev = vec![0.0; np];
    let mut acts = vec![0.0; total];
    let mut deltas = vec![0.0; total];
    let mut noisy = vec![0.0; layers[0]];
    let (lr, m, tol) = (
        settings.learning_rate,
        settings.momentum,
        settings.train_tolerance,
    );
    let kind = Kind {
        act: net.activation,
        gain: net.gain,
        linear_output: net.linear_output,
    };
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
            let y = forward(layers, kind, &net.params, &mut acts, x);
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
            update(
                layers,
                kind,
                &mut net.params,
                &mut dprev,
                &acts,
                &mut deltas,
                e,
                lr,
                m,
            );
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
        match observe(&stats) {
            Flow::Continue => {}
            Flow::Cancel => return (StopReason::Cancelled, epoch),
            Flow::TimeUp => return (StopReason::TimeLimit, epoch),
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

#[derive(Clone, Copy)]
struct Kind {
    act: Activation,
    gain: f64,
    linear_output: bool,
}

/// Forward pass over flat buffers; same arithmetic as `Network::forward`.
#[inline(always)]
fn forward(layers: &[usize], k: Kind, params: &[f64], acts: &mut [f64], x: &[f64]) -> f64 {
    let nl = layers.len();
    acts[..layers[0]].copy_from_slice(x);
    let (mut a0, mut p0) = (0, 0);
    for l in 1..nl {
        let (nin, nout) = (layers[l - 1], layers[l]);
        let linear = k.linear_output && l == nl - 1;
        for j in 0..nout {
            let w = &params[p0 + j * (nin + 1)..p0 + (j + 1) * (nin + 1)];
            let mut u = w[nin];
            for i in 0..nin {
                u += w[i] * acts[a0 + i];
            }
            acts[a0 + nin + j] = if linear { u } else { k.act.apply(k.gain, u) };
        }
        a0 += nin;
        p0 += nout * (nin + 1);
    }
    acts[a0]
}

/// δ of every neuron and the momentum update; same arithmetic as
/// `Network::backprop_step`. `deltas` is indexed like `acts`.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn update(
    layers: &[usize],
    k: Kind,
    params: &mut [f64],
    dprev: &mut [f64],
    acts: &[f64],
    deltas: &mut [f64],
    err: f64,
    lr: f64,
    m: f64,
) {
    let nl = layers.len();
    // Offsets of each layer in acts and in params.
    let mut aoff = [0usize; 16];
    let mut poff = [0usize; 16];
    for l in 1..nl {
        aoff[l] = aoff[l - 1] + layers[l - 1];
        poff[l] = poff[l - 1] + layers[l] * (layers[l - 1] + 1);
    }
    let out = aoff[nl - 1];
    let slope = if k.linear_output {
        1.0
    } else {
        k.act.slope(k.gain, acts[out])
    };
    deltas[out] = slope * err;
    for l in (1..nl - 1).rev() {
        let (nin, nout) = (layers[l], layers[l + 1]);
        let p0 = poff[l];
        for i in 0..nin {
            let mut sum = 0.0;
            for kk in 0..nout {
                sum += params[p0 + kk * (nin + 1) + i] * deltas[aoff[l + 1] + kk];
            }
            deltas[aoff[l] + i] = k.act.slope(k.gain, acts[aoff[l] + i]) * sum;
        }
    }
    for l in 1..nl {
        let (nin, nout) = (layers[l - 1], layers[l]);
        let p0 = poff[l - 1];
        for j in 0..nout {
            let ld = lr * deltas[aoff[l] + j];
            let r = p0 + j * (nin + 1);
            for i in 0..nin {
                let di = ld * acts[aoff[l - 1] + i] + m * dprev[r + i];
                dprev[r + i] = di;
                params[r + i] += di;
            }
            let dt = ld + m * dprev[r + nin];
            dprev[r + nin] = dt;
            params[r + nin] += dt;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ann::case::Case;
    use crate::ann::dataset::Dataset;

    /// The unrolled copies must give the very bits of the general loop and
    /// of `Network::backprop_step`.
    #[test]
    fn shaped_loop_equals_general_loop_and_network_step() {
        let case = Case::K4Stht;
        let mut s = Settings::paper(case);
        s.epochs = 3;
        s.stop_when_all_right = false;
        let data = Dataset::build(case, &s.train_values, &s.grid).unwrap();
        let enc = Encoded::new(&data, &s).unwrap();
        let net0 = Network::new(&s.layers, s.activation, 1.0, 0.5, &mut Rng::new(9)).unwrap();
        let mut fast = net0.clone();
        run(&mut fast, &enc, &s, &mut Rng::new(4), 0, None, &mut |_| {
            Flow::Continue
        });
        let mut general = net0.clone();
        let dynamic: Vec<usize> = std::hint::black_box(s.layers.clone());
        let args = (
            &enc,
            &s,
            &mut Rng::new(4),
            0,
            None,
            &mut |_: &EpochStats| Flow::Continue,
        );
        run_shaped(
            &dynamic,
            &mut general,
            (args.0, args.1, args.2, args.3, args.4, args.5),
        );
        assert_eq!(fast.params, general.params);
        // Against the Network methods, pattern by pattern.
        let mut reference = net0.clone();
        let mut rng = Rng::new(4);
        let mut order: Vec<usize> = (0..enc.x.len()).collect();
        let mut dprev = vec![0.0; reference.params.len()];
        let mut sc = reference.scratch();
        for _ in 0..3 {
            rng.shuffle(&mut order);
            for &p in &order {
                let e = enc.d[p] - reference.forward(&enc.x[p], &mut sc)[0];
                reference.backprop_step(&mut sc, e, 1.0, 0.9, &mut dprev);
            }
        }
        assert_eq!(fast.params, reference.params);
    }
}
