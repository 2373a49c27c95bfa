//! A refusal the command line itself makes (not the library's): a line that
//! names the flag and the value, and the hint that goes with it. `hint` in
//! `mod.rs` prints this hint before looking at the library's errors.

use std::fmt;

/// The command line refuses what it was given: `text` is the error line,
/// `hint` what to type instead.
#[derive(Debug)]
pub struct Refused {
    pub text: String,
    pub hint: String,
}

impl Refused {
    pub fn error(text: impl Into<String>, hint: impl Into<String>) -> anyhow::Error {
        Refused {
            text: text.into(),
            hint: hint.into(),
        }
        .into()
    }
}

impl fmt::Display for Refused {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text)
    }
}

impl std::error::Error for Refused {}
