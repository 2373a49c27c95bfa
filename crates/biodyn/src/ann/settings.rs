//! Training settings: the paper's back-propagation defaults and our
//! Levenberg–Marquardt defaults, in one struct a TUI can edit and a network
//! file can store.

use super::case::Case;
use super::error::AnnError;
use super::network::Activation;
use crate::band::Band;
use crate::body::model::Body;
use serde::{Deserialize, Serialize};
use std::fmt;

/// Which training algorithm (the value of the `trainer` setting; the
/// algorithms themselves sit behind `algorithm::Algorithm`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Trainer {
    /// The paper's online back-propagation with momentum.
    Backprop,
    /// Levenberg–Marquardt with weight decay, log target, log frequency and
    /// an ensemble: the trainer that generalises.
    Lm,
}

impl Trainer {
    pub const ALL: [Trainer; 2] = [Trainer::Backprop, Trainer::Lm];

    pub fn key(self) -> &'static str {
        match self {
            Trainer::Backprop => "backprop",
            Trainer::Lm => "lm",
        }
    }

    /// The name in sentences ("LM ignores them").
    pub fn label(self) -> &'static str {
        match self {
            Trainer::Backprop => "backprop",
            Trainer::Lm => "LM",
        }
    }

    pub fn parse(s: &str) -> Result<Trainer, AnnError> {
        match s.trim().to_ascii_lowercase().as_str() {
            "backprop" | "bp" => Ok(Trainer::Backprop),
            "lm" | "levenberg-marquardt" => Ok(Trainer::Lm),
            _ => Err(AnnError::UnknownTrainer(s.to_string())),
        }
    }
}

impl fmt::Display for Trainer {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.key())
    }
}

/// How an ensemble's predictions are combined.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum Combine {
    #[default]
    Mean,
    /// Robust to one member that fits the training set but wanders between
    /// the training curves.
    Median,
}

/// Everything that decides a training run. Same settings and seed, same bits.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Settings {
    pub trainer: Trainer,
    /// Neurons per layer, input layer first.
    pub layers: Vec<usize>,
    pub activation: Activation,
    /// Function gain g.
    pub gain: f64,
    /// Initial weights and thresholds are uniform in ±init_range.
    pub init_range: f64,
    pub seed: u64,
    /// Epoch limit (LM: iteration limit, per ensemble member).
    pub epochs: u64,
    /// Wall-time limit in seconds for the whole run, if any.
    pub time_limit_s: Option<f64>,
    /// Stop when the scaled RMS error falls to this, if set.
    pub rms_target: Option<f64>,
    /// Stop when the MPRE (%) falls to this, if set.
    pub mpre_target_pct: Option<f64>,
    /// Back-propagation: learning rate LR.
    pub learning_rate: f64,
    /// Back-propagation: momentum M, in [0, 1).
    pub momentum: f64,
    /// Back-propagation: uniform noise of this amplitude added to each scaled input, each epoch.
    pub input_noise: f64,
    /// An output is right when |Y − d| ≤ this on the scaled scale.
    pub train_tolerance: f64,
    /// The same, for testing (hold-out) data.
    pub test_tolerance: f64,
    /// Stop as soon as every training output is right.
    pub stop_when_all_right: bool,
    /// Scaling margin SM.
    pub scaling_margin: f64,
    /// Body masses (kg) or k4 values (N/m) the net is trained on.
    pub train_values: Vec<f64>,
    /// Training frequency grid.
    pub grid: Band,
    /// Train on ln|response|: relative error becomes uniform over the band.
    pub log_target: bool,
    /// Feed ln f instead of f: resolves the low-frequency end, where DPMI changes fastest.
    pub log_freq: bool,
    /// Feed ln of the parameter inputs (m1..m4 or k4): a resonance at
    /// f ∝ √(k/m) then sits on a straight line in (ln f, ln k) that one
    /// neuron can follow.
    #[serde(default)]
    pub log_param: bool,
    /// Linear output neuron instead of F (LM default; see `Network::linear_output`).
    #[serde(default)]
    pub linear_output: bool,
    /// L2 weight decay λ (LM): adds λ·Σθ² to the squared-error sum.
    pub weight_decay: f64,
    /// Number of networks trained from derived seeds.
    pub ensemble: usize,
    /// How their predictions are combined.
    #[serde(default)]
    pub combine: Combine,
    /// The body the training curves are built on (`basis`): None = the
    /// paper's, as before this field existed (and then not written).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub base: Option<Body>,
}

/// Paper's training grid: 0.5–20 Hz at 0.5 Hz (SPEC §4).
pub const TRAIN_GRID: Band = Band {
    from: 0.5,
    to: 20.0,
    step: 0.5,
};

