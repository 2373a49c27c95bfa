//! Records shaped as instruments and loggers write them (issue 30): a clock
//! in ms, units in brackets, no unit at all, no header, a gravity offset.
//! Each is read right, or refused with the reason; never guessed.

use super::{Record, RecordError, RecordOptions, UnitBy};
use crate::time::{Axis, G_N, Point, PointAxis};
use std::path::{Path, PathBuf};

/// A 500 Hz record of 1000 rows: `header`, then time written by `t` and
/// the values by `v` (the row's index k, its time in s).
fn write(
    dir: &Path,
    header: &str,
    t: impl Fn(f64) -> String,
    v: impl Fn(usize) -> String,
) -> PathBuf {
    let mut s = format!("{header}\n");
    for k in 0..1000 {
        s.push_str(&format!("{},{}\n", t(k as f64 / 500.0), v(k)));
    }
    let p = dir.join("r.csv");
    std::fs::write(&p, s).unwrap();
    p
}

fn wave(k: usize) -> f64 {
    (k as f64 * 0.37).sin()
}

fn open(p: &Path) -> Result<Record, RecordError> {
    Record::open(p, &RecordOptions::default())
}

/// A clock in ms (its name says so) is read at its rate: 500 Hz, not 0.5.
#[test]
fn a_clock_in_ms_or_us_is_read_at_its_rate() {
    let dir = tempfile::tempdir().unwrap();
    for (header, scale) in [
        ("time_ms,az", 1e3),
        ("Time [ms],az", 1e3),
        ("t (ms),az", 1e3),
        ("t_us,az", 1e6),
        ("Time [s],az", 1.0),
    ] {
        let p = write(
            dir.path(),
            header,
            |t| format!("{}", t * scale),
            |k| wave(k).to_string(),
        );
        let r = open(&p).unwrap();
        assert!((r.fs() - 500.0).abs() < 1e-6, "{header}: {}", r.fs());
        assert_eq!(r.time_unit().seconds, 1.0 / scale, "{header}");
    }
}

/// A time unit the reader does not know, or a first column that says no
/// time, is refused: never read as seconds.
#[test]
fn a_time_column_of_unknown_unit_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let p = write(
        dir.path(),
        "Time [min],az",
        |t| t.to_string(),
        |k| wave(k).to_string(),
    );
    let e = open(&p).unwrap_err();
    assert!(
        matches!(&e, RecordError::TimeUnit { unit, .. } if unit == "min"),
        "{e}"
    );
    let p = write(
        dir.path(),
        "stamp,az",
        |t| t.to_string(),
        |k| wave(k).to_string(),
    );
    let e = open(&p).unwrap_err();
    assert!(
        matches!(&e, RecordError::TimeUnknown { column, .. } if column == "stamp"),
        "{e}"
    );
    assert!(e.to_string().contains("t_ms"), "{e}");
}

/// `Acc Z [g]` is z in g (9.80665 m/s² each), not m/s²; so are `(g)` and
/// `in g`; `[mm/s²]` is a thousandth of a m/s².
#[test]
fn bracketed_units_scale_the_values() {
    let dir = tempfile::tempdir().unwrap();
    for (header, scale) in [
        ("Time [s],Acc Z [g]", G_N),
        ("t,Acc Z (g)", G_N),
        ("t,z in g", G_N),
        ("t,Accel-Z [m/s^2]", 1.0),
        ("t,acc z [mm/s²]", 1e-3),
    ] {
        let p = write(
            dir.path(),
            header,
            |t| t.to_string(),
            |k| wave(k).to_string(),
        );
        let r = open(&p).unwrap();
        let z = r.columns().axes.get(Axis::Z).unwrap();
        assert_eq!(z.unit_by, UnitBy::Header, "{header}");
        for (k, row) in r.enumerate() {
            let want = wave(k) * scale;
            assert!(
                (row.unwrap()[2] - want).abs() <= 1e-15 * want.abs().max(1.0),
                "{header}"
            );
        }
    }
    let p = write(
        dir.path(),
        "t,Acc Z [V]",
        |t| t.to_string(),
        |k| wave(k).to_string(),
    );
    let e = open(&p).unwrap_err();
    assert!(
        matches!(&e, RecordError::UnknownUnit { unit, .. } if unit == "V"),
        "{e}"
    );
}

