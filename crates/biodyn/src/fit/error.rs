//! Why a fit could not run. Data errors name the file, the line and the
//! column; parameter errors name the parameter and the value.

use crate::body::model::ModelError;
use crate::freq::function::Function;
use crate::io::ReadError;

/// The data columns a file may hold, as they appear in the message texts:
/// each function's magnitude and phase column, in table order (the order
/// of `Channel::ALL`), joined by ", ". Built from the table at compile time.
pub const KNOWN: &str = match std::str::from_utf8(&KNOWN_BYTES) {
    Ok(s) => s,
    Err(_) => panic!("the column names are UTF-8"),
};

/// Column `k` of [`KNOWN`]: function `k / 2`, magnitude then phase.
const fn column(k: usize) -> &'static str {
    let f = Function::ALL[k / 2];
    if k % 2 == 0 {
        f.mag_column()
    } else {
        f.phase_column()
    }
}

const SEPARATOR: &[u8] = b", ";

const KNOWN_LEN: usize = {
    let mut n = 0;
    let mut k = 0;
    while k < 2 * Function::ALL.len() {
        if k > 0 {
            n += SEPARATOR.len();
        }
        n += column(k).len();
        k += 1;
    }
    n
};

const KNOWN_BYTES: [u8; KNOWN_LEN] = {
    let mut out = [0; KNOWN_LEN];
    let mut at = 0;
    let mut k = 0;
    while k < 2 * Function::ALL.len() {
        let mut j = 0;
        while k > 0 && j < SEPARATOR.len() {
            out[at] = SEPARATOR[j];
            at += 1;
            j += 1;
        }
        let c = column(k).as_bytes();
        let mut j = 0;
        while j < c.len() {
            out[at] = c[j];
            at += 1;
            j += 1;
        }
        k += 1;
    }
    out
};

/// A measured-data file that cannot be used, with the place of the problem.
#[derive(Debug, thiserror::Error)]
pub enum DataError {
    #[error(transparent)]
    Read(#[from] ReadError),
    #[error(
        "{path}: the file is empty; its first line must be a header such as f_hz,apms_mag,apms_phase_deg"
    )]
    Empty { path: String },
    #[error("{path}: line {line}: {message}")]
    Csv {
        path: String,
        line: u64,
        message: String,
    },
    #[error("{path}: line 1: no f_hz column; the header needs f_hz and at least one of {known}", known = KNOWN)]
    NoFrequency { path: String },
    #[error("{path}: line 1, column {col}: unknown column '{name}'; known: f_hz, {known} and <column>_sd", known = KNOWN)]
    UnknownColumn {
        path: String,
        col: usize,
        name: String,
    },
    #[error(
        "{path}: line 1: the columns are separated by {sep}; save the file as comma-separated values"
    )]
    Separator { path: String, sep: &'static str },
    #[error("{path}: line 1, column {col}: column '{name}' appears twice")]
    Duplicate {
        path: String,
        col: usize,
        name: String,
    },
    #[error(
        "{path}: line 1, column {col}: '{name}' weights a column '{base}' the file does not have"
    )]
    OrphanSd {
        path: String,
        col: usize,
        name: String,
        base: String,
    },
    #[error("{path}: line {line}, column {col} ({name}): '{text}' is not a finite number")]
    NotNumber {
        path: String,
        line: u64,
        col: usize,
        name: String,
        text: String,
    },
    #[error(
        "{path}: line {line}, column {col} (f_hz): the frequency is empty; every row needs one"
    )]
    MissingFrequency { path: String, line: u64, col: usize },
    #[error("{path}: line {line}, column {col} (f_hz): {} Hz; a frequency must be from {} to {} Hz (the physical limits of a band)", crate::io::excerpt::num(*.value), crate::io::excerpt::num(crate::band::MIN_HZ), crate::io::excerpt::num(crate::band::MAX_HZ))]
    BadFrequency {
        path: String,
        line: u64,
        col: usize,
        value: f64,
    },
    #[error(
        "{path}: line {line}, column {col} (f_hz): {} Hz does not exceed the previous row's {} Hz; frequencies must increase", crate::io::excerpt::num(*.value), crate::io::excerpt::num(*.previous)
    )]
    NotIncreasing {
        path: String,
        line: u64,
        col: usize,
        value: f64,
        previous: f64,
    },
    #[error(
        "{path}: line {line}, column {col} ({name}): magnitude {} is not > 0; ln|H| is fitted, so leave the cell empty if it was not measured", crate::io::excerpt::num(*.value)
    )]
    BadMagnitude {
        path: String,
        line: u64,
        col: usize,
        name: String,
        value: f64,
    },
    #[error("{path}: line {line}, column {col} ({name}): standard deviation {} is not > 0", crate::io::excerpt::num(*.value))]
    BadSd {
        path: String,
        line: u64,
        col: usize,
        name: String,
        value: f64,
    },
    #[error(
        "{path}: line {line}, column {col} ({name}): empty, but {base} has a value on this line; give every weighted value its standard deviation"
    )]
    MissingSd {
        path: String,
        line: u64,
        col: usize,
        name: String,
        base: String,
    },
    #[error("{path}: no data rows below the header")]
    NoRows { path: String },
    #[error("{path}: no usable column: none of {known} has a value", known = KNOWN)]
    NoColumn { path: String },
}

