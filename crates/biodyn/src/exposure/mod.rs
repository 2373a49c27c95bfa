//! Daily exposure to whole-body vibration over a working day (SPEC §9;
//! Directive 2002/44/EC Annex B; UK SI 2005/1093 Schedule 2; the HSE
//! whole-body vibration calculator).
//!
//! - [`AxisExposure`]: one operation on one axis: k·a_w, the partial
//!   A(8) = k·a_w·√(T/8 h), points = 100·(A(8)/0.5)², the hours to reach
//!   the action and limit values 8 h·(V/(k·a_w))², the VDV over the
//!   operation k·VDV·(T/T_meas)^¼.
//! - [`Day`]: per axis A(8) = √(Σ A_i(8)²), points Σ, VDV (Σ VDV_i⁴)^¼;
//!   the day's exposure is the highest axis, with the EU verdicts.
//!   [`Week`]: A(8)week = √(⅕ Σ A(8)_day²).
//! - [`DayFile`]: the TOML day file, read, checked, saved; record
//!   operations are evaluated through a resolver the caller supplies;
//!   [`measure_record`] is the one that reads the record.
//! - [`DaySpine`]: with a person in the day file, ISO 2631-5's daily dose of
//!   every operation's z dose (Formula 5) and Annex C's risk.

mod day;
mod error;
mod evaluate;
mod file;
mod operation;
mod parse;
mod record;
mod spine;

pub use day::{AxisDay, Day, MAX_DAYS, Operation, Week};
pub use error::{DayError, EvalError, OperationError};
pub use file::{
    DayFile, MAX_DAY_H, MAX_OPERATION_NAME, OperationSpec, RecordSource, SCHEMA, Source, axes_text,
    parse_axes,
};
pub use operation::{AxisExposure, Measured, REFERENCE_H, hours_to_reach, partial_a8, points};
pub use record::measure_record;
pub use spine::{DaySpine, DoseOverflow, SpinePart};
