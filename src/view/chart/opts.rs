//! What a chart draws and by what: its series, how each stands out, and
//! its options. Its own file, so the chart's parts (`draw.rs`,
//! `layout.rs`) take them from a sibling, not from the `mod.rs` that uses
//! them; `mod.rs` re-exports them, so `view::chart::Series` stays.

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
