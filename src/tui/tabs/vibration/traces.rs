//! The seat traces (each axis of the record) and the head's, all on the
//! same scale, every screen column the min and max of its samples
//! (`Envelope::columns`), the time axis exactly the zoom window. Raw, or
//! weighted (`w`) each with its own ISO 2631-1 weighting: x, y Wd, z and
//! the head Wk.

use super::VibrationTab;
use super::compute::{Outcome, Traces};
use crate::view::envelope::Envelope;
use super::glyphs::fix;
use crate::tui::theme::Theme;
use crate::view::axis::{nice_step, tick_text};
use crate::view::chart::{self, Series, series_style};
use crate::view::format::num;
use biodyn::iso2631::rule;
use biodyn::time::Axis;
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Modifier, Style};
use ratatui::symbols::Marker;
use ratatui::text::{Line, Span};
use ratatui::widgets::Widget;

/// Rows a stacked chart needs to read: title, 2 plot rows, axis, labels.
const STACK_H: u16 = 6;

/// One chart: the seat axes it overlays (none: the head's chart).
type Cell = (Rect, Vec<Axis>);

/// The charts in `area`: seat above head as before for a vertical record;
/// for a tri-axial one, one chart per seat axis and the head stacked when
/// each gets `STACK_H` rows (160×48), else the seat axes overlaid in one
/// chart above the head (80×24): dense traces in one chart hide each
/// other, so stacking wins wherever it fits.
fn cells(tr: &Traces, area: Rect) -> Vec<Cell> {
    let axes: Vec<Axis> = tr.axes.axes().collect();
    let n = u16::try_from(axes.len() + 1).unwrap_or(u16::MAX);
    if tr.tri_axial() && area.height >= n.saturating_mul(STACK_H) {
        let rows = Layout::vertical(vec![Constraint::Ratio(1, u32::from(n)); usize::from(n)])
            .split(area);
        let mut out: Vec<Cell> = axes.iter().zip(rows.iter()).map(|(&a, &r)| (r, vec![a])).collect();
        if let Some(&last) = rows.last() {
            out.push((last, Vec::new()));
        }
        return out;
    }
    let [top, bottom] = halves(area);
    vec![(top, axes), (bottom, Vec::new())]
}

/// The colour index of a trace: z and head as before, x and y after them.
fn colour(axis: Option<Axis>) -> usize {
    match axis {
        Some(Axis::Z) => 0,
        None => 1,
        Some(Axis::X) => 2,
        Some(Axis::Y) => 3,
    }
}

/// The marker of `axis` in a chart of `overlaid` traces: braille (ASCII
/// `*`) alone or in colour; overlaid without colour each axis its own
/// glyph, so NO_COLOR and `--ascii` still tell them apart.
fn marker(axis: Option<Axis>, overlaid: bool, th: Theme) -> Marker {
    let distinct = overlaid && (th.mono || th.ascii);
    match (axis, distinct, th.ascii) {
        (Some(Axis::X), true, false) => Marker::Dot,
        (Some(Axis::X), true, true) => Marker::Custom('+'),
        (Some(Axis::Y), true, false) => Marker::Custom('×'),
        (Some(Axis::Y), true, true) => Marker::Custom('o'),
        (_, _, true) => Marker::Dot,
        _ => Marker::Braille,
    }
}

/// A marker's glyph for the legend in a title.
fn glyph(m: Marker, ascii: bool) -> String {
    match m {
        Marker::Custom(c) => c.to_string(),
        Marker::Dot if ascii => "*".into(),
        Marker::Dot => "•".into(),
        _ => "⣿".into(),
    }
}

/// "Wk-weighted" or "unweighted" for a chart of `axes` (the head: Wk).
fn what(weighted: bool, axes: &[Axis]) -> String {
    if !weighted {
        return "unweighted".into();
    }
    let mut w: Vec<&str> = axes.iter().map(|&a| rule(a).weighting.name()).collect();
    w.dedup();
    if w.is_empty() {
        w.push("Wk");
    }
    format!("{}-weighted", w.join("/"))
}

