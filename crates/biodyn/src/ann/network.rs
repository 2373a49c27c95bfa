//! A fully connected feed-forward network with the paper's neuron (SPEC §4):
//! U_j = Σ_i w_ij X_i, Y_j = F(U_j + t_j). The input layer only distributes.
//!
//! Parameters are stored flat, neuron by neuron: for each layer after the
//! input, each neuron's incoming weights followed by its threshold. The
//! threshold is then simply the weight of a constant input 1, which keeps
//! back-propagation and the Levenberg–Marquardt Jacobian one loop each.

use super::error::AnnError;
use super::exp::logistic_lanes;
use crate::rng::Rng;
use serde::{Deserialize, Serialize};

/// The activation F of every neuron after the input layer.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Activation {
    /// 1 / (1 + e^(−g·x)), range (0, 1): the paper's neuron.
    Logistic,
    /// tanh(g·x), range (−1, 1).
    Tanh,
}

impl Activation {
    /// The interval the scaled variables are mapped onto.
    pub fn range(self) -> (f64, f64) {
        match self {
            Activation::Logistic => (0.0, 1.0),
            Activation::Tanh => (-1.0, 1.0),
        }
    }

    pub fn key(self) -> &'static str {
        match self {
            Activation::Logistic => "logistic",
            Activation::Tanh => "tanh",
        }
    }

    #[inline]
    pub(crate) fn apply(self, gain: f64, x: f64) -> f64 {
        self.apply_all(gain, [x])[0]
    }

    /// `apply` on each of N values (a layer's neurons), the same bits as N
    /// calls; the logistic's exponentials run side by side in SIMD lanes.
    #[inline(always)]
    pub(crate) fn apply_all<const N: usize>(self, gain: f64, u: [f64; N]) -> [f64; N] {
        match self {
            // The crate's own logistic: the same bits on every platform.
            Activation::Logistic => logistic_lanes(u.map(|x| gain * x)),
            Activation::Tanh => u.map(|x| (gain * x).tanh()),
        }
    }

    /// dF/dx written through the output y, as back-propagation uses it.
    #[inline]
    pub(crate) fn slope(self, gain: f64, y: f64) -> f64 {
        match self {
            Activation::Logistic => gain * y * (1.0 - y),
            Activation::Tanh => gain * (1.0 - y * y),
        }
    }
}

/// Weights and thresholds of one network.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Network {
    /// Neurons per layer, input layer first (e.g. 5-6-4-2-1).
    pub layers: Vec<usize>,
    pub activation: Activation,
    /// Function gain g.
    pub gain: f64,
    /// Output neurons are linear (Y = U + t) instead of F: the
    /// Levenberg–Marquardt default, so that a log target that is a straight
    /// line in ln f needs no bend from the output sigmoid.
    #[serde(default)]
    pub linear_output: bool,
    /// Flat parameters; see the module doc for the order.
    pub params: Vec<f64>,
}

/// Per-call buffers so that the hot loops never allocate. Flat, with
/// offsets, so that the inner loops run over plain slices.
#[derive(Debug, Clone)]
pub struct Scratch {
    /// Outputs of every layer, input layer first.
    acts: Vec<f64>,
    /// δ of every neuron after the input layer.
    deltas: Vec<f64>,
    /// Start of layer l in `acts` (one extra entry: the total).
    aoff: Vec<usize>,
    /// Start of layer l+1's block in the flat parameters.
    poff: Vec<usize>,
}

/// Checks a layer list: at least an input and an output layer, no empty layer.
pub fn check_layers(layers: &[usize]) -> Result<(), AnnError> {
    if layers.len() < 2 {
        return Err(AnnError::TooFewLayers(layers.len()));
    }
    if let Some(i) = layers.iter().position(|&n| n == 0) {
        return Err(AnnError::ZeroNeurons { layer: i + 1 });
    }
    if layers.iter().any(|&n| n > 10_000) {
        return Err(AnnError::TooManyNeurons(layers.to_vec()));
    }
    Ok(())
}

/// Number of parameters (weights + thresholds) of an architecture.
pub fn param_count(layers: &[usize]) -> usize {
    layers.windows(2).map(|w| w[1] * (w[0] + 1)).sum()
}

impl Network {
    /// A network with every weight and threshold drawn uniformly from
    /// [−init_range, init_range): small enough that no neuron starts
    /// saturated, large enough to break the symmetry between neurons.
    pub fn new(
        layers: &[usize],
        activation: Activation,
        gain: f64,
        init_range: f64,
        rng: &mut Rng,
    ) -> Result<Network, AnnError> {
        check_layers(layers)?;
        let params = (0..param_count(layers))
            .map(|_| rng.symmetric(init_range))
            .collect();
        Ok(Network {
            layers: layers.to_vec(),
            activation,
            gain,
            linear_output: false,
            params,
        })
    }

