//! The terminal app: the real binary in a real terminal (tmux), and the
//! real `update` driven by keys and mouse events with its exports compared
//! byte for byte with the binary's output. One test binary.

#[path = "../common/mod.rs"]
mod common;

/// Keys into the real `update`, and the real binary beside it.
mod drive;
/// The Responses tab's export against `biodyn response` and `biodyn plot`.
mod responses_export;
/// The Seat and Day tabs' figures against `biodyn seat` and `biodyn day --plot`.
mod seat_day_export;
/// The Study tab's export, the band editor and the mouse.
mod study_band_mouse;
/// Start, edit, quit, signals and refusals in tmux.
mod terminal;
/// The mouse on the Model tab in tmux.
mod terminal_mouse;
/// The Vibration tab's export against `biodyn simulate`.
mod vibration_export;
