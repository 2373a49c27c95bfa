//! The paper's trainer: online error back-propagation with momentum,
//! Δw(t) = LR·δ_j·X_i + M·Δw(t−1), one pattern at a time, in an order
//! shuffled each epoch from the seeded generator.
//!
//! The epoch's RMS, MPRE and share right are taken from each pattern's
//! output just before its own update, as online trainers traditionally
//! report them: it costs no extra pass. The final report recomputes them
//! with a clean pass over the finished network.

use super::encoded::Encoded;
use super::metrics::EpochStats;
use super::network::{Activation, Network};
use super::rng::Rng;
use super::settings::{Settings, TrainerKind};
use super::stop::{Flow, StopReason, divergence};
use super::trainer::{Member, Trainer};
use std::time::Instant;

/// The `Trainer` of this file.
pub struct Backprop;

impl Trainer for Backprop {
    fn kind(&self) -> TrainerKind {
        TrainerKind::Backprop
    }

    fn run(
        &self,
        net: &mut Network,
        job: Member<'_>,
        observe: &mut dyn FnMut(&EpochStats) -> Flow,
    ) -> (StopReason, u64) {
        run(
            net,
            job.data,
            job.settings,
            job.rng,
            job.index,
            job.deadline,
            observe,
        )
    }
}

/// Trains `net` in place; returns why it stopped and the epochs done.
///
/// The paper's three architectures get their own copies of the loop with
/// the layer sizes as constants (`Dense` layers of fixed-size arrays), so
/// the compiler unrolls the tiny inner loops and no index is checked; the
/// arithmetic, and so every bit of the result, is the same as for any other
/// architecture (a test checks it against the general loop and against
/// `Network::backprop_step`).
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
        [2, 5, 3, 1] => run_fixed::<2, Net3<2, 5, 3>>(net, args),
        [5, 6, 4, 1] => run_fixed::<5, Net3<5, 6, 4>>(net, args),
        [5, 6, 4, 2, 1] => run_fixed::<5, Net4<5, 6, 4, 2>>(net, args),
        other => run_general(other, net, args),
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

/// One epoch's running metrics: Σ(d − Y)², max % error, outputs right.
#[derive(Clone, Copy)]
struct Running {
    se: f64,
    mpre: f64,
    right: usize,
}

impl Running {
    fn new() -> Running {
        Running {
            se: 0.0,
            mpre: 0.0,
            right: 0,
        }
    }

    #[inline(always)]
    fn add(&mut self, data: &Encoded, p: usize, y: f64, e: f64, tol: f64) {
        self.se += e * e;
        if e.abs() <= tol {
            self.right += 1;
        }
        let rel = data.pct_error(y, p);
        // NaN-safe max: a NaN error must survive to the divergence check.
        if rel > self.mpre || rel.is_nan() {
            self.mpre = rel;
        }
    }
}

/// The end of an epoch, common to both loops: statistics, divergence,
/// observer, targets, deadline. `Some` stops the run.
#[allow(clippy::too_many_arguments)]
fn end_epoch(
    run: Running,
    epoch: u64,
    params: &[f64],
    data: &Encoded,
    settings: &Settings,
    member: usize,
    deadline: Option<Instant>,
    observe: &mut dyn FnMut(&EpochStats) -> Flow,
) -> Option<StopReason> {
    let n = data.x.len() as f64;
    let stats = EpochStats {
        member,
        epoch,
        rms: (run.se / n).sqrt(),
        mpre_pct: run.mpre,
        share_right: run.right as f64 / n,
    };
    if let Some(d) = divergence(stats.rms, stats.mpre_pct, params) {
        return Some(d);
    }
    match observe(&stats) {
        Flow::Continue => {}
        Flow::Cancel => return Some(StopReason::Cancelled),
        Flow::TimeUp => return Some(StopReason::TimeLimit),
    }
    if let Some(stop) = data.target_reached(settings, &stats) {
        return Some(stop);
    }
    if deadline.is_some_and(|d| Instant::now() >= d) {
        return Some(StopReason::TimeLimit);
    }
    None
}

#[derive(Clone, Copy)]
struct Kind {
    act: Activation,
    gain: f64,
    linear_output: bool,
}

impl Kind {
    fn of(net: &Network) -> Kind {
        Kind {
            act: net.activation,
            gain: net.gain,
            linear_output: net.linear_output,
        }
    }
}

// ---------------------------------------------------------------------------
// The paper's architectures: layers with their sizes as constants.

