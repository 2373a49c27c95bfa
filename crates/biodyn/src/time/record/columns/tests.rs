//! The header and `--axes` mapping of columns to axes and points.

use super::*;

fn h(cols: &str) -> Vec<String> {
    cols.split(',').map(String::from).collect()
}

fn map(cols: &str, axes: &str, unit: Option<Unit>) -> Result<Columns, RecordError> {
    let (axes, points) = if axes.is_empty() {
        (PerAxis::default(), PerPoint::default())
    } else {
        parse_channels(axes).unwrap()
    };
    let given = Given {
        axes: &axes,
        points: &points,
    };
    map_columns(Path::new("r.csv"), &h(cols), given, unit, false)
}

fn names(c: &Columns) -> Vec<(Axis, String, Unit)> {
    c.axes
        .iter()
        .map(|(a, c)| (a, c.name.clone(), c.unit))
        .collect()
}

#[test]
fn headers_name_their_axes() {
    for (head, want) in [
        ("x", Some(Axis::X)),
        ("seat_x_m_s2", Some(Axis::X)),
        ("acc_z", Some(Axis::Z)),
        ("az_g", Some(Axis::Z)),
        ("AY", Some(Axis::Y)),
        ("y_mm_s2", Some(Axis::Y)),
        ("z_ms2", Some(Axis::Z)),
        ("acc", None),
        ("speed", None),
        ("axz", None),
        ("_z", None),
        ("acc_m_s2", None),
    ] {
        assert_eq!(axis_of(head), want, "{head}");
    }
}

#[test]
fn a_tri_axial_header_maps_every_axis_with_units() {
    let c = map("t_s,ax,ay_g,az_mm_s2", "", None).unwrap();
    assert_eq!(c.time, Some(0));
    use Unit::*;
    assert_eq!(
        names(&c),
        vec![
            (Axis::X, "ax".into(), MetrePerSecondSquared),
            (Axis::Y, "ay_g".into(), G),
            (Axis::Z, "az_mm_s2".into(), MillimetrePerSecondSquared)
        ]
    );
    let g = map("time,x,y,z", "", Some(G)).unwrap();
    assert!(
        g.axes
            .iter()
            .all(|(_, c)| c.unit == G && c.named_by == NamedBy::Header)
    );
}

#[test]
fn one_unnamed_column_is_z_and_says_so() {
    let c = map("t_s,acc_m_s2", "", None).unwrap();
    let z = c.axes.get(Axis::Z).unwrap();
    assert_eq!((z.index, z.named_by), (1, NamedBy::Only));
    // Without a time name, the first column is time as before.
    assert_eq!(map("sec,acc", "", None).unwrap().time, Some(0));
}

#[test]
fn ambiguous_records_are_refused() {
    let e = map("t_s,ax,ay,az,speed", "", None).unwrap_err().to_string();
    assert!(
        e.contains("columns ax, ay, az, speed, and no axis in the name of speed:"),
        "{e}"
    );
    let e = map("t_s,a1,a2", "", None).unwrap_err();
    assert!(matches!(e, RecordError::Unnamed { .. }), "{e}");
    let e = map("t_s,az,acc_z", "", None).unwrap_err();
    assert!(
        matches!(e, RecordError::SameAxis { axis: Axis::Z, .. }),
        "{e}"
    );
    let e = map("t_s,az_g", "", Some(Unit::MetrePerSecondSquared)).unwrap_err();
    assert!(matches!(e, RecordError::UnitClash { .. }), "{e}");
    // A header of axes only and no rate: no column is time.
    let e = map("x,y,z", "", None).unwrap_err();
    assert!(matches!(e, RecordError::NeedFs { .. }), "{e}");
}

