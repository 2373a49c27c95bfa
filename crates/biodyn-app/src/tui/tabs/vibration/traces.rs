//! The seat and head traces: one chart each on the same scale, every
//! screen column the min and max of its samples (`Envelope::columns`), the
//! time axis exactly the zoom window.

use super::VibrationTab;
use super::compute::Outcome;
use super::view::fix;
use crate::tui::theme::Theme;
use crate::view::chart::{self, Series, series_style};
use crate::view::format::num;
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::Span;
use ratatui::widgets::Widget;

pub(super) fn render(t: &VibrationTab, o: &Outcome, th: Theme, area: Rect, buf: &mut Buffer) {
    let tr = &o.traces;
    let total = tr.duration();
    let (start, len) = t.window(total);
    let (seat, head) = if t.weighted {
        (&tr.seat_w, &tr.head_w)
    } else {
        (&tr.seat, &tr.head)
    };
    let cols = usize::from(area.width.saturating_sub(2)).max(1);
    let from = (start * tr.fs).round() as usize;
    let to = ((start + len) * tr.fs).round() as usize;
    let dt = len / cols as f64;
    let series = |name: String, e: &super::envelope::Envelope| Series {
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
    let what = if t.weighted {
        "Wk-weighted"
    } else {
        "unweighted"
    };
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
    let [top, bottom] = halves(area);
    for (i, (name, e, cell)) in [
        ("seat".to_string(), seat, top),
        (format!("head ({})", o.head), head, bottom),
    ]
    .into_iter()
    .enumerate()
    {
        let title = if i == 0 {
            format!("{name}, {what}, {zoom}{busy}")
        } else {
            format!("{name}, {what}")
        };
        let x0 = tr.t0 + start;
        trace_chart(
            &fix(th, &title),
            &series(name, e),
            (x0, x0 + len),
            m,
            th,
            i,
            cell,
            buf,
        );
    }
}

/// Seat above head, one chart each on the same scale: two dense traces
/// in one chart would hide each other.
fn halves(area: Rect) -> [Rect; 2] {
    Layout::vertical([Constraint::Percentage(50), Constraint::Percentage(50)]).areas(area)
}

/// The y scale of both traces: the larger peak of the two, plus 5 %.
fn y_max(t: &VibrationTab, o: &Outcome) -> f64 {
    let tr = &o.traces;
    let (seat, head) = if t.weighted {
        (&tr.seat_w, &tr.head_w)
    } else {
        (&tr.seat, &tr.head)
    };
    seat.abs_max.max(head.abs_max).max(1e-12) * 1.05
}

/// The time labels (start, middle, end of the window) and the value
/// labels of a trace chart `height` rows high.
fn labels((x0, x1): (f64, f64), m: f64, height: u16) -> (Vec<String>, Vec<String>) {
    let step = x1 - x0;
    let sig = if step < 1e-2 { 6 } else { 5 };
    let x = [x0, x0 + step / 2.0, x1]
        .iter()
        .map(|&v| num(v, sig))
        .collect();
    // A middle label only where it cannot run into the others.
    let y = if height >= 8 {
        vec![num(-m, 3), "0".into(), num(m, 3)]
    } else {
        vec![num(-m, 3), num(m, 3)]
    };
    (x, y)
}

/// The columns of the plot inside a trace chart drawn in `area` (first,
/// count), placed as ratatui's `Chart` places them: right of the widest y
/// label (or of the first x label's overhang, at most a third of the
/// width) and the y axis line. None where the chart is not drawn.
fn plot_columns(area: Rect, x: &[String], y: &[String]) -> Option<(u16, u16)> {
    if area.width < 12 || area.height < 4 {
        return None;
    }
    let w = |s: &String| u16::try_from(Span::raw(s.as_str()).width()).unwrap_or(u16::MAX);
    let left = y
        .iter()
        .map(w)
        .max()
        .unwrap_or(0)
        .max(x.first().map_or(0, |l| w(l).saturating_sub(1)))
        .min(area.width / 3);
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
    let cell = halves(area).into_iter().find(|r| r.contains(at))?;
    let x0 = o.traces.t0 + start;
    // As `trace_chart` bounds the axis.
    let x1 = x0 + len;
    let x1 = if x1 > x0 { x1 } else { x0 + 1.0 };
    let (xl, yl) = labels((x0, x1), m, cell.height);
    let (first, width) = plot_columns(cell, &xl, &yl)?;
    let c = at.x.checked_sub(first).filter(|&c| c < width)?;
    let frac = (f64::from(c) + 0.5) / f64::from(width);
    Some((start + frac * len, frac))
}

/// One trace with the time axis exactly on the window (the shared chart
/// rounds its bounds outwards, which at 80 columns turns a 2.5 s window
/// into 10 s) and labels at its start, middle and end.
#[allow(clippy::too_many_arguments)]
fn trace_chart(
    title: &str,
    s: &Series,
    (x0, x1): (f64, f64),
    m: f64,
    th: Theme,
    i: usize,
    area: Rect,
    buf: &mut Buffer,
) {
    use ratatui::symbols::Marker;
    use ratatui::widgets::{Axis, Block, Borders, Chart, Dataset, GraphType};
    if area.width < 12 || area.height < 4 {
        return;
    }
    let x1 = if x1 > x0 { x1 } else { x0 + 1.0 };
    let (x_labels, y_labels) = labels((x0, x1), m, area.height);
    let x_labels: Vec<Span> = x_labels.into_iter().map(Span::raw).collect();
    let y_labels: Vec<Span> = y_labels.into_iter().map(Span::raw).collect();
    let marker = if th.ascii {
        Marker::Dot
    } else {
        Marker::Braille
    };
    let data = Dataset::default()
        .marker(marker)
        .graph_type(GraphType::Line)
        .style(series_style(i, th.mono))
        .data(&s.points);
    let mut block = Block::new()
        .borders(Borders::TOP)
        .title(Span::styled(title.to_string(), th.heading()));
    if th.ascii {
        block = block.border_set(ratatui::symbols::border::PLAIN);
    }
    Chart::new(vec![data])
        .block(block)
        .x_axis(
            Axis::default()
                .title("t s")
                .bounds([x0, x1])
                .labels(x_labels),
        )
        .y_axis(
            Axis::default()
                .title(fix(th, "m/s²"))
                .bounds([-m, m])
                .labels(y_labels),
        )
        .render(area, buf);
    if th.ascii {
        chart::asciify(area, buf);
    }
}
