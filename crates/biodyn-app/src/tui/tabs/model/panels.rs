//! The Model tab's side panels: the modes with the seat held still and
//! the main peaks, drawn from the shared derived data.

use crate::tui::shared::Shared;
use crate::tui::theme::Theme;
use crate::tui::widgets::block;
use crate::view::format::{num, unit};
use biodyn::freq::modes::ModeKind;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget, Wrap};

pub fn modes(s: &Shared, area: Rect, buf: &mut Buffer, th: Theme, shapes: bool) {
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
    Paragraph::new(lines)
        .block(block("modes (seat fixed)", th))
        .render(area, buf);
}

pub fn peaks(s: &Shared, area: Rect, buf: &mut Buffer, th: Theme) {
    let Some(d) = &s.derived else {
        Paragraph::new(Line::styled(s.computing(), th.dim()))
            .wrap(Wrap { trim: true })
            .block(block("main peaks", th))
            .render(area, buf);
        return;
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
    let title = if s.stale {
        "main peaks (updating…)"
    } else {
        "main peaks"
    };
    Paragraph::new(lines)
        .block(block(title, th))
        .render(area, buf);
}
