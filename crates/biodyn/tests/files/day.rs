//! Day files: the format read and written back, every refusal naming the
//! file, the line, the operation and the field, and record operations
//! through a resolver.

use biodyn::exposure::{DayError, DayFile, EvalError, Measured, Source};
use biodyn::iso2631::Verdict;
use biodyn::time::{Axis, PerAxis, Unit};
use std::path::Path;

const GOOD: &str = r#"
[[operation]]
name = "haul road"
hours = 3.25
aw_m_s2 = { x = 0.36, y = 0.21, z = 0.52 }
vdv_m_s175 = { x = 5.1, z = 7.0 }
measured_s = 600

[[operation]]
name = "loading"
hours = 2.5
record = "loading.csv"
axes = "x=ax,y=ay,z=az"
unit = "g"
"#;

fn parse(text: &str) -> Result<DayFile, DayError> {
    DayFile::parse(text, "day.toml", Path::new("/site"))
}

/// The message of a refused file, checked to start with the file's name.
fn refused(text: &str) -> String {
    let m = parse(text).expect_err("refused").to_string();
    assert!(m.starts_with("day.toml"), "{m}");
    assert!(!m.contains('\n'), "{m}");
    assert!(!m.contains("--"), "a library message names no flag: {m}");
    m
}

/// One measured operation with `extra` lines.
fn one(extra: &str) -> String {
    format!("[[operation]]\nname = \"drive\"\n{extra}\n")
}

#[test]
fn the_format_reads_as_written() {
    let d = parse(GOOD).unwrap();
    assert_eq!(d.operations.len(), 2);
    let o = &d.operations[0];
    assert_eq!((o.name.as_str(), o.hours), ("haul road", 3.25));
    let Source::Measured {
        aw,
        vdv,
        measured_s,
        ..
    } = &o.source
    else {
        panic!("measured")
    };
    assert_eq!(aw.get(Axis::Y), Some(&0.21));
    assert_eq!(vdv.get(Axis::Y), None);
    assert_eq!(vdv.get(Axis::Z), Some(&7.0));
    assert_eq!(*measured_s, Some(600.0));
    let Source::Record(r) = &d.operations[1].source else {
        panic!("record")
    };
    assert_eq!(r.path, "loading.csv");
    assert_eq!(r.resolved, Path::new("/site/loading.csv"));
    assert_eq!(r.unit, Some(Unit::G));
    assert_eq!(r.axes_text().as_deref(), Some("x=ax,y=ay,z=az"));
}

#[test]
fn parse_save_parse_is_exact() {
    let dir = tempfile::tempdir().unwrap();
    let d = parse(GOOD).unwrap();
    let p = dir.path().join("day.toml");
    d.save(&p).unwrap();
    let back = DayFile::load(&p).unwrap();
    assert_eq!(back.operations, {
        // The record path is taken from the new folder; nothing else moves.
        let mut ops = d.operations.clone();
        if let Source::Record(r) = &mut ops[1].source {
            r.resolved = dir.path().join("loading.csv");
        }
        ops
    });
    // And its text is stable: saving the loaded day writes the same bytes.
    assert_eq!(back.to_toml(), d.to_toml());
}

#[test]
fn a_day_that_would_not_load_back_is_not_saved() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("day.toml");
    std::fs::write(&p, "old").unwrap();
    let mut d = parse(GOOD).unwrap();
    d.operations[0].hours = 30.0;
    let e = d.save(&p).unwrap_err().to_string();
    assert!(
        e.contains("would not load back") && e.contains("hours = 30"),
        "{e}"
    );
    assert_eq!(std::fs::read_to_string(&p).unwrap(), "old");
}

#[test]
fn unknown_keys_are_named_with_their_line() {
    let m = refused(&one("hours = 1\naw_m_s2 = { z = 0.5 }\nhuors = 2"));
    // toml's words, the line (5: [[operation]], name, hours, aw_m_s2, huors) and the key.
    assert!(m.starts_with("day.toml:5:1:"), "{m}");
    assert!(m.contains("unknown field `huors`"), "{m}");
    let m = refused(&one("hours = 1\naw_m_s2 = { z = 0.5, w = 1 }"));
    assert!(m.contains("unknown field `w`"), "{m}");
    let m = refused("speed = 3\n");
    assert!(m.contains("unknown field `speed`"), "{m}");
}

