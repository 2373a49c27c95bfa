//! Every training setting described once: its name, help, how its text is
//! read and shown, its valid range, and which trainers use it. The command
//! line builds its `train` flags from this table, the TUI its settings rows,
//! and `Settings::validate` checks a whole set with it.
//!
//! ```
//! use biodyn::ann::{Settings, TrainerKind, Case, SETTINGS};
//! let mut s = Settings::lm(Case::K4Stht);
//! s.set("weight_decay", "1e-5").unwrap();
//! let rows: Vec<_> = SETTINGS.iter().filter(|x| x.applies_to(TrainerKind::Lm)).collect();
//! assert!(rows.iter().any(|x| x.key == "ensemble"));
//! assert!(!rows.iter().any(|x| x.key == "learning_rate"));
//! assert_eq!(s.get("weight_decay").unwrap(), "0.00001");
//! ```

use super::case::Case;
use super::error::{AnnError, excerpt};
use super::network::{Activation, check_layers};
use super::settings::{Combine, Settings, TrainerKind};
use crate::freq::band::Band;

/// How a setting's text reads: the command line types its flag by this,
/// a TUI may pick an editor by it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// A real number.
    Real,
    /// A real number, or empty / "none" for unset.
    OptionalReal,
    /// A whole number ≥ 0.
    Whole,
    /// true or false.
    Flag,
    /// Neuron counts, input layer first: 5-6-4-1.
    Layers,
    /// Comma-separated real numbers.
    Values,
    /// FROM:TO:STEP in Hz (the command line sets it with --from/--to/--step).
    Band,
    /// One of a closed list of words.
    Choice(&'static [&'static str]),
}

/// One training setting.
pub struct Setting {
    /// The name for `Settings::get`/`set` (the TOML field, where there is one).
    pub key: &'static str,
    /// The command line's long flag, without the dashes.
    pub flag: &'static str,
    /// The TUI row's label.
    pub label: &'static str,
    pub help: &'static str,
    /// The valid values in words, for help texts.
    pub range: &'static str,
    pub kind: Kind,
    /// The trainers that read it; the others ignore it.
    pub trainers: &'static [TrainerKind],
    get: fn(&Settings) -> String,
    set: fn(&mut Settings, &str, &'static str) -> Result<(), AnnError>,
    check: fn(&Settings, Case) -> Result<(), AnnError>,
}

impl std::fmt::Debug for Setting {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.key)
    }
}

impl Setting {
    pub fn applies_to(&self, trainer: TrainerKind) -> bool {
        self.trainers.contains(&trainer)
    }

    /// The value as text; `set` reads it back to the same value.
    pub fn get(&self, s: &Settings) -> String {
        (self.get)(s)
    }

    /// Reads `text` into `s`. Only the reading is checked here; the range
    /// (which may depend on the case) is `Settings::validate`'s.
    pub fn set(&self, s: &mut Settings, text: &str) -> Result<(), AnnError> {
        (self.set)(s, text.trim(), self.label)
    }

    /// Checks this setting's value in `s` for `case`.
    pub fn check(&self, s: &Settings, case: Case) -> Result<(), AnnError> {
        (self.check)(s, case)
    }

    /// The setting named `name`: its key, flag or label.
    pub fn find(name: &str) -> Option<&'static Setting> {
        let n = name.trim();
        SETTINGS
            .iter()
            .find(|s| s.key == n || s.flag == n || s.label == n)
    }
}

const BOTH: &[TrainerKind] = &[TrainerKind::Backprop, TrainerKind::Lm];
const BACKPROP: &[TrainerKind] = &[TrainerKind::Backprop];
const LM: &[TrainerKind] = &[TrainerKind::Lm];

fn bad(setting: &'static str, text: &str, want: &'static str) -> AnnError {
    AnnError::BadText {
        setting,
        text: excerpt(text),
        want,
    }
}

