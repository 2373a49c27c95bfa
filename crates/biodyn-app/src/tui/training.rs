//! Tab 4, Training: one of the six networks of SPEC §4, trained on the
//! `biodyn::ann` worker thread while the user keeps working. Progress
//! arrives on the main channel (at most ~30 messages a second); the result
//! (metrics, hold-out errors, prediction against the analytic curve) stays
//! on screen after the run and can be saved.

use super::app::App;
use super::event::Msg;
use super::field::{Field, Purpose};
use super::keys::Action;
use super::theme::Theme;
use crate::view::chart::{self, ChartOpts, Series};
use crate::view::format::{exact, magnitude_axis, num};
use biodyn::Band;
use biodyn::ann::{
    Case, Curve, Event, Finished, HoldoutResult, Outcome, Progress, Settings, Trainer, Worker,
    netfile,
};
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Paragraph, Widget, Wrap};
use std::collections::VecDeque;
use std::path::Path;

/// A report from the training worker.
pub type TrainMsg = Event;

/// Progress messages kept for the "recent" chart (about 3 s at 30 a second).
const RECENT: usize = 90;

/// Rows of the settings list, in order.
const ROWS: [&str; 11] = [
    "case",
    "trainer",
    "layers",
    "learning rate",
    "momentum",
    "train tolerance",
    "test tolerance",
    "scaling margin",
    "epoch limit",
    "seed",
    "held-out value",
];
const ROW_CASE: usize = 0;
const ROW_TRAINER: usize = 1;
const ROW_HOLDOUT: usize = 10;

/// One run: live while the worker trains, kept after it ends.
#[derive(Debug)]
pub struct Run {
    pub case: Case,
    pub settings: Settings,
    pub last: Option<Progress>,
    /// (epoch over the whole run, RMS) of the latest progress messages.
    pub recent: VecDeque<(f64, f64)>,
    pub finished: Option<Finished>,
    pub failed: Option<String>,
    pub outcome: Option<Outcome>,
    /// Prediction vs analytic at the chosen held-out value.
    pub prediction: Option<Prediction>,
}

#[derive(Debug, Clone)]
pub struct Prediction {
    pub value: f64,
    /// The analytic curve and the network's, ready to draw without copying.
    pub curves: [Series; 2],
    pub max_err_pct: f64,
    pub mean_err_pct: f64,
    pub extrapolation: bool,
}

#[derive(Debug)]
pub struct TrainingTab {
    pub case: Case,
    pub settings: Settings,
    pub row: usize,
    /// Index into the case's held-out values.
    pub holdout: usize,
    /// On a narrow screen, the loss chart shows the recent window instead of the whole run.
    pub recent_only: bool,
    pub worker: Option<Worker>,
    pub run: Option<Run>,
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
            worker: None,
            run: None,
        }
    }
}

impl TrainingTab {
    pub fn running(&self) -> bool {
        self.worker.is_some()
    }

    fn paused(&self) -> bool {
        self.worker.as_ref().is_some_and(Worker::is_paused)
    }

