//! What can be wrong with a day file, one line each: the file, the line,
//! the operation (number and name), the field and its value, and the fix.

use super::hours::hours_text;
use super::meta::MetaError;
use crate::io::excerpt::located;

#[derive(Debug, thiserror::Error)]
pub enum DayError {
    #[error("{path}: cannot read the day file: {reason}")]
    Read { path: String, reason: String },
    /// toml's own message (an unknown key, a wrong type, bad syntax) at its
    /// line and column, with an excerpt of the line.
    #[error("{origin}:{line}:{col}: {message}")]
    Syntax {
        origin: String,
        line: usize,
        col: usize,
        message: String,
    },
    #[error(
        "{origin}:{line}: schema = {found}: this biodyn reads day files of schema {expected}; convert the file or use a matching biodyn"
    )]
    Schema {
        origin: String,
        line: usize,
        found: i64,
        expected: u32,
    },
    #[error("{origin}:{line}: {reason}")]
    Spine {
        origin: String,
        line: usize,
        reason: String,
    },
    #[error(
        "{origin}: no [[operation]] tables: a day file lists each operation with name, hours and aw_m_s2 = {{ x = …, y = …, z = … }} or record = \"FILE.csv\""
    )]
    NoOperations { origin: String },
    /// One operation's field (boxed: the other variants stay small).
    #[error(transparent)]
    Operation(Box<OperationError>),
    #[error(
        "{origin}: the operations' hours add up to {}, more than the 24 h of a day; split the file into days",
        hours_text(*.total_h)
    )]
    OverADay { origin: String, total_h: f64 },
    /// The `[report]` table's key, its value and the fix.
    #[error(transparent)]
    Report(MetaError),
    #[error("{path}: cannot save the day file: {reason} (the existing file, if any, is unchanged)")]
    Save { path: String, reason: String },
}

/// One operation's field, its value and the fix. `number` counts from 1,
/// as the file is read; `line` is None for what a record gave.
#[derive(Debug, Clone, PartialEq)]
pub struct OperationError {
    pub origin: String,
    pub line: Option<usize>,
    pub number: usize,
    pub name: String,
    pub field: String,
    pub value: Option<String>,
    pub fix: String,
}

impl std::fmt::Display for OperationError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.origin)?;
        if let Some(l) = self.line {
            write!(f, ":{l}")?;
        }
        write!(
            f,
            ": operation {} ('{}'): {}",
            self.number, self.name, self.field
        )?;
        if let Some(v) = &self.value {
            write!(f, " = {v}")?;
        }
        write!(f, ": {}", self.fix)
    }
}

impl std::error::Error for OperationError {}

/// A record operation that the caller's resolver could not read: the
/// operation and the record named, then the resolver's reason.
#[derive(Debug, thiserror::Error)]
pub enum EvalError<E> {
    #[error("{origin}: operation {number} ('{name}'): record = \"{record}\": {reason}")]
    Record {
        origin: String,
        number: usize,
        name: String,
        record: String,
        reason: E,
    },
    #[error(transparent)]
    Day(#[from] DayError),
}

/// A toml error at its line and column, the message bounded and the line
/// quoted.
pub(crate) fn syntax(text: &str, origin: &str, e: &toml::de::Error) -> DayError {
    let (line, col, m) = located(text, e.span().map(|s| s.start), e.message());
    DayError::Syntax {
        origin: origin.to_string(),
        line,
        col,
        message: m,
    }
}
