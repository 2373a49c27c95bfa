//! Drawing the fit dialog over the charts: the free-parameter list with
//! starts and seed, the progress of a running fit, and the result (values,
//! 95 % intervals, undetermined parameters marked and said in words,
//! residual r.m.s. per column). Reads state; changes nothing.

use super::data::DataOverlay;
use super::fit::{FitDialog, Row, Running, Stage};
use crate::tui::keys;
use crate::tui::shared::Shared;
use crate::tui::theme::Theme;
use crate::tui::widgets::block;
use crate::view::format::{clip, num, wrap};
use biodyn::Param;
use biodyn::fit::{Fit, name_of};
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Style;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Clear, Paragraph, Widget};

/// Widest the dialog gets; the charts stay visible around it.
const MAX_WIDTH: u16 = 96;

pub fn render(d: &FitDialog, o: &DataOverlay, s: &Shared, area: Rect, buf: &mut Buffer) {
    let w = area.width.min(MAX_WIDTH);
    let inner = w.saturating_sub(2) as usize;
    let (title, lines, focus, scroll) = match &d.stage {
        Stage::Setup => {
            let (lines, focus) = setup_lines(d, o, s, inner);
            ("fit — choose free parameters", lines, Some(focus), 0)
        }
        Stage::Running(r) => ("fit — running", running_lines(d, o, r, s, inner), None, 0),
        Stage::Result { fit, scroll } => {
            ("fit — result", result_lines(fit, s, inner), None, *scroll)
        }
    };
    let h = (lines.len() as u16 + 2).min(area.height);
    let r = claim(area, w, h);
    let room = h.saturating_sub(2) as usize;
    let max = lines.len().saturating_sub(room);
    // The list keeps its selected row in view; the result scrolls by hand.
    let top = match focus {
        Some(f) => f.saturating_sub(room.saturating_sub(1)).min(max),
        None => (scroll as usize).min(max),
    };
    crate::view::probe::dialog(r, buf);
    Clear.render(r, buf);
    let shown: Vec<Line> = lines.into_iter().skip(top).collect();
    let more = if max > 0 {
        keys::arrows(" (↑↓ more)", s.theme.ascii)
    } else {
        String::new()
    };
    Paragraph::new(shown)
        .block(block(&format!("{title}{more}"), s.theme))
        .render(r, buf);
}

/// Rows or columns of the charts worth leaving beside the dialog: fewer
/// would show a strip of a chart (its axis labels, a corner) cut from it.
const MARGIN_ROWS: u16 = 5;
const MARGIN_COLS: u16 = 12;

/// The rectangle of a `w`×`h` dialog in `area`: centred, the charts
/// visible around it; in a side where what is left of them would be a
/// strip under `MARGIN_ROWS` rows or `MARGIN_COLS` columns, the dialog
/// takes that side's whole extent (at 80×24 the whole area).
fn claim(area: Rect, w: u16, h: u16) -> Rect {
    let (w, h) = (w.min(area.width), h.min(area.height));
    let w = if (area.width - w) / 2 < MARGIN_COLS { area.width } else { w };
    let h = if (area.height - h) / 2 < MARGIN_ROWS { area.height } else { h };
    Rect::new(
        area.x + (area.width - w) / 2,
        area.y + (area.height - h) / 2,
        w,
        h,
    )
}

/// `text` wrapped to the dialog's `inner` width, each row after a space.
fn para_lines(text: &str, inner: usize, style: Style) -> Vec<Line<'static>> {
    wrap(text, inner.saturating_sub(1).max(8), true)
        .into_iter()
        .map(|l| Line::styled(format!(" {l}"), style))
        .collect()
}

/// "start 3 of 8 · best cost 12.3 · 0.4 s", also the status-line summary.
pub fn progress_text(r: &Running) -> String {
    let secs = r.started.elapsed().as_secs_f64();
    let done = r.last.map_or(0, |p| p.done);
    let best = r
        .last
        .filter(|p| p.best_cost.is_finite())
        .map_or("–".into(), |p| num(p.best_cost, 4));
    let stop = if r.cancelling {
        " · cancelling…"
    } else {
        ""
    };
    match r.last {
        // The starts are done: the profile intervals are being walked.
        Some(p) if p.done == p.starts && p.profiles > 0 => format!(
            "fit: intervals {} of {} · best cost {best} · {secs:.1} s{stop}",
            p.profiled, p.profiles
        ),
        _ => format!(
            "fit: start {done} of {} · best cost {best} · {secs:.1} s{stop}",
            r.starts
        ),
    }
}

/// " pelvis-seat (N/m)": what the library's short name refers to.
fn what(s: &Shared, p: Param) -> String {
    let d = s.describe(p);
    let label = s.body.label(p);
    d.strip_prefix(&label).unwrap_or(&d).trim().to_string()
}

