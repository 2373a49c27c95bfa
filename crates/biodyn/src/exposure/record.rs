//! A record operation of a day: the record read on its axes and weighted
//! (Wd on x and y, Wk on z), no body: its a_w and VDV per axis, before k,
//! over the record's duration.

use super::file::RecordSource;
use super::operation::Measured;
use crate::iso2631::AxesAccumulator;
use crate::time::{PerAxis, Record, RecordError, RecordOptions};

/// Reads the record `src` names and measures each of its axes, streaming.
pub fn measure_record(src: &RecordSource) -> Result<PerAxis<Measured>, RecordError> {
    let opts = RecordOptions {
        axes: src.axes.clone().unwrap_or_default(),
        unit: src.unit,
        fs: None,
        ..RecordOptions::default()
    };
    let rec = Record::open(&src.resolved, &opts)?;
    let mut acc = AxesAccumulator::new(&rec.axes(), rec.fs());
    for row in rec {
        acc.push(&row?);
    }
    Ok(acc.metrics().map(|_, m| Measured {
        aw: m.aw,
        vdv: Some(m.vdv),
        measured_s: Some(m.duration_s),
    }))
}