fn real(text: &str, label: &'static str) -> Result<f64, AnnError> {
    text.parse().map_err(|_| bad(label, text, "a number"))
}

fn optional(text: &str, label: &'static str) -> Result<Option<f64>, AnnError> {
    match text {
        "" | "none" | "-" => Ok(None),
        t => real(t, label).map(Some),
    }
}

fn whole(text: &str, label: &'static str) -> Result<u64, AnnError> {
    text.parse()
        .map_err(|_| bad(label, text, "a whole number ≥ 0"))
}

fn flag(text: &str, label: &'static str) -> Result<bool, AnnError> {
    match text.to_ascii_lowercase().as_str() {
        "true" | "yes" | "on" => Ok(true),
        "false" | "no" | "off" => Ok(false),
        _ => Err(bad(label, text, "true or false")),
    }
}

fn show_opt(v: Option<f64>) -> String {
    v.map_or_else(|| "none".into(), |x| format!("{x}"))
}

/// `5-6-4-1` (or commas); an empty part (`5--1`) is refused, not skipped.
pub fn parse_layers(text: &str) -> Result<Vec<usize>, AnnError> {
    text.split(['-', ','])
        .map(|p| p.trim().parse::<usize>())
        .collect::<Result<_, _>>()
        .map_err(|_| bad("layers", text, "neuron counts like 5-6-4-1"))
}

fn finite_pos(v: f64) -> bool {
    v.is_finite() && v > 0.0
}

fn non_neg(field: &'static str, v: f64) -> Result<(), AnnError> {
    if v.is_finite() && v >= 0.0 {
        Ok(())
    } else {
        Err(AnnError::BadSetting { field, value: v })
    }
}

fn non_neg_opt(field: &'static str, v: Option<f64>) -> Result<(), AnnError> {
    v.map_or(Ok(()), |v| non_neg(field, v))
}

fn ok(_: &Settings, _: Case) -> Result<(), AnnError> {
    Ok(())
}

