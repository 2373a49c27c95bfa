//! The Model tab's side panels: the modes with the seat held still and
//! the main peaks, drawn from the shared derived data. Lines too long for
//! the panel (an error's reason and advice, a peak at the band edge) wrap,
//! and `rows` says how tall each panel wants to be for that.

use crate::tui::shared::Shared;
use crate::tui::theme::Theme;
use crate::tui::widgets::{block, glued, unglue};
use crate::view::format::{glue_units, num, unit};
use biodyn::freq::ModeKind;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget, Wrap};

/// Rows `lines` take inside a panel `width` wide (borders included).
pub fn rows(lines: &[Line], width: u16) -> u16 {
    let inner = usize::from(width.saturating_sub(2)).max(1);
    let n: usize = lines
        .iter()
        .map(|l| {
            // Glued span by span, as `glued` draws them.
            let text: String = l.spans.iter().map(|s| glue_units(&s.content)).collect();
            crate::view::format::wrapped_rows(&text, inner, false)
        })
        .sum();
    u16::try_from(n).unwrap_or(u16::MAX).saturating_add(2)
}

pub fn modes(s: &Shared, area: Rect, buf: &mut Buffer, th: Theme, shapes: bool) {
    // A number keeps its unit on its row (`glued`), as `rows` counts.
    Paragraph::new(glued(modes_lines(s, th, shapes)))
        .wrap(Wrap { trim: false })
        .block(block("modes (seat fixed)", th))
        .render(area, buf);
    unglue(area, buf);
}

pub fn modes_lines(s: &Shared, th: Theme, shapes: bool) -> Vec<Line<'static>> {
    // Shape magnitudes per segment (largest 1), when there is room for them.
    let shape = |v: &[f64]| -> String {
        if !shapes {
            return String::new();
        }
        let cells: Vec<String> = v.iter().map(|x| format!("{:>6}", num(*x, 2))).collect();
        format!("  {}", cells.join(""))
    };
    let mut lines = Vec::new();
    match &s.modes {
        None => lines.push(Line::styled("computing the modes…", th.dim())),
        Some(Err(e)) => lines.push(Line::styled(e.clone(), th.error())),
        Some(Ok(m)) => {
            let heads: Vec<String> = (1..=s.body.segments.len())
                .map(|i| format!("{:>6}", format!("|x{i}|")))
                .collect();
            lines.push(Line::styled(
                format!(
                    "{:<2} {:>7} {:>7} {:>6}{}",
                    "#",
                    "fn Hz",
                    "fd Hz",
                    "ζ",
                    if shapes {
                        format!("  {}", heads.join(""))
                    } else {
                        String::new()
                    }
                ),
                th.heading(),
            ));
            for (i, mode) in m.damped.iter().enumerate() {
                let text = match mode.kind {
                    ModeKind::Oscillatory {
                        damped_hz,
                        natural_hz,
                        damping_ratio,
                    } => format!(
                        "{:<2} {:>7} {:>7} {:>6}{}",
                        i + 1,
                        num(natural_hz, 4),
                        num(damped_hz, 4),
                        num(damping_ratio, 3),
                        shape(&mode.shape_mag)
                    ),
                    ModeKind::Overdamped { rate_per_s, .. } => format!(
                        "{:<2} {:<22}{}",
                        i + 1,
                        format!("overdamped, {}/s", num(rate_per_s, 4)),
                        shape(&mode.shape_mag)
                    ),
                };
                lines.push(Line::raw(text));
            }
        }
    }
    lines
}

pub fn peaks(s: &Shared, area: Rect, buf: &mut Buffer, th: Theme) {
    let title = if s.stale && s.derived.is_some() {
        "main peaks (updating…)"
    } else {
        "main peaks"
    };
    Paragraph::new(glued(peaks_lines(s, th)))
        .wrap(Wrap { trim: false })
        .block(block(title, th))
        .render(area, buf);
    unglue(area, buf);
}

pub fn peaks_lines(s: &Shared, th: Theme) -> Vec<Line<'static>> {
    let Some(d) = &s.derived else {
        return vec![Line::styled(s.computing(), th.dim())];
    };
    let mut lines = vec![Line::styled(
        format!("{:<5} {:>8} {:>9}", "", "f Hz", "magnitude"),
        th.heading(),
    )];
    for c in &d.functions {
        let f = c.function;
        match c.main {
            Some(p) => {
                let edge = if p.at_edge { " (band edge)" } else { "" };
                lines.push(Line::from(vec![
                    Span::styled(format!("{:<5}", f.name()), th.key()),
                    Span::raw(format!(
                        " {:>8} {:>9} {}{edge}",
                        num(p.f_hz, 4),
                        num(p.mag, 4),
                        unit(f)
                    )),
                ]));
            }
            None => lines.push(Line::raw(format!("{:<5} no peak", f.name()))),
        }
        if c.peaks.len() > 1 {
            let list: Vec<String> = c
                .peaks
                .iter()
                .filter(|p| Some(**p) != c.main)
                .map(|p| format!("{} Hz", num(p.f_hz, 3)))
                .collect();
            lines.push(Line::styled(
                format!("      also {}", list.join(", ")),
                th.dim(),
            ));
        }
    }
    lines
}
