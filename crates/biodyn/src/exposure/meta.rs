//! Who, where, when and with what: the facts a report is handed over with
//! (the site, the worker, the machine, the task, the date, the instrument
//! and its last calibration, the assessor, notes). All optional; read from
//! a TOML file of these keys (`assess --meta FILE.toml`, `day --meta`) or
//! from a day file's `[report]` table, the same keys there.
//!
//! ```toml
//! site = "North quarry"
//! worker = "J. Smith"
//! machine = "Volvo A30G dumper, fleet no. 12"
//! date = 2026-12-05                 # a TOML date, or text
//! instrument = "SV 106, SN 12345"
//! calibrated = "2026-06-01"
//! ```
//!
//! Unknown keys are refused, naming the key and the known ones (a typo
//! never drops a fact silently); each value is one line of printable text
//! (notes may have several lines), at most [`MAX_META`] characters
//! ([`MAX_NOTES`] for notes). Writers still escape it for their format.

use crate::io::excerpt::{is_invisible, line_col, located, quote};
use crate::io::{FileKind, ReadError, read_text};
use serde::{Deserialize, Serialize};
use std::path::Path;
use toml::Spanned;

/// The keys, in the order a report shows them.
pub const META_KEYS: [&str; 9] = [
    "site",
    "worker",
    "machine",
    "task",
    "date",
    "instrument",
    "calibrated",
    "assessor",
    "notes",
];

/// Longest value, characters (notes: [`MAX_NOTES`]).
pub const MAX_META: usize = 200;

/// Longest notes, characters.
pub const MAX_NOTES: usize = 4000;

/// The facts given; None where not given.
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize)]
pub struct Meta {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub site: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub worker: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub machine: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub task: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub date: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub instrument: Option<String>,
    /// The instrument's last calibration date.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub calibrated: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub assessor: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub notes: Option<String>,
}

/// What can be wrong with the facts: one line, the file, the line and the
/// key, and the fix.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MetaError {
    #[error("{path}: cannot read the report's details: {reason}")]
    Read { path: String, reason: String },
    /// toml's own message (an unknown key with the known ones, bad syntax).
    #[error("{origin}:{line}:{col}: {message}")]
    Syntax {
        origin: String,
        line: usize,
        col: usize,
        message: String,
    },
    #[error("{origin}:{line}: {key}: {fix}")]
    Value {
        origin: String,
        line: usize,
        /// As written: `site`, or `report.site` in a day file.
        key: String,
        fix: String,
    },
}

/// The keys as a file holds them: each a text or a TOML date.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct MetaToml {
    site: Option<Spanned<toml::Value>>,
    worker: Option<Spanned<toml::Value>>,
    machine: Option<Spanned<toml::Value>>,
    task: Option<Spanned<toml::Value>>,
    date: Option<Spanned<toml::Value>>,
    instrument: Option<Spanned<toml::Value>>,
    calibrated: Option<Spanned<toml::Value>>,
    assessor: Option<Spanned<toml::Value>>,
    notes: Option<Spanned<toml::Value>>,
}

impl MetaToml {
    fn fields(&self) -> [(&'static str, Option<&Spanned<toml::Value>>); 9] {
        [
            ("site", self.site.as_ref()),
            ("worker", self.worker.as_ref()),
            ("machine", self.machine.as_ref()),
            ("task", self.task.as_ref()),
            ("date", self.date.as_ref()),
            ("instrument", self.instrument.as_ref()),
            ("calibrated", self.calibrated.as_ref()),
            ("assessor", self.assessor.as_ref()),
            ("notes", self.notes.as_ref()),
        ]
    }

    /// The checked facts; `prefix` names the table in messages
    /// (`report.` in a day file, "" in a file of its own).
    pub(super) fn check(&self, text: &str, origin: &str, prefix: &str) -> Result<Meta, MetaError> {
        let mut meta = Meta::default();
        for (key, v) in self.fields() {
            let Some(v) = v else { continue };
            let err = |fix: String| MetaError::Value {
                origin: origin.into(),
                line: line_col(text, v.span().start).0,
                key: format!("{prefix}{key}"),
                fix,
            };
            let s = match v.get_ref() {
                toml::Value::String(s) => s.clone(),
                toml::Value::Datetime(d) => d.to_string(),
                other => {
                    return Err(err(format!(
                        "is {} {}; give text in quotes, e.g. {key} = \"{}\"",
                        article(other.type_str()),
                        other.type_str(),
                        example(key)
                    )));
                }
            };
            let notes = key == "notes";
            let max = if notes { MAX_NOTES } else { MAX_META };
            let bad = |c: char| {
                is_invisible(c) || (c.is_control() && !(notes && (c == '\n' || c == '\t')))
            };
            if s.trim().is_empty() {
                return Err(err("is empty; give the text, or leave the key out".into()));
            }
            if s.chars().any(bad) || s.chars().count() > max {
                return Err(err(format!(
                    "\"{}\": give {} of at most {max} printable characters",
                    quote(&s),
                    if notes { "text" } else { "one line" }
                )));
            }
            if let Some(slot) = meta.slot(key) {
                *slot = Some(s.trim().to_string());
            }
        }
        Ok(meta)
    }
}

fn article(word: &str) -> &'static str {
    if word.starts_with(['a', 'e', 'i', 'o', 'u']) {
        "an"
    } else {
        "a"
    }
}

/// An example value per key, for messages.
fn example(key: &str) -> &'static str {
    match key {
        "date" | "calibrated" => "2026-06-01",
        "worker" | "assessor" => "J. Smith",
        "instrument" => "SV 106, SN 12345",
        _ => "North quarry",
    }
}

