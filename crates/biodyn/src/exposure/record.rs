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
use crate::time::{Axis, PerAxis, Record, RecordError, RecordOptions};
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
        acc.check_offsets().map_err(judge)?;
    }
    let dz = if z {
        spine.measure().ok().map(|m| m.dose.dz)
    } else {
        None
    };
    Ok(acc.metrics().map(|a, m| Measured {
        aw: m.aw,
        vdv: Some(m.vdv),
        measured_s: Some(m.duration_s),
        dz: if a == Axis::Z { dz } else { None },
    }))
}
