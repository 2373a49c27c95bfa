//! ISO 2631-1 whole-body vibration assessment (SPEC §7).
//!
//! - [`Weighting`], [`WeightingFilter`], [`WEIGHTINGS`]: the eight
//!   whole-body weightings of ISO 8041-1 (Wb, Wc, Wd, We, Wf, Wj, Wk, Wm) as
//!   the analog formula and as digital filters that hold the analog |W|
//!   within 0.1 % over each band at fs ≥ 1000 Hz; their table of parameters,
//!   bands, quantities and purposes.
//! - [`Metrics`], [`Accumulator`], [`Exposure`]: a_w = (1/T ∫ a_w(t)² dt)^½,
//!   peak, crest factor, MTVV (the largest 1 s running r.m.s.),
//!   VDV = (∫ a_w(t)⁴ dt)^¼; the daily exposure A(8) = a_w (T/8 h)^½ and VDV
//!   over the exposure.
//! - [`Verdict`], [`Eu`], [`comfort`], [`additional_methods`]: EU 2002/44/EC
//!   action and limit values ([`A8_ACTION`], [`A8_LIMIT`], [`VDV_ACTION`],
//!   [`VDV_LIMIT`]), Annex C comfort words, the checks that call for the
//!   additional methods.
//! - [`BandBank`], [`band_centres`]: one-third-octave band r.m.s., 0.5–80 Hz.
//! - [`POINTS`], [`PointsAccumulator`], [`PointsComfort`]: comfort at the
//!   backrest, the feet and the seat's rotations (§8.2.2, Table 1), each
//!   point's vibration total value and the overall one (§8.2.3).
//! - [`assess`]: all of it over a simulated body in one streaming pass.

mod assess;
mod axes;
mod axes_only;
mod bands;
mod judgeable;
mod metrics;
mod per_axis;
mod points;
mod power_sum;
mod sickness;
pub mod spine;
mod verdict;
mod weighting;

pub use assess::{
    AssessError, Assessment, BandLevel, Channel, MAX_EXPOSURE_H, MIN_RECORD_S, SeatValue, Stroke,
    assess, assess_axes, assess_points, assess_with,
};
pub use axes::{AXES, AxisRule, rule};
pub use axes_only::{AxesAssessment, assess_axes_only};
pub use bands::{BandBank, band_centres};
pub use judgeable::{
    JudgeError, Mean, OFFSET_NOTED, OFFSET_REFUSED, OUT_OF_BAND_FS, OUT_OF_BAND_SHARE, OffsetShare,
    check_band, check_offset, check_rate, offset_share, step_energies,
};
pub use metrics::{Accumulator, Exposure, Metrics};
pub use per_axis::{AxesAccumulator, AxisResult, Health, vector_sum};
pub use points::{
    POINTS, PointAxisComfort, PointComfort, PointRule, PointsAccumulator, PointsComfort, Sample,
    point_rule, total_value,
};
pub use power_sum::{PowerSum, power_root};
pub use sickness::{K_M, MIN_SICKNESS_S, Sickness, SicknessAccumulator, VOMIT_PCT_MAX};
pub use verdict::{
    A8_ACTION, A8_LIMIT, Eu, VDV_ACTION, VDV_LIMIT, Verdict, above, additional_methods, comfort,
};
pub use weighting::{
    Definition as WeightingDefinition, Params as WeightingParams, Quantity, Step as WeightingStep,
    TABLE as WEIGHTINGS, Weighting, WeightingFilter,
};