#[test]
fn hours_must_be_over_zero_and_at_most_a_day() {
    for (h, shown) in [
        ("-1", "-1"),
        ("0", "0"),
        ("nan", "NaN"),
        ("inf", "inf"),
        ("25", "25"),
    ] {
        let m = refused(&one(&format!("hours = {h}\naw_m_s2 = {{ z = 0.5 }}")));
        assert!(
            m.contains("day.toml:3: operation 1 ('drive'): hours = ") && m.contains(shown),
            "{h}: {m}"
        );
    }
    let m = refused(&one("aw_m_s2 = { z = 0.5 }"));
    assert!(m.contains("operation 1 ('drive'): hours: missing"), "{m}");
    // 3 × 9 h = 27 h: each is a day's worth, together more than one.
    let nine = one("hours = 9\naw_m_s2 = { z = 0.5 }");
    let m = refused(&nine.repeat(3));
    assert!(m.contains("add up to 27 h, more than the 24 h"), "{m}");
    // 24 h exactly is a day.
    assert!(parse(&one("hours = 24\naw_m_s2 = { z = 0.5 }")).is_ok());
}

#[test]
fn an_operation_has_exactly_one_source() {
    let m = refused(&one("hours = 1"));
    assert!(m.contains("aw_m_s2: missing, and no record either"), "{m}");
    let m = refused(&one("hours = 1\naw_m_s2 = { z = 0.5 }\nrecord = \"a.csv\""));
    assert!(m.contains("aw_m_s2: given with record"), "{m}");
    let m = refused(&one("hours = 1\naw_m_s2 = {}"));
    assert!(m.contains("aw_m_s2 = {}: names no axis"), "{m}");
    let m = refused(&one("hours = 1\naw_m_s2 = { z = 0.5 }\nunit = \"g\""));
    assert!(m.contains("unit = \"g\": reads a record's columns"), "{m}");
    let m = refused(&one("hours = 1\nrecord = \"a.csv\"\nmeasured_s = 60"));
    assert!(m.contains("measured_s: given with record"), "{m}");
    let m = refused(&one("hours = 1\nrecord = \"\""));
    assert!(m.contains("record = \"\": give the path"), "{m}");
}

#[test]
fn a_w_and_vdv_must_be_finite_and_not_negative() {
    let m = refused(&one("hours = 1\naw_m_s2 = { x = 0.3, z = -0.5 }"));
    assert!(
        m.contains(
            "day.toml:4: operation 1 ('drive'): aw_m_s2.z = -0.5: must be a finite number ≥ 0"
        ),
        "{m}"
    );
    let m = refused(&one("hours = 1\naw_m_s2 = { y = nan }"));
    assert!(m.contains("aw_m_s2.y = NaN"), "{m}");
    let m = refused(&one(
        "hours = 1\naw_m_s2 = { z = 0.5 }\nvdv_m_s175 = { z = -3 }\nmeasured_s = 60",
    ));
    assert!(m.contains("vdv_m_s175.z = -3"), "{m}");
}

#[test]
fn a_vdv_needs_its_duration_and_its_axis() {
    let m = refused(&one(
        "hours = 1\naw_m_s2 = { z = 0.5 }\nvdv_m_s175 = { z = 7 }",
    ));
    assert!(m.contains("vdv_m_s175: needs measured_s"), "{m}");
    let m = refused(&one("hours = 1\naw_m_s2 = { z = 0.5 }\nmeasured_s = 600"));
    assert!(
        m.contains("measured_s = 600: is the duration of measured VDVs"),
        "{m}"
    );
    let m = refused(&one(
        "hours = 1\naw_m_s2 = { z = 0.5 }\nvdv_m_s175 = { z = 7 }\nmeasured_s = 0",
    ));
    assert!(m.contains("measured_s = 0: the seconds"), "{m}");
    let m = refused(&one(
        "hours = 1\naw_m_s2 = { z = 0.5 }\nvdv_m_s175 = { x = 7 }\nmeasured_s = 60",
    ));
    assert!(m.contains("vdv_m_s175.x: aw_m_s2 has no x"), "{m}");
}