pub(super) fn render(t: &VibrationTab, o: &Outcome, th: Theme, area: Rect, buf: &mut Buffer) {
    let tr = &o.traces;
    let total = tr.duration();
    let (start, len) = t.window(total);
    let cols = usize::from(area.width.saturating_sub(2)).max(1);
    let from = (start * tr.fs).round() as usize;
    let to = ((start + len) * tr.fs).round() as usize;
    let dt = len / cols as f64;
    let series = |name: String, e: &Envelope| Series {
        name,
        points: e
            .columns(from, to, cols)
            .into_iter()
            .enumerate()
            .flat_map(|(c, (lo, hi))| {
                let x = tr.t0 + start + (c as f64 + 0.5) * dt;
                [(x, lo), (x, hi)]
            })
            .collect(),
    };
    let m = y_max(t, o);
    let zoom = if t.zoom == 0 {
        format!("all {} s", num(total, 4))
    } else {
        format!(
            "{}–{} s of {}",
            num(tr.t0 + start, 5),
            num(tr.t0 + start + len, 5),
            num(total, 4)
        )
    };
    let busy = if t.running { " (updating…)" } else { "" };
    let x0 = tr.t0 + start;
    for (i, (cell, axes)) in cells(tr, area).into_iter().enumerate() {
        let overlaid = axes.len() > 1;
        // Largest first, so a smaller trace is drawn over it, not hidden.
        let mut traces: Vec<(Option<Axis>, &Envelope)> = if axes.is_empty() {
            vec![(None, tr.head(t.weighted))]
        } else {
            axes.iter()
                .map(|&a| (Some(a), tr.seat_axis(a, t.weighted)))
                .collect()
        };
        traces.sort_by(|a, b| b.1.abs_max.total_cmp(&a.1.abs_max));
        let name = match axes.as_slice() {
            [] => format!("head ({})", o.head),
            [Axis::Z] if tr.pan => "seat pan".into(),
            [Axis::Z] if !tr.tri_axial() => "seat".into(),
            [a] => format!("seat {a} ({})", a.direction()),
            _ => "seat".into(),
        };
        let mut title = vec![Span::styled(name.clone(), th.heading())];
        if overlaid {
            for &a in &axes {
                let g = glyph(marker(Some(a), true, th), th.ascii);
                let look = series_style(colour(Some(a)), th.mono).add_modifier(Modifier::BOLD);
                title.push(Span::styled(format!(" {a}{g}"), look));
            }
        }
        let what = what(t.weighted, &axes);
        let tail = if i == 0 {
            format!(", {what}, {zoom}{busy}")
        } else {
            format!(", {what}")
        };
        title.push(Span::styled(fix(th, &tail), th.heading()));
        let peaks = if axes.contains(&Axis::Z) {
            spine_peaks(o)
        } else {
            Vec::new()
        };
        if !peaks.is_empty() {
            title.push(Span::styled(format!(" {} spine peaks", peak_glyph(th)), th.error()));
        }
        let data: Vec<Look> = traces
            .into_iter()
            .map(|(a, e)| Look {
                series: series(a.map_or("head".into(), |a| a.to_string()), e),
                marker: marker(a, overlaid, th),
                style: series_style(colour(a), th.mono),
            })
            .collect();
        let plot = trace_chart(Line::from(title), &data, (x0, x0 + len), m, th, cell, buf);
        mark_peaks(&peaks, (x0, x0 + len), m, th, cell, buf);
        // The axis titles last, where no trace or peak mark is (as every chart's).
        if let Some(p) = plot {
            chart::place_titles(p, buf, ("t s", &fix(th, "m/s²")), &[], None);
        }
    }
}

/// Peaks marked on the seat trace: ISO 2631-5's spinal response peaks
/// that set the dose, the largest ten of at least half the largest (the
/// dose sums sixth powers: a peak at half counts 1/64), at their times.
const MARKED: usize = 10;

fn spine_peaks(o: &Outcome) -> Vec<f64> {
    match &o.assessment.spine {
        Some(Ok(sp)) => sp
            .largest(MARKED)
            .into_iter()
            .filter(|&(_, v)| v >= 0.5 * sp.dose.largest)
            .map(|(t, _)| o.traces.t0 + t)
            .collect(),
        _ => Vec::new(),
    }
}

fn peak_glyph(th: Theme) -> &'static str {
    if th.ascii { "v" } else { "▼" }
}

/// A peak's glyph on the plot's top row, in the column the chart draws
/// its time in (as `x_ticks` places a tick).
fn mark_peaks(peaks: &[f64], (x0, x1): (f64, f64), m: f64, th: Theme, area: Rect, buf: &mut Buffer) {
    let (_, y_text) = y_axis(m, area.height);
    let Some((first, width)) = plot_columns(area, &y_text) else {
        return;
    };
    let (len, dots) = (x1 - x0, f64::from(width) * 2.0 - 1.0);
    for &t in peaks.iter().filter(|&&t| t >= x0 && t <= x1 && len > 0.0) {
        let c = first + (((t - x0) / len * dots).floor() / 2.0).floor() as u16;
        // Over the trace, never over the axis title written on that row.
        if let Some(cell) = buf.cell_mut((c.min(first + width - 1), area.y + 1))
            && !cell.symbol().chars().any(char::is_alphanumeric)
            && !matches!(cell.symbol(), "/" | "²" | "^")
        {
            cell.set_symbol(peak_glyph(th)).set_style(th.error());
        }
    }
}

