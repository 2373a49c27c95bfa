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
