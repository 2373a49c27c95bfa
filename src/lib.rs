//! The biodyn front ends over the `biodyn` library: the headless command line
//! (`cli`) and the full-screen terminal app (`tui`). A library so that tests and
//! benches reach them by their normal paths; the `biodyn` binary is `main.rs`.

pub mod cli;
pub mod tui;
pub mod view;
