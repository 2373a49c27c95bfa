//! Error measures of SPEC §4: RMS on the scaled scale, MPRE in physical
//! units, the share of outputs within a tolerance, and per-curve % errors.

use serde::Serialize;

/// sqrt(mean (Y − d)²) over scaled outputs and targets.
pub fn rms(pred: &[f64], target: &[f64]) -> f64 {
    if pred.is_empty() {
        return 0.0;
    }
    let s: f64 = pred
        .iter()
        .zip(target)
        .map(|(y, d)| (y - d) * (y - d))
        .sum();
    (s / pred.len() as f64).sqrt()
}

/// 100·|ŷ − y|/|y| for one pattern, in physical units.
pub fn pct_error(pred: f64, actual: f64) -> f64 {
    100.0 * (pred - actual).abs() / actual.abs()
}

/// Maximum percentage relative error over patterns (physical units).
pub fn mpre_pct(pred: &[f64], actual: &[f64]) -> f64 {
    pred.iter()
        .zip(actual)
        .map(|(p, a)| pct_error(*p, *a))
        .fold(0.0, f64::max)
}

/// Share (0..=1) of outputs with |Y − d| ≤ tol on the scaled scale.
pub fn share_right(pred: &[f64], target: &[f64], tol: f64) -> f64 {
    if pred.is_empty() {
        return 1.0;
    }
    let n = pred
        .iter()
        .zip(target)
        .filter(|(y, d)| (*y - *d).abs() <= tol)
        .count();
    n as f64 / pred.len() as f64
}

/// Max and mean % error of a predicted curve against the analytic one.
pub fn curve_error(pred: &[f64], actual: &[f64]) -> (f64, f64) {
    let e: Vec<f64> = pred
        .iter()
        .zip(actual)
        .map(|(p, a)| pct_error(*p, *a))
        .collect();
    let max = e.iter().copied().fold(0.0, f64::max);
    let mean = if e.is_empty() {
        0.0
    } else {
        e.iter().sum::<f64>() / e.len() as f64
    };
    (max, mean)
}

/// Metrics of one epoch (LM: one iteration) of one ensemble member.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct EpochStats {
    /// Ensemble member, 0-based.
    pub member: usize,
    /// Epochs completed by this member.
    pub epoch: u64,
    pub rms: f64,
    pub mpre_pct: f64,
    /// Share of training outputs right within the training tolerance.
    pub share_right: f64,
}

/// Prediction error on one hold-out curve.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HoldoutResult {
    /// `body_mass` or `k4`.
    pub param: &'static str,
    pub value: f64,
    pub max_err_pct: f64,
    pub mean_err_pct: f64,
    /// Outside the range of the training values.
    pub extrapolation: bool,
    /// Share of points within the testing tolerance (scaled scale).
    pub share_right: f64,
}

/// Worst hold-out max error among interpolation (false) or extrapolation (true) curves.
pub fn worst_holdout(holdout: &[HoldoutResult], extrapolation: bool) -> Option<f64> {
    holdout
        .iter()
        .filter(|h| h.extrapolation == extrapolation)
        .map(|h| h.max_err_pct)
        .reduce(f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hand_computed_values() {
        assert_eq!(rms(&[0.5, 0.1], &[0.2, 0.5]), (0.25f64 / 2.0 * 1.0).sqrt());
        assert_eq!(mpre_pct(&[110.0, 19.0], &[100.0, 20.0]), 10.0);
        assert_eq!(
            share_right(&[0.5, 0.6, 0.7], &[0.5005, 0.6, 0.71], 0.001),
            2.0 / 3.0
        );
        // Mean % error of the curve: (|1.1 − 1| / 1 · 100 + 0) / 2 = 5 %; to
        // rounding (1.1 is not exact in binary), not to its last bit.
        assert!((curve_error(&[1.1, 2.0], &[1.0, 2.0]).1 - 5.0).abs() < 1e-12);
    }
}
