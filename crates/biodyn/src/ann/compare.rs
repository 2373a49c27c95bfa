//! A trained network beside the analytic engine: the one comparison that
//! `biodyn predict`, the Training tab and the hold-out report all use.

use super::case::Case;
use super::error::AnnError;
use super::metrics::{curve_error, pct_error, share_right};
use super::trained::TrainedNet;
use crate::band::Band;
use crate::body::model::Body;
use crate::freq::response::Solver;

/// The network's curve and the analytic one over a band, with the errors.
#[derive(Debug, Clone, PartialEq)]
pub struct Comparison {
    /// The parameter the case varies (body mass in kg or k4 in N/m), as the body has it.
    pub value: f64,
    pub freqs: Vec<f64>,
    pub predicted: Vec<f64>,
    pub analytic: Vec<f64>,
    /// 100·|predicted − analytic|/|analytic| per frequency.
    pub err_pct: Vec<f64>,
    pub max_err_pct: f64,
    pub mean_err_pct: f64,
    /// `value` lies outside the range of the training values.
    pub extrapolation: bool,
    /// Part of the band lies outside the training grid's frequencies.
    pub beyond_grid: bool,
}

impl Comparison {
    /// Share of points within `tol` of the analytic value on the network's
    /// scaled output scale (the paper's "right" outputs).
    pub fn share_right(&self, net: &TrainedNet, tol: f64) -> f64 {
        let scaled =
            |v: &[f64]| -> Vec<f64> { v.iter().map(|&y| net.scaling.scale_output(y)).collect() };
        share_right(&scaled(&self.predicted), &scaled(&self.analytic), tol)
    }
}

/// Smallest and largest of `v` (infinite bounds when empty).
pub fn range_of(v: &[f64]) -> (f64, f64) {
    v.iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &x| {
            (l.min(x), h.max(x))
        })
}

impl TrainedNet {
    /// The trained range of the case's parameter.
    pub fn value_range(&self) -> (f64, f64) {
        range_of(&self.settings.train_values)
    }

    /// Compares on the net's own body (its base, or the paper's) at
    /// `value` (body mass or k4).
    pub fn compare(&self, value: f64, band: &Band) -> Result<Comparison, AnnError> {
        if !(value.is_finite() && value > 0.0) {
            return Err(AnnError::BadTrainValue {
                param: self.case.param_name(),
                value,
            });
        }
        let body = self.case.body_on(self.base(), value)?;
        self.compare_at(&body, value, band)
    }

    /// Compares on any body the net takes inputs from: as many segments
    /// as it was trained on (mass cases), a 4th link (k4 cases).
    pub fn compare_body(&self, body: &Body, band: &Band) -> Result<Comparison, AnnError> {
        self.compare_at(body, self.case.value_of(body), band)
    }

    /// `body` is the case's body at `value` (its body mass or k4).
    fn compare_at(&self, body: &Body, value: f64, band: &Band) -> Result<Comparison, AnnError> {
        band.validate()?;
        let case: Case = self.case;
        let freqs = band.freqs();
        let predicted = self.predict_body(body, &freqs)?;
        let solver = Solver::new(body);
        let analytic: Vec<f64> = freqs
            .iter()
            .map(|&f| solver.at(f).mag(case.function()))
            .collect();
        let err_pct = predicted
            .iter()
            .zip(&analytic)
            .map(|(&p, &a)| pct_error(p, a))
            .collect();
        let (max_err_pct, mean_err_pct) = curve_error(&predicted, &analytic);
        let (lo, hi) = self.value_range();
        let g = &self.settings.grid;
        Ok(Comparison {
            value,
            extrapolation: value < lo || value > hi,
            beyond_grid: band.from < g.from || band.to > g.to,
            freqs,
            predicted,
            analytic,
            err_pct,
            max_err_pct,
            mean_err_pct,
        })
    }
}
