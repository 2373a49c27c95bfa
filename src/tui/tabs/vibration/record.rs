//! The record the tab reads: opened as `biodyn assess --input` opens it
//! (its axes, unit and mean settings; the fs row for a file without a time
//! column), and whether a refusal is one the settings can fix.

use super::compute::{Input, Source};
use biodyn::time::{PerAxis, Record, RecordError, RecordOptions, Unit};
use std::path::Path;

/// Whether a file source is refused for its columns (no axis named, two
/// columns on one axis, a column not there, a unit clash): what the axes
/// and unit settings fix, so the path is kept and the run shows why.
pub fn refused_for_columns(input: &Input) -> bool {
    let Source::File {
        path, axes, unit, ..
    } = &input.source
    else {
        return false;
    };
    let opts = RecordOptions {
        axes: axes.clone(),
        unit: *unit,
        fs: Some(input.fs_hz),
        ..RecordOptions::default()
    };
    matches!(
        Record::open(path, &opts),
        Err(RecordError::Unnamed { .. }
            | RecordError::SameAxis { .. }
            | RecordError::SamePoint { .. }
            | RecordError::MissingColumn { .. }
            | RecordError::UnitClash { .. })
    )
}

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

