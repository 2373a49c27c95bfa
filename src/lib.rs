//! biodyn: biodynamics of the seated human body under vertical whole-body
//! vibration. The library holds the physics and the networks; it has no
//! terminal code and prints nothing. The `biodyn` binary's TUI and CLI are
//! thin front ends over it.

pub mod ann;
pub mod band;
pub mod model;
pub mod response;

pub use band::Band;
pub use model::{Body, End, Link, Param, Segment};
pub use response::{Function, Response, Solver};
pub mod modes;
pub mod peaks;
pub mod preset;
pub mod study;

pub use preset::Preset;
