//! The Training tab's state: the case and settings for the next run,
//! the selected row, the held-out value, and the run (live or ended).

use super::run::Run;
use super::settings::{Row, rows};
use crate::view::format::num;
use biodyn::ann::{Case, Settings};

#[derive(Debug)]
pub struct TrainingTab {
    pub case: Case,
    pub settings: Settings,
    /// Index into `rows(settings.trainer)`.
    pub row: usize,
    /// Index into the case's held-out values.
    pub holdout: usize,
    /// On a narrow screen, the loss chart shows the recent window instead of the whole run.
    pub recent_only: bool,
    pub run: Option<Run>,
    /// The network path the user was warned exists: Enter again replaces it.
    pub overwrite_ok: Option<String>,
}

impl Default for TrainingTab {
    fn default() -> Self {
        let case = Case::MassStht;
        TrainingTab {
            case,
            settings: Settings::lm(case),
            row: 0,
            holdout: 1,
            recent_only: false,
            run: None,
            overwrite_ok: None,
        }
    }
}

impl TrainingTab {
    pub fn running(&self) -> bool {
        self.run.as_ref().is_some_and(Run::running)
    }

    pub fn paused(&self) -> bool {
        self.run.as_ref().is_some_and(Run::paused)
    }

    /// The rows shown now (the chosen trainer's settings).
    pub fn rows(&self) -> Vec<Row> {
        rows(self.settings.trainer)
    }

    /// The selected row.
    pub fn current(&self) -> Row {
        let r = self.rows();
        r.get(self.row).or(r.last()).copied().unwrap_or(Row::Case)
    }

    pub fn holdout_value(&self) -> f64 {
        let v = self.case.holdout_values();
        v.get(self.holdout).or(v.first()).copied().unwrap_or(75.0)
    }

    /// A row's value as the list shows it.
    pub fn value(&self, row: Row) -> String {
        match row {
            Row::Case => self.case.key().into(),
            Row::Trainer => self.settings.trainer.key().into(),
            Row::Setting(s) => s.get(&self.settings),
            Row::Holdout => format!(
                "{} {}",
                num(self.holdout_value(), 4),
                self.case.param_unit()
            ),
        }
    }

}
