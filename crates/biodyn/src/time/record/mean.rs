//! `remove_mean`: each channel's mean over the whole record, from a first
//! pass over the file, subtracted from every row of the second.

use super::{Columns, Record, RecordError, RecordOptions};
use crate::time::{PointRow, Row};
use std::path::Path;

/// Each channel's mean over the whole record `path` (a first pass over
/// it), set on `columns` for the reports: the seat's axes by slot, the
/// other points by theirs.
pub(super) fn means(
    path: &Path,
    opts: &RecordOptions,
    columns: &mut Columns,
) -> Result<(Row, PointRow), RecordError> {
    let first = RecordOptions {
        remove_mean: false,
        ..opts.clone()
    };
    let (mut seat, mut points, mut n) = ([0.0; 3], [0.0; 9], 0u64);
    for frame in Record::open(path, &first)?.frames() {
        let (row, p) = frame?;
        for (s, v) in seat.iter_mut().zip(row) {
            *s += v;
        }
        for (s, v) in points.iter_mut().zip(p) {
            *s += v;
        }
        n += 1;
    }
    let n = n.max(1) as f64;
    let (seat, points) = (seat.map(|s| s / n), points.map(|s| s / n));
    for (axis, c) in columns.axes.iter_mut() {
        c.mean_removed = Some(seat[axis.index()]);
    }
    for (p, c) in columns.points.iter_mut() {
        c.mean_removed = Some(points[p.slot()]);
    }
    Ok((seat, points))
}
