//! A record operation of a day: the record read on its axes and weighted
//! (Wd on x and y, Wk on z), no body: its a_w and VDV per axis, before k,
//! over the record's duration; on z also ISO 2631-5's dose Dz, where the
//! method can judge the record (at least 1 s, no large mean). A record
//! whose rate cannot carry the band, or whose mean is far beyond vibration,
//! is refused as `assess` refuses it.

use super::file::RecordSource;
use super::operation::Measured;
use crate::iso2631::spine::SpineAccumulator;
use crate::iso2631::{AxesAccumulator, JudgeError, MIN_RECORD_S};
use crate::time::{Axis, PerAxis, Record, RecordError, RecordOptions, UnitBy};
use std::path::PathBuf;

/// Why a record operation has no values.
#[derive(Debug, thiserror::Error)]
pub enum MeasureError {
    #[error(transparent)]
    Record(#[from] RecordError),
    #[error("{}: {source}", .path.display())]
    Judge { path: PathBuf, source: JudgeError },
}

/// Reads the record `src` names and measures each of its axes, streaming.
pub fn measure_record(src: &RecordSource) -> Result<PerAxis<Measured>, MeasureError> {
    measure_record_noted(src).map(|(m, _)| m)
}

/// What a report must say of a record it judged: a unit assumed, a mean
/// removed, a mean that may move a value by 1–5 % (each naming the file).
fn record_notes(rec: &Record) -> Vec<String> {
    let file = crate::io::excerpt(&rec.path().display().to_string(), 200);
    let c = rec.columns();
    let mut notes = Vec::new();
    let assumed: Vec<String> = c
        .axes
        .iter()
        .filter(|(_, a)| a.unit_by == UnitBy::Assumed)
        .map(|(_, a)| format!("'{}'", crate::io::excerpt(&a.name, 60)))
        .collect();
    if !assumed.is_empty() {
        notes.push(format!(
            "{file}: m/s² assumed for {}: the header gives no unit (unit = \"g\" in the operation, or a name such as az_g or Acc Z [g], says otherwise)",
            assumed.join(", ")
        ));
    }
    let removed: Vec<String> = c
        .axes
        .iter()
        .filter_map(|(a, col)| col.mean_removed.map(|m| format!("{a} {m:.4} m/s²")))
        .collect();
    if !removed.is_empty() {
        notes.push(format!("{file}: mean removed: {}", removed.join(", ")));
    }
    notes
}

/// [`measure_record`], and the notes every report of it carries.
pub fn measure_record_noted(
    src: &RecordSource,
) -> Result<(PerAxis<Measured>, Vec<String>), MeasureError> {
    let opts = RecordOptions {
        axes: src.axes.clone().unwrap_or_default(),
        unit: src.unit,
        fs: src.fs,
        remove_mean: src.remove_mean,
        ..RecordOptions::default()
    };
    let rec = Record::open(&src.resolved, &opts)?;
    let judge = |source| MeasureError::Judge {
        path: src.resolved.clone(),
        source,
    };
    let z = rec.axes().has(Axis::Z);
    let mut acc = AxesAccumulator::new(&rec.axes(), rec.fs());
    acc.check_rate().map_err(judge)?;
    let mut spine = SpineAccumulator::new(rec.fs());
    let mut notes = record_notes(&rec);
    for row in rec {
        let row = row?;
        acc.push(&row);
        if z {
            spine.push(row[Axis::Z.index()]);
        }
    }
    // Too short is refused by the day, before a mean can be weighed.
    let long = acc
        .metrics()
        .iter()
        .all(|(_, m)| m.duration_s >= MIN_RECORD_S);
    if long {
        let offsets = acc.check_offsets().map_err(judge)?;
        let file = crate::io::excerpt(&src.resolved.display().to_string(), 200);
        notes.extend(offsets.into_iter().map(|n| format!("{file}: {n}")));
    }
    let dz = if z {
        spine.measure().ok().map(|m| m.dose.dz)
    } else {
        None
    };
    let measured = acc.metrics().map(|a, m| Measured {
        aw: m.aw,
        vdv: Some(m.vdv),
        measured_s: Some(m.duration_s),
        dz: if a == Axis::Z { dz } else { None },
    });
    Ok((measured, notes))
}
