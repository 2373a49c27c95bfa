//! How a report names its input: the file, its time column, each axis's
//! column and unit (or the generated signal), as a table line, a CSV
//! comment and a JSON block. `biodyn simulate`/`assess` and the TUI's
//! export say it alike.

use crate::view::format::num;
use biodyn::time::{Columns, NamedBy, UnitBy};
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

fn unit_by(u: UnitBy) -> &'static str {
    match u {
        UnitBy::Header => "header",
        UnitBy::Given => "given",
        UnitBy::Assumed => "assumed",
    }
}

/// The columns whose unit was assumed (m/s²: their names give none).
fn assumed(c: &Columns) -> Vec<String> {
    let seat = c.axes.iter().filter(|(_, c)| c.unit_by == UnitBy::Assumed);
    let points = c
        .points
        .iter()
        .filter(|(p, c)| c.unit_by == UnitBy::Assumed && !p.point.is_angular());
    seat.map(|(_, c)| shown(&c.name))
        .chain(points.map(|(_, c)| shown(&c.name)))
        .collect()
}

/// The means removed before judging: "z 9.8066 m/s² (1.0000 g)".
fn removed(c: &Columns) -> Vec<String> {
    let g = biodyn::time::G_N;
    let seat = c.axes.iter().filter_map(|(a, c)| {
        c.mean_removed
            .map(|m| format!("{a} {} m/s² ({} g)", num(m, 4), num(m / g, 4)))
    });
    let points = c.points.iter().filter_map(|(p, c)| {
        c.mean_removed
            .map(|m| format!("{p} {} {}", num(m, 4), c.unit_name().replace("s2", "s²")))
    });
    seat.chain(points).collect()
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
                        json!({"column": c.name, "unit": c.unit.name(), "unit_from": unit_by(c.unit_by), "named_by": named_by(c.named_by), "mean_removed": c.mean_removed}),
                    );
                }
                let mut v = json!({
                    "file": path.display().to_string(),
                    "time_column": time,
                    "time_unit": time.as_ref().map(|_| columns.time_unit.name),
                    "fs_hz": fs,
                    "axes": axes,
                });
                if !columns.points.is_empty() {
                    let mut points = serde_json::Map::new();
                    for (p, c) in columns.points.iter() {
                        points.insert(
                            p.name().into(),
                            json!({"column": c.name, "unit": c.unit_name(), "unit_from": unit_by(c.unit_by), "named_by": named_by(c.named_by), "mean_removed": c.mean_removed}),
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
                    Some(t) if columns.time_unit.seconds != 1.0 => {
                        s.push_str(&format!("; time {} ({})", shown(t), columns.time_unit.name))
                    }
                    Some(t) => s.push_str(&format!("; time {}", shown(t))),
                    None => s.push_str("; no time column"),
                }
                let assumed = assumed(columns);
                if !assumed.is_empty() {
                    s.push_str(&format!(
                        "; m/s² assumed for {}: the header gives no unit (name it az_g or Acc Z [g], or give the unit)",
                        assumed.join(", ")
                    ));
                }
                let removed = removed(columns);
                if !removed.is_empty() {
                    s.push_str(&format!("; mean removed: {}", removed.join(", ")));
                }
                s
            }
        }
    }
}
