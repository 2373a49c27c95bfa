//! Drawing the Training tab: the settings list, the run panel, the loss
//! chart (whole run and recent window), the prediction and the held-out
//! errors. Reads the tab's state; changes nothing.

use super::state::TrainingTab;
use crate::tui::shared::Shared;
use crate::tui::widgets::block;
use crate::view::chart::{self, ChartOpts, Series};
use crate::view::format::{axis_title, clip, num};
use biodyn::ann::HoldoutResult;
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget, Wrap};

/// Where the tab draws its settings list (framed), the run panel and the
/// right column; shared by drawing and clicks.
pub struct Areas {
    pub settings: Rect,
    pub status: Rect,
    pub right: Rect,
    /// Rows of the list scrolled off the top.
    pub scroll: usize,
}

pub fn areas(t: &TrainingTab, area: Rect) -> Areas {
    let rows = t.rows().len();
    let left_w = if area.width >= 120 { 44 } else { 34 };
    let [left, right] =
        Layout::horizontal([Constraint::Length(left_w), Constraint::Min(20)]).areas(area);
    let list_h = u16::try_from(rows).unwrap_or(u16::MAX).saturating_add(2);
    // The run panel keeps its seven rows; the list scrolls in the rest.
    let [settings, status] =
        Layout::vertical([Constraint::Max(list_h), Constraint::Min(7)]).areas(left);
    let inner = settings.height.saturating_sub(2) as usize;
    Areas {
        settings,
        status,
        right,
        scroll: (t.row + 1).saturating_sub(inner),
    }
}

