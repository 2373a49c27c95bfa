//! Points per operation against the HSE lines, 100 (the action value)
//! and 529 (the limit), as horizontal bars, then the day's.
//!
//! Each operation's bar is its highest axis's points (named beside it):
//! the Directive judges the highest axis, and points of different axes
//! never add (x, y and z are judged apart), so stacking the axes would
//! draw a sum nobody is exposed to. The day's bar is the day's highest
//! axis, the sum of its operations' points on that axis (points add,
//! A(8)² do), so an operation's share of the day reads off the bars.

use super::sheet::{Row, Sheet};
use crate::tui::theme::Theme;
use crate::tui::widgets::panel;
use crate::view::format::clip;
use biodyn::exposure::{OperationSpec, points};
use biodyn::iso2631::{A8_ACTION, A8_LIMIT, Verdict};
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Style;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget};

/// The action and limit values in points: 100 and 529.
fn lines_at() -> [f64; 2] {
    [points(A8_ACTION), points(A8_LIMIT)]
}

/// The bar's colour: the verdict on that A(8), as the verdict words'.
pub fn verdict_style(v: Verdict, th: Theme) -> Style {
    match v {
        Verdict::BelowAction => th.ok(),
        Verdict::AboveAction => th.heading(),
        Verdict::AboveLimit => th.error(),
    }
}

/// One bar: label, axis, points and the A(8) it judges.
struct Bar {
    label: String,
    axis: String,
    points: f64,
    a8: f64,
}

fn bars(sheet: &Sheet, ops: &[OperationSpec]) -> Vec<Bar> {
    let mut out = Vec::new();
    for (row, o) in sheet.rows.iter().zip(ops) {
        let best = match row {
            Row::Done(op) => op
                .axes
                .iter()
                .map(|(a, e)| (a, e.points, e.a8))
                .fold(None, |m: Option<(_, f64, f64)>, x| match m {
                    Some(b) if b.1 >= x.1 => Some(b),
                    _ => Some(x),
                }),
            _ => None,
        };
        out.push(match best {
            Some((a, p, a8)) => Bar {
                label: o.name.clone(),
                axis: a.name().into(),
                points: p,
                a8,
            },
            None => Bar {
                label: o.name.clone(),
                axis: "-".into(),
                points: 0.0,
                a8: 0.0,
            },
        });
    }
    if let Some(d) = &sheet.day {
        out.push(Bar {
            label: "the day".into(),
            axis: d.a8_axis.name().into(),
            points: d.points,
            a8: d.a8,
        });
    }
    out
}

/// The bars over `area` (the tab's lower panel, or the whole body zoomed).
pub fn render(sheet: &Sheet, ops: &[OperationSpec], th: Theme, area: Rect, buf: &mut Buffer) {
    let title = "points per operation, its highest axis (100 action, 529 limit)";
    let inner = panel(title, th, area, buf);
    let all = bars(sheet, ops);
    let w = inner.width as usize;
    let label_w = all
        .iter()
        .map(|b| b.label.chars().count())
        .max()
        .unwrap_or(0)
        .clamp(7, 16)
        .min(w / 4);
    // label, axis, points: "haul road  z   43.9 "
    let head = label_w + 10;
    let bar_w = w.saturating_sub(head + 1);
    if bar_w < 10 || inner.height < 2 {
        return;
    }
    let [action, limit] = lines_at();
    let max = all.iter().map(|b| b.points).fold(0.0, f64::max);
    // The limit line always shows, with room past it.
    let scale = (limit * 1.15).max(max * 1.05);
    let col = |p: f64| ((p / scale) * bar_w as f64).round() as usize;
    let marks = [col(action), col(limit)];
    let rows = inner.height as usize - 1;
    // The day's bar stays when operations must be cut.
    let shown: Vec<&Bar> = if all.len() > rows {
        let mut v: Vec<&Bar> = all[..rows.saturating_sub(1)].iter().collect();
        v.extend(all.last());
        v
    } else {
        all.iter().collect()
    };
    let mut lines = Vec::new();
    for bar in shown {
        let n = col(bar.points).min(bar_w);
        let style = verdict_style(Verdict::judge(bar.a8, A8_ACTION, A8_LIMIT), th);
        let mut spans = vec![Span::raw(format!(
            "{:<label_w$} {:>1} {:>6.1} ",
            clip(&bar.label, label_w),
            bar.axis,
            bar.points
        ))];
        spans.push(Span::styled("█".repeat(n), style));
        let rest: String = (n..bar_w)
            .map(|i| if marks.contains(&i) { '│' } else { ' ' })
            .collect();
        spans.push(Span::styled(rest, th.dim()));
        lines.push(Line::from(spans));
    }
    // The scale: each value's label ending at its line.
    let mut scale_line = vec![' '; bar_w + 1];
    for (m, v) in marks.iter().zip(["100┘", "529┘"]) {
        let chars: Vec<char> = v.chars().collect();
        let end = (*m + 1).min(bar_w + 1);
        let start = end.saturating_sub(chars.len());
        for (k, c) in chars.iter().enumerate().take(end - start) {
            scale_line[start + k] = *c;
        }
    }
    let scale_text: String = scale_line.into_iter().collect();
    lines.push(Line::styled(
        format!("{:head$}{}", "", scale_text.trim_end()),
        th.dim(),
    ));
    Paragraph::new(lines).render(inner, buf);
}
