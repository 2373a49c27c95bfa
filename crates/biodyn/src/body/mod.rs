//! The body: segments, links, their limits and validation, and presets (TOML
//! to and from a [`Body`](model::Body)).

pub mod limits;
pub mod model;
pub mod preset;
pub mod preset_error;
