//! Tab Training: one of the six networks of SPEC §4, trained on the
//! `biodyn::ann` worker thread while the user keeps working. Progress
//! arrives through the tab's mailbox (at most ~30 messages a second); the
//! result (metrics, hold-out errors, prediction against the analytic
//! curve) stays on screen after the run and can be saved.
//!
//! `settings.rs` is the rows (built from `biodyn::ann::SETTINGS`, the one
//! description of every training setting), `run.rs` the worker's
//! lifecycle, `predict.rs` the prediction (`TrainedNet::compare`),
//! `netio.rs` saving and loading networks, `view.rs` the drawing (with
//! `run_view.rs` the run panel, `holdouts_view.rs` the held-out errors,
//! `runs_view.rs` the last runs, `cell.rs` a value fitted to its column).

mod cell;
mod history;
mod holdouts_view;
mod mouse;
mod netio;
mod predict;
pub mod run;
pub mod settings;
mod state;
mod run_view;
mod runs_view;
mod view;

pub use history::{RUNS_KEPT, RunRecord};
pub use state::TrainingTab;

use crate::tui::component::{Change, Cx, Mouse, Tab};
use crate::tui::effect::Effect;
use crate::tui::popups::field::{Field, Purpose};
use crate::tui::keys::{self, Binding, Doc, b, code, k};
use crate::tui::shared::Shared;
use crate::view::format::num;
use biodyn::ann::{Case, Event, SETTINGS, Setting, Settings, Trainer, SettingKind};
use ratatui::buffer::Buffer;
use ratatui::crossterm::event::{KeyCode as KC, KeyEvent};
use ratatui::layout::Rect;
use run::{Ended, Run};
use settings::Row;
use std::any::Any;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Action {
    Up,
    Down,
    Left,
    Right,
    Edit,
    Start,
    PauseResume,
    Stop,
    ToggleView,
    SaveNet,
    LoadNet,
}

const PAUSE: Binding<Action> = b(
    &[k(' ')],
    Action::PauseResume,
    "pause / resume (while a training runs)",
    Some("space pause"),
);
const STOP: Binding<Action> = b(&[k('s')], Action::Stop, "stop (while a training runs)", Some("s stop"));
/// Pause and stop without their hints: the bar offers them only while a
/// run is going (the `?` page lists them always).
static IDLE_PAUSE: Doc = Doc {
    hint: None,
    ..PAUSE.doc
};
static IDLE_STOP: Doc = Doc {
    hint: None,
    ..STOP.doc
};

static KEYS: &[Binding<Action>] = &[
    b(
        &[code(KC::Up), k('k')],
        Action::Up,
        "previous setting",
        Some("↑↓ setting"),
    ),
    b(
        &[code(KC::Down), k('j')],
        Action::Down,
        "next setting",
        None,
    ),
    b(
        &[code(KC::Left), k('h')],
        Action::Left,
        "previous choice (case, trainer, held-out value, a true/false or listed setting)",
        Some("←→ choice"),
    ),
    b(
        &[code(KC::Right), k('l')],
        Action::Right,
        "next choice",
        None,
    ),
    b(
        &[code(KC::Enter), k('e')],
        Action::Edit,
        "edit the selected setting",
        Some("Enter edit"),
    ),
    b(&[k('t')], Action::Start, "start training", Some("t start")),
    PAUSE,
    STOP,
    b(
        &[k('v')],
        Action::ToggleView,
        "loss chart: whole run / recent window (narrow screens)",
        None,
    ),
    b(
        &[k('w')],
        Action::SaveNet,
        "save the trained network (asks for the path)",
        Some("w save net"),
    ),
    b(
        &[k('o')],
        Action::LoadNet,
        "load a saved network (biodyn predict --net's file) and show its prediction",
        Some("o load net"),
    ),
];

/// The field tag of "save network to"; settings fields use their index.
const SAVE_NET: usize = usize::MAX;
/// The field tag of "load network from".
const LOAD_NET: usize = usize::MAX - 1;

fn err(text: impl Into<String>) -> Vec<Effect> {
    vec![Effect::Error(text.into())]
}

fn say(text: impl Into<String>) -> Vec<Effect> {
    vec![Effect::Status(text.into())]
}