    /// One line for the status bar, so a run is visible from every tab.
    pub fn summary(&self) -> Option<String> {
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

    fn holdout_value(&self) -> f64 {
        let v = self.case.holdout_values();
        v.get(self.holdout).or(v.first()).copied().unwrap_or(75.0)
    }

    /// The settings row's value as the list shows it (and the field is pre-filled with).
    fn value(&self, row: usize) -> String {
        let s = &self.settings;
        match row {
            ROW_CASE => self.case.key().into(),
            ROW_TRAINER => s.trainer.key().into(),
            2 => s
                .layers
                .iter()
                .map(|l| l.to_string())
                .collect::<Vec<_>>()
                .join("-"),
            3 => exact(s.learning_rate),
            4 => exact(s.momentum),
            5 => exact(s.train_tolerance),
            6 => exact(s.test_tolerance),
            7 => exact(s.scaling_margin),
            8 => s.epochs.to_string(),
            9 => s.seed.to_string(),
            _ => format!(
                "{} {}",
                num(self.holdout_value(), 4),
                self.case.param_unit()
            ),
        }
    }
}

/// Takes the worker's reports.
pub fn on_msg(app: &mut App, ev: Event) {
    let t = &mut app.training;
    let v = t.holdout_value();
    let Some(run) = t.run.as_mut() else {
        return;
    };
    match ev {
        Event::Progress(p) => {
            let total = p
                .history
                .last()
                .map_or(p.epoch as f64, |h| h.total_epoch as f64);
            run.recent.push_back((total, p.rms));
            if run.recent.len() > RECENT {
                run.recent.pop_front();
            }
            run.last = Some(p);
        }
        Event::Finished(f) => {
            let stop = f.stop.to_string();
            run.finished = Some(f);
            // The worker sends Finished last: joining does not wait long.
            if let Some(w) = t.worker.take() {
                match w.join() {
                    Ok(out) => run.outcome = Some(out),
                    Err(e) => run.failed = Some(e.to_string()),
                }
            }
            predict(run, v);
            app.status.text = format!("training {} ended: {stop}", run.case);
            app.status.error = false;
        }
        Event::Failed(why) => {
            if let Some(w) = t.worker.take() {
                let _ = w.join();
            }
            app.status.text = format!("training failed: {why}");
            app.status.error = true;
            run.failed = Some(why);
        }
    }
}

/// Network against the analytic curve at `value`, from the finished net.
fn predict(run: &mut Run, value: f64) {
    run.prediction = None;
    let Some(out) = &run.outcome else {
        return;
    };
    if out.stop.is_diverged() {
        return;
    }
    let Ok(curve) = Curve::compute(run.case, value, &Band::default()) else {
        return;
    };
    let Ok(body) = run.case.body_at(value) else {
        return;
    };
    let Ok(pred) = out.net.predict_body(&body, &curve.freqs) else {
        return;
    };
    let errs: Vec<f64> = pred
        .iter()
        .zip(&curve.actual)
        .map(|(p, a)| 100.0 * (p - a).abs() / a.abs())
        .collect();
    let max = errs.iter().copied().fold(0.0, f64::max);
    let mean = errs.iter().sum::<f64>() / errs.len().max(1) as f64;
    let (lo, hi) = minmax(&out.net.settings.train_values);
    let pts = |ys: &[f64]| {
        curve
            .freqs
            .iter()
            .copied()
            .zip(ys.iter().copied())
            .collect()
    };
    run.prediction = Some(Prediction {
        value,
        curves: [
            Series {
                name: "analytic".into(),
                points: pts(&curve.actual),
            },
            Series {
                name: "network".into(),
                points: pts(&pred),
            },
        ],
        max_err_pct: max,
        mean_err_pct: mean,
        extrapolation: value < lo || value > hi,
    });
}

fn minmax(v: &[f64]) -> (f64, f64) {
    v.iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        })
}

/// Cancels a running training and waits for its thread (on quit).
pub fn stop(app: &mut App) {
    if let Some(w) = app.training.worker.take() {
        w.cancel();
        drop(w);
    }
}

fn start(app: &mut App) {
    let t = &mut app.training;
    if t.worker.is_some() {
        app.status.text = "a training is already running: s stops it".into();
        app.status.error = true;
        return;
    }
    let Some(tx) = app.tx.clone() else {
        app.status.text = "no event channel: cannot train here".into();
        app.status.error = true;
        return;
    };
    match Worker::start(t.case, t.settings.clone(), tx, Msg::Train) {
        Ok(w) => {
            t.worker = Some(w);
            t.run = Some(Run {
                case: t.case,
                settings: t.settings.clone(),
                last: None,
                recent: VecDeque::new(),
                finished: None,
                failed: None,
                outcome: None,
                prediction: None,
            });
            app.status.text = format!(
                "training {} with {}: space pauses, s stops",
                t.case, t.settings.trainer
            );
            app.status.error = false;
        }
        Err(e) => {
            app.status.text = format!("cannot start: {e}");
            app.status.error = true;
        }
    }
}

