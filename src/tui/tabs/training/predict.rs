//! The trained network against the analytic curve at one held-out value,
//! through `TrainedNet::compare`, the comparison `biodyn predict` prints.

use crate::view::chart::Series;
use biodyn::ann::{Outcome, TrainedNet};
use biodyn::{Band, Body};

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
    predict_net(&out.net, value, None).ok()
}

/// `net` against the analytic curve at `value` (body mass or k4): on the
/// net's own body, or on `body` (the model being edited) brought to that
/// value by `Case::body_on` (`TrainedNet::compare_body` then needs the
/// segments and links the net was trained on). Err says why not.
pub fn predict_net(net: &TrainedNet, value: f64, body: Option<&Body>) -> Result<Prediction, String> {
    let band = Band::default();
    let c = match body {
        Some(b) => net
            .case
            .body_on(Some(b), value)
            .and_then(|at| net.compare_body(&at, &band)),
        None => net.compare(value, &band),
    }
    .map_err(|e| e.to_string())?;
    let pts = |ys: &[f64]| -> Vec<(f64, f64)> {
        c.freqs.iter().copied().zip(ys.iter().copied()).collect()
    };
    Ok(Prediction {
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
