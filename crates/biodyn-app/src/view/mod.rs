//! Presentation shared by both fronts, with no terminal I/O: the chart widget
//! (drawn into a ratatui buffer, by the TUI on screen and by `biodyn plot` as
//! text) and number and label formatting.

pub mod chart;
pub mod format;