pub fn on_action(app: &mut App, a: Action) {
    let t = &mut app.training;
    match a {
        Action::Up => t.row = (t.row + ROWS.len() - 1) % ROWS.len(),
        Action::Down => t.row = (t.row + 1) % ROWS.len(),
        Action::Left | Action::Right => {
            let step = |i: usize, n: usize| {
                if a == Action::Left {
                    (i + n - 1) % n
                } else {
                    (i + 1) % n
                }
            };
            match t.row {
                ROW_CASE => {
                    let i = Case::ALL.iter().position(|&c| c == t.case).unwrap_or(0);
                    t.case = Case::ALL[step(i, Case::ALL.len())];
                    t.settings = Settings::for_trainer(t.case, t.settings.trainer);
                }
                ROW_TRAINER => {
                    let i = Trainer::ALL
                        .iter()
                        .position(|&x| x == t.settings.trainer)
                        .unwrap_or(0);
                    t.settings = Settings::for_trainer(t.case, Trainer::ALL[step(i, 2)]);
                }
                ROW_HOLDOUT => {
                    let n = t.case.holdout_values().len().max(1);
                    t.holdout = step(t.holdout, n);
                    let v = t.holdout_value();
                    if let Some(run) = t.run.as_mut()
                        && run.case == t.case
                    {
                        predict(run, v);
                    }
                }
                _ => {}
            }
        }
        Action::Edit => match t.row {
            ROW_CASE | ROW_TRAINER | ROW_HOLDOUT => {
                app.status.text = "←/→ picks this one".into();
                app.status.error = false;
            }
            row => {
                let label = ROWS[row].to_string();
                app.field = Some(Field::new(Purpose::TrainSetting(row), label, t.value(row)));
            }
        },
        Action::Start => start(app),
        Action::ToggleView => t.recent_only = !t.recent_only,
        Action::PauseResume => match &t.worker {
            Some(w) if w.is_paused() => {
                w.resume();
                app.status.text = "resumed".into();
                app.status.error = false;
            }
            Some(w) => {
                w.pause();
                app.status.text = "paused: space resumes".into();
                app.status.error = false;
            }
            None => {
                app.status.text = "no training running: t starts one".into();
                app.status.error = true;
            }
        },
        Action::Stop => match &t.worker {
            Some(w) => {
                w.cancel();
                app.status.text = "stopping…".into();
                app.status.error = false;
            }
            None => {
                app.status.text = "no training running".into();
                app.status.error = true;
            }
        },
        Action::SaveNet => {
            let done = t.run.as_ref().and_then(|r| r.outcome.as_ref());
            match done {
                Some(out) if !out.stop.is_diverged() => {
                    let name = format!("{}-{}.json", out.net.case, out.net.settings.trainer);
                    app.field = Some(Field::new(Purpose::SaveNet, "save network to", name));
                }
                Some(_) => {
                    app.status.text = "the run diverged: nothing worth saving".into();
                    app.status.error = true;
                }
                None => {
                    app.status.text = "no trained network yet: t trains one".into();
                    app.status.error = true;
                }
            }
        }
        _ => {}
    }
}

/// Parses a setting and checks the whole set against the case; refuses with why.
pub fn commit_setting(app: &mut App, row: usize, text: &str) -> Result<(), String> {
    let t = &mut app.training;
    let mut s = t.settings.clone();
    let text = text.trim();
    let float = |what: &str| -> Result<f64, String> {
        text.parse::<f64>()
            .map_err(|_| format!("{what}: '{text}' is not a number"))
    };
    let int = |what: &str| -> Result<u64, String> {
        text.parse::<u64>()
            .map_err(|_| format!("{what}: '{text}' is not a whole number ≥ 0"))
    };
    match row {
        2 => {
            s.layers = text
                .split(['-', ',', ' '])
                .filter(|p| !p.is_empty())
                .map(|p| {
                    p.parse::<usize>().map_err(|_| {
                        format!("layers: '{p}' is not a neuron count; write e.g. 5-6-4-1")
                    })
                })
                .collect::<Result<_, _>>()?;
        }
        3 => s.learning_rate = float("learning rate")?,
        4 => s.momentum = float("momentum")?,
        5 => s.train_tolerance = float("train tolerance")?,
        6 => s.test_tolerance = float("test tolerance")?,
        7 => s.scaling_margin = float("scaling margin")?,
        8 => s.epochs = int("epoch limit")?,
        9 => s.seed = int("seed")?,
        _ => return Ok(()),
    }
    s.validate(t.case).map_err(|e| e.to_string())?;
    t.settings = s;
    app.status.text = format!("{} = {}", ROWS[row], app.training.value(row));
    app.status.error = false;
    Ok(())
}