pub fn render(t: &TrainingTab, s: &Shared, area: Rect, buf: &mut Buffer) {
    let th = s.theme;
    let rows = t.rows();
    let Areas {
        settings,
        status,
        right,
        scroll,
    } = areas(t, area);
    let left_w = settings.width;

    // Names as wide as the longest, up to half the panel; values after a space.
    let inner_w = usize::from(left_w.saturating_sub(2));
    let name_w = rows
        .iter()
        .map(|r| r.name().chars().count())
        .max()
        .unwrap_or(0)
        .min(inner_w / 2);
    let lines: Vec<Line> = rows
        .iter()
        .enumerate()
        .map(|(i, &row)| {
            let arrows = row.arrows();
            let v = if arrows {
                format!("◀ {} ▶", t.value(row))
            } else {
                t.value(row)
            };
            let style = if i == t.row { th.selected() } else { th.base() };
            Line::from(vec![
                Span::styled(
                    format!("{:<name_w$} ", clip(row.name(), name_w)),
                    th.dim(),
                ),
                Span::styled(v, style),
            ])
        })
        .collect();
    let note = if t.running() { " (next run)" } else { "" };
    Paragraph::new(lines)
        .scroll((u16::try_from(scroll).unwrap_or(u16::MAX), 0))
        .block(block(&format!("settings{note}"), th))
        .render(settings, buf);
    render_status(t, s, status, buf);

    let done = t.run.as_ref().is_some_and(|r| r.outcome.is_some());
    let n_holdouts = t
        .run
        .as_ref()
        .and_then(|r| r.outcome.as_ref())
        .map_or(0, |o| o.holdout.len());
    let holdout_rows = if done {
        u16::try_from(n_holdouts + 3).unwrap_or(6)
    } else {
        0
    };
    // Once the run is over the prediction matters more than the loss curve;
    // when both charts cannot keep their frames (10 rows each), the loss
    // curve steps aside (z shows both).
    let loss_pct = match done {
        false => 50,
        true if right.height < 20 + holdout_rows => 0,
        true => 35,
    };
    // The runs table: newest at the bottom, up to a third of the column,
    // and never taking the 10 rows the prediction needs for its frame (at
    // 80×24 it shows the newest two; a taller terminal shows all eight).
    let spare = right.height.saturating_sub(holdout_rows + 10);
    let runs_rows = match u16::try_from(t.history.runs.len() + 3) {
        Ok(want) if want > 3 => want.min(right.height / 3).min(spare),
        _ => 0,
    };
    let runs_rows = if runs_rows >= 4 { runs_rows } else { 0 };
    let [right, runs] =
        Layout::vertical([Constraint::Min(0), Constraint::Length(runs_rows)]).areas(right);
    if runs_rows > 0 {
        super::runs_view::render(t, s, runs, buf);
    }
    let [loss, pred, holdouts] = Layout::vertical([
        Constraint::Percentage(loss_pct),
        Constraint::Min(5),
        Constraint::Length(holdout_rows),
    ])
    .areas(right);
    if loss.height > 0 {
        render_loss(t, s, loss, buf);
    }
    render_prediction(t, s, pred, buf);
    if holdout_rows > 0 {
        render_holdouts(t, s, holdouts, buf, loss.height == 0);
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

fn render_status(t: &TrainingTab, s: &Shared, area: Rect, buf: &mut Buffer) {
    let th = s.theme;
    let mut lines = Vec::new();
    let Some(run) = &t.run else {
        match (&t.settings.base, &t.base_err) {
            // The reason first: it is what the user has to act on.
            (None, Some(e)) if t.this_model => {
                lines.push(Line::styled("cannot train on this model:", th.error()));
                lines.push(Line::raw(e.clone()));
            }
            (base, _) => {
                let paper = t.case.paper();
                lines.push(Line::raw(format!(
                    "paper: {} epochs, MPRE {} %, RMS {}",
                    paper.epochs, paper.mpre_pct, paper.rms
                )));
                lines.push(Line::styled("t starts training", th.key()));
                let on = match base {
                    Some(b) => format!(
                        "Trains on a snapshot of tab 1's model ({} segments) at t.",
                        b.n()
                    ),
                    None => "Trains on the paper's body; the model row picks tab 1's.".into(),
                };
                lines.push(Line::styled(on, th.dim()));
            }
        }
        Paragraph::new(lines)
            .wrap(Wrap { trim: true })
            .block(block("run", th))
            .render(area, buf);
        return;
    };
    let state = if run.paused() {
        "paused".to_string()
    } else if run.running() {
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
    // One line each, numbers first: on a short panel the state line goes
    // before RMS and MPRE do.
    let clipped = |t: String| Line::raw(clip(&t, usize::from(area.width.saturating_sub(2))));
    match (&run.finished, &run.last) {
        (Some(f), _) => {
            lines.push(clipped(format!(
                "RMS {}  MPRE {}",
                f.rms.map_or("-".into(), |v| num(v, 3)),
                f.mpre_pct
                    .map_or("-".into(), |v| format!("{} %", num(v, 3)))
            )));
            lines.push(clipped(format!(
                "right {}  epochs {}  {}",
                f.share_right
                    .map_or("-".into(), |v| format!("{} %", num(v * 100.0, 3))),
                f.epochs,
                secs(run.working_s(f.train_seconds))
            )));
            // The live numbers were one member's last epoch; these are the
            // finished network's, measured once more on the training data.
            let members = run.outcome.as_ref().map_or(1, |o| o.net.members.len());
            lines.push(Line::styled(
                clip(
                    &if members > 1 {
                        let how = match run.settings.combine {
                            biodyn::ann::Combine::Mean => "mean",
                            biodyn::ann::Combine::Median => "median",
                        };
                        format!("of the final net ({how} of {members})")
                    } else {
                        "of the final net (re-measured)".to_string()
                    },
                    usize::from(area.width.saturating_sub(2)),
                ),
                th.dim(),
            ));
            lines.push(Line::styled(clip(&state, usize::from(area.width.saturating_sub(2))), state_style));
            lines.push(Line::styled(TrainingTab::trained_on(&run.settings), th.dim()));
        }
        (None, Some(p)) => {
            lines.push(Line::styled(format!("{state} {}", short_on(run)), state_style));
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
            let working = run.working_s(p.elapsed_s);
            // ETA only after a second of warm-up, when the rate means something.
            let eta = if working >= 1.0 && p.epochs_per_s > 0.0 {
                format!("ETA ≤ {}", secs(left / p.epochs_per_s))
            } else {
                "ETA …".into()
            };
            lines.push(Line::raw(format!("elapsed {}  {eta}", secs(working))));
        }
        (None, None) => {
            lines.push(Line::styled(format!("{state} {}", short_on(run)), state_style));
            lines.push(Line::raw("preparing data…"));
        }
    }
    Paragraph::new(lines)
        .wrap(Wrap { trim: true })
        .block(block(
            &format!("run: {} {}", run.case, run.settings.trainer),
            th,
        ))
        .render(area, buf);
}

/// "(paper's body)" or "(this model, 5 seg)": what a live run trains on.
fn short_on(run: &super::run::Run) -> String {
    match &run.settings.base {
        None => "(paper's body)".into(),
        Some(b) => format!("(this model, {} seg)", b.n()),
    }
}

fn render_loss(t: &TrainingTab, s: &Shared, area: Rect, buf: &mut Buffer) {
    let th = s.theme;
    let run = t.run.as_ref();
    let points = run
        .and_then(|r| r.last.as_ref())
        .map(|p| p.history.as_slice())
        .unwrap_or_default();
    let history = per_member(points);
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
            Some(r) if r.running() => "waiting for the first epochs…",
            Some(r) if r.failed.is_some() => "the run failed before its first report: no loss curve",
            Some(_) => "the run ended (diverged or stopped) before its first report: no loss curve",
            None => "the RMS error against epoch appears here while training (t starts)",
        };
        Paragraph::new(msg)
            .wrap(Wrap { trim: true })
            .block(block("RMS (log) vs epoch", th))
            .render(area, buf);
        return;
    }
    let all = history;
    let rec = [Series {
        name: "RMS".into(),
        points: recent,
    }];
    let x = if all.len() > 1 { "epoch of each member" } else { "epoch" };
    let opts = |title: &str| ChartOpts {
        x_title: x.into(),
        ..opts(title)
    };
    if area.width >= 90 {
        let [a, b] = Layout::horizontal([Constraint::Ratio(1, 2); 2]).areas(area);
        chart::render(a, buf, &all, &opts("RMS (log) vs epoch, whole run"));
        chart::render(b, buf, &rec, &opts("recent window"));
    } else if t.recent_only {
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

/// The loss history as one curve per ensemble member, each against its
/// own epochs (the worker numbers them over the whole run).
fn per_member(points: &[biodyn::ann::worker::HistoryPoint]) -> Vec<Series> {
    let mut out: Vec<Series> = Vec::new();
    let mut start = 0u64;
    let mut member = None;
    for h in points {
        if member != Some(h.member) {
            member = Some(h.member);
            start = h.total_epoch.saturating_sub(1);
            out.push(Series {
                name: format!("net {}", h.member + 1),
                points: Vec::new(),
            });
        }
        if let Some(s) = out.last_mut() {
            s.points.push(((h.total_epoch - start) as f64, h.rms));
        }
    }
    if let [one] = out.as_mut_slice() {
        one.name = "RMS".into();
    }
    out
}

fn render_prediction(t: &TrainingTab, s: &Shared, area: Rect, buf: &mut Buffer) {
    let th = s.theme;
    match t.prediction() {
        Some(p) => {
            let case = t.shown_case();
            let f = case.function();
            let whose = match (&t.loaded, t.show_loaded) {
                (Some(l), true) => format!("{}: ", clip(&l.path, 24)),
                _ => String::new(),
            };
            let on = if t.this_model { "this model, " } else { "" };
            let at = format!(
                "{whose}{} {on}at {} {} ({})",
                f.name(),
                num(p.value, 4),
                case.param_unit(),
                if p.extrapolation {
                    "extrap."
                } else {
                    "interp."
                }
            );
            // The errors go in the title when they fit whole, else they are
            // read in the held-out table below (never cut).
            let errs = format!(
                ": max {} %, mean {} %",
                num(p.max_err_pct, 3),
                num(p.mean_err_pct, 3)
            );
            let title = if at.chars().count() + errs.chars().count() + 4 <= usize::from(area.width) {
                format!("{at}{errs}")
            } else {
                at
            };
            let opts = ChartOpts {
                title,
                x_title: "f Hz".into(),
                y_title: axis_title(f, false),
                ascii: th.ascii,
                mono: th.mono,
                ..Default::default()
            };
            chart::render(area, buf, &p.curves, &opts);
        }
        None => {
            let msg = match (t.run.as_ref(), &t.prediction_err) {
                (_, Some(e)) => format!("no prediction on this model: {e}"),
                (Some(r), _) if r.outcome.as_ref().is_some_and(|o| o.stop.is_diverged()) => {
                    "the run diverged: no prediction to show".into()
                }
                (Some(r), _) if r.outcome.is_none() && r.failed.is_none() => {
                    "the prediction against the analytic curve appears when training ends".into()
                }
                _ => "train a network (t), or load one (o), to compare its prediction with the analytic curve".into(),
            };
            Paragraph::new(msg)
                .wrap(Wrap { trim: true })
                .block(block("prediction vs analytic", th))
                .render(area, buf);
        }
    }
}

fn render_holdouts(t: &TrainingTab, s: &Shared, area: Rect, buf: &mut Buffer, loss_hidden: bool) {
    let th = s.theme;
    let Some(out) = t.run.as_ref().and_then(|r| r.outcome.as_ref()) else {
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
        Span::raw(" network"),
    ])];
    let shown = t.holdout_value();
    lines.extend(out.holdout.iter().map(|h| {
        let mark = if h.value == shown { " ◀" } else { "" };
        Line::raw(format!("{}{mark}", row(h)))
    }));
    Paragraph::new(lines)
        .block(block(
            if loss_hidden {
                "held-out errors (◀ charted) — z: loss curve too"
            } else {
                "held-out errors (◀ charted)"
            },
            th,
        ))
        .render(area, buf);
}

/// The `z` zoom: the loss chart, and once a run has one, the prediction
/// under it.
pub fn render_zoomed(t: &TrainingTab, s: &Shared, area: Rect, buf: &mut Buffer) {
    if t.prediction().is_some() {
        let [loss, pred] = Layout::vertical([Constraint::Ratio(1, 2); 2]).areas(area);
        render_loss(t, s, loss, buf);
        render_prediction(t, s, pred, buf);
    } else {
        render_loss(t, s, area, buf);
    }
}
