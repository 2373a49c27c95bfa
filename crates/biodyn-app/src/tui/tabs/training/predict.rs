//! The trained network against the analytic curve at one held-out value,
//! through `TrainedNet::compare`, the comparison `biodyn predict` prints.

use crate::view::chart::Series;
use biodyn::Band;
use biodyn::ann::Outcome;

#[derive(Debug, Clone)]
pub struct Prediction {
    pub value: f64,
    /// The analytic curve and the network's, ready to draw without copying.
    pub curves: [Series; 2],
    pub max_err_pct: f64,
    pub mean_err_pct: f64,
    pub extrapolation: bool,
}

/// The finished net's prediction at `value` over the default band; None
/// for a diverged run or a value the case cannot build a body for.
pub fn predict(out: &Outcome, value: f64) -> Option<Prediction> {
    if out.stop.is_diverged() {
        return None;
    }
    let c = out.net.compare(value, &Band::default()).ok()?;
    let pts = |ys: &[f64]| -> Vec<(f64, f64)> {
        c.freqs.iter().copied().zip(ys.iter().copied()).collect()
    };
    Some(Prediction {
        value: c.value,
        curves: [
            Series {
                name: "analytic".into(),
                points: pts(&c.analytic),
            },
            Series {
                name: "network".into(),
                points: pts(&c.predicted),
            },
        ],
        max_err_pct: c.max_err_pct,
        mean_err_pct: c.mean_err_pct,
        extrapolation: c.extrapolation,
    })
}
