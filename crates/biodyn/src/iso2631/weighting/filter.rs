//! A weighting as a running digital filter: the parallel form's terms, each
//! discretised exactly for a first-order-hold input, side by side in lanes.

use super::formula::Weighting;
use crate::time::biquad::Biquad;
use crate::time::foh::{FIR_C, Term, fir_gain, foh_biquad, parallel};
use num_complex::Complex64;

impl Weighting {
    /// The digital filter for sampling rate `fs` (fs > 0, finite).
    pub fn digital(self, fs: f64) -> WeightingFilter {
        let (terms, d) = parallel(&self.sections(), self.params().k);
        WeightingFilter::new(self, fs, &terms, d)
    }
}

/// Parallel sections of every weighting: at most four stages have poles
/// (band limits, transition, step); a weighting with fewer leaves lanes idle.
pub(super) const SECTIONS: usize = 4;

/// A weighting as a running digital filter at one rate: the analog
/// weighting discretised exactly for a piecewise-linear input (Van Loan, as
/// the body is; the convention of `lsim`), realised as parallel biquads (one
/// per pole pair), then the 3-tap zero-phase FIR that undoes the hold's sinc²
/// droop. Phase is exact; |W| is within 0.1 % of the analog up to fs/12. The
/// FIR is centred, so each output is one sample late:
/// [`WeightingFilter::process`] returns the weighted value of the previous sample.
#[derive(Debug, Clone)]
pub struct WeightingFilter {
    pub weighting: Weighting,
    pub fs: f64,
    /// The sections, for the response.
    sections: [Biquad; SECTIONS],
    /// The same, one section per lane: they all take the same input, so a
    /// sample is one 4-wide biquad step.
    b0: [f64; SECTIONS],
    b1: [f64; SECTIONS],
    b2: [f64; SECTIONS],
    a1: [f64; SECTIONS],
    a2: [f64; SECTIONS],
    s1: [f64; SECTIONS],
    s2: [f64; SECTIONS],
    d: f64,
    /// The two previous hold outputs, older first.
    y: [f64; 2],
}

impl WeightingFilter {
    /// The filter of `weighting` at `fs` from its parallel form: one exact
    /// first-order-hold biquad per term, the direct part `d` beside them.
    fn new(weighting: Weighting, fs: f64, terms: &[Term], d: f64) -> WeightingFilter {
        let mut sections = [Biquad::new([0.0; 3], [0.0; 2]); SECTIONS];
        for (sec, t) in sections.iter_mut().zip(terms) {
            *sec = foh_biquad(*t, fs);
        }
        let lane =
            |f: fn(&Biquad) -> f64| -> [f64; SECTIONS] { std::array::from_fn(|i| f(&sections[i])) };
        WeightingFilter {
            weighting,
            fs,
            b0: lane(|s| s.b[0]),
            b1: lane(|s| s.b[1]),
            b2: lane(|s| s.b[2]),
            a1: lane(|s| s.a[0]),
            a2: lane(|s| s.a[1]),
            s1: [0.0; SECTIONS],
            s2: [0.0; SECTIONS],
            sections,
            d,
            y: [0.0; 2],
        }
    }

    /// Takes sample k, returns the weighted sample k − 1 (0 for the first).
    #[inline(always)]
    #[allow(clippy::needless_range_loop)] // lanes side by side: the form that vectorises
    pub fn process(&mut self, u: f64) -> f64 {
        let mut ys = [0.0; SECTIONS];
        for i in 0..SECTIONS {
            ys[i] = self.b0[i] * u + self.s1[i];
            self.s1[i] = self.b1[i] * u - self.a1[i] * ys[i] + self.s2[i];
            self.s2[i] = self.b2[i] * u - self.a2[i] * ys[i];
        }
        let y = self.d * u + ((ys[0] + ys[1]) + (ys[2] + ys[3]));
        let out = (1.0 + 2.0 * FIR_C) * self.y[1] - FIR_C * (self.y[0] + y);
        self.y = [self.y[1], y];
        out
    }

    pub fn reset(&mut self) {
        self.s1 = [0.0; SECTIONS];
        self.s2 = [0.0; SECTIONS];
        self.y = [0.0; 2];
    }

    /// The digital response at `f_hz`, aligned (without the one-sample lag).
    pub fn response(&self, f_hz: f64) -> Complex64 {
        let hold: Complex64 = self
            .sections
            .iter()
            .map(|s| s.response(f_hz, self.fs))
            .sum::<Complex64>()
            + self.d;
        hold * fir_gain(f_hz, self.fs)
    }

    /// The largest relative error of |W| against the analog formula at the
    /// one-third-octave centres of the weighting's band below fs/2.
    pub fn max_error(&self) -> f64 {
        self.weighting
            .centres()
            .filter(|&f| f < self.fs / 2.0)
            .map(|f| (self.response(f).norm() / self.weighting.analog(f).norm() - 1.0).abs())
            .fold(0.0, f64::max)
    }

    /// A warning when fs is too low for the weighting's band: content above
    /// fs/2 is lost, or the filter misses the analog |W| by more than 1 %.
    pub fn warning(&self) -> Option<String> {
        let (_, hi) = self.weighting.band();
        let name = self.weighting.name();
        if self.fs / 2.0 <= hi {
            return Some(format!(
                "fs {} Hz is too low for {name}: its band reaches {hi} Hz, above fs/2 = {} Hz; sample at 1000 Hz or more",
                self.fs,
                self.fs / 2.0
            ));
        }
        let e = self.max_error();
        (e > 0.01).then(|| {
            format!(
                "fs {} Hz is low for {name}: the digital weighting misses the analog one by {:.1} % in its band; sample at 1000 Hz or more",
                self.fs,
                e * 100.0
            )
        })
    }
}
