//! The paper's three shapes with the layer sizes as constants: `Dense`
//! layers of fixed-size arrays the compiler unrolls, no index checked, the
//! same arithmetic (and bits) as the general loop.

use super::epoch::{Args, Kind, Running, end_epoch, output_delta};
use crate::ann::encoded::Encoded;
use crate::ann::network::Network;
use crate::ann::settings::Settings;
use crate::ann::stop::StopReason;
use crate::rng::Rng;

/// One layer after the input, NIN inputs and NOUT neurons: weights,
/// thresholds and their last changes (momentum), in fixed-size arrays.
#[derive(Clone)]
pub(super) struct Dense<const NIN: usize, const NOUT: usize> {
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

/// A network of fixed shape with I inputs and one output.
pub(super) trait Fixed<const I: usize>: Sized {
    fn load(params: &[f64]) -> Self;
    fn store(&self, params: &mut [f64]);
    /// Forward pass and the update for target `d`: returns (Y, d − Y),
    /// Y from before the update.
    fn step(&mut self, x: &[f64; I], d: f64, k: Kind, lr: f64, m: f64) -> (f64, f64);
}

/// I-H1-H2-1.
pub(super) struct Net3<const I: usize, const H1: usize, const H2: usize>(
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
pub(super) struct Net4<const I: usize, const H1: usize, const H2: usize, const H3: usize>(
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
pub(super) fn run_fixed<const I: usize, N: Fixed<I>>(
    net: &mut Network,
    args: Args,
) -> (StopReason, u64) {
    let (data, settings, rng, member, halt, observe) = args;
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
            halt,
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
pub(super) fn epoch_fixed<const I: usize, N: Fixed<I>, const NOISE: bool>(
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
