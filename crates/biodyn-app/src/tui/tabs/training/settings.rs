//! The Training tab's settings rows: one table says, for every editable
//! setting, its name, how it is shown and parsed, and which trainers use
//! it. The list, the edit field and the commit all read this table; the
//! tab shows only the chosen trainer's rows.

use crate::view::format::exact;
use biodyn::ann::{Settings, Trainer};

/// One editable setting.
pub struct SettingRow {
    pub name: &'static str,
    /// The value as the list shows it (and the edit field is pre-filled with).
    pub show: fn(&Settings) -> String,
    /// Parses `text` into the settings; the reason on refusal. The whole
    /// set is validated against the case afterwards.
    pub parse: fn(&mut Settings, &str) -> Result<(), String>,
    pub trainers: &'static [Trainer],
}

const BOTH: &[Trainer] = &[Trainer::Backprop, Trainer::Lm];

fn float(what: &str, text: &str) -> Result<f64, String> {
    text.parse::<f64>()
        .ok()
        .filter(|v| v.is_finite())
        .ok_or_else(|| format!("{what}: '{text}' is not a number"))
}

fn whole(what: &str, text: &str) -> Result<u64, String> {
    text.parse::<u64>()
        .map_err(|_| format!("{what}: '{text}' is not a whole number ≥ 0"))
}

fn yes_no(what: &str, text: &str) -> Result<bool, String> {
    match text.to_ascii_lowercase().as_str() {
        "yes" | "y" | "true" | "on" | "1" => Ok(true),
        "no" | "n" | "false" | "off" | "0" => Ok(false),
        _ => Err(format!("{what}: '{text}' is not yes or no")),
    }
}

fn show_yes_no(b: bool) -> String {
    if b { "yes" } else { "no" }.into()
}

/// Every editable setting, in list order.
pub static SETTINGS: &[SettingRow] = &[
    SettingRow {
        name: "layers",
        show: |s| {
            s.layers
                .iter()
                .map(|l| l.to_string())
                .collect::<Vec<_>>()
                .join("-")
        },
        parse: |s, t| {
            s.layers = t
                .split(['-', ',', ' '])
                .filter(|p| !p.is_empty())
                .map(|p| {
                    p.parse::<usize>().map_err(|_| {
                        format!("layers: '{p}' is not a neuron count; write e.g. 5-6-4-1")
                    })
                })
                .collect::<Result<_, _>>()?;
            Ok(())
        },
        trainers: BOTH,
    },
    SettingRow {
        name: "learning rate",
        show: |s| exact(s.learning_rate),
        parse: |s, t| {
            s.learning_rate = float("learning rate", t)?;
            Ok(())
        },
        trainers: &[Trainer::Backprop],
    },
    SettingRow {
        name: "momentum",
        show: |s| exact(s.momentum),
        parse: |s, t| {
            s.momentum = float("momentum", t)?;
            Ok(())
        },
        trainers: &[Trainer::Backprop],
    },
    SettingRow {
        name: "train tolerance",
        show: |s| exact(s.train_tolerance),
        parse: |s, t| {
            s.train_tolerance = float("train tolerance", t)?;
            Ok(())
        },
        trainers: BOTH,
    },
    SettingRow {
        name: "test tolerance",
        show: |s| exact(s.test_tolerance),
        parse: |s, t| {
            s.test_tolerance = float("test tolerance", t)?;
            Ok(())
        },
        trainers: BOTH,
    },
    SettingRow {
        name: "scaling margin",
        show: |s| exact(s.scaling_margin),
        parse: |s, t| {
            s.scaling_margin = float("scaling margin", t)?;
            Ok(())
        },
        trainers: BOTH,
    },
    SettingRow {
        name: "epoch limit",
        show: |s| s.epochs.to_string(),
        parse: |s, t| {
            s.epochs = whole("epoch limit", t)?;
            Ok(())
        },
        trainers: BOTH,
    },
    SettingRow {
        name: "seed",
        show: |s| s.seed.to_string(),
        parse: |s, t| {
            s.seed = whole("seed", t)?;
            Ok(())
        },
        trainers: BOTH,
    },
    SettingRow {
        name: "ensemble size",
        show: |s| s.ensemble.to_string(),
        parse: |s, t| {
            let n = whole("ensemble size", t)?;
            s.ensemble = usize::try_from(n)
                .map_err(|_| format!("ensemble size: '{t}' is too large"))?;
            Ok(())
        },
        trainers: BOTH,
    },
    SettingRow {
        name: "log target",
        show: |s| show_yes_no(s.log_target),
        parse: |s, t| {
            s.log_target = yes_no("log target", t)?;
            Ok(())
        },
        trainers: BOTH,
    },
    SettingRow {
        name: "weight decay",
        show: |s| exact(s.weight_decay),
        parse: |s, t| {
            s.weight_decay = float("weight decay", t)?;
            Ok(())
        },
        trainers: &[Trainer::Lm],
    },
];

/// A row of the list as shown.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Row {
    /// ←→ picks the case.
    Case,
    /// ←→ picks the trainer.
    Trainer,
    /// An entry of `SETTINGS`, by index.
    Setting(usize),
    /// ←→ picks the held-out value the prediction is drawn at.
    Holdout,
}

impl Row {
    pub fn name(self) -> &'static str {
        match self {
            Row::Case => "case",
            Row::Trainer => "trainer",
            Row::Setting(i) => SETTINGS.get(i).map_or("?", |s| s.name),
            Row::Holdout => "held-out value",
        }
    }
}

/// The rows shown for `trainer`, in order.
pub fn rows(trainer: Trainer) -> Vec<Row> {
    let mut out = vec![Row::Case, Row::Trainer];
    out.extend(
        SETTINGS
            .iter()
            .enumerate()
            .filter(|(_, s)| s.trainers.contains(&trainer))
            .map(|(i, _)| Row::Setting(i)),
    );
    out.push(Row::Holdout);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_trainer_lists_only_its_own_settings() {
        let names = |t| -> Vec<&str> { rows(t).iter().map(|r| r.name()).collect() };
        let bp = names(Trainer::Backprop);
        let lm = names(Trainer::Lm);
        assert!(bp.contains(&"learning rate") && !bp.contains(&"weight decay"));
        assert!(lm.contains(&"weight decay") && !lm.contains(&"momentum"));
        assert!(lm.contains(&"ensemble size") && lm.contains(&"log target"));
    }

    #[test]
    fn every_setting_shows_what_it_parses() {
        let case = biodyn::ann::Case::MassStht;
        for t in Trainer::ALL {
            let s = Settings::for_trainer(case, t);
            for row in SETTINGS.iter().filter(|r| r.trainers.contains(&t)) {
                let mut back = s.clone();
                (row.parse)(&mut back, &(row.show)(&s)).expect(row.name);
                assert_eq!(back, s, "{}", row.name);
            }
        }
    }
}
