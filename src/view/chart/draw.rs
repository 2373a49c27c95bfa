//! Drawing a laid-out chart: axes with their ticks and labels, the curves
//! (each on its own canvas, laid together so none hides another), the
//! cursor, the peaks and the legend (the axis titles: `titles.rs`).

use super::layout::{Layout, label_span};
use super::opts::{ChartOpts, Series};
use crate::view::glyph::{
    CURSOR, PEAK, dim_glyph, dim_marker, dim_style, dots, legend_glyph, marker, peak_glyph,
    series_style,
};
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Color, Style};
use ratatui::widgets::canvas::{Canvas, Line as CanvasLine, Points};
use ratatui::widgets::{Block, Widget};

/// Writes `text` at (x, y), at most `w` cells, in `style` over a reset cell.
fn put(buf: &mut Buffer, x: u16, y: u16, text: &str, w: u16, style: Style) {
    for (i, ch) in text.chars().take(w as usize).enumerate() {
        if let Some(cell) = buf.cell_mut((x + i as u16, y)) {
            cell.set_char(ch).set_fg(Color::Reset).set_style(style);
        }
    }
}

/// The axis lines with a tick mark at each label, and the labels.
pub(super) fn axes(lay: &Layout, buf: &mut Buffer, opts: &ChartOpts) {
    let p = lay.plot;
    let (ax, ay) = (p.x - 1, p.bottom());
    let plain = Style::default();
    let tick_rows: Vec<u16> = lay
        .y_plan
        .ticks
        .iter()
        .filter_map(|t| lay.y.cell(t.at))
        .collect();
    for r in 0..p.height {
        let g = if tick_rows.contains(&r) { "┤" } else { "│" };
        put(buf, ax, p.y + r, g, 1, plain);
    }
    let tick_cols: Vec<u16> = lay
        .x_plan
        .ticks
        .iter()
        .filter_map(|t| lay.x.cell(t.at))
        .collect();
    put(buf, ax, ay, "└", 1, plain);
    for c in 0..p.width {
        let g = if tick_cols.contains(&c) { "┬" } else { "─" };
        put(buf, p.x + c, ay, g, 1, plain);
    }
    for t in &lay.y_plan.ticks {
        if let Some(r) = lay.y.cell(t.at) {
            let n = t.label.chars().count() as u16;
            put(buf, ax.saturating_sub(n), p.y + r, &t.label, n, plain);
        }
    }
    for t in &lay.x_plan.ticks {
        if let Some(c) = lay.x.cell(t.at) {
            let (a, _) = label_span(i32::from(p.x + c), &t.label);
            let n = t.label.chars().count() as u16;
            put(buf, a.max(0) as u16, ay + 1, &t.label, n, plain);
        }
    }
    let _ = opts;
}

/// The curves, the cursor beneath them and the peaks above them; a
/// dimmed series (`dim[i]`) goes beneath the cursor and the other curves.
pub(super) fn data(
    lay: &Layout,
    buf: &mut Buffer,
    data: &[Vec<(f64, f64)>],
    dim: &[bool],
    opts: &ChartOpts,
) {
    let p = lay.plot;
    let cursor_col = opts.cursor_x.and_then(|c| lay.column(c, opts.log_x));
    let cursor_style = if opts.mono {
        Style::default()
    } else {
        Style::default().fg(Color::DarkGray)
    };
    let cursor = if opts.ascii { CURSOR.1 } else { CURSOR.0 };
    let is_dim = |i: usize| dim.get(i).copied().unwrap_or(false);
    if data.len() <= 1 && !is_dim(0) {
        // One curve: the cursor first, the curve straight over it.
        if let Some(c) = cursor_col {
            for r in p.top()..p.bottom() {
                put(buf, c, r, &cursor.to_string(), 1, cursor_style);
            }
        }
        if let Some(d) = data.first() {
            paint(lay, d, 0, false, opts, p, buf);
        }
        peaks(lay, buf, opts);
        return;
    }
    let scratch_area = Rect::new(0, 0, p.width, p.height);
    // Each series alone on a scratch canvas, in the reference cells.
    let layers: Vec<(bool, Buffer)> = data
        .iter()
        .enumerate()
        .map(|(i, d)| {
            let mut b = Buffer::empty(scratch_area);
            paint(lay, d, i, is_dim(i), opts, scratch_area, &mut b);
            (is_dim(i), b)
        })
        .collect();
    // How many normal and dimmed layers drew each cell; most cells are
    // empty in all of them.
    let n = usize::from(p.width) * usize::from(p.height);
    let mut drawn: Vec<(u8, u8)> = vec![(0, 0); n];
    for (faint, layer) in &layers {
        for (k, cell) in layer.content.iter().enumerate().take(n) {
            if cell.symbol() != " " {
                let d = &mut drawn[k];
                if *faint {
                    d.1 = d.1.saturating_add(1);
                } else {
                    d.0 = d.0.saturating_add(1);
                }
            }
        }
    }
    for (k, &(normal, faint)) in drawn.iter().enumerate() {
        let (c, r) = (
            (k % usize::from(p.width)) as u16,
            (k / usize::from(p.width)) as u16,
        );
        let Some(out) = buf.cell_mut((p.x + c, p.y + r)) else {
            continue;
        };
        let on_cursor = cursor_col == Some(p.x + c);
        // A normal curve wins the cell; then the cursor; then a dim curve.
        let (want_dim, count) = match (normal, faint) {
            (0, 0) => (false, 0),
            (0, _) if on_cursor => (true, 0),
            (0, f) => (true, f),
            (m, _) => (false, m),
        };
        if count == 0 {
            if on_cursor {
                out.set_char(cursor).set_style(cursor_style);
            }
            continue;
        }
        // Curves sharing a cell take turns by column: both stay visible.
        let turn = usize::from(c) % usize::from(count);
        let src = layers
            .iter()
            .filter(|(faint, _)| *faint == want_dim)
            .filter_map(|(_, l)| l.content.get(k))
            .filter(|cell| cell.symbol() != " ")
            .nth(turn);
        if let Some(src) = src {
            out.set_symbol(src.symbol()).set_fg(src.fg);
            if src.bg != Color::Reset {
                out.set_bg(src.bg);
            }
        }
    }
    peaks(lay, buf, opts);
}