pub fn save_net(app: &mut App, path: &str) -> Result<(), String> {
    if path.is_empty() {
        return Err("give a file path, e.g. mass-stht.json".into());
    }
    let Some(out) = app.training.run.as_ref().and_then(|r| r.outcome.as_ref()) else {
        return Err("no trained network to save".into());
    };
    netfile::save(Path::new(path), &out.net).map_err(|e| e.to_string())?;
    app.status.text = format!("saved network to {path}");
    app.status.error = false;
    Ok(())
}

// ---- view -------------------------------------------------------------------

fn block(title: String, th: Theme) -> Block<'static> {
    Block::bordered()
        .border_set(th.border_set())
        .title(Span::styled(format!(" {title} "), th.heading()))
}

pub fn render(app: &App, area: Rect, buf: &mut Buffer) {
    let th = app.theme;
    let t = &app.training;
    let left_w = if area.width >= 120 { 44 } else { 34 };
    let [left, right] =
        Layout::horizontal([Constraint::Length(left_w), Constraint::Min(20)]).areas(area);
    let [settings, status] = Layout::vertical([
        Constraint::Length(ROWS.len() as u16 + 2),
        Constraint::Min(3),
    ])
    .areas(left);

    let lines: Vec<Line> = ROWS
        .iter()
        .enumerate()
        .map(|(i, name)| {
            let arrows = matches!(i, ROW_CASE | ROW_TRAINER | ROW_HOLDOUT);
            let v = if arrows {
                format!("◀ {} ▶", t.value(i))
            } else {
                t.value(i)
            };
            let style = if i == t.row { th.selected() } else { th.base() };
            Line::from(vec![
                Span::styled(format!("{name:<16}"), th.dim()),
                Span::styled(v, style),
            ])
        })
        .collect();
    let note = if t.running() { " (next run)" } else { "" };
    let inner = settings.height.saturating_sub(2) as usize;
    let scroll = (t.row + 1).saturating_sub(inner) as u16;
    Paragraph::new(lines)
        .scroll((scroll, 0))
        .block(block(format!("settings{note}"), th))
        .render(settings, buf);
    render_status(app, status, buf);

    let done = t.run.as_ref().is_some_and(|r| r.outcome.is_some());
    let holdout_rows = if done { 5 } else { 0 };
    // Once the run is over the prediction matters more than the loss curve.
    let [loss, pred, holdouts] = Layout::vertical([
        Constraint::Percentage(if done { 35 } else { 50 }),
        Constraint::Min(5),
        Constraint::Length(holdout_rows),
    ])
    .areas(right);
    render_loss(app, loss, buf);
    render_prediction(app, pred, buf);
    if holdout_rows > 0 {
        render_holdouts(app, holdouts, buf);
    }
}

fn secs(s: f64) -> String {
    if s < 60.0 {
        format!("{s:.1} s")
    } else if s < 3600.0 {
        format!("{}m{:02}s", (s / 60.0) as u64, (s % 60.0) as u64)
    } else {
        format!(
            "{}h{:02}m",
            (s / 3600.0) as u64,
            ((s % 3600.0) / 60.0) as u64
        )
    }
}