fn setup_lines(
    d: &FitDialog,
    o: &DataOverlay,
    s: &Shared,
    inner: usize,
) -> (Vec<Line<'static>>, usize) {
    let th = s.theme;
    let b = &s.body;
    // The data's description names every column: wrapped, never cut.
    let mut lines = para_lines(&format!("data {}", o.describe()), inner, th.base());
    lines.extend(para_lines(
        "free parameters (space frees/fixes, a all, d default) and start values:",
        inner,
        th.dim(),
    ));
    let first_row = lines.len();
    let name_w = d
        .rows
        .iter()
        .filter_map(|r| match r {
            Row::Param(p) => Some(name_of(b, *p).chars().count()),
            _ => None,
        })
        .max()
        .unwrap_or(2)
        .max(6);
    for (i, row) in d.rows.iter().enumerate() {
        let text = match *row {
            Row::Param(p) => format!(
                " [{}] {:<name_w$}  {:<26} {:>10}",
                if d.is_free(p) { "x" } else { " " },
                name_of(b, p),
                clip(&what(s, p), 26),
                num(b.get(p), 6)
            ),
            Row::Starts => format!(
                "     {:<name_w$}  {:<26} {:>10}",
                "starts", "Levenberg–Marquardt runs", d.starts
            ),
            Row::Seed => format!(
                "     {:<name_w$}  {:<26} {:>10}",
                "seed", "of the start points", d.seed
            ),
        };
        let style = if i == d.sel { th.selected() } else { th.base() };
        lines.push(Line::styled(clip(&text, inner), style));
    }
    let n = d.free.len();
    lines.extend(para_lines(
        &format!(
            "{n} free · {} starts · seed {} · Enter fits, Esc closes",
            d.starts, d.seed
        ),
        inner,
        th.dim(),
    ));
    if let Some(note) = &d.note {
        for l in wrap(note, inner.saturating_sub(1).max(8), true) {
            lines.push(Line::styled(format!(" {l}"), th.error()));
        }
    }
    (lines, first_row + d.sel)
}

fn running_lines(
    d: &FitDialog,
    o: &DataOverlay,
    r: &Running,
    s: &Shared,
    inner: usize,
) -> Vec<Line<'static>> {
    let th = s.theme;
    let mut lines: Vec<Line> = wrap(
        &format!(
            "fitting {} to {}",
            d.free_list(&s.body).replace(',', ", "),
            o.data.path
        ),
        inner.saturating_sub(1).max(8),
        true,
    )
    .into_iter()
    .map(|l| Line::raw(format!(" {l}")))
    .collect();
    lines.push(Line::styled(format!(" {}", progress_text(r)), th.heading()));
    let bar_w = inner.saturating_sub(4).max(1);
    // Starts, then the intervals, as one bar.
    let (done, all) = r.last.map_or((0, r.starts), |p| {
        (p.done + p.profiled, p.starts + p.profiles)
    });
    let full = (bar_w * done) / all.max(1);
    lines.push(Line::raw(format!(
        " [{}{}]",
        "=".repeat(full),
        " ".repeat(bar_w - full)
    )));
    for l in wrap(
        "Esc cancels (within a start or a step of the intervals); the model changes only when you apply",
        inner.saturating_sub(1).max(8),
        true,
    ) {
        lines.push(Line::styled(format!(" {l}"), th.dim()));
    }
    lines
}

/// A value for eyes: 4 significant figures.
fn val(v: f64) -> String {
    num(v, 4)
}

/// An interval end; "—" ("--" in ASCII) where the data do not bound it.
fn end(v: Option<f64>, th: Theme) -> String {
    v.map_or_else(|| if th.ascii { "--" } else { "—" }.into(), val)
}

/// The result table's columns, the most important first: the verdict and
/// the name are never dropped; a narrow dialog drops the start value, then
/// the unit, then the fitted value, until the rest fits.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Col {
    Name,
    Unit,
    Start,
    Fitted,
    Interval,
    Verdict,
}

/// Shown left to right.
const ORDER: [Col; 6] = [
    Col::Name,
    Col::Unit,
    Col::Start,
    Col::Fitted,
    Col::Interval,
    Col::Verdict,
];
/// Dropped first to last while the table is wider than the dialog.
const DROP: [Col; 3] = [Col::Start, Col::Unit, Col::Fitted];