#[test]
fn bad_unit_and_axes_strings_are_named() {
    let rec = |extra: &str| one(&format!("hours = 1\nrecord = \"a.csv\"\n{extra}"));
    let m = refused(&rec("unit = \"ft/s2\""));
    assert!(
        m.contains("unit = \"ft/s2\": the units are m/s2, g and mm/s2"),
        "{m}"
    );
    for (axes, why) in [
        ("x=ax,w=aw", "'w' is not an axis"),
        ("x=ax,x=ay", "x is named twice"),
        ("z=", "z has no column"),
        ("ax", "'ax' is not AXIS=COLUMN"),
    ] {
        let m = refused(&rec(&format!("axes = \"{axes}\"")));
        assert!(m.contains(&format!("axes = \"{axes}\": {why}")), "{m}");
    }
}

#[test]
fn names_and_empty_files() {
    let m = refused("[[operation]]\nname = \"  \"\nhours = 1\naw_m_s2 = { z = 0.5 }\n");
    assert!(
        m.contains("day.toml:2: operation 1 ('  '): name = \"  \": a name is one line"),
        "{m}"
    );
    let m = refused("[[operation]]\nname = \"a\\nb\"\nhours = 1\naw_m_s2 = { z = 0.5 }\n");
    assert!(
        m.contains("name = \"a\\nb\""),
        "control characters are escaped: {m}"
    );
    let m = refused("[[operation]]\nhours = 1\naw_m_s2 = { z = 0.5 }\n");
    assert!(m.contains("operation 1 (''): name: missing"), "{m}");
    let m = refused("");
    assert!(m.contains("day.toml: no [[operation]] tables"), "{m}");
    let m = refused("schema = 2\n");
    assert!(m.contains("day.toml:1: schema = 2"), "{m}");
}

#[test]
fn unreadable_files_are_named() {
    let dir = tempfile::tempdir().unwrap();
    let e = DayFile::load(dir.path()).unwrap_err().to_string();
    assert!(
        e.contains("is a directory") && e.contains("day file"),
        "{e}"
    );
    let p = dir.path().join("big.toml");
    std::fs::File::create(&p)
        .unwrap()
        .set_len((1 << 20) + 1)
        .unwrap();
    let e = DayFile::load(&p).unwrap_err().to_string();
    assert!(e.contains("over the 1 MiB cap"), "{e}");
}

/// z 0.8 m/s² (in the record) for 2.5 h beside the haul road: the day's z
/// A(8) = √(0.52²·3.25/8 + 0.8²·2.5/8) = √(0.10985 + 0.2) = 0.556642…
#[test]
fn records_come_through_the_resolver() {
    let d = parse(GOOD).unwrap();
    let mut asked = Vec::new();
    let day = d
        .evaluate(|r| {
            asked.push(r.resolved.clone());
            let mut m = PerAxis::default();
            m.set(
                Axis::Z,
                Measured {
                    aw: 0.8,
                    vdv: Some(9.0),
                    measured_s: Some(600.0),
                    dz: None,
                },
            );
            Ok::<_, String>(m)
        })
        .unwrap();
    assert_eq!(asked, vec![Path::new("/site/loading.csv").to_path_buf()]);
    assert_eq!(day.a8_axis, Axis::Z);
    assert!((day.a8 - 0.309_85f64.sqrt()).abs() < 1e-12, "{}", day.a8);
    assert_eq!(day.eu_a8, Verdict::AboveAction);
    // y and x lack a VDV in one operation each: no day VDV.
    assert_eq!(day.vdv, None);

    let e = d
        .evaluate(|_| Err::<PerAxis<Measured>, _>("no reader"))
        .unwrap_err();
    assert!(matches!(e, EvalError::Record { number: 2, .. }));
    assert_eq!(
        e.to_string(),
        "day.toml: operation 2 ('loading'): record = \"loading.csv\": no reader"
    );
    let e = d
        .evaluate(|_| {
            let mut m = PerAxis::default();
            m.set(
                Axis::X,
                Measured {
                    aw: -1.0,
                    vdv: None,
                    measured_s: None,
                    dz: None,
                },
            );
            Ok::<_, String>(m)
        })
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with(
            "day.toml: operation 2 ('loading'): record = \"loading.csv\": axis x gave a_w -1"
        ),
        "{e}"
    );
}