/// One layer after the input, NIN inputs and NOUT neurons: weights,
/// thresholds and their last changes (momentum), in fixed-size arrays.
#[derive(Clone)]
struct Dense<const NIN: usize, const NOUT: usize> {
    w: [[f64; NIN]; NOUT],
    t: [f64; NOUT],
    dw: [[f64; NIN]; NOUT],
    dt: [f64; NOUT],
}

impl<const NIN: usize, const NOUT: usize> Dense<NIN, NOUT> {
    /// Parameters of the layer in the flat order of `Network::params`.
    const LEN: usize = NOUT * (NIN + 1);

    /// The layer from the front of `params`, momentum zero; and the rest.
    fn load(params: &[f64]) -> (Self, &[f64]) {
        let mut l = Dense {
            w: [[0.0; NIN]; NOUT],
            t: [0.0; NOUT],
            dw: [[0.0; NIN]; NOUT],
            dt: [0.0; NOUT],
        };
        let (mine, rest) = params.split_at(Self::LEN);
        for ((w, t), row) in l.w.iter_mut().zip(&mut l.t).zip(mine.chunks_exact(NIN + 1)) {
            w.copy_from_slice(&row[..NIN]);
            *t = row[NIN];
        }
        (l, rest)
    }

    /// Writes the weights back to the front of `params`; returns the rest.
    fn store<'p>(&self, params: &'p mut [f64]) -> &'p mut [f64] {
        let (mine, rest) = params.split_at_mut(Self::LEN);
        for ((w, t), row) in self
            .w
            .iter()
            .zip(&self.t)
            .zip(mine.chunks_exact_mut(NIN + 1))
        {
            row[..NIN].copy_from_slice(w);
            row[NIN] = *t;
        }
        rest
    }

    /// Y_j = F(t_j + Σ_i w_ji·X_i), summed in the order of `Network::forward`.
    #[inline(always)]
    fn forward(&self, x: &[f64; NIN], k: Kind, linear: bool) -> [f64; NOUT] {
        let mut u = self.t;
        for (uj, w) in u.iter_mut().zip(&self.w) {
            for (wi, xi) in w.iter().zip(x) {
                *uj += wi * xi;
            }
        }
        if linear {
            u
        } else {
            k.act.apply_all(k.gain, u)
        }
    }

    /// δ of the layer below, whose outputs `x` feed this one, from this
    /// layer's δ `d` (weights before this pattern's update).
    #[inline(always)]
    fn back(&self, x: &[f64; NIN], d: &[f64; NOUT], k: Kind) -> [f64; NIN] {
        let mut below = [0.0; NIN];
        for (i, (b, xi)) in below.iter_mut().zip(x).enumerate() {
            let mut sum = 0.0;
            for (w, dk) in self.w.iter().zip(d) {
                sum += w[i] * dk;
            }
            *b = k.act.slope(k.gain, *xi) * sum;
        }
        below
    }

    /// Δw = LR·δ_j·X_i + M·Δw_prev, w += Δw; thresholds alike.
    #[inline(always)]
    fn update(&mut self, x: &[f64; NIN], d: &[f64; NOUT], lr: f64, m: f64) {
        let rows = self.w.iter_mut().zip(&mut self.dw);
        let ts = self.t.iter_mut().zip(&mut self.dt);
        for (((w, dw), (t, dt)), dj) in rows.zip(ts).zip(d) {
            let ld = lr * dj;
            for ((wi, di), xi) in w.iter_mut().zip(dw.iter_mut()).zip(x) {
                *di = ld * xi + m * *di;
                *wi += *di;
            }
            *dt = ld + m * *dt;
            *t += *dt;
        }
    }
}

/// δ of the single output neuron.
#[inline(always)]
fn output_delta(k: Kind, y: f64, e: f64) -> [f64; 1] {
    let slope = if k.linear_output {
        1.0
    } else {
        k.act.slope(k.gain, y)
    };
    [slope * e]
}

/// A network of fixed shape with I inputs and one output.
trait Fixed<const I: usize>: Sized {
    fn load(params: &[f64]) -> Self;
    fn store(&self, params: &mut [f64]);
    /// Forward pass and the update for target `d`: returns (Y, d − Y),
    /// Y from before the update.
    fn step(&mut self, x: &[f64; I], d: f64, k: Kind, lr: f64, m: f64) -> (f64, f64);
}

/// I-H1-H2-1.
struct Net3<const I: usize, const H1: usize, const H2: usize>(
    Dense<I, H1>,
    Dense<H1, H2>,
    Dense<H2, 1>,
);

