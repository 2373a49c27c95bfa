//! A fully connected feed-forward network with the paper's neuron (SPEC §4):
//! U_j = Σ_i w_ij X_i, Y_j = F(U_j + t_j). The input layer only distributes.
//!
//! Parameters are stored flat, neuron by neuron: for each layer after the
//! input, each neuron's incoming weights followed by its threshold. The
//! threshold is then simply the weight of a constant input 1, which keeps
//! back-propagation and the Levenberg–Marquardt Jacobian one loop each.

use super::error::AnnError;
use super::rng::Rng;
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
    fn apply(self, gain: f64, x: f64) -> f64 {
        match self {
            Activation::Logistic => 1.0 / (1.0 + (-gain * x).exp()),
            Activation::Tanh => (gain * x).tanh(),
        }
    }

    /// dF/dx written through the output y, as back-propagation uses it.
    #[inline]
    fn slope(self, gain: f64, y: f64) -> f64 {
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

/// Per-call buffers so that the hot loops never allocate.
#[derive(Debug, Clone)]
pub struct Scratch {
    /// Outputs of every layer, input layer first.
    acts: Vec<Vec<f64>>,
    /// δ of every layer after the input.
    deltas: Vec<Vec<f64>>,
    /// Start of each layer's block in the flat parameters.
    offs: Vec<usize>,
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
        Scratch {
            acts: self.layers.iter().map(|&n| vec![0.0; n]).collect(),
            deltas: self.layers[1..].iter().map(|&n| vec![0.0; n]).collect(),
            offs: self
                .layers
                .windows(2)
                .scan(0, |off, w| {
                    let start = *off;
                    *off += w[1] * (w[0] + 1);
                    Some(start)
                })
                .collect(),
        }
    }

    /// Runs the network; the outputs are left in the scratch and returned.
    pub fn forward<'s>(&self, x: &[f64], s: &'s mut Scratch) -> &'s [f64] {
        s.acts[0].copy_from_slice(x);
        let mut off = 0;
        let nl = self.layers.len();
        for l in 1..nl {
            let linear = self.linear_output && l == nl - 1;
            let (nin, nout) = (self.layers[l - 1], self.layers[l]);
            let (prev, rest) = s.acts.split_at_mut(l);
            let (a_in, a_out) = (&prev[l - 1], &mut rest[0]);
            for (j, out) in a_out.iter_mut().enumerate().take(nout) {
                let w = &self.params[off + j * (nin + 1)..off + (j + 1) * (nin + 1)];
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
            off += nout * (nin + 1);
        }
        &s.acts[self.layers.len() - 1]
    }

    /// Back-propagates from the last `forward`: with `out_factor` per output
    /// (d − Y for the paper's rule, 1 for a Jacobian row), writes into `grad`
    /// the factor δ_j·X_i for every parameter, in the flat order.
    pub fn backward(&self, s: &mut Scratch, out_factor: &[f64], grad: &mut [f64]) {
        let nl = self.layers.len();
        let last = nl - 2;
        for (j, d) in s.deltas[last].iter_mut().enumerate() {
            let slope = if self.linear_output {
                1.0
            } else {
                self.activation.slope(self.gain, s.acts[nl - 1][j])
            };
            *d = slope * out_factor[j];
        }
        for l in (1..nl - 1).rev() {
            // δ of layer l (index l-1 in deltas) from layer l+1.
            let (nin, nout) = (self.layers[l], self.layers[l + 1]);
            let o = s.offs[l];
            let (lo, hi) = s.deltas.split_at_mut(l);
            let (dl, dn) = (&mut lo[l - 1], &hi[0]);
            for (i, d) in dl.iter_mut().enumerate() {
                let mut sum = 0.0;
                for (k, dk) in dn.iter().enumerate().take(nout) {
                    sum += self.params[o + k * (nin + 1) + i] * dk;
                }
                *d = self.activation.slope(self.gain, s.acts[l][i]) * sum;
            }
        }
        for l in 1..nl {
            let nin = self.layers[l - 1];
            let o = s.offs[l - 1];
            for (j, dj) in s.deltas[l - 1].iter().enumerate() {
                let g = &mut grad[o + j * (nin + 1)..o + (j + 1) * (nin + 1)];
                for (gi, xi) in g[..nin].iter_mut().zip(&s.acts[l - 1]) {
                    *gi = dj * xi;
                }
                g[nin] = *dj;
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
        let h = 1.0 / (1.0 + (1.25f64).exp());
        let y = 1.0 / (1.0 + (-(2.0 * h - 0.5)).exp());
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
                for p in 0..net.params.len() {
                    let h = 1e-6;
                    let (mut a, mut b) = (net.clone(), net.clone());
                    a.params[p] += h;
                    b.params[p] -= h;
                    let fd = (a.eval(&x)[0] - b.eval(&x)[0]) / (2.0 * h);
                    assert!((fd - g[p]).abs() < 1e-7, "param {p}: {fd} vs {}", g[p]);
                }
            }
        }
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
