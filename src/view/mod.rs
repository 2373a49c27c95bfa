//! Presentation shared by both fronts, with no terminal I/O: the chart widget
//! (drawn into a ratatui buffer, by the TUI on screen and by `biodyn plot` as
//! text), number and label formatting, trend sentences, and the report
//! writers (table | csv | json) every command's output goes through.

pub mod axis;
pub mod chart;
pub mod envelope;
pub mod figure;
pub mod format;
pub mod glyph;
pub mod probe;
pub mod report;
pub mod trend;