impl Meta {
    /// The value of `key` (one of [`META_KEYS`]).
    pub fn get(&self, key: &str) -> Option<&str> {
        let v = match key {
            "site" => &self.site,
            "worker" => &self.worker,
            "machine" => &self.machine,
            "task" => &self.task,
            "date" => &self.date,
            "instrument" => &self.instrument,
            "calibrated" => &self.calibrated,
            "assessor" => &self.assessor,
            "notes" => &self.notes,
            _ => return None,
        };
        v.as_deref()
    }

    fn slot(&mut self, key: &str) -> Option<&mut Option<String>> {
        Some(match key {
            "site" => &mut self.site,
            "worker" => &mut self.worker,
            "machine" => &mut self.machine,
            "task" => &mut self.task,
            "date" => &mut self.date,
            "instrument" => &mut self.instrument,
            "calibrated" => &mut self.calibrated,
            "assessor" => &mut self.assessor,
            "notes" => &mut self.notes,
            _ => return None,
        })
    }

    /// The keys given and their values, in [`META_KEYS`]' order.
    pub fn iter(&self) -> impl Iterator<Item = (&'static str, &str)> + '_ {
        META_KEYS
            .iter()
            .filter_map(|k| self.get(k).map(|v| (*k, v)))
    }

    pub fn is_empty(&self) -> bool {
        self.iter().next().is_none()
    }

    /// `self` with every key `over` gives replaced by `over`'s (the
    /// command line's `--meta` over a day file's `[report]`).
    pub fn merged(&self, over: &Meta) -> Meta {
        let mut out = self.clone();
        for (k, v) in over.iter() {
            if let Some(slot) = out.slot(k) {
                *slot = Some(v.to_string());
            }
        }
        out
    }

    /// Reads a file of the keys: a regular file within
    /// [`FileKind::Meta`]'s cap.
    pub fn load(path: &Path) -> Result<Meta, MetaError> {
        let shown = path.display().to_string();
        let text = read_text(path, FileKind::Meta).map_err(|e: ReadError| MetaError::Read {
            path: shown.clone(),
            reason: e.reason(),
        })?;
        Meta::parse(&text, &shown)
    }

    /// Parses a file of the keys; `origin` labels errors.
    pub fn parse(text: &str, origin: &str) -> Result<Meta, MetaError> {
        let t: MetaToml = toml::from_str(text).map_err(|e| {
            let (line, col, message) = located(text, e.span().map(|s| s.start), e.message());
            MetaError::Syntax {
                origin: origin.into(),
                line,
                col,
                message,
            }
        })?;
        t.check(text, origin, "")
    }

    /// The keys as TOML lines (`site = "…"`), loading back to the same.
    pub fn to_toml(&self) -> String {
        self.iter()
            .map(|(k, v)| format!("{k} = {}\n", toml::Value::String(v.to_string())))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_key_reads_and_a_date_may_be_a_toml_date() {
        let m = Meta::parse(
            "site = \"North quarry\"\nworker = \"J. Smith\"\nmachine = \"A30G\"\ntask = \"haul\"\ndate = 2026-12-05\ninstrument = \"SV 106\"\ncalibrated = \"2026-06-01\"\nassessor = \"A. Hyg\"\nnotes = \"line 1\\nline 2\"\n",
            "m.toml",
        )
        .unwrap();
        assert_eq!(m.iter().count(), 9);
        assert_eq!(m.date.as_deref(), Some("2026-12-05"));
        assert_eq!(m.notes.as_deref(), Some("line 1\nline 2"));
        assert_eq!(Meta::parse(&m.to_toml(), "back").unwrap(), m);
        assert!(Meta::parse("", "e").unwrap().is_empty());
    }

    #[test]
    fn an_unknown_key_names_itself_and_the_known_ones() {
        let e = Meta::parse("site = \"a\"\nsight = \"b\"\n", "m.toml").unwrap_err();
        let s = e.to_string();
        assert!(s.starts_with("m.toml:2:"), "{s}");
        assert!(s.contains("sight"), "{s}");
        for k in META_KEYS {
            assert!(s.contains(k), "{k}: {s}");
        }
    }

    #[test]
    fn control_characters_numbers_and_empty_text_are_refused() {
        for (text, words) in [
            (
                "site = \"a\\u001b[31mb\"",
                "site: \"a\\u{1b}[31mb\": give one line",
            ),
            ("worker = \"a\\nb\"", "worker: \"a\\nb\": give one line"),
            ("task = \"\\u202Eevil\"", "task:"),
            (
                "date = 20261205",
                "date: is an integer; give text in quotes, e.g. date = \"2026-06-01\"",
            ),
            ("site = \"  \"", "site: is empty"),
        ] {
            let e = Meta::parse(text, "m.toml").unwrap_err().to_string();
            assert!(e.starts_with("m.toml:1: "), "{e}");
            assert!(e.contains(words), "{text}: {e}");
        }
        let long = format!("site = \"{}\"", "a".repeat(MAX_META + 1));
        assert!(Meta::parse(&long, "m").is_err());
        let notes = format!("notes = \"{}\"", "a".repeat(MAX_META + 1));
        assert!(Meta::parse(&notes, "m").is_ok());
    }

    #[test]
    fn the_command_line_wins_key_by_key() {
        let file = Meta::parse("site = \"A\"\nworker = \"W\"", "f").unwrap();
        let flag = Meta::parse("site = \"B\"\ndate = \"2026-01-01\"", "g").unwrap();
        let m = file.merged(&flag);
        assert_eq!(
            m.iter().collect::<Vec<_>>(),
            [("site", "B"), ("worker", "W"), ("date", "2026-01-01")]
        );
    }
}