impl<const I: usize, const H1: usize, const H2: usize> Fixed<I> for Net3<I, H1, H2> {
    fn load(p: &[f64]) -> Self {
        let (a, p) = Dense::load(p);
        let (b, p) = Dense::load(p);
        let (c, _) = Dense::load(p);
        Net3(a, b, c)
    }

    fn store(&self, p: &mut [f64]) {
        let p = self.0.store(p);
        let p = self.1.store(p);
        self.2.store(p);
    }

    #[inline(always)]
    fn step(&mut self, x: &[f64; I], d: f64, k: Kind, lr: f64, m: f64) -> (f64, f64) {
        let a1 = self.0.forward(x, k, false);
        let a2 = self.1.forward(&a1, k, false);
        let [y] = self.2.forward(&a2, k, k.linear_output);
        let e = d - y;
        let d3 = output_delta(k, y, e);
        let d2 = self.2.back(&a2, &d3, k);
        let d1 = self.1.back(&a1, &d2, k);
        self.0.update(x, &d1, lr, m);
        self.1.update(&a1, &d2, lr, m);
        self.2.update(&a2, &d3, lr, m);
        (y, e)
    }
}

/// I-H1-H2-H3-1.
struct Net4<const I: usize, const H1: usize, const H2: usize, const H3: usize>(
    Dense<I, H1>,
    Dense<H1, H2>,
    Dense<H2, H3>,
    Dense<H3, 1>,
);

impl<const I: usize, const H1: usize, const H2: usize, const H3: usize> Fixed<I>
    for Net4<I, H1, H2, H3>
{
    fn load(p: &[f64]) -> Self {
        let (a, p) = Dense::load(p);
        let (b, p) = Dense::load(p);
        let (c, p) = Dense::load(p);
        let (d, _) = Dense::load(p);
        Net4(a, b, c, d)
    }

    fn store(&self, p: &mut [f64]) {
        let p = self.0.store(p);
        let p = self.1.store(p);
        let p = self.2.store(p);
        self.3.store(p);
    }

    #[inline(always)]
    fn step(&mut self, x: &[f64; I], d: f64, k: Kind, lr: f64, m: f64) -> (f64, f64) {
        let a1 = self.0.forward(x, k, false);
        let a2 = self.1.forward(&a1, k, false);
        let a3 = self.2.forward(&a2, k, false);
        let [y] = self.3.forward(&a3, k, k.linear_output);
        let e = d - y;
        let d4 = output_delta(k, y, e);
        let d3 = self.3.back(&a3, &d4, k);
        let d2 = self.2.back(&a2, &d3, k);
        let d1 = self.1.back(&a1, &d2, k);
        self.0.update(x, &d1, lr, m);
        self.1.update(&a1, &d2, lr, m);
        self.2.update(&a2, &d3, lr, m);
        self.3.update(&a3, &d4, lr, m);
        (y, e)
    }
}

/// The loop for a fixed shape. The weights live in the layers during an
/// epoch and are written back to `net.params` after each (for the
/// divergence check, and so that a stopped run leaves them there).
fn run_fixed<const I: usize, N: Fixed<I>>(net: &mut Network, args: Args) -> (StopReason, u64) {
    let (data, settings, rng, member, deadline, observe) = args;
    let n = data.x.len();
    let xs: Vec<[f64; I]> = data
        .x
        .iter()
        .map(|r| r.as_slice().try_into().expect("pattern width = inputs"))
        .collect();
    let mut order: Vec<usize> = (0..n).collect();
    let mut f = N::load(&net.params);
    let k = Kind::of(net);
    let noise = settings.input_noise;
    for epoch in 1..=settings.epochs {
        rng.shuffle(&mut order);
        let run = if noise > 0.0 {
            epoch_fixed::<I, N, true>(&mut f, &xs, data, settings, k, &order, rng)
        } else {
            epoch_fixed::<I, N, false>(&mut f, &xs, data, settings, k, &order, rng)
        };
        f.store(&mut net.params);
        let end = end_epoch(
            run,
            epoch,
            &net.params,
            data,
            settings,
            member,
            deadline,
            observe,
        );
        if let Some(stop) = end {
            return (stop, epoch);
        }
    }
    (StopReason::EpochLimit, settings.epochs)
}

