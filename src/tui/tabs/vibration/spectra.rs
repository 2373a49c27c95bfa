//! The one-third-octave spectra of seat and head as paired bars (seat
//! left, head right) with the band centres under them.

use super::compute::Outcome;
use super::glyphs::fix;
use crate::tui::theme::Theme;
use crate::tui::widgets::block;
use crate::view::chart::series_style;
use crate::view::format::num;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::widgets::{Paragraph, Widget, Wrap};

/// Glyphs for the top of a bar, by eighths.
const EIGHTHS: [&str; 9] = [" ", "▁", "▂", "▃", "▄", "▅", "▆", "▇", "█"];

/// Seat and head bars side by side in each band, the band centres under them.
pub(super) fn render(o: &Outcome, th: Theme, running: bool, area: Rect, buf: &mut Buffer) {
    let bands = &o.assessment.bands;
    let max = bands
        .iter()
        .flat_map(|b| [b.seat, b.head])
        .flatten()
        .fold(0.0, f64::max);
    let busy = if running { " (updating…)" } else { "" };
    let title = format!(
        "1/3 octave r.m.s., top {} m/s², seat|head{busy}",
        num(max, 3)
    );
    let b = block(&fix(th, &title), th);
    let inner = b.inner(area);
    b.render(area, buf);
    let n = bands.len().max(1);
    let gw = usize::from(inner.width) / n;
    if gw < 2 || inner.height < 3 {
        Paragraph::new("widen the terminal to see the bands")
            .wrap(Wrap { trim: true })
            .render(inner, buf);
        return;
    }
    let bw = if gw >= 5 { 2 } else { 1 };
    let plot_h = usize::from(inner.height - 1);
    let base_y = inner.y + inner.height - 2;
    // (style, glyph for ascii) of seat and head
    let looks = [
        (series_style(0, th.mono), "#"),
        (series_style(1, th.mono), "%"),
    ];
    for (i, band) in bands.iter().enumerate() {
        let x0 = inner.x + u16::try_from(i * gw).unwrap_or(u16::MAX);
        for (j, v) in [band.seat, band.head].into_iter().enumerate() {
            let Some(v) = v.filter(|_| max > 0.0) else {
                continue;
            };
            let eighths = ((v / max) * (plot_h * 8) as f64).round() as usize;
            let (style, ascii) = looks[j];
            for row in 0..plot_h {
                let e = eighths.saturating_sub(row * 8).min(8);
                if e == 0 {
                    break;
                }
                let glyph = if th.ascii {
                    if e >= 4 { ascii } else { " " }
                } else {
                    EIGHTHS[e]
                };
                let y = base_y.saturating_sub(u16::try_from(row).unwrap_or(u16::MAX));
                for dx in 0..bw {
                    let x = x0 + u16::try_from(j * bw + dx).unwrap_or(0);
                    if let Some(cell) = buf.cell_mut((x, y)) {
                        cell.set_symbol(glyph).set_style(style);
                    }
                }
            }
        }
    }
    // Band centres: each where it fits without touching the previous.
    let y = inner.y + inner.height - 1;
    let mut free = inner.x;
    for (i, band) in bands.iter().enumerate() {
        let x = inner.x + u16::try_from(i * gw).unwrap_or(u16::MAX);
        let label = format!("{}", band.f_hz);
        let w = u16::try_from(label.len()).unwrap_or(u16::MAX);
        if x >= free && x + w <= inner.x + inner.width {
            buf.set_string(x, y, &label, th.dim());
            free = x + w + 1;
        }
    }
}
