//! What a figure is: panels of curves, measured points, bars and marks on
//! two axes. Its own file, so the drawing (`draw.rs`) and the builders
//! take the types from a sibling, not from the `mod.rs` that uses them.

use super::style::{Fill, Look};

/// One axis of a panel.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Axis {
    pub title: String,
    pub log: bool,
    /// Start a linear axis at 0 when every value is ≥ 0 (a magnitude).
    pub floor_zero: bool,
    /// A categorical axis: category i sits at i, labelled `names[i]`, and
    /// the numeric ticks give way to the names (input classes, operations).
    pub names: Vec<String>,
}

/// One line through its points, in order.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    pub name: String,
    pub points: Vec<(f64, f64)>,
    pub look: Look,
}

/// Measured values: (x, y, standard deviation where known).
#[derive(Debug, Clone, PartialEq)]
pub struct Points {
    pub name: String,
    pub points: Vec<(f64, f64, Option<f64>)>,
}

/// Bars from 0: (x from, x to, height), e.g. one-third-octave bands.
#[derive(Debug, Clone, PartialEq)]
pub struct Bars {
    pub name: String,
    pub bars: Vec<(f64, f64, f64)>,
    pub fill: Fill,
}

/// Filled rectangles (x from, x to, y from, y to): a map's cells, one set
/// per shade. A panel with cells has its key beside the plot, not over it
/// (a map fills every corner).
#[derive(Debug, Clone, PartialEq)]
pub struct Cells {
    pub name: String,
    pub cells: Vec<(f64, f64, f64, f64)>,
    pub fill: Fill,
}

/// One chart of a figure.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Panel {
    pub title: String,
    pub x: Axis,
    pub y: Axis,
    pub curves: Vec<Curve>,
    pub points: Vec<Points>,
    pub bars: Vec<Bars>,
    pub cells: Vec<Cells>,
    /// Points marked on top (peaks), named `marks_name` in the legend.
    pub marks: Vec<(f64, f64)>,
    pub marks_name: String,
}

/// Panels in a grid of `columns`, row by row, each `panel_px` in size.
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    pub panels: Vec<Panel>,
    pub columns: usize,
    pub panel_px: (u32, u32),
}

/// Sizes a figure is drawn at, pixels (1 px = 1/96 in: 800 px ≈ 21 cm).
pub const WIDTH_PX: std::ops::RangeInclusive<u32> = 200..=4000;
pub const HEIGHT_PX: std::ops::RangeInclusive<u32> = 150..=4000;

/// A single panel's default size.
pub const PANEL_PX: (u32, u32) = (800, 500);

impl Figure {
    /// One panel at `size`.
    pub fn single(panel: Panel, size: (u32, u32)) -> Figure {
        Figure {
            panels: vec![panel],
            columns: 1,
            panel_px: size,
        }
    }

    /// The whole figure's size in pixels.
    pub fn size(&self) -> (u32, u32) {
        let cols = self.columns.max(1);
        let rows = self.panels.len().div_ceil(cols).max(1);
        (
            self.panel_px.0.saturating_mul(cols as u32),
            self.panel_px.1.saturating_mul(rows as u32),
        )
    }
}
