//! Figures for a paper: the same data the TUI's charts and `biodyn plot`
//! draw as text, written as plain SVG 1.1 through plotters' SVG backend.
//!
//! A figure is a grid of panels; a panel has two axes (linear or log, round
//! ticks from `view::axis`, the same rule as the text charts), curves (each
//! with its own colour *and* dash pattern, so it reads in black and white),
//! measured points with their standard deviations as error bars, bars (the
//! one-third-octave bands) and marked points (peaks). The SVG has absolute
//! coordinates only: no `transform` (the y title is written level, above
//! the axis), no scripts, fonts by generic family; `read` reads one back.

pub mod assess;
pub mod day;
pub mod design;
mod draw;
mod key;
mod legend;
mod model;
pub mod read;
pub mod response;
pub mod seat;
mod style;

pub use model::{Axis, Bars, Cells, Curve, Figure, HEIGHT_PX, PANEL_PX, Panel, Points, WIDTH_PX};
pub use style::{Fill, Look};