/// Series `i` (axis units) on a canvas over `area` of `buf`, its points
/// moved to the dots that land in the reference cells (see `Mapping::renorm`).
fn paint(
    lay: &Layout,
    d: &[(f64, f64)],
    i: usize,
    faint: bool,
    opts: &ChartOpts,
    area: Rect,
    buf: &mut Buffer,
) {
    let m = if faint {
        dim_marker(opts.ascii)
    } else {
        marker(i, opts.ascii)
    };
    let (kx, ky) = dots(m);
    let pts: Vec<(f64, f64)> = d
        .iter()
        .map(|&(x, y)| {
            let tx = lay.x.renorm(lay.x.norm(x), kx);
            let ty = lay.y.renorm(lay.y.norm(y), ky);
            (tx, 1.0 - ty)
        })
        .collect();
    let style = if faint {
        dim_style(opts.mono)
    } else {
        series_style(i, opts.mono)
    };
    let color = style.fg.unwrap_or(Color::Reset);
    Canvas::default()
        .marker(m)
        .x_bounds([0.0, 1.0])
        .y_bounds([0.0, 1.0])
        .paint(|ctx| {
            ctx.draw(&Points {
                coords: &pts,
                color,
            });
            for w in pts.windows(2) {
                ctx.draw(&CanvasLine::new(w[0].0, w[0].1, w[1].0, w[1].1, color));
            }
        })
        .render(area, buf);
}

/// The peak marks, over everything else.
fn peaks(lay: &Layout, buf: &mut Buffer, opts: &ChartOpts) {
    let peak = if opts.ascii { PEAK.1 } else { PEAK.0 };
    let peak_style = if opts.mono {
        Style::default()
    } else {
        Style::default().fg(Color::White)
    };
    for &(x, y) in &opts.marks {
        if let (Some(c), Some(r)) = (lay.column(x, opts.log_x), lay.row(y, opts.log_y)) {
            put(buf, c, r, &peak.to_string(), 1, peak_style);
        }
    }
}

/// A boxed legend at the top right of the plot: each series' glyph and
/// name, and the peak glyph; None when it would cover over 60 % of the
/// plot's width or height.
pub(super) struct Legend {
    pub area: Rect,
    rows: Vec<(String, Style, String)>,
    inner_w: u16,
}

/// Where the legend goes and what it lists (drawn by `legend`, after the
/// axis titles are placed around it).
pub(super) fn legend_box(
    lay: &Layout,
    series: &[Series],
    dim: &[bool],
    opts: &ChartOpts,
) -> Option<Legend> {
    if series.len() < 2 && opts.marks.is_empty() {
        return None;
    }
    let mut rows: Vec<(String, Style, String)> = series
        .iter()
        .enumerate()
        .filter(|(_, s)| !s.name.is_empty())
        .map(|(i, s)| {
            let (g, style) = if dim.get(i).copied().unwrap_or(false) {
                (dim_glyph(opts.ascii), dim_style(opts.mono))
            } else {
                (legend_glyph(i, opts.ascii), series_style(i, opts.mono))
            };
            (g.to_string(), style, s.name.clone())
        })
        .collect();
    if !opts.marks.is_empty() {
        let style = if opts.mono {
            Style::default()
        } else {
            Style::default().fg(Color::White)
        };
        rows.push((peak_glyph(opts.ascii).into(), style, "peak".into()));
    }
    let p = lay.plot;
    let inner_w = rows
        .iter()
        .map(|(_, _, n)| n.chars().count() + 2)
        .max()
        .unwrap_or(0) as u16;
    let (w, h) = (inner_w + 2, rows.len() as u16 + 2);
    if rows.is_empty()
        || u32::from(w) * 10 > u32::from(p.width) * 6
        || u32::from(h) * 10 > u32::from(p.height) * 6
    {
        return None;
    }
    let x = p.right() - w;
    // Below the y title when they would meet.
    let title_end = p.x + opts.y_title.chars().count() as u16;
    let y = if !opts.y_title.is_empty() && x <= title_end && h < p.height {
        p.y + 1
    } else {
        p.y
    };
    Some(Legend {
        area: Rect::new(x, y, w, h),
        rows,
        inner_w,
    })
}

/// Draws the legend over the plot.
pub(super) fn legend(l: &Legend, buf: &mut Buffer) {
    let area = l.area;
    for yy in area.top()..area.bottom() {
        for xx in area.left()..area.right() {
            if let Some(cell) = buf.cell_mut((xx, yy)) {
                cell.set_char(' ').set_fg(Color::Reset);
            }
        }
    }
    Block::bordered().render(area, buf);
    for (k, (g, style, name)) in l.rows.iter().enumerate() {
        let yy = area.y + 1 + k as u16;
        put(buf, area.x + 1, yy, g, 1, *style);
        put(buf, area.x + 3, yy, name, l.inner_w - 2, Style::default());
    }
}
