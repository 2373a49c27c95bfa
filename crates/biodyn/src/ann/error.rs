//! Errors of the network side; each names the field and the value.

use crate::band::BandError;
use crate::body::model::ModelError;
use crate::io::excerpt::{Short, short_quote};
use std::path::PathBuf;

#[derive(Debug, thiserror::Error)]
pub enum AnnError {
    #[error("layer {layer} has 0 neurons: every layer needs at least one")]
    ZeroNeurons { layer: usize },
    #[error("{0} layer(s) given: a network needs at least an input and an output layer")]
    TooFewLayers(usize),
    #[error("layers {0:?}: more than 10000 neurons in a layer")]
    TooManyNeurons(Vec<usize>),
    #[error(
        "layers start with {found} input(s), but case '{case}' has {expected} ({names}): the first layer must have {expected} neurons"
    )]
    WrongInputCount {
        case: &'static str,
        expected: usize,
        found: usize,
        names: String,
    },
    #[error("layers end with {0} output(s): each case has one output, the response magnitude")]
    WrongOutputCount(usize),
    #[error("epochs = 0: give at least 1 epoch")]
    ZeroEpochs,
    #[error("learning rate = {}: it must be a finite number > 0", Short(*.0))]
    BadLearningRate(f64),
    #[error("momentum = {}: it must lie in [0, 1)", Short(*.0))]
    BadMomentum(f64),
    #[error("function gain = {}: it must be a finite number > 0", Short(*.0))]
    BadGain(f64),
    #[error("{field} = {}: it must be a finite number >= 0", Short(*.value))]
    BadSetting { field: &'static str, value: f64 },
    #[error("scaling margin = {}: it must be a finite number >= 0", Short(*.0))]
    BadMargin(f64),
    #[error(
        "the network predicts {value} at {} Hz, not a finite number: its weights or biases overflow (a damaged or hand-edited file); train it again",
        Short(*.f_hz)
    )]
    NonFinitePrediction { f_hz: f64, value: f64 },
    /// A size past what fits or can finish (`bounds`): the setting, its
    /// value and why.
    #[error("{setting} = {value}: {why}")]
    TooBig {
        setting: &'static str,
        value: String,
        why: String,
    },
    #[error("ensemble = 0: at least one network is needed")]
    ZeroEnsemble,
    #[error("unknown case '{}': use mass-stht, mass-dpmi, mass-apms, k4-stht, k4-dpmi, k4-apms", short_quote(.0))]
    UnknownCase(String),
    #[error("unknown trainer '{}': use backprop or lm", short_quote(.0))]
    UnknownTrainer(String),
    #[error("no training values: give at least one {0}")]
    NoTrainValuesFor(&'static str),
    #[error("no training values given")]
    NoTrainValues,
    #[error("{param} = {}: a training or prediction value must be a finite number > 0", Short(*.value))]
    BadTrainValue { param: &'static str, value: f64 },
    #[error("the training set is empty")]
    EmptyDataset,
    #[error("value {} is not finite: the training data cannot be scaled", Short(*.0))]
    NonFiniteData(f64),
    #[error("value {} has no logarithm: turn off the log transform for this column", Short(*.0))]
    LogOfNonPositive(f64),
    #[error("the training model is not valid: {0}")]
    BadBase(ModelError),
    #[error(
        "the model has {n} segments: a mass case takes every segment mass as an input, at most {max}; pick a k4 case or a smaller model"
    )]
    TooManySegments { n: usize, max: usize },
    #[error(
        "k4 cases vary k4, the 4th link; this model has {0} links: pick a mass case or add a link"
    )]
    NoK4Link(usize),
    #[error(
        "the body has {found} segments, but this {case} network takes {expected} segment masses as inputs: predict on a model with {expected} segments (the one it was trained on)"
    )]
    SegmentCount {
        case: &'static str,
        found: usize,
        expected: usize,
    },
    #[error("layers {layers:?} need {expected} weights and thresholds, but {found} are stored")]
    ParamCount {
        layers: Vec<usize>,
        expected: usize,
        found: usize,
    },
    #[error("parameter {0} is not a finite number")]
    NonFiniteParam(usize),
    #[error(transparent)]
    Model(#[from] ModelError),
    #[error(transparent)]
    Band(#[from] BandError),
    #[error("cannot {action} '{path}': {source}")]
    Io {
        action: &'static str,
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("'{path}' is not a valid network file: {message}")]
    Corrupted { path: PathBuf, message: String },
    #[error("'{path}' holds a network for case '{found}', not '{expected}'")]
    WrongCase {
        path: PathBuf,
        expected: &'static str,
        found: &'static str,
    },
    #[error("'{path}' holds architecture {found:?}, but {expected:?} was asked for")]
    WrongArchitecture {
        path: PathBuf,
        expected: Vec<usize>,
        found: Vec<usize>,
    },
    #[error(
        "'{path}' is a network file of version {found}; this biodyn reads versions 1 to {expected}"
    )]
    WrongVersion {
        path: PathBuf,
        expected: u32,
        found: u32,
    },
    #[error("the training worker stopped unexpectedly (it panicked)")]
    WorkerPanicked,
    #[error("{setting}: '{text}' is not {want}")]
    BadText {
        setting: &'static str,
        text: String,
        want: &'static str,
    },
    #[error("unknown training setting '{0}'")]
    UnknownSetting(String),
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_in_messages_stay_short() {
        assert_eq!(Short(1e300).to_string(), "1e300");
        assert_eq!(Short(-1e-300).to_string(), "-1e-300");
        assert_eq!(Short(54000.0).to_string(), "54000");
        assert_eq!(Short(0.5).to_string(), "0.5");
        assert_eq!(Short(0.0).to_string(), "0");
        assert_eq!(Short(f64::NAN).to_string(), "NaN");
        let e = AnnError::BadLearningRate(1e300).to_string();
        assert!(e.len() < 60, "{e}");
    }
}