fn render_status(app: &App, area: Rect, buf: &mut Buffer) {
    let th = app.theme;
    let t = &app.training;
    let mut lines = Vec::new();
    let Some(run) = &t.run else {
        let paper = t.case.paper();
        lines.push(Line::raw(format!(
            "paper: {} epochs, MPRE {} %, RMS {}",
            paper.epochs, paper.mpre_pct, paper.rms
        )));
        lines.push(Line::styled("t starts training", th.key()));
        lines.push(Line::styled(
            "Data come from the paper's model (SPEC §4), not the edited one.",
            th.dim(),
        ));
        Paragraph::new(lines)
            .wrap(Wrap { trim: true })
            .block(block("run".into(), th))
            .render(area, buf);
        return;
    };
    let state = if t.paused() {
        "paused".to_string()
    } else if t.running() {
        "running".to_string()
    } else if let Some(e) = &run.failed {
        format!("failed: {e}")
    } else if let Some(f) = &run.finished {
        format!("ended: {}", f.stop)
    } else {
        "ended".into()
    };
    let state_style =
        if run.failed.is_some() || run.finished.as_ref().is_some_and(|f| f.stop.is_diverged()) {
            th.error()
        } else {
            th.heading()
        };
    lines.push(Line::styled(state, state_style));
    match (&run.finished, &run.last) {
        (Some(f), _) => {
            lines.push(Line::raw(format!(
                "epochs {}  {}",
                f.epochs,
                secs(f.train_seconds)
            )));
            lines.push(Line::raw(format!(
                "RMS {}  MPRE {}",
                f.rms.map_or("-".into(), |v| num(v, 3)),
                f.mpre_pct
                    .map_or("-".into(), |v| format!("{} %", num(v, 3)))
            )));
            lines.push(Line::raw(format!(
                "right {}",
                f.share_right
                    .map_or("-".into(), |v| format!("{} %", num(v * 100.0, 3)))
            )));
        }
        (None, Some(p)) => {
            let member = if p.members > 1 {
                format!(" (net {}/{})", p.member + 1, p.members)
            } else {
                String::new()
            };
            lines.push(Line::raw(format!(
                "epoch {}/{}{member}",
                p.epoch, p.max_epochs
            )));
            lines.push(Line::raw(format!(
                "RMS {}  MPRE {} %",
                num(p.rms, 3),
                num(p.mpre_pct, 3)
            )));
            lines.push(Line::raw(format!(
                "right {} %  {} ep/s",
                num(p.share_right * 100.0, 3),
                num(p.epochs_per_s, 3)
            )));
            let left = (p.max_epochs.saturating_sub(p.epoch)
                + (p.members.saturating_sub(p.member + 1)) as u64 * p.max_epochs)
                as f64;
            // ETA only after a second of warm-up, when the rate means something.
            let eta = if p.elapsed_s >= 1.0 && p.epochs_per_s > 0.0 {
                format!("ETA ≤ {}", secs(left / p.epochs_per_s))
            } else {
                "ETA …".into()
            };
            lines.push(Line::raw(format!("elapsed {}  {eta}", secs(p.elapsed_s))));
        }
        (None, None) => lines.push(Line::raw("preparing data…")),
    }
    Paragraph::new(lines)
        .wrap(Wrap { trim: true })
        .block(block(
            format!("run: {} {}", run.case, run.settings.trainer),
            th,
        ))
        .render(area, buf);
}