/// One trace as drawn: its points, marker and colour.
struct Look {
    series: Series,
    marker: Marker,
    style: Style,
}

/// Seat above head, one chart each on the same scale: two dense traces
/// in one chart would hide each other.
fn halves(area: Rect) -> [Rect; 2] {
    Layout::vertical([Constraint::Percentage(50), Constraint::Percentage(50)]).areas(area)
}

/// The y scale of every trace: the largest peak of them, plus 5 %.
fn y_max(t: &VibrationTab, o: &Outcome) -> f64 {
    let tr = &o.traces;
    tr.axes
        .axes()
        .map(|a| tr.seat_axis(a, t.weighted).abs_max)
        .fold(tr.head(t.weighted).abs_max, f64::max)
        .max(1e-12)
        * 1.05
}

/// The value axis of a trace chart `height` rows high over ±`m`: its
/// bound (a whole number of round steps, 1, 2 or 5 × 10ⁿ, at or above
/// `m`) and the labels ratatui spreads evenly from -bound to +bound, one
/// per step: the ends and 0 written (0 only from 8 rows), the rest blank.
fn y_axis(m: f64, height: u16) -> (f64, Vec<String>) {
    // The plot's rows: the chart's minus the title, the axis and its labels.
    let rows = usize::from(height.saturating_sub(3)).max(2);
    let mut step = nice_step(m / 4.0);
    loop {
        let k = (m / step - 1e-9).ceil().max(1.0) as usize;
        // Every step on a row of its own, or a coarser step.
        if 2 * k < rows || k == 1 {
            let bound = k as f64 * step;
            let labels = (0..=2 * k)
                .map(|i| {
                    let v = (i as f64 - k as f64) * step;
                    let end = i == 0 || i == 2 * k;
                    let zero = i == k && height >= 8;
                    if end || zero {
                        tick_text(v, step)
                    } else {
                        String::new()
                    }
                })
                .collect();
            return (bound, labels);
        }
        step = nice_step(step * 1.5);
    }
}

/// The time ticks of a plot `width` columns wide from column `first`
/// over [x0, x1] s: round values (a 1, 2 or 5 × 10ⁿ step, the finest
/// with about 8 columns per tick whose labels keep two columns apart),
/// each with the column ratatui's
/// braille canvas draws that time in.
fn x_ticks((x0, x1): (f64, f64), first: u16, width: u16) -> Vec<(u16, String)> {
    let len = x1 - x0;
    if len.is_nan() || len <= 0.0 || width < 2 {
        return Vec::new();
    }
    let dots = f64::from(width) * 2.0 - 1.0;
    let col = |v: f64| first + (((v - x0) / len * dots).floor() / 2.0).floor() as u16;
    // About one tick per 8 columns at most, as the other charts space them.
    let mut step = nice_step(len / (f64::from(width) / 8.0).max(1.0));
    for _ in 0..40 {
        let k0 = (x0 / step - 1e-9).ceil() as i64;
        let k1 = (x1 / step + 1e-9).floor() as i64;
        let ticks: Vec<(u16, String)> = (k0..=k1)
            .map(|k| {
                let v = k as f64 * step;
                (col(v.clamp(x0, x1)), tick_text(v, step))
            })
            .collect();
        let end = first + width;
        let spans: Vec<(i32, i32)> = ticks
            .iter()
            .map(|(c, l)| {
                let w = l.chars().count() as i32;
                let a = (i32::from(*c) - w / 2).clamp(0, i32::from(end) - w);
                (a, a + w)
            })
            .collect();
        let apart = spans.windows(2).all(|p| p[1].0 - p[0].1 >= 2);
        if apart && ticks.len() <= 12 {
            return ticks;
        }
        step = nice_step(step * 1.5);
    }
    Vec::new()
}

/// The columns of the plot inside a trace chart drawn in `area` (first,
/// count), placed as ratatui's `Chart` places them: right of the widest y
/// label (at most a third of the width; the x labels are ours, written
/// after, so none reaches left) and the y axis line. None where the chart
/// is not drawn.
fn plot_columns(area: Rect, y: &[String]) -> Option<(u16, u16)> {
    if area.width < 12 || area.height < 4 {
        return None;
    }
    let w = |s: &String| u16::try_from(Span::raw(s.as_str()).width()).unwrap_or(u16::MAX);
    let left = y.iter().map(w).max().unwrap_or(0).min(area.width / 3);
    let first = area.x + left + 1;
    Some((first, area.right().saturating_sub(first)))
}

