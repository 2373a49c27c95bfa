//! Preset errors, and placing a toml error at its line and column with a
//! bounded excerpt of that line.

use crate::band::BandError;
use crate::body::model::ModelError;
/// Shared with the day files; the preset code names it from here.
pub(crate) use crate::io::excerpt::line_col;
use crate::io::excerpt::{located, message};

#[derive(Debug, thiserror::Error)]
pub enum PresetError {
    #[error("{path}: cannot read: {source}")]
    Read {
        path: String,
        #[source]
        source: std::io::Error,
    },
    #[error("{path}: is a directory; give the path of a .toml preset file")]
    IsDir { path: String },
    #[error("{path}: the file is empty; a preset needs [[segment]] and [[link]] tables")]
    Empty { path: String },
    #[error("{path}: not a text file (binary data at byte {offset}); a preset is UTF-8 TOML")]
    Binary { path: String, offset: usize },
    #[error("{origin}:{line}:{col}: {message}")]
    Syntax {
        origin: String,
        line: usize,
        col: usize,
        message: String,
    },
    #[error("{origin}:{line}: {message}")]
    Field {
        origin: String,
        line: usize,
        message: String,
    },
    #[error("{origin}: {source}")]
    Model {
        origin: String,
        #[source]
        source: ModelError,
    },
    // The band's own message prints numbers in full (1e300 as 301 digits):
    // shortened here so a preset's error stays one short line. Not a
    // `source`, so an error chain does not print the long form after it.
    #[error("{origin}: [band]: {}", message(&.error.to_string()))]
    Band { origin: String, error: BandError },
    #[error("{path}: cannot save: {source} (the existing file, if any, is unchanged)")]
    Save {
        path: String,
        #[source]
        source: std::io::Error,
    },
    #[error(
        "no preset file '{0}' and no built-in preset of that name; built-ins: paper-75kg, paper-65kg, paper-85kg, boileau-rakheja-1998"
    )]
    NotFound(String),
}

/// A toml error as `origin:line:col: message (in `excerpt of the line`)`,
/// bounded in length whatever the input.
pub(crate) fn syntax_error(text: &str, origin: &str, e: &toml::de::Error) -> PresetError {
    let raw = e.message();
    let (at, raw_message) = match e.span() {
        Some(s) => (Some(s.start), raw.to_string()),
        // toml reports a dotted key or header too deep to follow without a
        // place; find it ourselves.
        None if raw.contains("recursion") => (
            deep_key_offset(text),
            format!(
                "a dotted key or table header nests {DEEP_KEY} or more levels deep; flatten it"
            ),
        ),
        None => (None, raw.to_string()),
    };
    let (line, col, message) = located(text, at, &raw_message);
    PresetError::Syntax {
        origin: origin.to_string(),
        line,
        col,
        message,
    }
}

/// Depth at which toml stops following a dotted key.
const DEEP_KEY: usize = 80;

/// Offset of the first key or table header with at least [`DEEP_KEY`] dots.
fn deep_key_offset(text: &str) -> Option<usize> {
    let mut offset = 0;
    for line in text.split_inclusive('\n') {
        let indent = line.len() - line.trim_start().len();
        let key = line.trim_start().split('=').next().unwrap_or("");
        if key.matches('.').count() + 1 >= DEEP_KEY {
            return Some(offset + indent);
        }
        offset += line.len();
    }
    None
}
