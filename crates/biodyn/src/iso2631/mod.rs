//! ISO 2631-1 whole-body vibration assessment (SPEC §7).
//!
//! - [`weighting`]: Wk, Wd, Wf as the analog formula and as digital filters
//!   that hold the analog |W| within 1 % from 0.5 to 80 Hz at fs ≥ 1000 Hz.
//! - [`metrics`]: a_w, peak, crest factor, MTVV, VDV; A(8) and VDV over an exposure.
//! - [`verdict`]: EU 2002/44/EC action and limit values, Annex C comfort
//!   words, the checks that call for the additional methods.
//! - [`bands`]: one-third-octave band r.m.s., 0.5–80 Hz.
//! - [`assess`]: all of it over a simulated body in one streaming pass.

pub mod assess;
pub mod bands;
pub mod metrics;
pub mod verdict;
pub mod weighting;

pub use assess::{AssessError, Assessment, BandLevel, Channel, assess};
pub use metrics::{Accumulator, Exposure, Metrics};
pub use verdict::{Eu, Verdict, comfort};
pub use weighting::{Weighting, WeightingFilter};