    /// Checks that the stored parameters fit the declared architecture.
    pub fn validate(&self) -> Result<(), AnnError> {
        check_layers(&self.layers)?;
        let want = param_count(&self.layers);
        if self.params.len() != want {
            return Err(AnnError::ParamCount {
                layers: self.layers.clone(),
                expected: want,
                found: self.params.len(),
            });
        }
        if let Some(i) = self.params.iter().position(|p| !p.is_finite()) {
            return Err(AnnError::NonFiniteParam(i));
        }
        if !(self.gain.is_finite() && self.gain > 0.0) {
            return Err(AnnError::BadGain(self.gain));
        }
        Ok(())
    }

    pub fn inputs(&self) -> usize {
        self.layers[0]
    }

    pub fn outputs(&self) -> usize {
        self.layers[self.layers.len() - 1]
    }

    pub fn scratch(&self) -> Scratch {
        let mut aoff = vec![0];
        for &n in &self.layers {
            aoff.push(aoff[aoff.len() - 1] + n);
        }
        let mut poff = Vec::with_capacity(self.layers.len());
        let mut off = 0;
        for w in self.layers.windows(2) {
            poff.push(off);
            off += w[1] * (w[0] + 1);
        }
        let total = aoff[aoff.len() - 1];
        Scratch {
            acts: vec![0.0; total],
            deltas: vec![0.0; total - self.layers[0]],
            aoff,
            poff,
        }
    }