/// The result table as lines of text, fitted to `inner` columns: the
/// header, then one row per parameter (with whether it is determined).
fn result_table(fit: &Fit, th: Theme, inner: usize) -> Vec<(String, bool)> {
    let header = |c: Col| match c {
        Col::Name => "parameter",
        Col::Unit => "unit",
        Col::Start => "start",
        Col::Fitted => "fitted",
        Col::Interval => "95 % interval",
        Col::Verdict => "determined",
    };
    let cell = |c: Col, p: &biodyn::fit::ParamFit| match c {
        Col::Name => p.name.clone(),
        Col::Unit => p.unit.to_string(),
        Col::Start => val(p.start),
        Col::Fitted => val(p.value),
        Col::Interval => format!("{} – {}", end(p.ci95_low, th), end(p.ci95_high, th)),
        Col::Verdict => {
            let mut det = if p.determined { "yes" } else { "NO" }.to_string();
            if p.at_bound {
                det += " at bound";
            }
            if p.other_minimum {
                det += " *";
            }
            det
        }
    };
    let width = |c: Col| {
        fit.params
            .iter()
            .map(|p| cell(c, p).chars().count())
            .chain([header(c).chars().count()])
            .max()
            .unwrap_or(0)
    };
    let mut shown: Vec<Col> = ORDER.to_vec();
    // One leading space, two between columns.
    let total = |cols: &[Col]| 1 + cols.iter().map(|&c| width(c)).sum::<usize>() + 2 * (cols.len() - 1);
    for drop in DROP {
        if total(&shown) <= inner {
            break;
        }
        shown.retain(|&c| c != drop);
    }
    let line = |texts: Vec<(Col, String)>| {
        let mut s = String::from(" ");
        for (i, (c, t)) in texts.iter().enumerate() {
            if i > 0 {
                s += "  ";
            }
            let w = width(*c);
            // Names and words to the left, numbers to the right.
            if matches!(c, Col::Name | Col::Interval | Col::Verdict) {
                s += &format!("{t:<w$}");
            } else {
                s += &format!("{t:>w$}");
            }
        }
        clip(s.trim_end(), inner)
    };
    let mut out = vec![(line(shown.iter().map(|&c| (c, header(c).to_string())).collect()), true)];
    for p in &fit.params {
        out.push((line(shown.iter().map(|&c| (c, cell(c, p))).collect()), p.determined));
    }
    out
}

fn result_lines(fit: &Fit, s: &Shared, inner: usize) -> Vec<Line<'static>> {
    let th = s.theme;
    let mut lines = Vec::new();
    let para = |lines: &mut Vec<Line<'static>>, text: &str, style: Style| {
        for l in wrap(text, inner.saturating_sub(1).max(8), true) {
            lines.push(Line::styled(format!(" {l}"), style));
        }
    };
    let method = match fit.settings.intervals {
        biodyn::fit::Intervals::Profile => "profile-likelihood",
        biodyn::fit::Intervals::Curvature => "curvature",
    };
    para(
        &mut lines,
        &format!(
            "{} of {} starts reached the best cost {} in {:.2} s ({} values at {} frequencies); {method} intervals",
            fit.converged_starts,
            fit.settings.starts,
            num(fit.cost, 4),
            fit.seconds,
            fit.values,
            fit.points
        ),
        th.base(),
    );
    for (i, (text, determined)) in result_table(fit, th, inner).into_iter().enumerate() {
        let style = if i == 0 {
            th.heading()
        } else if determined {
            th.base()
        } else {
            th.error()
        };
        lines.push(Line::from(Span::styled(text, style)));
    }
    let rms: Vec<String> = fit
        .residual_rms
        .iter()
        .map(|c| {
            if c.column.ends_with("_deg") {
                format!("{} {:.2}°", c.column, c.rms)
            } else {
                format!("{} {:.2} %", c.column, 100.0 * c.rms)
            }
        })
        .collect();
    para(
        &mut lines,
        &format!("residual r.m.s.: {}", rms.join(", ")),
        th.base(),
    );
    let undetermined = fit.undetermined();
    if undetermined.is_empty() {
        para(
            &mut lines,
            "Every free parameter is determined: its 95 % interval lies within a factor of 2 of its value.",
            th.ok(),
        );
    } else {
        let names: Vec<&str> = undetermined.iter().map(|p| p.name.as_str()).collect();
        para(
            &mut lines,
            &format!(
                "Not determined by these data: {}. Their 95 % intervals reach past a factor of 2 of the fitted value, so read those values as unknown; fix them, or load data that show them (phases, STHT for the head-neck link).",
                names.join(", ")
            ),
            th.error(),
        );
    }
    if fit.params.iter().any(|p| p.other_minimum) {
        para(
            &mut lines,
            "* the interval takes in another start's minimum that the data do not reject: they cannot choose between them.",
            th.base(),
        );
        for p in fit.params.iter().filter(|p| p.ci95_pieces.len() > 1) {
            let pieces: Vec<String> = p
                .ci95_pieces
                .iter()
                .map(|&(l, h)| format!("{} – {}", end(l, th), end(h, th)))
                .collect();
            para(
                &mut lines,
                &format!("  {} has gaps: {} {}", p.name, pieces.join(" or "), p.unit),
                th.base(),
            );
        }
    }
    if fit
        .params
        .iter()
        .any(|p| p.ci95_low.is_none() || p.ci95_high.is_none())
    {
        let dash = if th.ascii { "--" } else { "—" };
        para(
            &mut lines,
            &format!("{dash} unbounded: the interval reaches the parameter's box (1/1000 to 1000 × its start): the data do not bound it there."),
            th.base(),
        );
    }
    if fit.converged_starts == 1 && fit.settings.starts > 1 {
        para(
            &mut lines,
            "Only one start reached the best cost: more starts may find a better minimum.",
            th.base(),
        );
    }
    para(
        &mut lines,
        "Enter applies the fitted values as one edit (u undoes it, ^S saves the preset); Esc discards.",
        th.heading(),
    );
    lines
}
