//! The loop for any architecture, its offsets computed once.

use super::epoch::{Args, Kind, Running, end_epoch, output_delta};
use crate::ann::network::Network;
use crate::ann::stop::{POLL_WORK, StopReason};

pub(super) fn run_general(layers: &[usize], net: &mut Network, args: Args) -> (StopReason, u64) {
    let (data, settings, rng, member, halt, observe) = args;
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
    // A large network's epoch can take minutes: the time limit and a
    // cancel are checked every POLL_WORK weight updates inside it too.
    let stride = (POLL_WORK / np.max(1)).max(1);
    for epoch in 1..=settings.epochs {
        rng.shuffle(&mut order);
        let mut run = Running::new();
        for (i, &p) in order.iter().enumerate() {
            if i > 0
                && i % stride == 0
                && let Some(stop) = halt.check()
            {
                return (stop, epoch - 1);
            }
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
            halt,
            observe,
        );
        if let Some(stop) = end {
            return (stop, epoch);
        }
    }
    (StopReason::EpochLimit, settings.epochs)
}

/// A run-time shape with its offsets computed once.
pub(super) struct General<'a> {
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