#[test]
fn given_axes_pick_their_columns() {
    let c = map("t_s,a1,a2,a3", "z=a3,x=a1", None).unwrap();
    assert_eq!(c.axes.get(Axis::Z).unwrap().index, 3);
    assert_eq!(c.axes.get(Axis::X).unwrap().index, 1);
    assert!(!c.axes.has(Axis::Y));
    let e = map("t_s,a1", "z=a9", None).unwrap_err();
    assert!(matches!(e, RecordError::MissingColumn { .. }), "{e}");
    let e = map("t_s,a1", "z=t_s", None).unwrap_err();
    assert!(matches!(e, RecordError::TimeAsAxis { .. }), "{e}");
    let e = map("t_s,a1", "z=a1,x=a1", None).unwrap_err();
    assert!(matches!(e, RecordError::ColumnTwice { .. }), "{e}");
}

#[test]
fn axes_specs_parse_or_say_why() {
    let a = parse_axes(" z = acc , x=f").unwrap();
    assert_eq!(a.get(Axis::Z).map(String::as_str), Some("acc"));
    assert_eq!(a.get(Axis::X).map(String::as_str), Some("f"));
    for bad in ["", "q=a", "z", "z=", "z=a,z=b"] {
        assert!(
            matches!(parse_axes(bad), Err(RecordError::BadAxes { .. })),
            "{bad}"
        );
    }
}

fn point(p: crate::time::Point, a: Axis) -> PointAxis {
    PointAxis::new(p, a)
}

/// ISO 2631-1 §8.2.2's points by their header names, beside the seat's
/// axes: `backrest_x` is the backrest's, not the seat's x.
#[test]
fn headers_name_the_other_points() {
    use crate::time::Point::*;
    let c = map(
        "t_s,ax,ay,az,backrest_x,backrest_y_g,acc_backrest_z,feet_z_mm_s2,rx,seat_ry_rad_s2",
        "",
        None,
    )
    .unwrap();
    assert_eq!(c.axes.iter().count(), 3);
    let got: Vec<(PointAxis, usize, &str)> = c
        .points
        .iter()
        .map(|(p, col)| (p, col.index, col.unit_name()))
        .collect();
    assert_eq!(
        got,
        [
            (point(Backrest, Axis::X), 4, "m/s2"),
            (point(Backrest, Axis::Y), 5, "g"),
            (point(Backrest, Axis::Z), 6, "m/s2"),
            (point(Feet, Axis::Z), 7, "mm/s2"),
            (point(Rotation, Axis::X), 8, "rad/s2"),
            (point(Rotation, Axis::Y), 9, "rad/s2"),
        ]
    );
    assert_eq!(
        c.points.get(point(Backrest, Axis::Y)).unwrap().scale(),
        9.80665
    );
    assert_eq!(c.points.get(point(Rotation, Axis::X)).unwrap().scale(), 1.0);
    // The unit given applies to the linear points, not to the rotations.
    let g = map("t_s,az,feet_x,rz", "", Some(Unit::G)).unwrap();
    assert_eq!(
        g.points.get(point(Feet, Axis::X)).unwrap().unit,
        Some(Unit::G)
    );
    assert_eq!(g.points.get(point(Rotation, Axis::Z)).unwrap().unit, None);
    // A record without other points has none.
    assert!(map("t_s,ax,az", "", None).unwrap().points.is_empty());
}

