//! A record operation of a day: the record read on its axes and weighted
//! (Wd on x and y, Wk on z), no body: its a_w and VDV per axis, before k,
//! over the record's duration; on z also ISO 2631-5's dose Dz, where the
//! method can judge the record (at least 1 s, no large mean).

use super::file::RecordSource;
use super::operation::Measured;
use crate::iso2631::AxesAccumulator;
use crate::iso2631::spine::SpineAccumulator;
use crate::time::{Axis, PerAxis, Record, RecordError, RecordOptions};

/// Reads the record `src` names and measures each of its axes, streaming.
pub fn measure_record(src: &RecordSource) -> Result<PerAxis<Measured>, RecordError> {
    let opts = RecordOptions {
        axes: src.axes.clone().unwrap_or_default(),
        unit: src.unit,
        fs: src.fs,
        ..RecordOptions::default()
    };
    let rec = Record::open(&src.resolved, &opts)?;
    let z = rec.axes().has(Axis::Z);
    let mut acc = AxesAccumulator::new(&rec.axes(), rec.fs());
    let mut spine = SpineAccumulator::new(rec.fs());
    for row in rec {
        let row = row?;
        acc.push(&row);
        if z {
            spine.push(row[Axis::Z.index()]);
        }
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
