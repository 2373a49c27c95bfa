//! Every way a record can be refused: each names the file, and the line
//! and column where there is one.

use crate::io::ReadError;
use crate::io::excerpt::{excerpt, message, num, quote};
use crate::time::limits::{MAX_ACC, MAX_LINE};
use crate::time::{Axis, Channel, PointAxis, Unit};
use std::path::PathBuf;

/// Why a record cannot be read; each names the file, and the line and column
/// where there is one.
#[derive(Debug, thiserror::Error)]
pub enum RecordError {
    #[error(transparent)]
    Read(#[from] ReadError),
    #[error("{path}: line {line}: {}", message(.msg))]
    Csv {
        path: PathBuf,
        line: u64,
        msg: String,
    },
    #[error("{path}: the file is empty: it needs a header row, e.g. t_s,acc_m_s2")]
    NoHeader { path: PathBuf },
    #[error("{path}: no column named '{}'; the columns are {}", quote(.name), excerpt(.available, 160))]
    MissingColumn {
        path: PathBuf,
        name: String,
        available: String,
    },
    #[error(
        "{path}: no time column (t_s, t, time or time_s): give the sampling rate (fs), or add a t_s column"
    )]
    NeedFs { path: PathBuf },
    /// A header of one field that another separator splits: the record is
    /// not comma-separated.
    /// A first line of numbers only: the record has no header, and its
    /// first sample would be read as column names.
    #[error(
        "{path}: line 1 is numbers ({}), not a header: a record's first line names its columns, e.g. t_s,az_m_s2 (time in s, acceleration in m/s²) or t_ms,az_g; add one",
        excerpt(.first, 60)
    )]
    NumericHeader { path: PathBuf, first: String },
    /// The first column stands where time would, but its name says no time.
    #[error(
        "{path}: column '{}' stands first, where the time column goes, but its name says neither time nor its unit: name it t_s (seconds), t_ms or t_us, or give the sampling rate (fs) and say which columns are the axes",
        quote(.column)
    )]
    TimeUnknown { path: PathBuf, column: String },
    #[error(
        "{path}: time column '{}' is in '{}', a unit this reader does not know: write the time in s, ms or us and name the column t_s, t_ms or t_us",
        quote(.column),
        quote(.unit)
    )]
    TimeUnit {
        path: PathBuf,
        column: String,
        unit: String,
    },
    #[error(
        "{path}: column '{}' is in '{}', which is not a unit of acceleration this reader knows (m/s², g, mm/s²): convert the column, or rename it and give its unit",
        quote(.column),
        quote(.unit)
    )]
    UnknownUnit {
        path: PathBuf,
        column: String,
        unit: String,
    },
    #[error(
        "{path}: line 1: the header has no comma but {sep}: a record's columns are separated by commas; put commas in place of the {sep} (and decimal points for decimal commas)"
    )]
    Delimiter { path: PathBuf, sep: &'static str },
    #[error("{path}: line {line}, column '{}': '{}' is not a number", quote(.column), quote(.text))]
    Text {
        path: PathBuf,
        line: u64,
        column: String,
        text: String,
    },
    #[error(
        "{path}: line {line}, column '{}': {} is not a finite number (NaN or infinite)",
        quote(.column),
        quote(.text)
    )]
    NotFinite {
        path: PathBuf,
        line: u64,
        column: String,
        text: String,
    },
    #[error("{path}: line {line}: row has no column '{}' (too few fields)", quote(.column))]
    ShortRow {
        path: PathBuf,
        line: u64,
        column: String,
    },
    #[error("{path}: {rows} data row(s): a record needs at least two")]
    TooFewRows { path: PathBuf, rows: usize },
    #[error(
        "{path}: line {line}: time step {} s differs from the record's step {} s by more than 0.1 %: resample the record uniformly",
        num(*.step),
        num(*.expected)
    )]
    Uneven {
        path: PathBuf,
        line: u64,
        step: f64,
        expected: f64,
    },
    #[error(
        "{path}: line {line}: the first time step is {} s: time must increase, at a rate of at most 1e6 Hz",
        num(*.step)
    )]
    BadStep { path: PathBuf, line: u64, step: f64 },
    #[error(
        "{path}: the time column gives {} Hz but the sampling rate given is {} Hz: leave it out or fix it",
        num(*.file),
        num(*.given)
    )]
    FsMismatch {
        path: PathBuf,
        file: f64,
        given: f64,
    },
    #[error(
        "sampling rate {} Hz: it must be a finite number > 0 and at most 1e6",
        num(*.0)
    )]
    BadFs(f64),
    #[error("{path}: more than {cap} samples: split the record")]
    TooLong { path: PathBuf, cap: usize },
    #[error(
        "{path}: line {line} is over {} KiB: a record has one short row per line (is this a CSV file?)",
        MAX_LINE / 1024
    )]
    LineTooLong { path: PathBuf, line: u64 },
    #[error(
        "{path}: line {line}, column '{}': {} m/s² is over the {} m/s² cap (≈ 1000 g, beyond any seat vibration or shock): check the unit",
        quote(.column),
        num(*.value),
        num(MAX_ACC)
    )]
    TooLarge {
        path: PathBuf,
        line: u64,
        column: String,
        value: f64,
    },
    #[error(
        "{path}: acceleration columns {}, and no axis in the name of {}: say which column is which axis (x=COL,y=COL,z=COL), or name them x, y, z (ax, acc_x, x_m_s2) and the other points backrest_x, feet_z, rx …",
        excerpt(.columns, 100),
        excerpt(.unnamed, 50)
    )]
    Unnamed {
        path: PathBuf,
        columns: String,
        unnamed: String,
    },
    #[error(
        "{path}: columns '{}' and '{}' both name the {axis} axis: say which to read ({axis}=COL)",
        quote(.first),
        quote(.second)
    )]
    SameAxis {
        path: PathBuf,
        axis: Axis,
        first: String,
        second: String,
    },
    #[error(
        "{path}: column '{}' is in {suffix} by its name, but the unit given is {given}: leave the unit out or rename the column",
        quote(.column)
    )]
    UnitClash {
        path: PathBuf,
        column: String,
        suffix: Unit,
        given: Unit,
    },
    #[error(
        "{path}: columns '{}' and '{}' both name {channel}: say which to read ({channel}=COL)",
        quote(.first),
        quote(.second)
    )]
    SamePoint {
        path: PathBuf,
        channel: PointAxis,
        first: String,
        second: String,
    },
    #[error(
        "{path}: column '{}' is the rotation {channel}, in rad/s², but its name says {suffix}: name it {channel}_rad_s2 (or {channel})",
        quote(.column)
    )]
    RotationUnit {
        path: PathBuf,
        column: String,
        channel: PointAxis,
        suffix: Unit,
    },
    #[error(
        "{path}: column '{}' is {channel}, a linear acceleration, but its name says rad/s²: name it {channel}_m_s2 (or {channel}_g)",
        quote(.column)
    )]
    RadOnLinear {
        path: PathBuf,
        column: String,
        channel: PointAxis,
    },
    #[error("{path}: column '{}' is the time column: it cannot be the {axis} axis", quote(.column))]
    TimeAsAxis {
        path: PathBuf,
        column: String,
        axis: Channel,
    },
    #[error("{path}: column '{}' is given for both {first} and {second}", quote(.column))]
    ColumnTwice {
        path: PathBuf,
        column: String,
        first: Channel,
        second: Channel,
    },
    #[error("axes '{}': {why}; write AXIS=COLUMN pairs, e.g. x=ax,y=ay,z=az", quote(.spec))]
    BadAxes { spec: String, why: String },
    #[error(
        "{path}: no z (vertical) column, only {}: the body model is driven vertically; name the z column (z=COL)",
        .axes
    )]
    NoVertical { path: PathBuf, axes: String },
}
