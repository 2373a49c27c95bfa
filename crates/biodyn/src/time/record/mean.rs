//! `remove_mean`: each channel's mean over the whole record, from a first
//! pass over the file, subtracted from every row of the second.

use super::columns::Columns;
use super::error::RecordError;
use crate::time::{Frame, PointRow, Row};

/// Each channel's mean over `frames`, the whole record read once, set on
/// `columns` for the reports: the seat's axes by slot, the other points by
/// theirs.
pub(super) fn means(
    frames: impl Iterator<Item = Result<Frame, RecordError>>,
    columns: &mut Columns,
) -> Result<(Row, PointRow), RecordError> {
    let (mut seat, mut points, mut n) = ([0.0; 3], [0.0; 9], 0u64);
    for frame in frames {
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
