use super::*;

#[test]
fn a_parameter_edit_goes_through_the_library_parser() {
    let mut s = Settings::default();
    assert_eq!(
        s.signal().map(|x| x.to_string()).as_deref(),
        Some("sine:freq=5,amp=5")
    );
    s.commit(Row::Param(0, "freq"), "8").unwrap();
    assert_eq!(s.signal().unwrap().to_string(), "sine:freq=8,amp=5");
    let e = s.commit(Row::Param(0, "amp"), "-1").unwrap_err();
    assert!(e.contains("amp") && e.contains("> 0"), "{e}");
    // checked against fs: a sine at or above fs/2 is refused
    let e = s.commit(Row::Param(0, "freq"), "600").unwrap_err();
    assert!(e.contains("fs/2"), "{e}");
    let e = s.commit(Row::Fs, "10").unwrap_err();
    assert!(e.contains("fs/2"), "{e}");
    assert_eq!(s.fs_hz, 1000.0);
    let e = s.commit(Row::Exposure, "25").unwrap_err();
    assert!(e.contains("24"), "{e}");
    let e = s.commit(Row::Duration, "abc").unwrap_err();
    assert!(e.contains("not a number"), "{e}");
}

#[test]
fn a_sum_is_kept_under_its_first_kind_and_its_rows_name_the_part() {
    let mut s = Settings::default();
    s.commit(
        Row::Spec,
        "random:rms=0.8,band=1-20,seed=1+shock:peak=15,width=0.1,at=5",
    )
    .unwrap();
    assert_eq!(s.kind, Kind::Random);
    assert_eq!(s.kind_label(), "random + shock");
    assert!(s.rows().contains(&Row::Param(1, "peak")));
    assert_eq!(s.row_text(Row::Param(1, "peak")).0, "shock peak");
    s.commit(Row::Param(1, "at"), "2").unwrap();
    assert!(s.signal().unwrap().to_string().ends_with("at=2"));
    s.step_kind(1);
    assert_eq!(s.kind, Kind::Shock);
    s.step_kind(-1);
    assert_eq!(s.kind_label(), "random + shock");
    s.step_kind(3); // shock, class, file
    assert_eq!(s.kind, Kind::File);
    assert!(s.signal().is_none());
    assert_eq!(s.rows()[1], Row::Path);
    assert_eq!(s.rows()[2..4], [Row::Axes, Row::Unit]);
}

#[test]
fn the_axes_row_takes_the_flag_grammar_or_a_bare_z_column() {
    let z = axes_of("acc").unwrap();
    assert_eq!(z.get(Axis::Z).map(String::as_str), Some("acc"));
    assert!(!z.has(Axis::X));
    let xyz = axes_of(" x=ax, z=az ").unwrap();
    assert_eq!(xyz.get(Axis::X).map(String::as_str), Some("ax"));
    assert!(!xyz.has(Axis::Y));
    assert!(axes_of("").unwrap().is_empty());
    // the library's refusal, naming the part
    let e = axes_of("w=ax").unwrap_err();
    assert!(e.contains("'w' is not an axis"), "{e}");
    let e = axes_of("x=a,x=b").unwrap_err();
    assert!(e.contains("x is named twice"), "{e}");
    let mut s = Settings {
        kind: Kind::File,
        ..Settings::default()
    };
    assert!(s.commit(Row::Axes, "z=").is_err());
    assert_eq!(s.axes, "");
    // ←→ on the unit row: header, m/s², g, mm/s², and round again
    let seen: Vec<&str> = (0..5)
        .map(|_| {
            let l = unit_label(s.unit);
            s.step_unit(1);
            l
        })
        .collect();
    assert_eq!(seen, ["from header", "m/s2", "g", "mm/s2", "from header"]);
    // five steps from the header's word: at m/s² now; two back wrap
    assert_eq!(s.unit, Some(Unit::MetrePerSecondSquared));
    s.step_unit(-2);
    assert_eq!(s.unit, Some(Unit::MillimetrePerSecondSquared));
}
