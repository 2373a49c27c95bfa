//! The Training tab's state: the case and settings for the next run,
//! the selected row, the held-out value, and the run (live or ended).

use super::history::History;
use super::predict::{Prediction, predict_net};
use super::run::Run;
use super::settings::{Row, rows};
use crate::tui::keys;
use crate::view::format::num;
use biodyn::Body;
use biodyn::ann::{Case, Settings, TrainedNet};


/// A network read back from a file (`o`), as `biodyn predict --net` reads it.
#[derive(Debug)]
pub struct Loaded {
    pub path: String,
    pub net: TrainedNet,
    pub prediction: Option<Prediction>,
}

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
    /// The "model" row: train and predict on the model being edited, not
    /// the paper's (`settings.base` then holds a copy of it, kept in step
    /// with its edits; a run keeps the copy it started with).
    pub this_model: bool,
    /// Why the case cannot train on the model being edited (e.g. k4 on 3
    /// links); then `settings.base` stays None and `t` refuses with it.
    pub base_err: Option<String>,
    /// The last runs, to compare.
    pub history: History,
    /// A network loaded from a file; shown instead of the run's until the next run.
    pub loaded: Option<Loaded>,
    pub show_loaded: bool,
    /// Why the prediction cannot be drawn (e.g. this model has 3 segments).
    pub prediction_err: Option<String>,
    /// The last network path typed (save or load), to pre-fill the next.
    pub last_net_path: Option<String>,
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
            this_model: false,
            base_err: None,
            history: History::default(),
            loaded: None,
            show_loaded: false,
            prediction_err: None,
            last_net_path: None,
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

    /// The net whose prediction is shown: the loaded one or the run's.
    fn shown_net(&self) -> Option<&TrainedNet> {
        match (&self.loaded, self.show_loaded) {
            (Some(l), true) => Some(&l.net),
            _ => self.run.as_ref()?.outcome.as_ref().map(|o| &o.net),
        }
    }

    /// The shown net when it is of the chosen case; a net of another
    /// case (the case row moved on after its run) is not drawn, so the
    /// held-out row, the chart and the table never mix two cases' values.
    pub fn net_for_case(&self) -> Option<&TrainedNet> {
        self.shown_net().filter(|n| n.case == self.case)
    }

    /// The case of a shown net that is not the chosen one.
    pub fn other_case(&self) -> Option<Case> {
        self.shown_net().map(|n| n.case).filter(|&c| c != self.case)
    }

    /// The held-out values the row steps through: the shown net's (on its
    /// own body), else those of the next run (the chosen case's).
    pub fn holdout_values(&self) -> Vec<f64> {
        match self.net_for_case() {
            Some(net) => net.case.holdout_values_on(net.base()),
            None => self.case.holdout_values_on(self.settings.base.as_ref()),
        }
    }

    /// The run's held-out results, when its net is the one shown.
    pub fn shown_holdouts(&self) -> Option<&[biodyn::ann::HoldoutResult]> {
        if self.show_loaded && self.loaded.is_some() {
            return None;
        }
        let out = self.run.as_ref()?.outcome.as_ref()?;
        (out.net.case == self.case).then_some(out.holdout.as_slice())
    }

    pub fn holdout_value(&self) -> f64 {
        let v = self.holdout_values();
        v.get(self.holdout).or(v.first()).copied().unwrap_or(75.0)
    }

    /// Puts the body the next run trains on into the settings: the model
    /// being edited (a copy) with the "model" row on "this model", else
    /// none (the paper's). The first layer follows the body's inputs, and
    /// training values still at the old body's defaults take the new
    /// body's; a body the case cannot use leaves the paper's, with why.
    pub fn sync_base(&mut self, body: &Body) {
        let old_defaults = self.case.train_values_on(self.settings.base.as_ref());
        self.base_err = None;
        // The networks learn the body: a seat under it is left out (the body on a rigid seat).
        let body = &body.without_seat();
        let base = match self.this_model {
            false => None,
            true => match self.case.check_base(Some(body)) {
                Ok(()) => Some(body.clone()),
                Err(e) => {
                    self.base_err = Some(e.to_string());
                    None
                }
            },
        };
        let inputs = self.case.input_count(base.as_ref());
        if let Some(first) = self.settings.layers.first_mut() {
            *first = inputs;
        }
        if self.settings.train_values == old_defaults {
            self.settings.train_values = self.case.train_values_on(base.as_ref());
        }
        self.settings.base = base;
    }

    /// What a run's settings train on, for the run panel.
    pub fn trained_on(settings: &Settings) -> String {
        match &settings.base {
            None => "on the paper's body".into(),
            Some(b) => format!(
                "on this model: {} seg, {} kg",
                b.n(),
                num(b.get(biodyn::Param::BodyMass), 4)
            ),
        }
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
            Row::Model if self.this_model => "this model".into(),
            Row::Model => "paper".into(),
        }
    }

    /// The status line for a selected row: its whole value (the list may
    /// have cut a long one) and its range or what ←/→ picks (in ASCII
    /// spelt out: `<` and `>` would read as keys).
    pub fn describe(&self, row: Row, ascii: bool) -> String {
        let what = match row {
            Row::Setting(s) => s.range,
            Row::Case => "←/→: the network the next run trains",
            Row::Trainer => "←/→: backprop (the paper's) or lm",
            Row::Holdout => "←/→: the value the prediction is drawn at",
            Row::Model => "←/→: the paper's body or the model of tab 1",
        };
        let what = keys::arrows(what, ascii);
        format!("{} = {}  ({what})", row.name(), self.value(row))
    }

    /// The case the prediction panel shows: the loaded net's or the run's.
    pub fn shown_case(&self) -> Case {
        match (&self.loaded, self.show_loaded, &self.run) {
            (Some(l), true, _) => l.net.case,
            (_, _, Some(r)) => r.case,
            _ => self.case,
        }
    }

    /// The shown prediction, if any (none for a net of another case).
    pub fn prediction(&self) -> Option<&Prediction> {
        self.net_for_case()?;
        match (&self.loaded, self.show_loaded) {
            (Some(l), true) => l.prediction.as_ref(),
            _ => self.run.as_ref().and_then(|r| r.prediction.as_ref()),
        }
    }

    /// Recomputes the predictions (run and loaded net) at the held-out
    /// value: on the net's own body, or (the "model" row) on `body` brought
    /// to that value (`Case::body_on`), so the chart is drawn where ◀ points.
    pub fn repredict(&mut self, body: &Body) {
        let on = self.this_model.then_some(body);
        self.prediction_err = None;
        let i = self.holdout;
        let at = |n: &TrainedNet| {
            let v = n.case.holdout_values_on(n.base());
            v.get(i).or(v.first()).copied().unwrap_or(75.0)
        };
        let mut err = None;
        if let Some(run) = self.run.as_mut()
            && let Some(out) = run.outcome.as_ref()
            && !out.stop.is_diverged()
        {
            let p = predict_net(&out.net, at(&out.net), on);
            run.prediction = p.as_ref().ok().cloned();
            err = p.err();
        }
        if let Some(l) = self.loaded.as_mut() {
            let p = predict_net(&l.net, at(&l.net), on);
            l.prediction = p.as_ref().ok().cloned();
            if self.show_loaded {
                err = p.err();
            }
        }
        self.prediction_err = err;
    }

}
