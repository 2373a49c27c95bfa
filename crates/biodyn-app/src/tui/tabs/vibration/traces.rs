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
    let m = seat.abs_max.max(head.abs_max).max(1e-12) * 1.05;
    let what = if t.weighted { "Wk-weighted" } else { "unweighted" };
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
    // Seat above head, one chart each on the same scale: two dense traces
    // in one chart would hide each other.
    let [top, bottom] =
        Layout::vertical([Constraint::Percentage(50), Constraint::Percentage(50)]).areas(area);
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
        trace_chart(&fix(th, &title), &series(name, e), (x0, x0 + len), m, th, i, cell, buf);
    }
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
    let step = x1 - x0;
    let sig = if step < 1e-2 { 6 } else { 5 };
    let x_labels: Vec<Span> = [x0, x0 + step / 2.0, x1]
        .iter()
        .map(|&v| Span::raw(num(v, sig)))
        .collect();
    // A middle label only where it cannot run into the others.
    let y_labels = if area.height >= 8 {
        vec![Span::raw(num(-m, 3)), Span::raw("0"), Span::raw(num(m, 3))]
    } else {
        vec![Span::raw(num(-m, 3)), Span::raw(num(m, 3))]
    };
    let marker = if th.ascii { Marker::Dot } else { Marker::Braille };
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

