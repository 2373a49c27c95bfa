//! Training and hold-out data, computed by the analytic engine: never by a
//! second implementation of the physics.

use super::case::Case;
use super::error::AnnError;
use crate::band::Band;
use crate::body::model::Body;
use crate::freq::response::Solver;

/// One response curve: a parameter value and its magnitudes over a grid.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    /// Body mass in kg or k4 in N/m.
    pub value: f64,
    pub freqs: Vec<f64>,
    /// Physical network inputs, one row per frequency.
    pub inputs: Vec<Vec<f64>>,
    /// Analytic magnitude of the case's response function.
    pub actual: Vec<f64>,
}

impl Curve {
    /// The curve on the paper's body.
    pub fn compute(case: Case, value: f64, band: &Band) -> Result<Curve, AnnError> {
        Curve::compute_on(case, None, value, band)
    }

    /// The curve on `base` at `value` (`Case::body_on`); None: the paper's body.
    pub fn compute_on(
        case: Case,
        base: Option<&Body>,
        value: f64,
        band: &Band,
    ) -> Result<Curve, AnnError> {
        if !(value.is_finite() && value > 0.0) {
            return Err(AnnError::BadTrainValue {
                param: case.param_name(),
                value,
            });
        }
        band.validate()?;
        let body = case.body_on(base, value)?;
        let solver = Solver::new(&body);
        let freqs = band.freqs();
        let mut inputs = Vec::with_capacity(freqs.len());
        let mut actual = Vec::with_capacity(freqs.len());
        for &f in &freqs {
            inputs.push(case.inputs_of(&body, f)?);
            actual.push(solver.at(f).mag(case.function()));
        }
        Ok(Curve {
            value,
            freqs,
            inputs,
            actual,
        })
    }
}

/// The training set: curves at the training values on the training grid.
#[derive(Debug, Clone, PartialEq)]
pub struct Dataset {
    pub case: Case,
    pub curves: Vec<Curve>,
}

impl Dataset {
    /// The training set on the paper's body.
    pub fn build(case: Case, values: &[f64], grid: &Band) -> Result<Dataset, AnnError> {
        Dataset::build_on(case, None, values, grid)
    }

    /// The training set on `base` (None: the paper's body).
    pub fn build_on(
        case: Case,
        base: Option<&Body>,
        values: &[f64],
        grid: &Band,
    ) -> Result<Dataset, AnnError> {
        if values.is_empty() {
            return Err(AnnError::NoTrainValues);
        }
        case.check_base(base)?;
        let curves = values
            .iter()
            .map(|&v| Curve::compute_on(case, base, v, grid))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Dataset { case, curves })
    }

    /// All patterns' inputs, curve after curve.
    pub fn inputs(&self) -> Vec<Vec<f64>> {
        self.curves
            .iter()
            .flat_map(|c| c.inputs.iter().cloned())
            .collect()
    }

    pub fn targets(&self) -> Vec<f64> {
        self.curves
            .iter()
            .flat_map(|c| c.actual.iter().copied())
            .collect()
    }

    pub fn len(&self) -> usize {
        self.curves.iter().map(|c| c.freqs.len()).sum()
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Smallest and largest training value: the interpolation range.
    pub fn value_range(&self) -> (f64, f64) {
        self.curves
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), c| {
                (a.min(c.value), b.max(c.value))
            })
    }
}

/// A hold-out curve, marked inside (interpolation) or outside (extrapolation)
/// the range of the training values.
#[derive(Debug, Clone, PartialEq)]
pub struct Holdout {
    pub curve: Curve,
    pub extrapolation: bool,
}

/// Hold-out curves at `values` on `band` (default: the case's four values,
/// 0.5–20 Hz at 0.1 Hz), classified against the training values.
pub fn holdouts(
    case: Case,
    values: &[f64],
    train_values: &[f64],
    band: &Band,
) -> Result<Vec<Holdout>, AnnError> {
    holdouts_on(case, None, values, train_values, band)
}

/// As `holdouts`, on `base` (None: the paper's body).
pub fn holdouts_on(
    case: Case,
    base: Option<&Body>,
    values: &[f64],
    train_values: &[f64],
    band: &Band,
) -> Result<Vec<Holdout>, AnnError> {
    let lo = train_values.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = train_values
        .iter()
        .copied()
        .fold(f64::NEG_INFINITY, f64::max);
    values
        .iter()
        .map(|&v| {
            Ok(Holdout {
                curve: Curve::compute_on(case, base, v, band)?,
                extrapolation: v < lo || v > hi,
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_grid_gives_forty_points_per_curve() {
        let grid = Band::new(0.5, 20.0, 0.5).unwrap();
        let d = Dataset::build(Case::K4Apms, &Case::K4Apms.train_values(), &grid).unwrap();
        assert_eq!(d.len(), 120);
        assert_eq!(d.value_range(), (54_000.0, 126_000.0));
    }

    #[test]
    fn holdouts_are_classified() {
        let case = Case::MassStht;
        let h = holdouts(
            case,
            &case.holdout_values(),
            &case.train_values(),
            &Band::default(),
        )
        .unwrap();
        let ext: Vec<bool> = h.iter().map(|h| h.extrapolation).collect();
        assert_eq!(ext, vec![true, false, false, true]);
        assert_eq!(h[0].curve.freqs.len(), 196);
    }
}