    /// Runs the network; the outputs are left in the scratch and returned.
    pub fn forward<'s>(&self, x: &[f64], s: &'s mut Scratch) -> &'s [f64] {
        let nl = self.layers.len();
        s.acts[..self.layers[0]].copy_from_slice(x);
        for l in 1..nl {
            let linear = self.linear_output && l == nl - 1;
            let (nin, nout) = (self.layers[l - 1], self.layers[l]);
            let (done, rest) = s.acts.split_at_mut(s.aoff[l]);
            let a_in = &done[s.aoff[l - 1]..];
            let p0 = s.poff[l - 1];
            let block = &self.params[p0..p0 + nout * (nin + 1)];
            for (out, w) in rest[..nout].iter_mut().zip(block.chunks_exact(nin + 1)) {
                let mut u = w[nin];
                for (wi, xi) in w[..nin].iter().zip(a_in) {
                    u += wi * xi;
                }
                *out = if linear {
                    u
                } else {
                    self.activation.apply(self.gain, u)
                };
            }
        }
        &s.acts[s.aoff[nl - 1]..]
    }

    /// δ of every neuron from the last `forward`, given `out_factor` per
    /// output (d − Y for the paper's rule, 1 for a Jacobian row).
    fn deltas(&self, s: &mut Scratch, out_factor: &[f64]) {
        let nl = self.layers.len();
        let n0 = self.layers[0];
        let out_a = s.aoff[nl - 1];
        for (j, f) in out_factor.iter().enumerate().take(self.layers[nl - 1]) {
            let slope = if self.linear_output {
                1.0
            } else {
                self.activation.slope(self.gain, s.acts[out_a + j])
            };
            s.deltas[out_a - n0 + j] = slope * f;
        }
        for l in (1..nl - 1).rev() {
            let (nin, nout) = (self.layers[l], self.layers[l + 1]);
            let p0 = s.poff[l];
            let (lo, hi) = s.deltas.split_at_mut(s.aoff[l + 1] - n0);
            let dl = &mut lo[s.aoff[l] - n0..];
            let dn = &hi[..nout];
            let a = &s.acts[s.aoff[l]..s.aoff[l] + nin];
            for (i, (d, y)) in dl.iter_mut().zip(a).enumerate() {
                let mut sum = 0.0;
                for (k, dk) in dn.iter().enumerate() {
                    sum += self.params[p0 + k * (nin + 1) + i] * dk;
                }
                *d = self.activation.slope(self.gain, *y) * sum;
            }
        }
    }

    /// Back-propagates from the last `forward`: writes into `grad` the
    /// factor δ_j·X_i for every parameter, in the flat order.
    pub fn backward(&self, s: &mut Scratch, out_factor: &[f64], grad: &mut [f64]) {
        self.deltas(s, out_factor);
        let n0 = self.layers[0];
        for l in 1..self.layers.len() {
            let (nin, nout) = (self.layers[l - 1], self.layers[l]);
            let p0 = s.poff[l - 1];
            let a = &s.acts[s.aoff[l - 1]..s.aoff[l]];
            let d = &s.deltas[s.aoff[l] - n0..s.aoff[l] - n0 + nout];
            let block = &mut grad[p0..p0 + nout * (nin + 1)];
            for (g, dj) in block.chunks_exact_mut(nin + 1).zip(d) {
                for (gi, xi) in g[..nin].iter_mut().zip(a) {
                    *gi = dj * xi;
                }
                g[nin] = *dj;
            }
        }
    }

    /// The paper's online update after a `forward` on pattern (x, d):
    /// Δw(t) = LR·δ_j·X_i + M·Δw(t−1), w += Δw, thresholds alike. Fused
    /// with the δ computation so that no gradient is stored.
    pub fn backprop_step(
        &mut self,
        s: &mut Scratch,
        err: f64,
        lr: f64,
        momentum: f64,
        dprev: &mut [f64],
    ) {
        self.deltas(s, &[err]);
        let n0 = self.layers[0];
        for l in 1..self.layers.len() {
            let (nin, nout) = (self.layers[l - 1], self.layers[l]);
            let p0 = s.poff[l - 1];
            let len = nout * (nin + 1);
            let a = &s.acts[s.aoff[l - 1]..s.aoff[l]];
            let d = &s.deltas[s.aoff[l] - n0..s.aoff[l] - n0 + nout];
            let w = &mut self.params[p0..p0 + len];
            let dw = &mut dprev[p0..p0 + len];
            for ((wr, dr), dj) in w
                .chunks_exact_mut(nin + 1)
                .zip(dw.chunks_exact_mut(nin + 1))
                .zip(d)
            {
                let ld = lr * dj;
                for ((wi, di), xi) in wr[..nin].iter_mut().zip(&mut dr[..nin]).zip(a) {
                    *di = ld * xi + momentum * *di;
                    *wi += *di;
                }
                dr[nin] = ld + momentum * dr[nin];
                wr[nin] += dr[nin];
            }
        }
    }

    /// Convenience: one output for one input vector (allocates; not for hot loops).
    pub fn eval(&self, x: &[f64]) -> Vec<f64> {
        let mut s = self.scratch();
        self.forward(x, &mut s).to_vec()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ann::exp::logistic;

    #[test]
    fn forward_matches_a_hand_computation() {
        // 2-1-1 with known weights: hidden u = 0.5·1 + (−1)·2 + 0.25 = −1.25.
        let net = Network {
            layers: vec![2, 1, 1],
            activation: Activation::Logistic,
            gain: 1.0,
            linear_output: false,
            params: vec![0.5, -1.0, 0.25, 2.0, -0.5],
        };
        let h = logistic(-1.25);
        let y = logistic(2.0 * h - 0.5);
        // And the logistic is the textbook formula to within rounding.
        assert!((h - 1.0 / (1.0 + 1.25f64.exp())).abs() < 1e-16);
        assert_eq!(net.eval(&[1.0, 2.0]), vec![y]);
    }

    #[test]
    fn backward_matches_finite_differences() {
        let mut rng = Rng::new(3);
        for act in [Activation::Logistic, Activation::Tanh] {
            for linear in [false, true] {
                let mut net = Network::new(&[3, 4, 2, 1], act, 1.3, 0.8, &mut rng).unwrap();
                net.linear_output = linear;
                let x = [0.2, 0.7, 0.4];
                let mut s = net.scratch();
                net.forward(&x, &mut s);
                let mut g = vec![0.0; net.params.len()];
                net.backward(&mut s, &[1.0], &mut g);
                for (p, gp) in g.iter().enumerate() {
                    let h = 1e-6;
                    let (mut a, mut b) = (net.clone(), net.clone());
                    a.params[p] += h;
                    b.params[p] -= h;
                    let fd = (a.eval(&x)[0] - b.eval(&x)[0]) / (2.0 * h);
                    assert!((fd - gp).abs() < 1e-7, "param {p}: {fd} vs {gp}");
                }
            }
        }
    }

    #[test]
    fn fused_step_equals_gradient_with_momentum() {
        let mut rng = Rng::new(5);
        let mut a = Network::new(&[2, 5, 3, 1], Activation::Logistic, 1.0, 0.5, &mut rng).unwrap();
        let mut b = a.clone();
        let (mut da, mut db) = (vec![0.1; a.params.len()], vec![0.1; a.params.len()]);
        let (mut sa, mut sb) = (a.scratch(), b.scratch());
        let x = [0.3, 0.9];
        let e = 0.7 - a.forward(&x, &mut sa)[0];
        a.backprop_step(&mut sa, e, 1.0, 0.9, &mut da);
        b.forward(&x, &mut sb);
        let mut g = vec![0.0; b.params.len()];
        b.backward(&mut sb, &[e], &mut g);
        for k in 0..g.len() {
            db[k] = g[k] + 0.9 * db[k];
            b.params[k] += db[k];
        }
        assert_eq!(a.params, b.params);
        assert_eq!(da, db);
    }

    #[test]
    fn bad_layers_are_refused() {
        let mut rng = Rng::new(1);
        let e = Network::new(&[5, 0, 1], Activation::Logistic, 1.0, 0.5, &mut rng);
        assert!(matches!(e, Err(AnnError::ZeroNeurons { layer: 2 })));
        let e = Network::new(&[5], Activation::Logistic, 1.0, 0.5, &mut rng);
        assert!(matches!(e, Err(AnnError::TooFewLayers(1))));
        assert_eq!(param_count(&[5, 6, 4, 2, 1]), 36 + 28 + 10 + 3);
    }
}