/// One epoch in the order `order`; `NOISE` adds the input noise.
#[inline(always)]
fn epoch_fixed<const I: usize, N: Fixed<I>, const NOISE: bool>(
    f: &mut N,
    xs: &[[f64; I]],
    data: &Encoded,
    s: &Settings,
    k: Kind,
    order: &[usize],
    rng: &mut Rng,
) -> Running {
    let (lr, m, tol) = (s.learning_rate, s.momentum, s.train_tolerance);
    let mut run = Running::new();
    for &p in order {
        let mut x = xs[p];
        if NOISE {
            for xi in &mut x {
                *xi += rng.symmetric(s.input_noise);
            }
        }
        let (y, e) = f.step(&x, data.d[p], k, lr, m);
        run.add(data, p, y, e, tol);
    }
    run
}

// ---------------------------------------------------------------------------
// Any other architecture: flat buffers, sizes at run time.

fn run_general(layers: &[usize], net: &mut Network, args: Args) -> (StopReason, u64) {
    let (data, settings, rng, member, deadline, observe) = args;
    let n = data.x.len();
    let np = net.params.len();
    let nl = layers.len();
    // Offsets of each layer in acts and of its block in params.
    let mut aoff = vec![0usize; nl];
    let mut poff = vec![0usize; nl + 1];
    for l in 1..nl {
        aoff[l] = aoff[l - 1] + layers[l - 1];
        poff[l + 1] = poff[l] + layers[l] * (layers[l - 1] + 1);
    }
    let total: usize = layers.iter().sum();
    let mut order: Vec<usize> = (0..n).collect();
    let mut dprev = vec![0.0; np];
    let mut acts = vec![0.0; total];
    let mut deltas = vec![0.0; total];
    let (lr, m, tol) = (
        settings.learning_rate,
        settings.momentum,
        settings.train_tolerance,
    );
    let k = Kind::of(net);
    let g = General {
        layers,
        aoff: &aoff,
        poff: &poff,
        k,
    };
    for epoch in 1..=settings.epochs {
        rng.shuffle(&mut order);
        let mut run = Running::new();
        for &p in &order {
            acts[..layers[0]].copy_from_slice(&data.x[p]);
            if settings.input_noise > 0.0 {
                for a in &mut acts[..layers[0]] {
                    *a += rng.symmetric(settings.input_noise);
                }
            }
            let y = g.forward(&net.params, &mut acts);
            let e = data.d[p] - y;
            run.add(data, p, y, e, tol);
            g.update(&mut net.params, &mut dprev, &acts, &mut deltas, e, lr, m);
        }
        let end = end_epoch(
            run,
            epoch,
            &net.params,
            data,
            settings,
            member,
            deadline,
            observe,
        );
        if let Some(stop) = end {
            return (stop, epoch);
        }
    }
    (StopReason::EpochLimit, settings.epochs)
}

/// A run-time shape with its offsets computed once.
struct General<'a> {
    layers: &'a [usize],
    /// Start of layer l in `acts`.
    aoff: &'a [usize],
    /// Start of layer l's block in the flat parameters (l ≥ 1).
    poff: &'a [usize],
    k: Kind,
}

