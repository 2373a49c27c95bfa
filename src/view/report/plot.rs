//! `biodyn plot`'s text, built in one place so that the command and the
//! TUI's Responses export (`x`, a `.txt` name) print the same bytes for the
//! same model, band, function and axes.

use crate::view::chart::{self, ChartOpts, Series};
use crate::view::format::axis_title;
use biodyn::{Function, Response};
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;

/// Width and height of a chart exported as text: `biodyn plot`'s size in a pipe.
pub const PLOT_WIDTH: u16 = 100;
pub const PLOT_HEIGHT: u16 = 30;

/// How a chart is drawn as text (`biodyn plot`'s options).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PlotText {
    pub function: Function,
    pub log_x: bool,
    pub log_y: bool,
    pub ascii: bool,
    pub width: u16,
    pub height: u16,
}

/// One function of a sweep as a chart series: magnitudes, or phases in degrees.
pub fn series(name: &str, curve: &[Response], o: &PlotText, phase: bool) -> Series {
    curve_series(name, curve, o.function, phase)
}

/// `f`'s magnitudes (or phases, degrees) over a sweep, named `name`.
pub fn curve_series(name: &str, curve: &[Response], f: Function, phase: bool) -> Series {
    Series {
        name: name.to_string(),
        points: curve
            .iter()
            .map(|r| (r.f_hz, if phase { r.phase_deg(f) } else { r.mag(f) }))
            .collect(),
    }
}

/// The chart of `o.function` with `series` and the peaks `marks`, as the
/// lines of text `biodyn plot` prints (monochrome; a trailing newline).
pub fn chart_text(series: &[Series], marks: Vec<(f64, f64)>, phase: bool, o: &PlotText) -> String {
    chart_text_with(series, &[], marks, phase, o)
}

/// `chart_text` with series `i` drawn as `emphasis[i]` (a compared model dim).
pub fn chart_text_with(
    series: &[Series],
    emphasis: &[chart::Emphasis],
    marks: Vec<(f64, f64)>,
    phase: bool,
    o: &PlotText,
) -> String {
    let f = o.function;
    let opts = ChartOpts {
        title: format!(" {} — {} ", f.name(), f.long_name()),
        x_title: "f (Hz)".into(),
        y_title: axis_title(f, phase),
        log_x: o.log_x,
        log_y: o.log_y,
        ascii: o.ascii,
        mono: true,
        marks,
        ..Default::default()
    };
    let area = Rect::new(0, 0, o.width, o.height);
    let mut buf = Buffer::empty(area);
    chart::render_with(area, &mut buf, series, emphasis, &opts);
    let mut text = chart::buffer_text(&buf).join("\n");
    text.push('\n');
    text
}
