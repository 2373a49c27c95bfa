//! Records with other points: their channels read beside the seat's rows,
//! scaled to m/s² (rad/s²), the same on two threads as on one, and the
//! seat's rows alone unchanged by them.

use super::{Record, RecordOptions};
use crate::time::{Axis, Frame, G_N, Point, PointAxis, Row};

fn write(dir: &std::path::Path, rows: usize, bad_at: Option<usize>) -> std::path::PathBuf {
    let mut s = String::from("t_s,ax,az,backrest_x_g,feet_z,rx_rad_s2\n");
    for k in 0..rows {
        let t = k as f64 / 1000.0;
        if Some(k) == bad_at {
            s.push_str(&format!("{t},1,1,1,oops,1\n"));
            continue;
        }
        let v = (k as f64 * 0.37).sin();
        s.push_str(&format!(
            "{t},{v},{},{},{},{}\n",
            2.0 * v,
            0.1 * v,
            3.0 * v,
            -v
        ));
    }
    let p = dir.join("points.csv");
    std::fs::write(&p, s).unwrap();
    p
}

fn frames(p: &std::path::Path, chunk: Option<usize>) -> (Vec<Frame>, Option<String>) {
    let rec = Record::open_with(p, &RecordOptions::default(), chunk, 2).unwrap();
    let mut out = Vec::new();
    for f in rec.frames() {
        match f {
            Ok(f) => out.push(f),
            Err(e) => return (out, Some(e.to_string())),
        }
    }
    (out, None)
}

#[test]
fn point_channels_are_read_beside_the_seat() {
    let dir = tempfile::tempdir().unwrap();
    let n = 500;
    let p = write(dir.path(), n, None);
    let rec = Record::open(&p, &RecordOptions::default()).unwrap();
    let present: Vec<PointAxis> = rec.points().channels().collect();
    assert_eq!(
        present,
        [
            PointAxis::new(Point::Backrest, Axis::X),
            PointAxis::new(Point::Feet, Axis::Z),
            PointAxis::new(Point::Rotation, Axis::X),
        ]
    );
    let seat: Vec<Row> = rec.map(Result::unwrap).collect();
    let (par, err) = frames(&p, Some(100));
    assert!(err.is_none());
    assert_eq!(frames(&p, None), (par.clone(), None));
    assert_eq!(par.len(), n);
    for (k, ((row, pts), s)) in par.iter().zip(&seat).enumerate() {
        let v = (k as f64 * 0.37).sin();
        assert_eq!(row, s, "row {k}");
        assert_eq!(*row, [v, 0.0, 2.0 * v]);
        assert_eq!(pts[0], 0.1 * v * G_N, "backrest x in g, row {k}");
        assert_eq!(pts[5], 3.0 * v);
        assert_eq!(pts[6], -v);
        let others = [1, 2, 3, 4, 7, 8];
        assert!(others.iter().all(|&i| pts[i] == 0.0));
    }
    // A bad value in a point's column stops the record at its line, after
    // the rows before it, on two threads as on one.
    let bad = write(dir.path(), n, Some(321));
    let (rows, err) = frames(&bad, Some(100));
    assert_eq!(rows.len(), 321);
    let err = err.unwrap();
    assert!(err.contains("line 323, column 'feet_z'"), "{err}");
    assert_eq!(frames(&bad, None), (rows, Some(err)));
}

/// A record without other points gives frames with all points at 0.
#[test]
fn a_seat_record_has_no_points() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("seat.csv");
    std::fs::write(&p, "t_s,az\n0,1\n0.001,2\n0.002,3\n").unwrap();
    let rec = Record::open(&p, &RecordOptions::default()).unwrap();
    assert!(rec.points().is_empty());
    let f: Vec<Frame> = rec.frames().map(Result::unwrap).collect();
    assert_eq!(f.len(), 3);
    assert!(f.iter().all(|(_, p)| p.iter().all(|&v| v == 0.0)));
    assert_eq!(f[2].0, [0.0, 0.0, 3.0]);
}