impl Settings {
    /// The paper's settings (Table 5): LR 1, M 0.9, gain 1, noise 0,
    /// tolerances 0.001/0.003, SM 0.1, the paper's epoch count.
    pub fn paper(case: Case) -> Settings {
        Settings {
            trainer: Trainer::Backprop,
            layers: case.paper_layers().to_vec(),
            activation: Activation::Logistic,
            gain: 1.0,
            init_range: 0.5,
            seed: 1,
            epochs: case.paper().epochs,
            time_limit_s: None,
            rms_target: None,
            mpre_target_pct: None,
            learning_rate: 1.0,
            momentum: 0.9,
            input_noise: 0.0,
            train_tolerance: 0.001,
            test_tolerance: 0.003,
            stop_when_all_right: true,
            scaling_margin: 0.1,
            train_values: case.train_values(),
            grid: TRAIN_GRID,
            log_target: false,
            log_freq: false,
            log_param: false,
            linear_output: false,
            weight_decay: 0.0,
            ensemble: 1,
            combine: Combine::Mean,
            base: None,
        }
    }

    /// Our Levenberg–Marquardt defaults: the same networks, log target,
    /// log frequency, light weight decay and a 5-seed ensemble.
    pub fn lm(case: Case) -> Settings {
        Settings {
            trainer: Trainer::Lm,
            init_range: 1.0,
            epochs: 300,
            stop_when_all_right: false,
            log_target: true,
            log_freq: true,
            log_param: true,
            linear_output: true,
            weight_decay: 1e-6,
            ensemble: 5,
            combine: Combine::Median,
            ..Settings::paper(case)
        }
    }

    pub fn for_trainer(case: Case, trainer: Trainer) -> Settings {
        match trainer {
            Trainer::Backprop => Settings::paper(case),
            Trainer::Lm => Settings::lm(case),
        }
    }

    /// The trainer's defaults on `base` (None: the paper's body; a seat
    /// under it is left out): the
    /// first layer takes the base's inputs, the training values are the
    /// paper's scaled by the base's body mass or k4. Err when the case
    /// cannot train on the base (say why).
    pub fn for_trainer_on(
        case: Case,
        trainer: Trainer,
        base: Option<Body>,
    ) -> Result<Settings, AnnError> {
        let mut s = Settings::for_trainer(case, trainer);
        // The networks learn the body: a seat under it is left out, so the
        // cases vary the body on a rigid seat (SPEC §11).
        let base = base.map(|b| b.without_seat());
        case.check_base(base.as_ref())?;
        if let Some(first) = s.layers.first_mut() {
            *first = case.input_count(base.as_ref());
        }
        s.train_values = case.train_values_on(base.as_ref());
        s.base = base;
        Ok(s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_valid_for_every_case() {
        for c in Case::ALL {
            Settings::paper(c).validate(c).unwrap();
            Settings::lm(c).validate(c).unwrap();
        }
    }

    #[test]
    fn settings_round_trip_through_toml_for_presets() {
        for c in Case::ALL {
            let mut s = Settings::lm(c);
            s.time_limit_s = Some(2.5);
            let text = toml::to_string(&s).unwrap();
            assert_eq!(toml::from_str::<Settings>(&text).unwrap(), s, "{text}");
        }
        assert!(toml::from_str::<Settings>("nonsense = 1").is_err());
        // With a base body (a branch off the chest: a link between segments).
        let mut b = crate::body::model::Body::paper(80.0).unwrap();
        b.links[1].lower = crate::body::model::End::Segment(3);
        let s = Settings::for_trainer_on(Case::K4Apms, Trainer::Lm, Some(b)).unwrap();
        let text = toml::to_string(&s).unwrap();
        assert_eq!(toml::from_str::<Settings>(&text).unwrap(), s, "{text}");
        let json = serde_json::to_string(&s).unwrap();
        assert_eq!(serde_json::from_str::<Settings>(&json).unwrap(), s);
        // None is not written: files of older builds and newer ones agree.
        assert!(
            !toml::to_string(&Settings::lm(Case::K4Apms))
                .unwrap()
                .contains("base")
        );
    }

    #[test]
    fn a_seat_under_the_base_is_left_out_of_the_networks() {
        let p = crate::Preset::builtin("paper-75kg-suspension-seat")
            .unwrap()
            .unwrap();
        let s =
            Settings::for_trainer_on(Case::MassApms, Trainer::Lm, Some(p.body.clone())).unwrap();
        let base = s.base.clone().unwrap();
        assert_eq!(base, p.body.without_seat());
        assert!(!base.has_seat() && base.n() == 4);
        // Four segment masses and f: the pad and the frame are not inputs.
        assert_eq!(s.layers[0], 5);
        assert_eq!(s.train_values, [65.0, 75.0, 85.0]);
    }

    #[test]
    fn bad_settings_name_the_field() {
        let c = Case::K4Stht;
        let mut s = Settings::paper(c);
        s.momentum = 1.0;
        assert!(matches!(s.validate(c), Err(AnnError::BadMomentum(m)) if m == 1.0));
        let mut s = Settings::paper(c);
        s.layers = vec![5, 3, 1];
        let e = s.validate(c).unwrap_err().to_string();
        assert!(e.contains("k4-stht") && e.contains("2"), "{e}");
    }
}