impl TrainingTab {
    /// ←→ on a row: the next case, trainer, held-out value, flag or choice.
    fn choose(&mut self, row: Row, left: bool, body: &biodyn::Body, ascii: bool) -> Vec<Effect> {
        let step = |i: usize, n: usize| {
            if left {
                (i + n - 1) % n.max(1)
            } else {
                (i + 1) % n.max(1)
            }
        };
        match row {
            Row::Case => {
                let i = Case::ALL.iter().position(|&c| c == self.case).unwrap_or(0);
                if let Some(&c) = Case::ALL.get(step(i, Case::ALL.len())) {
                    self.case = c;
                }
                self.settings = Settings::for_trainer(self.case, self.settings.trainer);
                self.sync_base(body);
                // Back on the shown net's case, its chart follows the
                // held-out row as it is now.
                self.repredict(body);
                if let (true, Some(e)) = (self.this_model, &self.base_err) {
                    return err(format!("{}: {e}", self.case));
                }
                return say(self.describe(row, ascii));
            }
            Row::Trainer => {
                let all = Trainer::ALL;
                let i = all
                    .iter()
                    .position(|&x| x == self.settings.trainer)
                    .unwrap_or(0);
                if let Some(&t) = all.get(step(i, all.len())) {
                    self.settings = Settings::for_trainer(self.case, t);
                    self.sync_base(body);
                }
                // The trainer row stays selected; the list below it changes.
                return say(self.describe(row, ascii));
            }
            Row::Holdout => {
                let n = self.holdout_values().len();
                self.holdout = step(self.holdout, n);
                self.repredict(body);
                return say(self.describe(row, ascii));
            }
            Row::Model => {
                self.this_model = !self.this_model;
                self.sync_base(body);
                self.repredict(body);
                return match (&self.base_err, &self.prediction_err, self.this_model) {
                    (Some(e), _, true) => err(format!("{}: {e}", self.case)),
                    (None, Some(e), true) => err(format!("t trains on this model; no prediction on it: {e}")),
                    (None, None, true) => {
                        say("t trains on (and predictions use) the model being edited (tab 1)")
                    }
                    _ => say("t trains on (and predictions use) the paper's body"),
                };
            }
            Row::Setting(s) => {
                if let Some(text) = settings::step(s.kind, &s.get(&self.settings), left) {
                    return match self.commit_setting(s, &text) {
                        Ok(e) => e,
                        Err(why) => err(why),
                    };
                }
            }
        }
        Vec::new()
    }

    fn start(&mut self, cx: &Cx) -> Vec<Effect> {
        if self.running() {
            return err("a training is already running: s stops it");
        }
        // The run takes a copy of the model as it is now: later edits
        // change the next run, not this one.
        self.sync_base(&cx.shared.body);
        if let (true, Some(e)) = (self.this_model, &self.base_err) {
            return err(format!("cannot train {} on this model: {e}", self.case));
        }
        match Run::start(self.case, &self.settings, &cx.mailbox) {
            Ok(run) => {
                self.run = Some(run);
                self.show_loaded = false;
                say(if self.this_model {
                    format!(
                        "training {} on a snapshot of this model: edits now change only the next run",
                        self.case
                    )
                } else {
                    format!(
                        "training {} with {}: space pauses, s stops (here on tab Training)",
                        self.case, self.settings.trainer
                    )
                })
            }
            Err(e) => err(format!("cannot start: {e}")),
        }
    }

    fn act(&mut self, a: Action, cx: &Cx) -> Vec<Effect> {
        let n = self.rows().len();
        match a {
            Action::Up | Action::Down => {
                self.row = if a == Action::Up {
                    (self.row + n - 1) % n
                } else {
                    (self.row + 1) % n
                };
                // Its whole value and range (the list may have cut a long
                // one); the help text goes in the run panel.
                return say(self.describe(self.current(), cx.shared.theme.ascii));
            }
            Action::Left | Action::Right => {
                let ascii = cx.shared.theme.ascii;
                return self.choose(self.current(), a == Action::Left, &cx.shared.body, ascii);
            }
            Action::Edit => {
                let tag = |s: &Setting| SETTINGS.iter().position(|x| x.key == s.key);
                return match self.current() {
                    Row::Setting(s) => match tag(s) {
                        Some(i) => vec![Effect::OpenField(Field::new(
                            Purpose::Tab(i),
                            s.label,
                            s.get(&self.settings),
                        ))],
                        None => Vec::new(),
                    },
                    _ => say(keys::arrows("←/→ picks this one", cx.shared.theme.ascii)),
                };
            }
            Action::Start => return self.start(cx),
            Action::ToggleView => self.recent_only = !self.recent_only,
            Action::PauseResume => {
                return match self.run.as_mut().and_then(Run::toggle_pause) {
                    Some(true) => say("paused: space resumes"),
                    Some(false) => say("resumed"),
                    None => err("no training running: t starts one"),
                };
            }
            Action::Stop => {
                return match self.run.as_ref().is_some_and(Run::cancel) {
                    true => say("stopping…"),
                    false => err("no training running"),
                };
            }
            Action::LoadNet => {
                let name = self
                    .last_net_path
                    .clone()
                    .unwrap_or_else(|| format!("{}-{}.json", self.case, self.settings.trainer));
                return vec![Effect::OpenField(
                    Field::new(Purpose::Tab(LOAD_NET), "load network from", name).for_path(),
                )];
            }
            Action::SaveNet => {
                return match self.run.as_ref().and_then(|r| r.outcome.as_ref()) {
                    Some(out) if !out.stop.is_diverged() => {
                        let name = self.last_net_path.clone().unwrap_or_else(|| {
                            format!("{}-{}.json", out.net.case, out.net.settings.trainer)
                        });
                        self.overwrite_ok = None;
                        vec![Effect::OpenField(Field::new(
                            Purpose::Tab(SAVE_NET),
                            "save network to",
                            name,
                        )
                        .for_path())]
                    }
                    Some(_) => err("the run diverged: nothing worth saving"),
                    None => err("no trained network yet: t trains one"),
                };
            }
        }
        Vec::new()
    }

