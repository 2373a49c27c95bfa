//! The trained network against the analytic curve at one held-out value.
//! The curve, the interpolation/extrapolation test and the error figures
//! all come from `biodyn::ann`, as for `biodyn predict`.

use crate::view::chart::Series;
use biodyn::Band;
use biodyn::ann::{Case, Outcome, dataset, metrics};

#[derive(Debug, Clone)]
pub struct Prediction {
    pub value: f64,
    /// The analytic curve and the network's, ready to draw without copying.
    pub curves: [Series; 2],
    pub max_err_pct: f64,
    pub mean_err_pct: f64,
    pub extrapolation: bool,
}

/// The finished net's prediction at `value`; None for a diverged run or
/// a value the case cannot build a body for.
pub fn predict(case: Case, out: &Outcome, value: f64) -> Option<Prediction> {
    if out.stop.is_diverged() {
        return None;
    }
    let train = &out.net.settings.train_values;
    let held = dataset::holdouts(case, &[value], train, &Band::default()).ok()?;
    let h = held.into_iter().next()?;
    let body = case.body_at(value).ok()?;
    let pred = out.net.predict_body(&body, &h.curve.freqs).ok()?;
    let (max_err_pct, mean_err_pct) = metrics::curve_error(&pred, &h.curve.actual);
    let pts = |ys: &[f64]| -> Vec<(f64, f64)> {
        h.curve
            .freqs
            .iter()
            .copied()
            .zip(ys.iter().copied())
            .collect()
    };
    Some(Prediction {
        value,
        curves: [
            Series {
                name: "analytic".into(),
                points: pts(&h.curve.actual),
            },
            Series {
                name: "network".into(),
                points: pts(&pred),
            },
        ],
        max_err_pct,
        mean_err_pct,
        extrapolation: h.extrapolation,
    })
}