/// A real-valued field ≥ 0, described in one line.
macro_rules! non_negative {
    ($key:literal, $flag:literal, $label:literal, $help:literal, $trainers:expr, $field:ident) => {
        Setting {
            key: $key,
            flag: $flag,
            label: $label,
            help: $help,
            range: "a finite number >= 0",
            kind: Kind::Real,
            trainers: $trainers,
            get: |s| format!("{}", s.$field),
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
            kind: Kind::OptionalReal,
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
            kind: Kind::Flag,
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
        help: "Architecture, input layer first, e.g. 5-6-4-1 (default: the paper's for the case)",
        range: "neuron counts 1..10000; first = the case's inputs, last = 1",
        kind: Kind::Layers,
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
            if s.layers[0] != case.inputs() {
                return Err(AnnError::WrongInputCount {
                    case: case.key(),
                    expected: case.inputs(),
                    found: s.layers[0],
                    names: case.input_names().join(", "),
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
        kind: Kind::Whole,
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
        kind: Kind::Real,
        trainers: BACKPROP,
        get: |s| format!("{}", s.learning_rate),
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
        kind: Kind::Real,
        trainers: BACKPROP,
        get: |s| format!("{}", s.momentum),
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
        kind: Kind::Real,
        trainers: BOTH,
        get: |s| format!("{}", s.gain),
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
        kind: Kind::Real,
        trainers: BOTH,
        get: |s| format!("{}", s.scaling_margin),
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
        range: "a whole number >= 1",
        kind: Kind::Whole,
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
        kind: Kind::Values,
        trainers: BOTH,
        get: |s| {
            let v: Vec<String> = s.train_values.iter().map(|v| format!("{v}")).collect();
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
        kind: Kind::Band,
        trainers: BOTH,
        get: |s| format!("{}:{}:{}", s.grid.from, s.grid.to, s.grid.step),
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
        kind: Kind::Flag,
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
        help: "Neuron function: logistic (the paper's) or tanh",
        range: "logistic or tanh",
        kind: Kind::Choice(&["logistic", "tanh"]),
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
        kind: Kind::Whole,
        trainers: BOTH,
        get: |s| s.seed.to_string(),
        set: |s, t, l| {
            s.seed = whole(t, l)?;
            Ok(())
        },
        check: ok,
    },
];

impl Settings {
    /// Checks every setting against the case; the first problem is returned.
    pub fn validate(&self, case: Case) -> Result<(), AnnError> {
        SETTINGS.iter().try_for_each(|s| s.check(self, case))
    }

    /// The setting named `name` (key, flag or label) as text.
    pub fn get(&self, name: &str) -> Result<String, AnnError> {
        Ok(lookup(name)?.get(self))
    }

    /// Reads `text` into the setting named `name`. The value is not
    /// range-checked: call `validate` on the whole set.
    pub fn set(&mut self, name: &str, text: &str) -> Result<(), AnnError> {
        lookup(name)?.set(self, text)
    }
}

fn lookup(name: &str) -> Result<&'static Setting, AnnError> {
    Setting::find(name).ok_or_else(|| AnnError::UnknownSetting(excerpt(name)))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every setting's text reads back to the same value, for both trainers' defaults.
    #[test]
    fn get_then_set_round_trips() {
        for case in Case::ALL {
            for kind in TrainerKind::ALL {
                let base = Settings::for_trainer(case, kind);
                for s in &SETTINGS {
                    let mut t = base.clone();
                    s.set(&mut t, &s.get(&base)).unwrap();
                    assert_eq!(t, base, "{}", s.key);
                }
            }
        }
    }

    #[test]
    fn names_are_unique_and_found_by_key_flag_and_label() {
        for (i, a) in SETTINGS.iter().enumerate() {
            for b in &SETTINGS[i + 1..] {
                assert!(a.key != b.key && a.flag != b.flag && a.label != b.label);
            }
            for n in [a.key, a.flag, a.label] {
                assert_eq!(Setting::find(n).map(|s| s.key), Some(a.key));
            }
        }
    }

    #[test]
    fn lm_lists_its_own_options_and_not_the_backprop_ones() {
        let lm: Vec<&str> = SETTINGS
            .iter()
            .filter(|s| s.applies_to(TrainerKind::Lm))
            .map(|s| s.key)
            .collect();
        for k in ["ensemble", "log_target", "weight_decay"] {
            assert!(lm.contains(&k), "{k}");
        }
        for k in ["learning_rate", "momentum", "input_noise"] {
            assert!(!lm.contains(&k), "{k}");
        }
        assert!(
            !SETTINGS
                .iter()
                .any(|s| s.key == "weight_decay" && s.applies_to(TrainerKind::Backprop))
        );
    }

    #[test]
    fn bad_text_names_the_setting_and_quotes_a_short_excerpt() {
        let mut s = Settings::paper(Case::K4Stht);
        let e = s.set("lr", "fast").unwrap_err().to_string();
        assert_eq!(e, "learning rate: 'fast' is not a number");
        let long = "x".repeat(10_000);
        let e = s.set("momentum", &long).unwrap_err().to_string();
        assert!(e.len() < 120, "{e}");
        assert!(
            s.set("layers", "5--1").is_err(),
            "an empty layer is refused"
        );
        assert!(s.set("no-such", "1").is_err());
        s.set("epochs", "7").unwrap();
        assert_eq!(s.epochs, 7);
        s.set("RMS target", "none").unwrap();
        assert_eq!(s.rms_target, None);
    }

    #[test]
    fn validate_reports_the_first_bad_setting_in_table_order() {
        let c = Case::K4Stht;
        let mut s = Settings::paper(c);
        s.momentum = 1.0;
        s.ensemble = 0;
        assert!(matches!(s.validate(c), Err(AnnError::BadMomentum(m)) if m == 1.0));
        s.momentum = 0.5;
        assert!(matches!(s.validate(c), Err(AnnError::ZeroEnsemble)));
    }
}
