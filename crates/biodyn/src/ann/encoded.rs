//! What every trainer shares: the training data on the network's scale,
//! the per-pattern % error of the training loops, and the stop targets.
//! Trainers import this module; nothing here imports a trainer.

use super::dataset::Dataset;
use super::error::AnnError;
use super::exp::exp;
use super::metrics::EpochStats;
use super::scaling::Scaling;
use super::settings::Settings;
use super::stop::StopReason;

/// Training data on the network's scale.
#[derive(Debug, Clone)]
pub struct Encoded {
    pub scaling: Scaling,
    /// Scaled inputs, one row per pattern.
    pub x: Vec<Vec<f64>>,
    /// Scaled targets.
    pub d: Vec<f64>,
    /// Physical targets, for MPRE.
    pub actual: Vec<f64>,
    /// 100/|actual| per pattern, so that the per-pattern % error of the
    /// training loops needs no division.
    pct_scale: Vec<f64>,
    /// The output column's map back to physical units, folded to
    /// t = a + (y − lo)·c (then e^t for a log target).
    out_a: f64,
    out_lo: f64,
    out_c: f64,
    out_log: bool,
}

impl Encoded {
    pub fn new(data: &Dataset, settings: &Settings) -> Result<Encoded, AnnError> {
        let raw = data.inputs();
        let actual = data.targets();
        // Every segment mass (or k4), then f: as many as the base gives.
        let n = raw.first().map_or(data.case.inputs(), Vec::len);
        let mut input_log = vec![settings.log_param; n];
        if let Some(f) = input_log.last_mut() {
            *f = settings.log_freq;
        }
        let range = settings.activation.range();
        let scaling = Scaling::fit(
            &raw,
            &actual,
            &input_log,
            settings.log_target,
            settings.scaling_margin,
            range,
        )?;
        let x = raw
            .iter()
            .map(|r| {
                let mut o = vec![0.0; r.len()];
                scaling.scale_inputs(r, &mut o);
                o
            })
            .collect();
        let d = actual.iter().map(|&v| scaling.scale_output(v)).collect();
        let pct_scale = actual.iter().map(|a| 100.0 / a.abs()).collect();
        let (out_a, out_lo, out_c, out_log) = scaling.output_affine();
        Ok(Encoded {
            scaling,
            x,
            d,
            actual,
            pct_scale,
            out_a,
            out_lo,
            out_c,
            out_log,
        })
    }

    /// Physical % error 100·|ŷ − y|/|y| of scaled output `y` for pattern
    /// `p`: the training loops' per-pattern MPRE term. The same quantity as
    /// `metrics::pct_error` of the unscaled output, with the constant parts
    /// precomputed (so it may differ from it in the last bits).
    #[inline(always)]
    pub fn pct_error(&self, y: f64, p: usize) -> f64 {
        let t = self.out_a + (y - self.out_lo) * self.out_c;
        let phys = if self.out_log { exp(t) } else { t };
        (phys - self.actual[p]).abs() * self.pct_scale[p]
    }

    /// The stop reason if an epoch's metrics reach a target.
    pub fn target_reached(&self, s: &Settings, stats: &EpochStats) -> Option<StopReason> {
        if s.stop_when_all_right && stats.share_right >= 1.0 {
            return Some(StopReason::AllRight);
        }
        if s.rms_target.is_some_and(|t| stats.rms <= t) {
            return Some(StopReason::RmsTarget);
        }
        if s.mpre_target_pct.is_some_and(|t| stats.mpre_pct <= t) {
            return Some(StopReason::MpreTarget);
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ann::case::Case;
    use crate::ann::metrics;

    /// The training loops' precomputed % error is the MPRE term in
    /// physical units, for a plain and a log target.
    #[test]
    fn cheap_pct_error_is_the_physical_relative_error() {
        let case = Case::K4Dpmi;
        for log in [false, true] {
            let mut s = Settings::paper(case);
            s.log_target = log;
            let data = Dataset::build(case, &s.train_values, &s.grid).unwrap();
            let enc = Encoded::new(&data, &s).unwrap();
            let mut n = 0;
            for (p, &d) in enc.d.iter().enumerate() {
                for y in [d, d + 0.01, d - 0.2, 0.05, 0.97] {
                    let want = metrics::pct_error(enc.scaling.unscale_output(y), enc.actual[p]);
                    let got = enc.pct_error(y, p);
                    assert!(
                        (got - want).abs() <= 1e-9 * want.max(1.0),
                        "log {log}, pattern {p}, y {y}: {got} vs {want}"
                    );
                    n += 1;
                }
                assert!(enc.pct_error(d, p) < 1e-9);
            }
            assert_eq!(n, 5 * 120);
        }
    }
}
