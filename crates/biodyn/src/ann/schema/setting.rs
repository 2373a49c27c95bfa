//! One training setting's description and the readers and checks the
//! table's rows are built from.

use crate::ann::case::Case;
use crate::ann::error::AnnError;
use crate::ann::settings::{Settings, Trainer};
use crate::io::excerpt::short_quote;

/// How a setting's text reads: the command line types its flag by this,
/// a TUI may pick an editor by it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SettingKind {
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
    pub kind: SettingKind,
    /// The trainers that read it; the others ignore it.
    pub trainers: &'static [Trainer],
    pub(super) get: fn(&Settings) -> String,
    pub(super) set: fn(&mut Settings, &str, &'static str) -> Result<(), AnnError>,
    pub(super) check: fn(&Settings, Case) -> Result<(), AnnError>,
}

impl std::fmt::Debug for Setting {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.key)
    }
}

impl Setting {
    pub fn applies_to(&self, trainer: Trainer) -> bool {
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
}

pub(super) const BOTH: &[Trainer] = &[Trainer::Backprop, Trainer::Lm];
pub(super) const BACKPROP: &[Trainer] = &[Trainer::Backprop];
pub(super) const LM: &[Trainer] = &[Trainer::Lm];

pub(super) fn bad(setting: &'static str, text: &str, want: &'static str) -> AnnError {
    AnnError::BadText {
        setting,
        text: short_quote(text),
        want,
    }
}

pub(super) fn real(text: &str, label: &'static str) -> Result<f64, AnnError> {
    text.parse().map_err(|_| bad(label, text, "a number"))
}

pub(super) fn optional(text: &str, label: &'static str) -> Result<Option<f64>, AnnError> {
    match text {
        "" | "none" | "-" => Ok(None),
        t => real(t, label).map(Some),
    }
}

pub(super) fn whole(text: &str, label: &'static str) -> Result<u64, AnnError> {
    text.parse().map_err(|_| {
        // 1e30 or 2.5 is a number, just not a whole one that fits: say which.
        let why = match text.trim().parse::<f64>() {
            Ok(v) if v.is_finite() && v.fract() == 0.0 && v >= 0.0 => {
                "a whole number written in digits, at most 18446744073709551615"
            }
            Ok(v) if v.is_finite() && v >= 0.0 => "a whole number (no fraction)",
            _ => "a whole number ≥ 0",
        };
        bad(label, text, why)
    })
}

pub(super) fn flag(text: &str, label: &'static str) -> Result<bool, AnnError> {
    match text.to_ascii_lowercase().as_str() {
        "true" | "yes" | "on" => Ok(true),
        "false" | "no" | "off" => Ok(false),
        _ => Err(bad(label, text, "true or false")),
    }
}

pub(super) fn show_opt(v: Option<f64>) -> String {
    v.map_or_else(|| "none".into(), crate::io::excerpt::num)
}

/// `5-6-4-1` (or commas); an empty part (`5--1`) is refused, not skipped.
pub fn parse_layers(text: &str) -> Result<Vec<usize>, AnnError> {
    text.split(['-', ','])
        .map(|p| p.trim().parse::<usize>())
        .collect::<Result<_, _>>()
        .map_err(|_| bad("layers", text, "neuron counts like 5-6-4-1"))
}

pub(super) fn finite_pos(v: f64) -> bool {
    v.is_finite() && v > 0.0
}

pub(super) fn non_neg(field: &'static str, v: f64) -> Result<(), AnnError> {
    if v.is_finite() && v >= 0.0 {
        Ok(())
    } else {
        Err(AnnError::BadSetting { field, value: v })
    }
}

pub(super) fn non_neg_opt(field: &'static str, v: Option<f64>) -> Result<(), AnnError> {
    v.map_or(Ok(()), |v| non_neg(field, v))
}

pub(super) fn ok(_: &Settings, _: Case) -> Result<(), AnnError> {
    Ok(())
}
