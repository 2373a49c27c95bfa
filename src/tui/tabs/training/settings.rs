//! The Training tab's rows: the case, trainer and held-out value pickers,
//! then every setting `biodyn::ann::SETTINGS` describes for the chosen
//! trainer (the same table the `train` command builds its flags from).

use biodyn::ann::{SettingKind, SETTINGS, Setting, Trainer};

/// A row of the list as shown.
#[derive(Debug, Clone, Copy)]
pub enum Row {
    /// ←→ picks the case.
    Case,
    /// ←→ picks the trainer.
    Trainer,
    /// A described setting: Enter edits its text; ←→ toggles a flag or
    /// steps through a choice.
    Setting(&'static Setting),
    /// ←→ picks the held-out value the prediction is drawn at.
    Holdout,
    /// ←→ picks the body the next run trains on and predictions use: the
    /// paper's or the one being edited.
    Model,
}

impl PartialEq for Row {
    fn eq(&self, other: &Row) -> bool {
        match (self, other) {
            (Row::Setting(a), Row::Setting(b)) => a.key == b.key,
            (a, b) => std::mem::discriminant(a) == std::mem::discriminant(b),
        }
    }
}

impl Row {
    pub fn name(self) -> &'static str {
        match self {
            Row::Case => "case",
            Row::Trainer => "trainer",
            Row::Setting(s) => s.label,
            Row::Holdout => "held-out value",
            Row::Model => "model",
        }
    }

    /// True when ←→ changes the row (a picker, a flag, a choice).
    pub fn arrows(self) -> bool {
        match self {
            Row::Setting(s) => matches!(s.kind, SettingKind::Flag | SettingKind::Choice(_)),
            _ => true,
        }
    }

    /// The setting's help text, for the run panel when it is selected.
    pub fn help(self) -> Option<&'static str> {
        match self {
            Row::Setting(s) => Some(s.help),
            _ => None,
        }
    }
}

/// The rows shown for `trainer`, in order.
pub fn rows(trainer: Trainer) -> Vec<Row> {
    let mut out = vec![Row::Case, Row::Trainer, Row::Holdout, Row::Model];
    out.extend(
        SETTINGS
            .iter()
            .filter(|s| s.applies_to(trainer))
            .map(Row::Setting),
    );
    out
}

/// The next (or previous) text of a flag or choice setting, from `now`.
pub fn step(kind: SettingKind, now: &str, left: bool) -> Option<String> {
    let words: &[&str] = match kind {
        SettingKind::Flag => &["false", "true"],
        SettingKind::Choice(words) => words,
        _ => return None,
    };
    let n = words.len();
    let i = words.iter().position(|w| *w == now).unwrap_or(0);
    let j = if left { (i + n - 1) % n } else { (i + 1) % n };
    words.get(j).map(|w| w.to_string())
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
        assert_eq!(lm.first(), Some(&"case"));
        assert_eq!(lm.get(2), Some(&"held-out value"));
    }

    #[test]
    fn flags_toggle_and_choices_cycle() {
        assert_eq!(step(SettingKind::Flag, "true", false).as_deref(), Some("false"));
        assert_eq!(step(SettingKind::Flag, "false", true).as_deref(), Some("true"));
        let k = SettingKind::Choice(&["a", "b", "c"]);
        assert_eq!(step(k, "c", false).as_deref(), Some("a"));
        assert_eq!(step(k, "a", true).as_deref(), Some("c"));
        assert_eq!(step(SettingKind::Real, "1", true), None);
    }
}
