//! Why a seat computation cannot be done; each names the field and value.

use crate::body::ModelError;
use crate::io::excerpt::num;

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SeatError {
    #[error(
        "the model has no seat: SEAT and the suspension's travel need a preset with a [seat] table (the shipped paper-75kg-suspension-seat has one)"
    )]
    NoSeat,
    #[error("{path}: {why}")]
    Read { path: String, why: String },
    #[error("{path}: no rows: a PSD file has a header f_hz,psd_m2_s4_hz and at least two rows")]
    Empty { path: String },
    #[error(
        "{path}, line {line}: the header is '{found}': a PSD file starts with f_hz,psd_m2_s4_hz"
    )]
    Header {
        path: String,
        line: usize,
        found: String,
    },
    #[error("{path}, line {line}: {field} = '{value}' {why}")]
    Field {
        path: String,
        line: usize,
        field: &'static str,
        value: String,
        why: String,
    },
    #[error(
        "{path}, line {line}: f_hz = {} is not above the row before ({} Hz): frequencies must rise strictly; sort the file",
        num(*.f_hz), num(*.before)
    )]
    Unsorted {
        path: String,
        line: usize,
        f_hz: f64,
        before: f64,
    },
    #[error("{path}: {rows} row(s): a PSD needs at least two frequencies")]
    TooFew { path: String, rows: usize },
    #[error("{path}: every density is 0: the floor does not move, so SEAT is undefined")]
    Silent { path: String },
    #[error(
        "the floor's weighted r.m.s. is 0 over {} to {} Hz: SEAT is undefined",
        num(*.from_hz), num(*.to_hz)
    )]
    NoWeightedInput { from_hz: f64, to_hz: f64 },
    #[error(
        "the PSD's rows span {} to {} Hz, outside the 0.1 to 1000 Hz a seat's figures are integrated over (|W_k| is under 0.032 below and 1.3e-4 above)",
        num(*.from_hz), num(*.to_hz)
    )]
    OutsideRange { from_hz: f64, to_hz: f64 },
    #[error(
        "{what} did not settle to 1e-6 on the finest frequency grid (a step of 8e-5 in ln f): the model has a resonance too sharp to integrate"
    )]
    Unresolved { what: &'static str },
    #[error("'{name}' cannot be varied: {why}")]
    BadVary { name: String, why: String },
    #[error(
        "'{name}' is varied from {} to {}: the box needs 0 < LO < HI",
        num(*.lo), num(*.hi)
    )]
    BadRange { name: String, lo: f64, hi: f64 },
    #[error("'{0}' is varied twice: give each parameter once")]
    VariedTwice(String),
    #[error("{count} parameters are varied: the search and its map take one or two")]
    TooManyVaried { count: usize },
    #[error("no parameter is varied: give one or two")]
    NothingVaried,
    #[error(
        "the r.m.s. travel limit is {} m: it must be finite and > 0",
        num(*.0)
    )]
    BadLimit(f64),
    #[error(
        "no point of the box keeps the r.m.s. travel within {} m: the least is {} m, at {at}; widen the box or raise the limit",
        num(*.limit), num(*.least)
    )]
    Infeasible { limit: f64, least: f64, at: String },
    #[error("{name} = {}: {source}", num(*.value))]
    Model {
        name: String,
        value: f64,
        source: Box<ModelError>,
    },
}