    /// Reads a setting and checks the whole set against the case.
    fn commit_setting(&mut self, row: &Setting, text: &str) -> Result<Vec<Effect>, String> {
        let mut s = self.settings.clone();
        let text = text.trim();
        // A whole-number row refuses -5 and 0 in the same words: its range.
        let whole = |e: String| match row.kind {
            SettingKind::Whole => format!("{} = {text:?}: give {}", row.label, row.range),
            _ => e,
        };
        row.set(&mut s, text).map_err(|e| whole(e.to_string()))?;
        let was_valid = self.settings.validate(self.case).is_ok();
        // The row's own range in its words; a size past what fits
        // (`ann::bounds`, across rows) with the library's reason.
        let own = row.check(&s, self.case).is_err();
        s.validate(self.case).map_err(|e| {
            if was_valid && own {
                whole(e.to_string())
            } else {
                e.to_string()
            }
        })?;
        self.settings = s;
        Ok(say(format!("{} = {}", row.label, row.get(&self.settings))))
    }

}

impl Tab for TrainingTab {
    fn new(_shared: &Shared) -> Self {
        TrainingTab::default()
    }

    fn title(&self) -> &'static str {
        "Training"
    }

    fn keys(&self) -> Vec<&'static Doc> {
        let live = self.running();
        KEYS.iter()
            .map(|b| match b.action {
                Action::PauseResume if !live => &IDLE_PAUSE,
                Action::Stop if !live => &IDLE_STOP,
                _ => &b.doc,
            })
            .collect()
    }

    fn on_key(&mut self, ev: &KeyEvent, cx: &Cx) -> Option<Vec<Effect>> {
        keys::lookup(KEYS, ev).map(|a| self.act(a, cx))
    }

    fn commit(&mut self, tag: usize, text: &str, cx: &Cx) -> Result<Vec<Effect>, String> {
        match tag {
            SAVE_NET => self.save_net(text.trim(), cx.shared),
            LOAD_NET => self.load_net(text.trim(), &cx.shared.body),
            i => match SETTINGS.get(i) {
                Some(row) => self.commit_setting(row, text),
                None => Ok(Vec::new()),
            },
        }
    }

    fn on_msg(&mut self, msg: Box<dyn Any + Send>, cx: &Cx) -> Vec<Effect> {
        let v = self.holdout_value();
        let (Ok(ev), Some(run)) = (msg.downcast::<Event>(), self.run.as_mut()) else {
            return Vec::new();
        };
        match run.on_event(*ev, v) {
            Ended::Not => Vec::new(),
            Ended::Finished(s) => {
                if let (Some(out), Some(f)) = (&run.outcome, &run.finished) {
                    let record = RunRecord::of(out, run.working_s(f.train_seconds));
                    self.history.push(record);
                }
                self.repredict(&cx.shared.body);
                say(s)
            }
            Ended::Failed(s) => err(s),
        }
    }

    fn on_change(&mut self, change: Change, cx: &Cx) {
        // The next run and the predictions on this model follow its edits.
        if self.this_model && change != Change::Derived {
            self.sync_base(&cx.shared.body);
            self.repredict(&cx.shared.body);
        }
    }

    fn on_mouse(&mut self, m: Mouse, area: Rect, cx: &Cx) -> Vec<Effect> {
        self.mouse(m, area, cx)
    }

    fn render(&self, s: &Shared, area: Rect, buf: &mut Buffer) {
        view::render(self, s, area, buf);
    }

    fn inputs(&self) -> Vec<std::path::PathBuf> {
        let loaded = self.loaded.as_ref().map(|l| crate::tui::paths::expand(&l.path));
        loaded.into_iter().collect()
    }

    fn has_chart(&self, _s: &Shared) -> bool {
        self.run.is_some() || self.prediction().is_some()
    }

    fn render_zoomed(&self, s: &Shared, area: Rect, buf: &mut Buffer) {
        view::render_zoomed(self, s, area, buf);
    }

    /// One line for the status bar, so a run is visible from every tab.
    fn summary(&self) -> Option<String> {
        let run = self.run.as_ref()?;
        let state = if self.paused() {
            "paused"
        } else if self.running() {
            "training"
        } else {
            return None;
        };
        let p = run.last.as_ref();
        Some(format!(
            "{state} {}: epoch {} RMS {}",
            run.case,
            p.map_or(0, |p| p.epoch),
            p.map_or("-".into(), |p| num(p.rms, 3))
        ))
    }

    fn busy(&self) -> Option<&'static str> {
        self.running().then_some("a training is running")
    }

    fn shutdown(&mut self) {
        if let Some(run) = self.run.as_mut() {
            run.shutdown();
        }
    }
}
