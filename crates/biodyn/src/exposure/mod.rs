//! Daily exposure to whole-body vibration over a working day (SPEC §9;
//! Directive 2002/44/EC Annex B; UK SI 2005/1093 Schedule 2; the HSE
//! whole-body vibration calculator).
//!
//! - [`AxisExposure`]: one operation on one axis: k·a_w, the partial
//!   A(8) = k·a_w·√(T/8 h), points = 100·(A(8)/0.5)², the hours to reach
//!   the action and limit values 8 h·(V/(k·a_w))², the VDV over the
//!   operation k·VDV·(T/T_meas)^¼.
//! - [`Day`]: per axis A(8) = √(Σ A_i(8)²), points Σ, VDV (Σ VDV_i⁴)^¼;
//!   the day's exposure is the highest axis, with the EU verdicts; a VDV
//!   missing from an operation leaves the known part as a lower bound
//!   ([`DayVdv`]).
//!   [`Week`]: A(8)week = √(⅕ Σ A(8)_day²).
//! - [`DayFile`]: the TOML day file, read, checked, saved; record
//!   operations are evaluated through a resolver the caller supplies;
//!   [`measure_record`] is the one that reads the record.
//! - [`parse_hours`], [`hours_text`]: hours as people write them (`6:30`,
//!   `6h30`, `45min`), read and printed once for every front.
//! - [`Meta`]: who, where, when, with what: a report's details.
//! - [`DaySpine`]: with a person in the day file, ISO 2631-5's daily dose of
//!   every operation's z dose (Formula 5) and Annex C's risk.

mod caps;
mod day;
mod error;
mod evaluate;
mod file;
mod hours;
mod meta;
mod operation;
mod parse;
mod reach;
mod record;
mod spine;
mod week;

pub use caps::{MAX_AW, MAX_DZ, MAX_MEASURED_S, MAX_RECORD_FS, MAX_VDV, MIN_MEASURED_S};
pub use day::{AxisDay, Day, DayVdv, Operation};
pub use error::{DayError, EvalError, OperationError};
pub use file::{
    DayFile, MAX_DAY_H, MAX_OPERATION_NAME, OperationSpec, RecordSource, SCHEMA, Source, axes_text,
    parse_axes,
};
pub use hours::{
    HOURS_FORMS, HOURS_TOLERANCE, HoursError, MAX_HOURS, check_hours, hours_text, parse_hours,
};
pub use meta::{MAX_META, MAX_NOTES, META_KEYS, Meta, MetaError};
pub use operation::{AxisExposure, Measured, partial_a8};
pub use reach::{AxisReach, REFERENCE_H, VdvHours, hours_to_reach, hours_to_reach_vdv, points};
pub use record::{MeasureError, measure_record, measure_record_noted};
pub use spine::{DaySpine, DoseOverflow, SpinePart};
pub use week::{MAX_DAYS, Week};
