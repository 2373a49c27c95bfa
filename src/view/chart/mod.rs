//! Response charts, shared by the TUI tabs and `biodyn plot` so that both
//! look alike.
//!
//! ratatui's Chart has no log axis, no autoscale, and spreads its axis
//! labels evenly whatever they say; so the axes are drawn here. Data are
//! transformed (log10 on request), bounds are padded to round numbers so
//! the axes do not jump (a magnitude axis starts at 0), and each tick is a
//! round number drawn in the cell its value maps to, by the same rule as
//! the data points (see `axis`). The curves themselves go through ratatui's
//! Canvas, one series at a time, and are laid together so that none hides
//! another entirely: where curves share a cell, the cells alternate between
//! them. Each series has its own marker as well as its own colour, so
//! meaning never rides on colour alone; `ascii` gives every series, the
//! cursor and the peaks their own plain ASCII glyph. A series can be drawn
//! dimmed (`Emphasis::Dim`, a compared model): grey and a light glyph of
//! its own, beneath the cursor and every other curve.

mod draw;
mod layout;
mod opts;
mod titles;

pub use super::glyph::{
    asciify, cursor_glyph, dim_glyph, dim_style, legend_glyph, peak_glyph, series_style,
};
pub use layout::{Layout, layout};
pub use opts::{ChartOpts, Emphasis, Series};
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::widgets::Widget;
pub use titles::place as place_titles;

/// Draws the chart into `buf` over `area`, every series normal.
pub fn render(area: Rect, buf: &mut Buffer, series: &[Series], opts: &ChartOpts) {
    render_with(area, buf, series, &[], opts);
}

/// `render` with series `i` drawn as `emphasis[i]` (normal past its end).
pub fn render_with(
    area: Rect,
    buf: &mut Buffer,
    series: &[Series],
    emphasis: &[Emphasis],
    opts: &ChartOpts,
) {
    if area.width < 10 || area.height < 5 {
        return;
    }
    layout::frame(area, opts).render(area, buf);
    let data = layout::transformed(series, opts);
    let Some(lay) = layout::layout_of(area, &data, opts) else {
        if opts.ascii {
            asciify(area, buf);
        }
        return;
    };
    draw::axes(&lay, buf, opts);
    let dim: Vec<bool> = (0..series.len())
        .map(|i| emphasis.get(i) == Some(&Emphasis::Dim))
        .collect();
    draw::data(&lay, buf, &data, &dim, opts);
    let legend = draw::legend_box(&lay, series, &dim, opts);
    let avoid: Vec<Rect> = legend.iter().map(|l| l.area).collect();
    let cursor = opts
        .cursor_x
        .and_then(|c| lay.column(c, opts.log_x))
        .map(|c| {
            let g = super::glyph::CURSOR;
            (c, if opts.ascii { g.1 } else { g.0 })
        });
    titles::place(
        lay.plot,
        buf,
        (&opts.x_title, &opts.y_title),
        &avoid,
        cursor,
    );
    if let Some(l) = &legend {
        draw::legend(l, buf);
    }
    if opts.ascii {
        asciify(area, buf);
    }
}

/// The buffer as text lines, trailing blanks trimmed: for `biodyn plot` and
/// for snapshot tests.
pub fn buffer_text(buf: &Buffer) -> Vec<String> {
    let area = buf.area;
    (area.top()..area.bottom())
        .map(|y| {
            let mut line = String::new();
            for x in area.left()..area.right() {
                if let Some(c) = buf.cell((x, y)) {
                    line.push_str(c.symbol());
                }
            }
            line.trim_end().to_string()
        })
        .collect()
}

#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_dim;