impl General<'_> {
    /// Forward pass over flat buffers, inputs already in `acts`; same
    /// arithmetic as `Network::forward`.
    fn forward(&self, params: &[f64], acts: &mut [f64]) -> f64 {
        let (layers, k) = (self.layers, self.k);
        let nl = layers.len();
        for l in 1..nl {
            let (nin, nout) = (layers[l - 1], layers[l]);
            let linear = k.linear_output && l == nl - 1;
            let (a0, p0) = (self.aoff[l - 1], self.poff[l]);
            let block = &params[p0..p0 + nout * (nin + 1)];
            let (below, here) = acts.split_at_mut(self.aoff[l]);
            let a_in = &below[a0..];
            for (out, w) in here[..nout].iter_mut().zip(block.chunks_exact(nin + 1)) {
                let mut u = w[nin];
                for (wi, xi) in w[..nin].iter().zip(a_in) {
                    u += wi * xi;
                }
                *out = if linear { u } else { k.act.apply(k.gain, u) };
            }
        }
        acts[self.aoff[nl - 1]]
    }

    /// δ of every neuron and the momentum update; same arithmetic as
    /// `Network::backprop_step`. `deltas` is indexed like `acts`.
    #[allow(clippy::too_many_arguments)]
    fn update(
        &self,
        params: &mut [f64],
        dprev: &mut [f64],
        acts: &[f64],
        deltas: &mut [f64],
        err: f64,
        lr: f64,
        m: f64,
    ) {
        let (layers, aoff, poff, k) = (self.layers, self.aoff, self.poff, self.k);
        let nl = layers.len();
        let out = aoff[nl - 1];
        deltas[out] = output_delta(k, acts[out], err)[0];
        for l in (1..nl - 1).rev() {
            let (nin, nout) = (layers[l], layers[l + 1]);
            let p0 = poff[l + 1];
            let (lo, hi) = deltas.split_at_mut(aoff[l + 1]);
            let dn = &hi[..nout];
            for (i, (d, y)) in lo[aoff[l]..]
                .iter_mut()
                .zip(&acts[aoff[l]..aoff[l] + nin])
                .enumerate()
            {
                let mut sum = 0.0;
                for (kk, dk) in dn.iter().enumerate() {
                    sum += params[p0 + kk * (nin + 1) + i] * dk;
                }
                *d = k.act.slope(k.gain, *y) * sum;
            }
        }
        for l in 1..nl {
            let (nin, nout) = (layers[l - 1], layers[l]);
            let p0 = poff[l];
            let len = nout * (nin + 1);
            let a = &acts[aoff[l - 1]..aoff[l - 1] + nin];
            let d = &deltas[aoff[l]..aoff[l] + nout];
            let rows = params[p0..p0 + len].chunks_exact_mut(nin + 1);
            let drows = dprev[p0..p0 + len].chunks_exact_mut(nin + 1);
            for ((wr, dr), dj) in rows.zip(drows).zip(d) {
                let ld = lr * dj;
                for ((wi, di), xi) in wr[..nin].iter_mut().zip(&mut dr[..nin]).zip(a) {
                    *di = ld * xi + m * *di;
                    *wi += *di;
                }
                dr[nin] = ld + m * dr[nin];
                wr[nin] += dr[nin];
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ann::case::Case;
    use crate::ann::dataset::Dataset;

    fn general(net: &mut Network, enc: &Encoded, s: &Settings, seed: u64) -> (StopReason, u64) {
        let layers: Vec<usize> = std::hint::black_box(net.layers.clone());
        let mut rng = Rng::new(seed);
        let mut observe = |_: &EpochStats| Flow::Continue;
        run_general(&layers, net, (enc, s, &mut rng, 0, None, &mut observe))
    }

    /// The fixed-shape copies must give the very bits of the general loop
    /// and of `Network::backprop_step`, for each of the paper's shapes.
    #[test]
    fn fixed_loops_equal_general_loop_and_network_step() {
        for case in [Case::K4Stht, Case::MassDpmi, Case::MassStht] {
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
            let mut slow = net0.clone();
            general(&mut slow, &enc, &s, 4);
            assert_eq!(fast.params, slow.params, "{case}");
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
            assert_eq!(fast.params, reference.params, "{case}");
        }
    }

    /// Input noise, tanh, a linear output and per-epoch statistics take the
    /// same course in both loops too.
    #[test]
    fn fixed_and_general_loops_agree_on_the_options() {
        let case = Case::MassStht;
        let s0 = Settings::paper(case);
        let data = Dataset::build(case, &s0.train_values, &s0.grid).unwrap();
        for (act, linear, noise) in [
            (Activation::Logistic, false, 0.02),
            (Activation::Tanh, true, 0.0),
            (Activation::Tanh, false, 0.01),
        ] {
            let mut s = Settings::paper(case);
            s.epochs = 4;
            s.stop_when_all_right = false;
            s.activation = act;
            s.input_noise = noise;
            s.linear_output = linear;
            let enc = Encoded::new(&data, &s).unwrap();
            let mut net0 = Network::new(&s.layers, act, 1.0, 0.5, &mut Rng::new(2)).unwrap();
            net0.linear_output = linear;
            let mut fast = net0.clone();
            let mut seen_fast = Vec::new();
            run(&mut fast, &enc, &s, &mut Rng::new(6), 0, None, &mut |e| {
                seen_fast.push((e.rms.to_bits(), e.mpre_pct.to_bits(), e.share_right));
                Flow::Continue
            });
            let mut slow = net0.clone();
            let mut seen_slow = Vec::new();
            let layers: Vec<usize> = std::hint::black_box(slow.layers.clone());
            let mut observe = |e: &EpochStats| {
                seen_slow.push((e.rms.to_bits(), e.mpre_pct.to_bits(), e.share_right));
                Flow::Continue
            };
            let args = (&enc, &s, &mut Rng::new(6), 0, None, &mut observe as _);
            run_general(&layers, &mut slow, args);
            assert_eq!(fast.params, slow.params, "{act:?} {linear} {noise}");
            assert_eq!(seen_fast, seen_slow);
            assert_ne!(fast.params, net0.params);
        }
    }
}
