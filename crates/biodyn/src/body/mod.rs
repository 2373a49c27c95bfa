//! The body: rigid segments (masses m_i) joined to each other or to the seat
//! by Kelvin–Voigt links (a spring k and a damper c in parallel), their limits
//! and validation, and presets (TOML to and from a [`Body`](crate::Body)).
//!
//! The model types ([`Body`](crate::Body), [`Segment`](crate::Segment),
//! [`Link`](crate::Link), [`End`](crate::End), [`Param`](crate::Param),
//! [`Preset`](crate::Preset)) are re-exported at the crate root; this module
//! holds the paper's constants ([`PAPER_K`], [`PAPER_C`], [`PAPER_SHARES`],
//! [`PAPER_SEGMENTS`]), the limits, the shipped presets ([`SHIPPED`]) and the
//! errors.

pub(crate) mod limits;
pub(crate) mod model;
pub(crate) mod preset;
mod preset_error;

pub use limits::{MAX_C, MAX_K};
pub use model::{ModelError, PAPER_C, PAPER_K, PAPER_SEGMENTS, PAPER_SHARES};
pub use preset::{DEFAULT_NAME, Origin, SHIPPED, listed_presets};
pub use preset_error::PresetError;
