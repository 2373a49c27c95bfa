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

pub use super::glyph::{
    asciify, cursor_glyph, dim_glyph, dim_style, legend_glyph, peak_glyph, series_style,
};
pub use layout::{Layout, layout};
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::widgets::Widget;

/// One named curve.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    pub name: String,
    pub points: Vec<(f64, f64)>,
}

/// How a series stands out among the others.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Emphasis {
    /// Its own colour and marker, by its index (glyph.rs).
    #[default]
    Normal,
    /// A reference laid under the others (a compared model): dark grey and
    /// `·` (`.` in ASCII); where it meets a normal series or the cursor in
    /// a cell, they win.
    Dim,
}

/// Everything about a chart except its data.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ChartOpts {
    pub title: String,
    pub x_title: String,
    pub y_title: String,
    pub log_x: bool,
    pub log_y: bool,
    /// Plain ASCII glyphs only.
    pub ascii: bool,
    /// No colours at all (NO_COLOR, or plain text output).
    pub mono: bool,
    /// A vertical line at this x (the frequency cursor).
    pub cursor_x: Option<f64>,
    /// Points to mark (peaks), drawn on top and named "peak" in the legend.
    pub marks: Vec<(f64, f64)>,
    /// Fixed y range in data units; None autoscales with padding (from 0
    /// when every value is ≥ 0: a magnitude axis never goes negative).
    pub y_range: Option<(f64, f64)>,
}

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
    draw::titles(&lay, buf, opts);
    draw::legend(&lay, buf, series, &dim, opts);
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
