//! How a report names its input: the file, its time column, each axis's
//! column and unit (or the generated signal), as a table line, a CSV
//! comment and a JSON block. `biodyn simulate`/`assess` and the TUI's
//! export say it alike.

use biodyn::time::{Columns, NamedBy};
use serde_json::{Value, json};
use std::path::PathBuf;

/// What was read, for reports.
#[derive(Debug, Clone)]
pub enum Source {
    Signal(String),
    Record {
        path: PathBuf,
        time: Option<String>,
        /// Boxed: with the other points' columns it is far larger than a signal's name.
        columns: Box<Columns>,
    },
}

fn named_by(n: NamedBy) -> &'static str {
    match n {
        NamedBy::Header => "header",
        NamedBy::Given => "given",
        NamedBy::Only => "only column",
    }
}

/// A file or column name for a terminal: control characters escaped, so a
/// hostile header cannot drive the terminal.
fn shown(s: &str) -> String {
    biodyn::io::excerpt(s, 200)
}

/// "x = ax (m/s2), z = az_g (g)"; then the other points', "rx = rx (rad/s2)".
pub fn axes_words(c: &Columns) -> String {
    let seat = c
        .axes
        .iter()
        .map(|(a, c)| format!("{a} = {} ({})", shown(&c.name), c.unit));
    let points = c
        .points
        .iter()
        .map(|(p, c)| format!("{p} = {} ({})", shown(&c.name), c.unit_name()));
    seat.chain(points).collect::<Vec<_>>().join(", ")
}

impl Source {
    /// The comment line a CSV of this input starts with: a record's file,
    /// columns and units (a generated signal needs none: the command line
    /// names it).
    pub fn csv_comment(&self) -> Option<String> {
        match self {
            Source::Signal(_) => None,
            Source::Record { .. } => Some(format!("# input: {}\n", self.line())),
        }
    }

    /// The input block of a JSON report.
    pub fn json(&self, fs: f64) -> Value {
        match self {
            Source::Signal(spec) => json!({
                "signal": spec,
                "fs_hz": fs,
                "axes": {"z": {"column": null, "unit": "m/s2", "named_by": "generated"}},
            }),
            Source::Record {
                path,
                time,
                columns,
            } => {
                let mut axes = serde_json::Map::new();
                for (a, c) in columns.axes.iter() {
                    axes.insert(
                        a.name().into(),
                        json!({"column": c.name, "unit": c.unit.name(), "named_by": named_by(c.named_by)}),
                    );
                }
                let mut v = json!({
                    "file": path.display().to_string(),
                    "time_column": time,
                    "fs_hz": fs,
                    "axes": axes,
                });
                if !columns.points.is_empty() {
                    let mut points = serde_json::Map::new();
                    for (p, c) in columns.points.iter() {
                        points.insert(
                            p.name().into(),
                            json!({"column": c.name, "unit": c.unit_name(), "named_by": named_by(c.named_by)}),
                        );
                    }
                    v["points"] = Value::Object(points);
                }
                v
            }
        }
    }

    /// One line for a table report: what was read, each axis's column and unit.
    pub fn line(&self) -> String {
        match self {
            Source::Signal(spec) => format!("{} (generated, vertical: z)", shown(spec)),
            Source::Record {
                path,
                time,
                columns,
            } => {
                let mut s = format!(
                    "{}: {}",
                    shown(&path.display().to_string()),
                    axes_words(columns)
                );
                if columns
                    .axes
                    .iter()
                    .any(|(_, c)| c.named_by == NamedBy::Only)
                {
                    s.push_str(", the only acceleration column, taken as vertical");
                }
                match time {
                    Some(t) => s.push_str(&format!("; time {}", shown(t))),
                    None => s.push_str("; no time column"),
                }
                s
            }
        }
    }
}