/// Every refusal that involves another point, each typed and naming the
/// columns.
#[test]
fn ambiguous_point_columns_are_refused() {
    use crate::time::Point::*;
    let e = map("t_s,az,backrest_x,acc_backrest_x", "", None).unwrap_err();
    assert!(
        matches!(&e, RecordError::SamePoint { channel, first, second, .. }
            if *channel == point(Backrest, Axis::X) && first == "backrest_x" && second == "acc_backrest_x"),
        "{e}"
    );
    assert!(e.to_string().contains("(backrest_x=COL)"), "{e}");
    let e = map("t_s,az,rx,seat_rx", "", None).unwrap_err();
    assert!(matches!(e, RecordError::SamePoint { .. }), "{e}");
    // A rotation in g, a linear channel in rad/s².
    let e = map("t_s,az,rx_g", "", None).unwrap_err();
    assert!(
        matches!(&e, RecordError::RotationUnit { suffix: Unit::G, column, .. } if column == "rx_g"),
        "{e}"
    );
    assert!(e.to_string().contains("name it rx_rad_s2"), "{e}");
    let e = map("t_s,az,ry_m_s2", "", None).unwrap_err();
    assert!(matches!(e, RecordError::RotationUnit { .. }), "{e}");
    let e = map("t_s,az,feet_z_rad_s2", "", None).unwrap_err();
    assert!(matches!(e, RecordError::RadOnLinear { .. }), "{e}");
    // A column naming nothing among several is refused, points or not.
    let e = map("t_s,az,backrest_x,speed", "", None).unwrap_err();
    assert!(
        matches!(&e, RecordError::Unnamed { unnamed, .. } if unnamed == "speed"),
        "{e}"
    );
    assert!(e.to_string().contains("backrest_x, feet_z, rx"), "{e}");
    // Given columns: one column for two channels, time as a point, a
    // column not there, a rotation given in g by its name.
    let e = map("t_s,a1,b1", "z=a1,backrest_x=a1", None).unwrap_err();
    assert!(
        matches!(&e, RecordError::ColumnTwice { first: Channel::Seat(Axis::Z), second: Channel::Point(p), .. }
            if *p == point(Backrest, Axis::X)),
        "{e}"
    );
    assert!(e.to_string().contains("both z and backrest_x"), "{e}");
    let e = map("t_s,a1", "z=a1,rx=t_s", None).unwrap_err();
    assert!(
        matches!(
            e,
            RecordError::TimeAsAxis {
                axis: Channel::Point(_),
                ..
            }
        ),
        "{e}"
    );
    assert!(e.to_string().contains("cannot be the rx axis"), "{e}");
    let e = map("t_s,a1", "z=a1,feet_z=f9", None).unwrap_err();
    assert!(matches!(e, RecordError::MissingColumn { .. }), "{e}");
    let e = map("t_s,a1,r_g", "z=a1,rz=r_g", None).unwrap_err();
    assert!(matches!(e, RecordError::RotationUnit { .. }), "{e}");
}

/// `--axes` names the other points too; only the columns named are read.
#[test]
fn given_points_pick_their_columns() {
    use crate::time::Point::*;
    let c = map(
        "t_s,a1,b1,f1,r1",
        "z=a1,backrest_x=b1,feet_z=f1,seat_rx=r1",
        None,
    )
    .unwrap();
    assert_eq!(c.axes.iter().count(), 1);
    let got: Vec<(PointAxis, usize, NamedBy)> = c
        .points
        .iter()
        .map(|(p, col)| (p, col.index, col.named_by))
        .collect();
    assert_eq!(
        got,
        [
            (point(Backrest, Axis::X), 2, NamedBy::Given),
            (point(Feet, Axis::Z), 3, NamedBy::Given),
            (point(Rotation, Axis::X), 4, NamedBy::Given),
        ]
    );
    let (axes, points) = parse_channels("backrest_y=q, RZ = w ,x=e").unwrap();
    assert_eq!(axes.get(Axis::X).map(String::as_str), Some("e"));
    assert_eq!(
        points.get(point(Backrest, Axis::Y)).map(String::as_str),
        Some("q")
    );
    assert_eq!(
        points.get(point(Rotation, Axis::Z)).map(String::as_str),
        Some("w")
    );
    for bad in [
        "backrest_x=a,backrest_x=b",
        "rx=a,seat_rx=b",
        "backrest_q=a",
        "feet_z=",
        "back_x=a",
    ] {
        assert!(
            matches!(parse_channels(bad), Err(RecordError::BadAxes { .. })),
            "{bad}"
        );
    }
    let e = parse_channels("rx=a,seat_rx=b").unwrap_err().to_string();
    assert!(e.contains("rx is named twice"), "{e}");
    // Where only the seat's axes mean anything (a day's exposure), a point is refused.
    let e = parse_axes("z=a,backrest_x=b").unwrap_err().to_string();
    assert!(e.contains("'backrest_x' is another measuring point"), "{e}");
}
