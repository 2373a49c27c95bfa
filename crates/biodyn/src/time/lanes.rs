//! A parallel-form filter running: N exact first-order-hold biquads (one
//! per term of `foh::parallel`) side by side in lanes — they all take the
//! same input, so a sample is one N-wide biquad step — plus the direct part
//! and the hold's 3-tap compensator. The ISO 2631-1/8041-1 weightings run
//! on four lanes, ISO 2631-5's seat-to-spine transfer on six.

use super::biquad::Biquad;
use super::foh::{FIR_C, Term, fir_gain, foh_biquad};
use num_complex::Complex64;

/// The filter at one rate; unused lanes (fewer terms than N) stay idle.
/// The compensator is centred, so [`Lanes::process`] returns the output of
/// the previous sample.
#[derive(Debug, Clone)]
pub struct Lanes<const N: usize> {
    pub fs: f64,
    /// The terms' biquads, for the response.
    sections: [Biquad; N],
    b0: [f64; N],
    b1: [f64; N],
    b2: [f64; N],
    a1: [f64; N],
    a2: [f64; N],
    s1: [f64; N],
    s2: [f64; N],
    d: f64,
    /// The two previous hold outputs, older first.
    y: [f64; 2],
}

impl<const N: usize> Lanes<N> {
    /// One exact first-order-hold biquad per term (at most N), the direct
    /// part `d` beside them, at `fs` Hz.
    pub fn new(terms: &[Term], d: f64, fs: f64) -> Lanes<N> {
        // The lanes are summed in pairs.
        const { assert!(N >= 2 && N % 2 == 0, "an even number of lanes") };
        let mut sections = [Biquad::new([0.0; 3], [0.0; 2]); N];
        for (sec, t) in sections.iter_mut().zip(terms) {
            *sec = foh_biquad(*t, fs);
        }
        let lane = |f: fn(&Biquad) -> f64| -> [f64; N] { std::array::from_fn(|i| f(&sections[i])) };
        Lanes {
            fs,
            b0: lane(|s| s.b[0]),
            b1: lane(|s| s.b[1]),
            b2: lane(|s| s.b[2]),
            a1: lane(|s| s.a[0]),
            a2: lane(|s| s.a[1]),
            s1: [0.0; N],
            s2: [0.0; N],
            sections,
            d,
            y: [0.0; 2],
        }
    }

    /// Takes sample k, returns the output at sample k − 1 (0 for the first).
    /// The lanes are summed in pairs, the pairs in order: the same bits on
    /// every target.
    #[inline(always)]
    #[allow(clippy::needless_range_loop)] // lanes side by side: the form that vectorises
    pub fn process(&mut self, u: f64) -> f64 {
        let mut ys = [0.0; N];
        for i in 0..N {
            ys[i] = self.b0[i] * u + self.s1[i];
            self.s1[i] = self.b1[i] * u - self.a1[i] * ys[i] + self.s2[i];
            self.s2[i] = self.b2[i] * u - self.a2[i] * ys[i];
        }
        let mut sum = ys[0] + ys[1];
        for i in 1..N / 2 {
            sum += ys[2 * i] + ys[2 * i + 1];
        }
        let y = self.d * u + sum;
        let out = (1.0 + 2.0 * FIR_C) * self.y[1] - FIR_C * (self.y[0] + y);
        self.y = [self.y[1], y];
        out
    }

    /// Back to rest.
    pub fn reset(&mut self) {
        self.s1 = [0.0; N];
        self.s2 = [0.0; N];
        self.y = [0.0; 2];
    }

    /// The response at `f_hz`, aligned (without the one-sample lag).
    pub fn response(&self, f_hz: f64) -> Complex64 {
        let hold: Complex64 = self
            .sections
            .iter()
            .map(|s| s.response(f_hz, self.fs))
            .sum::<Complex64>()
            + self.d;
        hold * fir_gain(f_hz, self.fs)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Reset restarts: the same input after `reset` gives the same outputs
    /// as the first time, and the response is the lanes' sum.
    #[test]
    fn reset_restarts_and_the_response_is_the_sum() {
        let terms = [[4.0, 0.5, 4.0, 1.0], [900.0, 3.0, 2500.0, 30.0]];
        let mut f = Lanes::<4>::new(&terms, 0.1, 200.0);
        let input: Vec<f64> = (0..50).map(|k| (k as f64 * 0.3).sin()).collect();
        let first: Vec<f64> = input.iter().map(|&u| f.process(u)).collect();
        f.reset();
        let again: Vec<f64> = input.iter().map(|&u| f.process(u)).collect();
        assert_eq!(first, again);
        assert!(first.iter().any(|&v| v != 0.0));
        let b: Vec<Biquad> = terms.iter().map(|&t| foh_biquad(t, 200.0)).collect();
        let want =
            (b[0].response(3.0, 200.0) + b[1].response(3.0, 200.0) + 0.1) * fir_gain(3.0, 200.0);
        assert!((f.response(3.0) - want).norm() < 1e-15);
    }
}