/// Everything else that stops a fit before or after it runs.
#[derive(Debug, thiserror::Error)]
pub enum FitError {
    #[error(transparent)]
    Data(#[from] DataError),
    #[error("no parameter is free: free at least one")]
    EmptyFree,
    #[error(
        "the model has a seat under the body: fitting refers the body's functions to the floor's motion, not the pan's; fit the body on a rigid seat (a preset without [seat])"
    )]
    SeatModel,
    #[error("{name}: the model has no such parameter")]
    NotInModel { name: String },
    #[error("link {}: the model has no such link", .index + 1)]
    NoSuchLink { index: usize },
    #[error(
        "{name}: it is {} in the start model; the fit works on ln {name}, so the start must be > 0",
        crate::io::num(*.value)
    )]
    ZeroStart { name: String, value: f64 },
    #[error(
        "body-mass and {mass} are both free; body-mass scales every segment mass, so free either body-mass or single masses"
    )]
    MassTwice { mass: String },
    #[error("body-mass: the model gives no body mass; free single masses")]
    NoBodyMass,
    #[error(
        "body-mass: segment '{segment}' has no share of body mass, so body mass cannot scale it; free single masses instead"
    )]
    NoShare { segment: String },
    #[error(
        "body-mass: segment '{segment}' has {mass} kg, not its share {share} × {body_mass} kg; free single masses instead"
    )]
    OffShare {
        segment: String,
        mass: f64,
        share: f64,
        body_mass: f64,
    },
    #[error("bound on {name}: {name} is not a free parameter")]
    BoundNotFree { bound: usize, name: String },
    #[error("bound on {name}: {name} is bounded twice; give one bound per parameter")]
    BoundTwice { bound: usize, name: String },
    #[error("bound on {name}: {} is not a number > 0 (parameters are positive)", crate::io::num(*.value))]
    BadBound {
        bound: usize,
        name: String,
        value: f64,
    },
    #[error("bound on {name}: {} is above the model's limit {} {unit}", crate::io::num(*.hi), crate::io::num(*.max))]
    AboveLimit {
        bound: usize,
        name: String,
        hi: f64,
        max: f64,
        unit: &'static str,
    },
    #[error("bound on {name}: {} is below the model's floor {} {unit}", crate::io::excerpt::num(*.lo), crate::io::excerpt::num(*.min))]
    BelowLimit {
        bound: usize,
        name: String,
        lo: f64,
        min: f64,
        unit: &'static str,
    },
    #[error("bound on {name}: the box [{}, {}] is empty; give both ends", crate::io::num(*.lo), crate::io::num(*.hi))]
    EmptyBox {
        bound: usize,
        name: String,
        lo: f64,
        hi: f64,
    },
    #[error(
        "{path}: {values} measured values for {params} free parameters; a fit needs more values than free parameters"
    )]
    TooFewValues {
        path: String,
        values: usize,
        params: usize,
    },
    #[error("the model has {n} segments; fits take at most {max}")]
    TooBig { n: usize, max: usize },
    #[error("fit starts {starts}: give between 1 and {max}")]
    BadStarts { starts: usize, max: usize },
    #[error("the fitted model is not valid: {0}")]
    Model(#[from] ModelError),
    #[error(
        "{path}: the model cannot be solved at these frequencies from any start (an undamped resonance on a data point?)"
    )]
    Unsolvable { path: String },
    #[error("the fit was cancelled")]
    Cancelled,
}
