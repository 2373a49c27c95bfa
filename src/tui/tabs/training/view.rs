//! Drawing the Training tab: the settings list, the run panel, the loss
//! chart (whole run and recent window), the prediction and the held-out
//! errors. Reads the tab's state; changes nothing.

use super::cell::{file_name, fit_value};
use super::settings::Row;
use super::state::TrainingTab;
use crate::tui::keys;
use crate::tui::shared::Shared;
use crate::tui::widgets::block;
use crate::view::chart::{self, ChartOpts, Series};
use crate::view::format::{axis_title, clip, num};
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
    // The run panel takes the rows its lines need (at least seven), the
    // list keeping five; the list scrolls in the rest.
    let max = left.height.saturating_sub(5);
    let panel_h = super::run_view::height(t, usize::from(left.width.saturating_sub(2)), max)
        .clamp(7.min(max), max.max(7));
    let [settings, status] =
        Layout::vertical([Constraint::Max(list_h), Constraint::Min(panel_h)]).areas(left);
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
            // A long value is cut between its numbers, never inside one
            // (the status line shows it whole when the row is selected).
            let room = inner_w.saturating_sub(name_w + 1);
            let v = if arrows {
                format!("◀ {} ▶", t.value(row))
            } else {
                let kind = match row {
                    Row::Setting(s) => Some(s.kind),
                    _ => None,
                };
                fit_value(&t.value(row), kind, room)
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
    super::run_view::render(t, s, status, buf);

    // The held-out table and the prediction are the shown net's, and only
    // while the case row still names its case.
    let done = t.shown_holdouts().is_some();
    let n_holdouts = t.shown_holdouts().map_or(0, <[_]>::len);
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
        super::holdouts_view::render(t, s, holdouts, buf, loss.height == 0);
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
fn per_member(points: &[biodyn::ann::HistoryPoint]) -> Vec<Series> {
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
                // The file's name (the status line had the whole path).
                (Some(l), true) => format!("{}: ", file_name(&l.path, 24)),
                _ => String::new(),
            };
            let on = if t.this_model { "this model " } else { "" };
            let value = format!("{} {}", num(p.value, 4), case.param_unit());
            let how = if p.extrapolation {
                "extrap."
            } else {
                "interp."
            };
            let at = format!("{whose}{} {on}at {value} ({how})", f.name());
            // The errors go in the title when they fit whole, else they are
            // read in the held-out table below; a narrow chart drops words
            // (the file, "at", interp./extrap.), never cuts a number.
            let errs = format!(
                ": max {} %, mean {} %",
                num(p.max_err_pct, 3),
                num(p.mean_err_pct, 3)
            );
            let candidates = [
                format!("{at}{errs}"),
                at,
                format!("{} {on}{value} ({how})", f.name()),
                format!("{} {on}{value}", f.name()),
                format!("{} {value}", f.name()),
            ];
            // Inside the frame's corners; the errors also leave a little rule.
            let room = |i: usize| usize::from(area.width).saturating_sub(if i == 0 { 4 } else { 2 });
            let title = candidates
                .iter()
                .enumerate()
                .find(|(i, c)| c.chars().count() <= room(*i))
                .map(|(_, c)| c)
                .or(candidates.last())
                .cloned()
                .unwrap_or_default();
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
                _ if t.other_case().is_some() => keys::arrows(
                    &format!(
                        "no {} network yet: t trains one (the shown run is {}: ←/→ on the case row goes back to it)",
                        t.case,
                        t.other_case().map_or("", |c| c.key())
                    ),
                    th.ascii,
                ),
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
