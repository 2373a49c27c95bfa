//! Why a spinal assessment (ISO 2631-5) cannot be made: the person's
//! description, or a record the method cannot judge.

use crate::io::excerpt::Short;

/// What is wrong, naming the key or the value (quoted, control characters
/// escaped) and the fix.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SpineError {
    #[error("spine: '{0}' is not key=value; give age=A,years=N,days=D,sex=male|female")]
    Part(String),
    #[error("spine: unknown key '{0}'; the keys are age, years, days, sex")]
    Key(String),
    #[error("spine: '{0}' is given twice")]
    Twice(String),
    #[error("spine: {} missing; give age=A,years=N,days=D,sex=male|female", missing_words(.0))]
    Missing(String),
    #[error("spine: {key} '{value}' is not a number")]
    Number { key: &'static str, value: String },
    #[error(
        "spine: age {} is out of range: the age the exposure starts at must be from 14 to under 100 years (ISO 2631-5 Annex C is for the adult working spine)",
        Short(*.0)
    )]
    Age(f64),
    #[error("spine: years '{0}' must be a whole number of years of exposure, at least 1")]
    Years(String),
    #[error("spine: days '{0}' must be a whole number of exposure days a year, 1 to 366")]
    Days(String),
    #[error("spine: sex '{0}' must be male or female (Annex C's constants differ)")]
    Sex(String),
    #[error(
        "spine: age {} plus {years} years passes 100: Annex C's strength model stops there; give fewer years",
        Short(*.age)
    )]
    PastMaxAge { age: f64, years: u32 },
    #[error(
        "spine: the record is {0} s long: too short for one shock (the spinal response rings for about 0.5 s); record at least 1 s"
    )]
    TooShort(f64),
    #[error(
        "spine: fs {} Hz is too low for ISO 2631-5: the seat-to-spine transfer reaches 67 Hz (420 rad/s) and a record's band 80 Hz, above fs/2; sample at 1000 Hz (at least 160 Hz)",
        Short(*.0)
    )]
    LowRate(f64),
    #[error(
        "spine: the seat's z acceleration has a mean of {mean:.4} m/s², {pct:.1} % of its largest spinal response peak: ISO 2631-5 §5.2 takes a conditioned record (mean removed, no gravity offset) and the transfer passes the mean unchanged; remove the mean and run again"
    )]
    Mean { mean: f64, pct: f64 },
}

fn missing_words(keys: &str) -> String {
    if keys.contains(',') {
        format!("{keys} are")
    } else {
        format!("{keys} is")
    }
}
