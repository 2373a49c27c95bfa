//! The record the tab reads: opened as `biodyn assess --input` opens it
//! (its axes, unit and mean settings; the fs row for a file without a time
//! column), and how the tab names its columns.

use biodyn::time::{PerAxis, Record, RecordError, RecordOptions, Unit};
use std::path::Path;

/// Opens the record at `path`: its own time column, or `fs_hz` for a file
/// without one (the tab's fs row serves only those).
pub fn open_record(
    path: &Path,
    axes: &PerAxis<String>,
    unit: Option<Unit>,
    remove_mean: bool,
    fs_hz: f64,
) -> Result<Record, RecordError> {
    let mut opts = RecordOptions {
        axes: axes.clone(),
        unit,
        fs: None,
        remove_mean,
        ..RecordOptions::default()
    };
    match Record::open(path, &opts) {
        Err(RecordError::NeedFs { .. }) => {
            opts.fs = Some(fs_hz);
            Record::open(path, &opts)
        }
        r => r,
    }
}

/// "x ax, y ay, z az in g" (": m/s2 assumed" where no name gave one); each column's unit when they differ; "z acc
/// (the only one) in g" for a column taken as z for want of an axis name.
pub(super) fn columns_words(columns: &PerAxis<biodyn::time::AxisColumn>) -> String {
    let units: Vec<Unit> = columns.iter().map(|(_, c)| c.unit).collect();
    let one = units.windows(2).all(|w| w[0] == w[1]);
    let each: Vec<String> = columns
        .iter()
        .map(|(a, c)| {
            let only = if c.named_by == biodyn::time::NamedBy::Only {
                " (the only one)"
            } else {
                ""
            };
            let unit = if one { String::new() } else { format!(" {}", c.unit) };
            format!("{a} {}{only}{unit}", c.name)
        })
        .collect();
    // A unit no name gave is said to be assumed (issue 30).
    let assumed = columns
        .iter()
        .any(|(_, c)| c.unit_by == biodyn::time::UnitBy::Assumed);
    let mut s = match units.first() {
        Some(u) if one && assumed => format!("{}: {u} assumed", each.join(", ")),
        Some(u) if one => format!("{} in {u}", each.join(", ")),
        _ if assumed => format!("{}; m/s2 assumed where no unit is named", each.join(", ")),
        _ => each.join(", "),
    };
    let removed: Vec<String> = columns
        .iter()
        .filter_map(|(a, c)| c.mean_removed.map(|m| format!("{a} {}", crate::view::format::num(m, 4))))
        .collect();
    if !removed.is_empty() {
        s.push_str(&format!("; mean removed: {} m/s²", removed.join(", ")));
    }
    s
}