/// `X,Y,Z` names the axes but no unit: m/s² is assumed and the record says
/// so (every report reads `unit_by`); a unit given is the given one's.
#[test]
fn no_unit_in_the_header_is_assumed_and_said() {
    let dir = tempfile::tempdir().unwrap();
    let p = write(
        dir.path(),
        "t,X,Y,Z",
        |t| t.to_string(),
        |k| format!("{0},{0},{0}", wave(k)),
    );
    let r = open(&p).unwrap();
    assert!(
        r.columns()
            .axes
            .iter()
            .all(|(_, c)| c.unit_by == UnitBy::Assumed)
    );
    let opts = RecordOptions {
        unit: Some(crate::time::Unit::G),
        ..RecordOptions::default()
    };
    let r = Record::open(&p, &opts).unwrap();
    assert!(
        r.columns()
            .axes
            .iter()
            .all(|(_, c)| c.unit_by == UnitBy::Given)
    );
}

/// A first line of numbers is data, not a header: refused, never a column
/// named `0.000` with its sample lost.
#[test]
fn a_record_without_header_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("r.csv");
    std::fs::write(&p, "0.000,0.12\n0.002,0.5\n0.004,-0.3\n").unwrap();
    let e = open(&p).unwrap_err();
    assert!(
        matches!(&e, RecordError::NumericHeader { first, .. } if first == "0.000,0.12"),
        "{e}"
    );
    // One word among numbers is a header.
    std::fs::write(&p, "t_s,0.12\n0.002,0.5\n0.004,-0.3\n").unwrap();
    assert!(!matches!(open(&p), Err(RecordError::NumericHeader { .. })));
}

/// With `remove_mean`, each channel's mean over the whole record is
/// subtracted from every row and named on its column; the rows are the
/// vibration alone (to rounding).
#[test]
fn remove_mean_subtracts_each_channels_mean() {
    let dir = tempfile::tempdir().unwrap();
    let p = write(
        dir.path(),
        "t_s,az_g,ax,backrest_x",
        |t| t.to_string(),
        |k| {
            format!(
                "{},{},{}",
                1.0 + 0.05 * wave(k),
                0.3 + wave(k),
                -2.0 + wave(k)
            )
        },
    );
    let mean: f64 = (0..1000).map(wave).sum::<f64>() / 1000.0;
    let opts = RecordOptions {
        remove_mean: true,
        ..RecordOptions::default()
    };
    let r = Record::open(&p, &opts).unwrap();
    let z = r.columns().axes.get(Axis::Z).unwrap().mean_removed.unwrap();
    assert!((z - G_N * (1.0 + 0.05 * mean)).abs() < 1e-12, "{z}");
    let bx = PointAxis::new(Point::Backrest, Axis::X);
    let b = r.columns().points.get(bx).unwrap().mean_removed.unwrap();
    assert!((b - (-2.0 + mean)).abs() < 1e-12, "{b}");
    for (k, f) in r.frames().enumerate() {
        let (row, points) = f.unwrap();
        let v = wave(k) - mean;
        assert!((row[2] - G_N * 0.05 * v).abs() < 1e-12, "row {k}");
        assert!((row[0] - v).abs() < 1e-12, "row {k}");
        assert!((points[bx.slot()] - v).abs() < 1e-12, "row {k}");
    }
    // Without it nothing is removed or named.
    let r = open(&p).unwrap();
    assert!(
        r.columns()
            .axes
            .iter()
            .all(|(_, c)| c.mean_removed.is_none())
    );
}