/// The time (s from the record's start) under `column` in the traces
/// drawn in `area`, and where it sits across the plot (0..1): the middle
/// of the column, as the chart maps the window onto the plot's width.
pub(super) fn time_at(
    t: &VibrationTab,
    o: &Outcome,
    area: Rect,
    at: ratatui::layout::Position,
) -> Option<(f64, f64)> {
    let total = o.traces.duration();
    let (start, len) = t.window(total);
    let m = y_max(t, o);
    let (cell, _) = cells(&o.traces, area)
        .into_iter()
        .find(|(r, _)| r.contains(at))?;
    let (_, yl) = y_axis(m, cell.height);
    let (first, width) = plot_columns(cell, &yl)?;
    let c = at.x.checked_sub(first).filter(|&c| c < width)?;
    let frac = (f64::from(c) + 0.5) / f64::from(width);
    Some((start + frac * len, frac))
}

/// Traces in one chart with the time axis exactly on the window (the
/// shared chart rounds its bounds outwards, which at 80 columns turns a
/// 2.5 s window into 10 s) and round ticks inside it; the plot's
/// rectangle, for the axis titles the caller places after its marks.
fn trace_chart(
    title: Line<'static>,
    looks: &[Look],
    (x0, x1): (f64, f64),
    m: f64,
    th: Theme,
    area: Rect,
    buf: &mut Buffer,
) -> Option<Rect> {
    use ratatui::widgets::{Axis, Block, Borders, Chart, Dataset, GraphType};
    if area.width < 12 || area.height < 4 {
        return None;
    }
    let x1 = if x1 > x0 { x1 } else { x0 + 1.0 };
    let (bound, y_text) = y_axis(m, area.height);
    let (first, width) = plot_columns(area, &y_text)?;
    let ticks = x_ticks((x0, x1), first, width);
    // Blank x labels keep ratatui's label row and axis line; the round
    // ticks are written below at their own columns.
    let x_labels = vec![Span::raw(""), Span::raw("")];
    let y_labels: Vec<Span> = y_text.iter().cloned().map(Span::raw).collect();
    let data: Vec<Dataset> = looks
        .iter()
        .map(|l| {
            Dataset::default()
                .marker(l.marker)
                .graph_type(GraphType::Line)
                .style(l.style)
                .data(&l.series.points)
        })
        .collect();
    let mut block = Block::new().borders(Borders::TOP).title(title);
    if th.ascii {
        block = block.border_set(ratatui::symbols::border::PLAIN);
    }
    Chart::new(data)
        .block(block)
        .x_axis(Axis::default().bounds([x0, x1]).labels(x_labels))
        .y_axis(Axis::default().bounds([-bound, bound]).labels(y_labels))
        .render(area, buf);
    mark_ticks(area, first, width, &ticks, &y_text, buf);
    if th.ascii {
        chart::asciify(area, buf);
    }
    // ratatui's plot: below the top border, above the axis and label rows.
    Some(Rect::new(first, area.y + 1, width, area.height.saturating_sub(3)))
}

/// The round ticks on ratatui's axes: `┬` on the time axis and each time
/// label centred under it (kept inside the chart), `┤` on the value axis
/// where a value label is.
fn mark_ticks(
    area: Rect,
    first: u16,
    width: u16,
    ticks: &[(u16, String)],
    y_text: &[String],
    buf: &mut Buffer,
) {
    // Inside the top border: the label row at the bottom, the axis above.
    let (label_row, axis_row) = (area.bottom() - 1, area.bottom() - 2);
    let end = first + width;
    for (c, l) in ticks {
        if let Some(cell) = buf.cell_mut((*c, axis_row)) {
            cell.set_symbol("┬");
        }
        let w = u16::try_from(l.chars().count()).unwrap_or(u16::MAX);
        let a = c.saturating_sub(w / 2).min(end.saturating_sub(w)).max(area.x);
        buf.set_string(a, label_row, l, ratatui::style::Style::default());
    }
    // ratatui's rows for n labels over a plot `gh` rows high.
    let gh = area.height.saturating_sub(3);
    let n = u16::try_from(y_text.len()).unwrap_or(0);
    if n < 2 || gh == 0 {
        return;
    }
    let bottom = area.y + 1 + gh - 1;
    for (i, l) in (0u16..).zip(y_text) {
        if l.is_empty() {
            continue;
        }
        let row = bottom - i * (gh - 1) / (n - 1);
        if let Some(cell) = buf.cell_mut((first - 1, row)) {
            cell.set_symbol("┤");
        }
    }
}
