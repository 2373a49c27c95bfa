//! The table of training settings: one row per setting, in the order
//! `Settings::validate` checks them (and a TUI lists them).

use super::setting::*;
use crate::ann::error::AnnError;
use crate::ann::network::{Activation, check_layers};
use crate::ann::settings::Combine;
use crate::band::Band;
use crate::io::excerpt::num;

/// A real-valued field ≥ 0, described in one line.
macro_rules! non_negative {
    ($key:literal, $flag:literal, $label:literal, $help:literal, $trainers:expr, $field:ident) => {
        Setting {
            key: $key,
            flag: $flag,
            label: $label,
            help: $help,
            range: "a finite number >= 0",
            kind: SettingKind::Real,
            trainers: $trainers,
            get: |s| num(s.$field),
            set: |s, t, l| {
                s.$field = real(t, l)?;
                Ok(())
            },
            check: |s, _| non_neg($key, s.$field),
        }
    };
}

/// An optional stop target or limit ≥ 0.
macro_rules! optional_limit {
    ($key:literal, $flag:literal, $label:literal, $help:literal, $field:ident) => {
        Setting {
            key: $key,
            flag: $flag,
            label: $label,
            help: $help,
            range: "a finite number >= 0, or none",
            kind: SettingKind::OptionalReal,
            trainers: BOTH,
            get: |s| show_opt(s.$field),
            set: |s, t, l| {
                s.$field = optional(t, l)?;
                Ok(())
            },
            check: |s, _| non_neg_opt($key, s.$field),
        }
    };
}

/// A true/false field.
macro_rules! switch {
    ($key:literal, $flag:literal, $label:literal, $help:literal, $field:ident) => {
        Setting {
            key: $key,
            flag: $flag,
            label: $label,
            help: $help,
            range: "true or false",
            kind: SettingKind::Flag,
            trainers: BOTH,
            get: |s| s.$field.to_string(),
            set: |s, t, l| {
                s.$field = flag(t, l)?;
                Ok(())
            },
            check: ok,
        }
    };
}

