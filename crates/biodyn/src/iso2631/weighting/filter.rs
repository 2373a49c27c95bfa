//! A weighting as a running digital filter: the parallel form's terms, each
//! discretised exactly for a first-order-hold input, side by side in lanes.

use super::formula::Weighting;
use crate::time::foh::parallel;
use crate::time::lanes::Lanes;
use num_complex::Complex64;

impl Weighting {
    /// The digital filter for sampling rate `fs` (fs > 0, finite).
    pub fn digital(self, fs: f64) -> WeightingFilter {
        let (terms, d) = parallel(&self.sections(), self.params().k);
        WeightingFilter {
            weighting: self,
            fs,
            lanes: Lanes::new(&terms, d, fs),
        }
    }
}

/// Parallel sections of every weighting: at most four stages have poles
/// (band limits, transition, step); a weighting with fewer leaves lanes idle.
pub(super) const SECTIONS: usize = 4;

/// A weighting as a running digital filter at one rate: the analog
/// weighting discretised exactly for a piecewise-linear input (Van Loan, as
/// the body is; the convention of `lsim`), realised as parallel biquads (one
/// per pole pair), then the 3-tap zero-phase FIR that undoes the hold's sinc²
/// droop (`time::lanes`). Phase is exact; |W| is within 0.1 % of the analog
/// up to fs/12. The FIR is centred, so each output is one sample late:
/// [`WeightingFilter::process`] returns the weighted value of the previous sample.
#[derive(Debug, Clone)]
pub struct WeightingFilter {
    pub weighting: Weighting,
    pub fs: f64,
    lanes: Lanes<SECTIONS>,
}

impl WeightingFilter {
    /// Takes sample k, returns the weighted sample k − 1 (0 for the first).
    #[inline(always)]
    pub fn process(&mut self, u: f64) -> f64 {
        self.lanes.process(u)
    }

    pub fn reset(&mut self) {
        self.lanes.reset();
    }

    /// The digital response at `f_hz`, aligned (without the one-sample lag).
    pub fn response(&self, f_hz: f64) -> Complex64 {
        self.lanes.response(f_hz)
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
