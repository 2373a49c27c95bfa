//! Scaling with a scaling margin (SPEC §4): each variable's [min, max] over
//! the training set is widened by SM·(max − min) on each side and mapped
//! linearly onto the activation's range. The headroom lets a net predict a
//! little beyond what it was trained on; without it the logistic would have
//! to reach its asymptotes at the training extremes.
//!
//! A column may first be taken to its natural logarithm (log-frequency input,
//! log-magnitude target): the same relative change then moves the scaled value
//! by the same amount anywhere in the band.

use super::error::AnnError;
use serde::{Deserialize, Serialize};

/// One variable: optional log transform, then its training min and max.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Column {
    pub log: bool,
    /// Min and max of the (transformed) training values, before the margin.
    pub min: f64,
    pub max: f64,
}

/// Scaling of all inputs and the output of one network.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Scaling {
    /// SM, a fraction of each column's span added on either side.
    pub margin: f64,
    /// The activation's range the columns are mapped onto.
    pub lo: f64,
    pub hi: f64,
    pub inputs: Vec<Column>,
    pub output: Column,
}

impl Column {
    fn fit(values: impl Iterator<Item = f64>, log: bool) -> Result<Column, AnnError> {
        let mut min = f64::INFINITY;
        let mut max = f64::NEG_INFINITY;
        for v in values {
            let t = if log {
                if v.is_nan() || v <= 0.0 {
                    return Err(AnnError::LogOfNonPositive(v));
                }
                v.ln()
            } else {
                v
            };
            if !t.is_finite() {
                return Err(AnnError::NonFiniteData(v));
            }
            min = min.min(t);
            max = max.max(t);
        }
        if !(min.is_finite() && max.is_finite()) {
            return Err(AnnError::EmptyDataset);
        }
        Ok(Column { log, min, max })
    }

    /// Widened interval [a, b] that maps onto the activation range.
    pub(crate) fn widened(&self, margin: f64) -> (f64, f64) {
        let span = self.max - self.min;
        // A constant column (one training value) still needs a non-zero span.
        let span = if span > 0.0 {
            span
        } else {
            self.max.abs().max(1.0)
        };
        (self.min - margin * span, self.max + margin * span)
    }
}

impl Scaling {
    /// Fits the scaling to training rows (`inputs[p][i]`) and targets.
    pub fn fit(
        inputs: &[Vec<f64>],
        targets: &[f64],
        input_log: &[bool],
        output_log: bool,
        margin: f64,
        range: (f64, f64),
    ) -> Result<Scaling, AnnError> {
        if !(margin.is_finite() && margin >= 0.0) {
            return Err(AnnError::BadMargin(margin));
        }
        if inputs.is_empty() {
            return Err(AnnError::EmptyDataset);
        }
        let cols = input_log
            .iter()
            .enumerate()
            .map(|(i, &log)| Column::fit(inputs.iter().map(|r| r[i]), log))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Scaling {
            margin,
            lo: range.0,
            hi: range.1,
            inputs: cols,
            output: Column::fit(targets.iter().copied(), output_log)?,
        })
    }

    fn value_to_unit(&self, c: &Column, v: f64) -> f64 {
        let t = if c.log { v.ln() } else { v };
        let (a, b) = c.widened(self.margin);
        self.lo + (self.hi - self.lo) * (t - a) / (b - a)
    }

    fn unit_to_value(&self, c: &Column, s: f64) -> f64 {
        let (a, b) = c.widened(self.margin);
        let t = a + (s - self.lo) / (self.hi - self.lo) * (b - a);
        if c.log { t.exp() } else { t }
    }

    /// Physical inputs to the network's scale, into `out`.
    pub fn scale_inputs(&self, raw: &[f64], out: &mut [f64]) {
        for ((o, c), &v) in out.iter_mut().zip(&self.inputs).zip(raw) {
            *o = self.value_to_unit(c, v);
        }
    }

    pub fn scale_output(&self, v: f64) -> f64 {
        self.value_to_unit(&self.output, v)
    }

    /// The network's output back to physical units.
    pub fn unscale_output(&self, s: f64) -> f64 {
        self.unit_to_value(&self.output, s)
    }

    /// `unscale_output` as (a, lo, c, log): t = a + (s − lo)·c, then e^t if
    /// `log`. For loops that unscale many outputs.
    pub fn output_affine(&self) -> (f64, f64, f64, bool) {
        let (a, b) = self.output.widened(self.margin);
        (a, self.lo, (b - a) / (self.hi - self.lo), self.output.log)
    }

    pub fn unscale_input(&self, i: usize, s: f64) -> f64 {
        self.unit_to_value(&self.inputs[i], s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn margin_maps_training_extremes_inside_the_range() {
        let rows = vec![vec![10.0], vec![20.0]];
        let s = Scaling::fit(&rows, &[1.0, 3.0], &[false], false, 0.1, (0.0, 1.0)).unwrap();
        let mut x = [0.0];
        s.scale_inputs(&[10.0], &mut x);
        // span 10, widened to [9, 21]: 10 → 1/12.
        assert!((x[0] - 1.0 / 12.0).abs() < 1e-15);
        assert!((s.scale_output(3.0) - 11.0 / 12.0).abs() < 1e-15);
        assert!((s.unscale_output(11.0 / 12.0) - 3.0).abs() < 1e-12);
    }

    #[test]
    fn log_column_round_trips_and_refuses_non_positive() {
        let rows = vec![vec![0.5], vec![20.0]];
        let s = Scaling::fit(&rows, &[2.0, 200.0], &[true], true, 0.1, (-1.0, 1.0)).unwrap();
        for v in [0.7, 3.0, 150.0] {
            let back = s.unscale_output(s.scale_output(v));
            assert!((back - v).abs() / v < 1e-12);
        }
        assert!(Scaling::fit(&rows, &[0.0, 1.0], &[true], true, 0.1, (0.0, 1.0)).is_err());
        assert!(Scaling::fit(&rows, &[1.0, 2.0], &[false], false, -0.1, (0.0, 1.0)).is_err());
    }
}