/// The table, in the order `validate` checks it (and a TUI lists it).
pub static SETTINGS: [Setting; 25] = [
    Setting {
        key: "layers",
        flag: "layers",
        label: "layers",
        help: "Architecture, input layer first, e.g. 5-6-4-1 (default: the paper's for the case); LM takes at most 2000 weights and thresholds, and a run at most 1 GiB for them",
        range: "1..10000 neurons a layer; first = inputs, last = 1",
        kind: SettingKind::Layers,
        trainers: BOTH,
        get: |s| {
            let v: Vec<String> = s.layers.iter().map(|l| l.to_string()).collect();
            v.join("-")
        },
        set: |s, t, _| {
            s.layers = parse_layers(t)?;
            Ok(())
        },
        check: |s, case| {
            check_layers(&s.layers)?;
            let base = s.base.as_ref();
            if s.layers[0] != case.input_count(base) {
                return Err(AnnError::WrongInputCount {
                    case: case.key(),
                    expected: case.input_count(base),
                    found: s.layers[0],
                    names: case.input_names_on(base).join(", "),
                });
            }
            let out = s.layers[s.layers.len() - 1];
            if out != 1 {
                return Err(AnnError::WrongOutputCount(out));
            }
            Ok(())
        },
    },
    Setting {
        key: "epochs",
        flag: "epochs",
        label: "epoch limit",
        help: "Epoch limit (LM: iterations per ensemble member); default: the paper's epoch count for backprop, 300 for LM",
        range: "a whole number >= 1",
        kind: SettingKind::Whole,
        trainers: BOTH,
        get: |s| s.epochs.to_string(),
        set: |s, t, l| {
            s.epochs = whole(t, l)?;
            Ok(())
        },
        check: |s, _| {
            if s.epochs == 0 {
                Err(AnnError::ZeroEpochs)
            } else {
                Ok(())
            }
        },
    },
    Setting {
        key: "learning_rate",
        flag: "lr",
        label: "learning rate",
        help: "Back-propagation learning rate (paper: 1)",
        range: "a finite number > 0",
        kind: SettingKind::Real,
        trainers: BACKPROP,
        get: |s| num(s.learning_rate),
        set: |s, t, l| {
            s.learning_rate = real(t, l)?;
            Ok(())
        },
        check: |s, _| {
            if finite_pos(s.learning_rate) {
                Ok(())
            } else {
                Err(AnnError::BadLearningRate(s.learning_rate))
            }
        },
    },
    Setting {
        key: "momentum",
        flag: "momentum",
        label: "momentum",
        help: "Back-propagation momentum (paper: 0.9)",
        range: "in [0, 1)",
        kind: SettingKind::Real,
        trainers: BACKPROP,
        get: |s| num(s.momentum),
        set: |s, t, l| {
            s.momentum = real(t, l)?;
            Ok(())
        },
        check: |s, _| {
            if s.momentum.is_finite() && (0.0..1.0).contains(&s.momentum) {
                Ok(())
            } else {
                Err(AnnError::BadMomentum(s.momentum))
            }
        },
    },
    Setting {
        key: "gain",
        flag: "gain",
        label: "function gain",
        help: "Gain g of the activation function (paper: 1)",
        range: "a finite number > 0",
        kind: SettingKind::Real,
        trainers: BOTH,
        get: |s| num(s.gain),
        set: |s, t, l| {
            s.gain = real(t, l)?;
            Ok(())
        },
        check: |s, _| {
            if finite_pos(s.gain) {
                Ok(())
            } else {
                Err(AnnError::BadGain(s.gain))
            }
        },
    },
    non_negative!(
        "init_range",
        "init-range",
        "initial weights",
        "Initial weights uniform in ±this",
        BOTH,
        init_range
    ),
    non_negative!(
        "input_noise",
        "input-noise",
        "input noise",
        "Back-propagation: uniform noise of this amplitude on each scaled input, each epoch",
        BACKPROP,
        input_noise
    ),
    non_negative!(
        "train_tolerance",
        "train-tolerance",
        "train tolerance",
        "An output is right when |Y - d| <= this on the scaled scale (paper: 0.001)",
        BOTH,
        train_tolerance
    ),
    non_negative!(
        "test_tolerance",
        "test-tolerance",
        "test tolerance",
        "The same, for the hold-out curves (paper: 0.003)",
        BOTH,
        test_tolerance
    ),
    non_negative!(
        "weight_decay",
        "weight-decay",
        "weight decay",
        "L2 weight decay λ (LM)",
        LM,
        weight_decay
    ),
    optional_limit!(
        "time_limit_s",
        "time-limit",
        "time limit s",
        "Wall-time limit per case in seconds",
        time_limit_s
    ),
    optional_limit!(
        "rms_target",
        "rms-target",
        "RMS target",
        "Stop at this RMS (scaled)",
        rms_target
    ),
    optional_limit!(
        "mpre_target_pct",
        "mpre-target",
        "MPRE target %",
        "Stop at this MPRE in %",
        mpre_target_pct
    ),
    Setting {
        key: "scaling_margin",
        flag: "scaling-margin",
        label: "scaling margin",
        help: "Scaling margin SM (paper: 0.1)",
        range: "a finite number >= 0",
        kind: SettingKind::Real,
        trainers: BOTH,
        get: |s| num(s.scaling_margin),
        set: |s, t, l| {
            s.scaling_margin = real(t, l)?;
            Ok(())
        },
        check: |s, _| {
            if s.scaling_margin.is_finite() && s.scaling_margin >= 0.0 {
                Ok(())
            } else {
                Err(AnnError::BadMargin(s.scaling_margin))
            }
        },
    },
    Setting {
        key: "ensemble",
        flag: "ensemble",
        label: "ensemble size",
        help: "Networks trained from derived seeds and combined",
        range: "a whole number from 1 to 1000",
        kind: SettingKind::Whole,
        trainers: BOTH,
        get: |s| s.ensemble.to_string(),
        set: |s, t, l| {
            let n = whole(t, l)?;
            s.ensemble = usize::try_from(n).map_err(|_| bad(l, t, "a smaller count"))?;
            Ok(())
        },
        check: |s, _| {
            if s.ensemble == 0 {
                Err(AnnError::ZeroEnsemble)
            } else {
                Ok(())
            }
        },
    },
    Setting {
        key: "train_values",
        flag: "train-values",
        label: "training values",
        help: "Training values: body masses in kg or k4 in N/m, comma-separated",
        range: "finite numbers > 0, at least one",
        kind: SettingKind::Values,
        trainers: BOTH,
        get: |s| {
            let v: Vec<String> = s.train_values.iter().map(|&v| num(v)).collect();
            v.join(",")
        },
        set: |s, t, l| {
            s.train_values = t
                .split(',')
                .map(|p| real(p.trim(), l))
                .collect::<Result<_, _>>()?;
            Ok(())
        },
        check: |s, case| {
            if s.train_values.is_empty() {
                return Err(AnnError::NoTrainValuesFor(case.param_name()));
            }
            if let Some(&v) = s.train_values.iter().find(|v| !finite_pos(**v)) {
                return Err(AnnError::BadTrainValue {
                    param: case.param_name(),
                    value: v,
                });
            }
            Ok(())
        },
    },
    Setting {
        key: "grid",
        flag: "grid",
        label: "training grid Hz",
        help: "Training frequency grid (paper: 0.5 to 20 Hz at 0.5 Hz)",
        range: "FROM:TO:STEP with 0 < FROM < TO, STEP > 0",
        kind: SettingKind::Band,
        trainers: BOTH,
        get: |s| {
            format!(
                "{}:{}:{}",
                num(s.grid.from),
                num(s.grid.to),
                num(s.grid.step)
            )
        },
        set: |s, t, l| {
            let parts: Vec<f64> = t
                .split(':')
                .map(|p| real(p.trim(), l))
                .collect::<Result<_, _>>()?;
            let [from, to, step] = parts[..] else {
                return Err(bad(l, t, "FROM:TO:STEP in Hz, e.g. 0.5:20:0.25"));
            };
            s.grid = Band { from, to, step };
            Ok(())
        },
        check: |s, _| Ok(s.grid.validate()?),
    },
    switch!(
        "log_target",
        "log-target",
        "log target",
        "Train on ln|response|: relative error becomes uniform over the band",
        log_target
    ),
    switch!(
        "log_freq",
        "log-freq",
        "log frequency",
        "Feed ln f instead of f",
        log_freq
    ),
    switch!(
        "log_param",
        "log-param",
        "log parameter",
        "Feed ln of m1..m4 or k4",
        log_param
    ),
    switch!(
        "linear_output",
        "linear-output",
        "linear output",
        "Linear output neuron instead of the activation function",
        linear_output
    ),
    Setting {
        key: "median",
        flag: "median",
        label: "median of members",
        help: "Combine ensemble members by their median instead of their mean",
        range: "true or false",
        kind: SettingKind::Flag,
        trainers: BOTH,
        get: |s| (s.combine == Combine::Median).to_string(),
        set: |s, t, l| {
            s.combine = if flag(t, l)? {
                Combine::Median
            } else {
                Combine::Mean
            };
            Ok(())
        },
        check: ok,
    },
    switch!(
        "stop_when_all_right",
        "stop-when-all-right",
        "stop when all right",
        "Stop as soon as every training output is right",
        stop_when_all_right
    ),
    Setting {
        key: "activation",
        flag: "activation",
        label: "activation",
        help: "Neuron function (the paper's: logistic)",
        range: "logistic or tanh",
        kind: SettingKind::Choice(&["logistic", "tanh"]),
        trainers: BOTH,
        get: |s| s.activation.key().into(),
        set: |s, t, l| {
            s.activation = match t.to_ascii_lowercase().as_str() {
                "logistic" => Activation::Logistic,
                "tanh" => Activation::Tanh,
                _ => return Err(bad(l, t, "logistic or tanh")),
            };
            Ok(())
        },
        check: ok,
    },
    Setting {
        key: "seed",
        flag: "seed",
        label: "seed",
        help: "Seed of the weight initialisation and the pattern order",
        range: "a whole number >= 0",
        kind: SettingKind::Whole,
        trainers: BOTH,
        get: |s| s.seed.to_string(),
        set: |s, t, l| {
            s.seed = whole(t, l)?;
            Ok(())
        },
        check: ok,
    },
];