fn render_loss(app: &App, area: Rect, buf: &mut Buffer) {
    let th = app.theme;
    let run = app.training.run.as_ref();
    let history: Vec<(f64, f64)> = run
        .and_then(|r| r.last.as_ref())
        .map(|p| {
            p.history
                .iter()
                .map(|h| (h.total_epoch as f64, h.rms))
                .collect()
        })
        .unwrap_or_default();
    let recent: Vec<(f64, f64)> = run
        .map(|r| r.recent.iter().copied().collect())
        .unwrap_or_default();
    let opts = |title: &str| ChartOpts {
        title: title.into(),
        x_title: "epoch".into(),
        y_title: "RMS".into(),
        log_x: false,
        log_y: true,
        ascii: th.ascii,
        mono: th.mono,
        cursor_x: None,
        marks: Vec::new(),
        y_range: None,
    };
    if history.is_empty() {
        let msg = match run {
            Some(_) => "waiting for the first epochs…",
            None => "the RMS error against epoch appears here while training (t starts)",
        };
        Paragraph::new(msg)
            .wrap(Wrap { trim: true })
            .block(block("RMS (log) vs epoch".into(), th))
            .render(area, buf);
        return;
    }
    let all = [Series {
        name: "RMS".into(),
        points: history,
    }];
    if area.width >= 90 {
        let [a, b] = Layout::horizontal([Constraint::Ratio(1, 2); 2]).areas(area);
        chart::render(a, buf, &all, &opts("RMS (log) vs epoch, whole run"));
        let rec = [Series {
            name: "RMS".into(),
            points: recent,
        }];
        chart::render(b, buf, &rec, &opts("recent window"));
    } else if app.training.recent_only {
        let rec = [Series {
            name: "RMS".into(),
            points: recent,
        }];
        chart::render(
            area,
            buf,
            &rec,
            &opts("RMS (log), recent window (v: whole run)"),
        );
    } else {
        chart::render(area, buf, &all, &opts("RMS (log), whole run (v: recent)"));
    }
}

fn render_prediction(app: &App, area: Rect, buf: &mut Buffer) {
    let th = app.theme;
    let t = &app.training;
    match t
        .run
        .as_ref()
        .and_then(|r| r.prediction.as_ref().map(|p| (r, p)))
    {
        Some((run, p)) => {
            let f = run.case.function();
            let title = format!(
                "{} at {} {} ({}): max {} %, mean {} %",
                f.name(),
                num(p.value, 4),
                run.case.param_unit(),
                if p.extrapolation {
                    "extrap."
                } else {
                    "interp."
                },
                num(p.max_err_pct, 3),
                num(p.mean_err_pct, 3)
            );
            let opts = ChartOpts {
                title,
                x_title: "f Hz".into(),
                y_title: magnitude_axis(f),
                ascii: th.ascii,
                mono: th.mono,
                ..Default::default()
            };
            chart::render(area, buf, &p.curves, &opts);
        }
        None => {
            let msg = match t.run.as_ref() {
                Some(r) if r.outcome.as_ref().is_some_and(|o| o.stop.is_diverged()) => {
                    "the run diverged: no prediction to show"
                }
                Some(r) if r.outcome.is_none() && r.failed.is_none() => {
                    "the prediction against the analytic curve appears when training ends"
                }
                _ => "train a network (t) to compare its prediction with the analytic curve",
            };
            Paragraph::new(msg)
                .wrap(Wrap { trim: true })
                .block(block("prediction vs analytic".into(), th))
                .render(area, buf);
        }
    }
}

fn render_holdouts(app: &App, area: Rect, buf: &mut Buffer) {
    let th = app.theme;
    let Some(out) = app.training.run.as_ref().and_then(|r| r.outcome.as_ref()) else {
        return;
    };
    let row = |h: &HoldoutResult| {
        format!(
            "{:>7} {} {} max {:>5}% mean {:>5}%",
            num(h.value, 4),
            out.net.case.param_unit(),
            if h.extrapolation { "extrap" } else { "interp" },
            num(h.max_err_pct, 3),
            num(h.mean_err_pct, 3)
        )
    };
    // The chart above may be too short for its own legend: name the series here.
    let mut lines = vec![Line::from(vec![
        Span::styled(
            chart::legend_glyph(0, th.ascii),
            chart::series_style(0, th.mono),
        ),
        Span::raw(" analytic  "),
        Span::styled(
            chart::legend_glyph(1, th.ascii),
            chart::series_style(1, th.mono),
        ),
        Span::raw(" network   "),
        Span::styled("held-out errors", th.heading()),
    ])];
    lines.extend(out.holdout.iter().map(|h| Line::raw(row(h))));
    Paragraph::new(lines).render(area, buf);
}
