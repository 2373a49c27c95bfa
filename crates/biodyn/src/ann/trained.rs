//! A trained network (or ensemble) with everything needed to use it: the
//! case, the settings it was trained with and its scaling.

use super::case::Case;
use super::error::AnnError;
use super::network::{Network, Scratch};
use super::scaling::Scaling;
use super::settings::{Combine, Settings};
use crate::body::model::Body;
use serde::{Deserialize, Serialize};

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct TrainedNet {
    pub case: Case,
    pub settings: Settings,
    pub scaling: Scaling,
    /// One network, or the members of an ensemble (prediction = their mean).
    pub members: Vec<Network>,
}

/// Reusable buffers for prediction.
#[derive(Debug, Clone)]
pub struct Predictor {
    x: Vec<f64>,
    scratch: Vec<Scratch>,
    ys: Vec<f64>,
}

impl TrainedNet {
    pub fn predictor(&self) -> Predictor {
        Predictor {
            x: vec![0.0; self.scaling.inputs.len()],
            scratch: self.members.iter().map(Network::scratch).collect(),
            ys: Vec::with_capacity(self.members.len()),
        }
    }

    /// The members' physical predictions for physical inputs, combined by
    /// the ensemble rule of the settings (mean or median).
    pub fn predict_with(&self, raw: &[f64], p: &mut Predictor) -> f64 {
        self.scaling.scale_inputs(raw, &mut p.x);
        p.ys.clear();
        for (m, s) in self.members.iter().zip(&mut p.scratch) {
            p.ys.push(self.scaling.unscale_output(m.forward(&p.x, s)[0]));
        }
        let n = p.ys.len();
        match self.settings.combine {
            Combine::Mean => p.ys.iter().sum::<f64>() / n as f64,
            Combine::Median => {
                p.ys.sort_by(f64::total_cmp);
                if n % 2 == 1 {
                    p.ys[n / 2]
                } else {
                    0.5 * (p.ys[n / 2 - 1] + p.ys[n / 2])
                }
            }
        }
    }

    /// Prediction for physical inputs (allocates; use `predict_with` in loops).
    pub fn predict(&self, raw: &[f64]) -> f64 {
        let mut p = self.predictor();
        self.predict_with(raw, &mut p)
    }

    /// The body the net was trained on (None: the paper's).
    pub fn base(&self) -> Option<&Body> {
        self.settings.base.as_ref()
    }

    /// The names of the net's inputs (m1..mn and f, or k4 and f).
    pub fn input_names(&self) -> Vec<String> {
        self.case.input_names_on(self.base())
    }

    /// The net's physical inputs for `body` at `f_hz`; Err when the body
    /// has another number of segments than the net has mass inputs.
    pub fn inputs_for(&self, body: &Body, f_hz: f64) -> Result<Vec<f64>, AnnError> {
        let x = self.case.inputs_of(body, f_hz)?;
        let want = self.scaling.inputs.len();
        if x.len() != want {
            return Err(AnnError::SegmentCount {
                case: self.case.key(),
                found: body.n(),
                expected: want.saturating_sub(1),
            });
        }
        Ok(x)
    }

    /// The predicted magnitude curve for a body over `freqs`; Err at the
    /// first frequency where the net gives no finite number (weights or
    /// biases that overflow: a damaged or hand-edited file), never `inf`.
    pub fn predict_body(&self, body: &Body, freqs: &[f64]) -> Result<Vec<f64>, AnnError> {
        let mut p = self.predictor();
        let mut x = self.inputs_for(body, 0.0)?;
        let last = x.len() - 1;
        freqs
            .iter()
            .map(|&f| {
                x[last] = f;
                let y = self.predict_with(&x, &mut p);
                if y.is_finite() {
                    Ok(y)
                } else {
                    Err(AnnError::NonFinitePrediction { f_hz: f, value: y })
                }
            })
            .collect()
    }

    /// Checks the stored net against its case and settings.
    pub fn validate(&self) -> Result<(), AnnError> {
        self.settings.validate(self.case)?;
        if self.members.is_empty() {
            return Err(AnnError::ZeroEnsemble);
        }
        for m in &self.members {
            m.validate()?;
            if m.layers != self.settings.layers {
                return Err(AnnError::ParamCount {
                    layers: m.layers.clone(),
                    expected: super::network::param_count(&self.settings.layers),
                    found: m.params.len(),
                });
            }
        }
        let want = self.case.input_count(self.base());
        if self.scaling.inputs.len() != want {
            return Err(AnnError::WrongInputCount {
                case: self.case.key(),
                expected: want,
                found: self.scaling.inputs.len(),
                names: self.input_names().join(", "),
            });
        }
        Ok(())
    }
}
