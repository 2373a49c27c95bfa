//! Day files as people write them: hours as text or minutes, a whole day
//! summed to within float error, every value capped as a record's cells
//! are, a record's `fs` and `remove_mean`, the `[report]` table.

use biodyn::exposure::{DayError, DayFile, MAX_AW, Meta, Source};
use std::path::Path;

fn parse(text: &str) -> Result<DayFile, DayError> {
    DayFile::parse(text, "day.toml", Path::new("/site"))
}

fn refused(text: &str) -> String {
    let m = parse(text).expect_err("refused").to_string();
    assert!(m.starts_with("day.toml"), "{m}");
    assert!(!m.contains('\n'), "{m}");
    assert!(!m.contains("--"), "a library message names no flag: {m}");
    m
}

/// One operation called "drive" with `extra` lines.
fn one(extra: &str) -> String {
    format!("[[operation]]\nname = \"drive\"\n{extra}\n")
}

fn hours_of(line: &str) -> f64 {
    parse(&one(&format!("{line}\naw_m_s2 = {{ z = 0.5 }}")))
        .unwrap_or_else(|e| panic!("{line}: {e}"))
        .operations[0]
        .hours
}

#[test]
fn hours_as_text_or_minutes() {
    assert_eq!(hours_of("hours = \"3:15\""), 3.25);
    assert_eq!(hours_of("hours = \"3h15\""), 3.25);
    assert_eq!(hours_of("hours = \"45min\""), 0.75);
    assert_eq!(hours_of("hours = \"2.5\""), 2.5);
    assert_eq!(hours_of("hours = 3"), 3.0);
    assert_eq!(hours_of("minutes = 195"), 3.25);
    assert_eq!(hours_of("minutes = 1440"), 24.0);
}

#[test]
fn bad_hours_and_minutes_are_named_with_the_forms() {
    let m = refused(&one("hours = \"3:75\"\naw_m_s2 = { z = 0.5 }"));
    assert_eq!(
        m,
        "day.toml:3: operation 1 ('drive'): hours = \"3:75\": minutes past the hour are 0 to 59; write e.g. hours = \"4:15\""
    );
    let m = refused(&one("hours = \"half a day\"\naw_m_s2 = { z = 0.5 }"));
    assert!(
        m.contains("hours = \"half a day\": not hours;")
            && m.contains("6.5, 6:30, 6h30, 6h or 45min"),
        "{m}"
    );
    let m = refused(&one("hours = \"25:00\"\naw_m_s2 = { z = 0.5 }"));
    assert!(m.contains("at most 24"), "{m}");
    let m = refused(&one("hours = 2\nminutes = 30\naw_m_s2 = { z = 0.5 }"));
    assert!(
        m.contains("day.toml:4: operation 1 ('drive'): minutes = 30: given with hours"),
        "{m}"
    );
    for bad in ["0", "-5", "1441", "nan"] {
        let m = refused(&one(&format!("minutes = {bad}\naw_m_s2 = {{ z = 0.5 }}")));
        assert!(
            m.contains("minutes = ") && m.contains("at most 1440"),
            "{m}"
        );
    }
    let m = refused(&one("hours = true\naw_m_s2 = { z = 0.5 }"));
    assert!(m.contains("hours as a number (3.25) or a text"), "{m}");
    let m = refused(&one("aw_m_s2 = { z = 0.5 }"));
    assert!(
        m.contains("hours: missing") && m.contains("minutes = 150"),
        "{m}"
    );
}

#[test]
fn a_whole_day_summed_in_floats_is_a_day() {
    // 0.1 + 16.1 + 7.8 = 24.000000000000004 in binary floating point.
    let day = [0.1, 16.1, 7.8]
        .iter()
        .map(|h| one(&format!("hours = {h}\naw_m_s2 = {{ z = 0.5 }}")))
        .collect::<String>();
    let sum: f64 = [0.1, 16.1, 7.8].iter().sum();
    assert!(sum > 24.0, "{sum}");
    assert!(parse(&day).is_ok());
    // A minute over is still refused, in hours and minutes.
    let over = format!("{day}{}", one("minutes = 1\naw_m_s2 = { z = 0.5 }"));
    let m = refused(&over);
    assert!(
        m.contains("add up to 24 h 1 min, more than the 24 h of a day"),
        "{m}"
    );
}

#[test]
fn every_value_is_capped_as_records_are() {
    for (line, field, cap) in [
        (
            "aw_m_s2 = { z = 1e308 }",
            "aw_m_s2.z = 1e308",
            "cap of 1e4 m/s²",
        ),
        (
            "aw_m_s2 = { x = 10000.5 }",
            "aw_m_s2.x = 10000.5",
            "cap of 1e4 m/s²",
        ),
        (
            "aw_m_s2 = { z = 1 }\nvdv_m_s175 = { z = 2e6 }\nmeasured_s = 600",
            "vdv_m_s175.z = 2e6",
            "cap of 1e6 m/s^1.75",
        ),
        (
            "aw_m_s2 = { z = 1 }\ndz_m_s2 = 1e300\nmeasured_s = 600",
            "dz_m_s2 = 1e300",
            "cap of 1e6 m/s²",
        ),
    ] {
        let m = refused(&one(&format!("hours = 1\n{line}")));
        assert!(
            m.contains(&format!("operation 1 ('drive'): {field}: ")) && m.contains(cap),
            "{line}: {m}"
        );
    }
    // At the cap is allowed.
    assert!(parse(&one(&format!("hours = 1\naw_m_s2 = {{ z = {MAX_AW} }}"))).is_ok());
    for t in ["1e-300", "1", "2e6"] {
        let m = refused(&one(&format!(
            "hours = 1\naw_m_s2 = {{ z = 1 }}\nvdv_m_s175 = {{ z = 5 }}\nmeasured_s = {t}"
        )));
        assert!(
            m.contains(&format!("measured_s = {t}: ")) && m.contains("from 2 to 1e6 s"),
            "{m}"
        );
    }
}

/// The caps keep the sheet finite: the largest values allowed give a
/// finite day (no `inf` points with exit status 0).
#[test]
fn the_largest_values_allowed_give_a_finite_day() {
    let text = one(
        "hours = 24\naw_m_s2 = { x = 1e4, z = 1e4 }\nvdv_m_s175 = { x = 1e6, z = 1e6 }\ndz_m_s2 = 1e6\nmeasured_s = 2",
    );
    let day = parse(&format!(
        "spine = \"age=25,years=10,days=240,sex=male\"\n{text}"
    ))
    .unwrap()
    .evaluate(|_| Err::<_, String>("no record".into()))
    .unwrap();
    assert!(day.a8.is_finite() && day.points.is_finite());
    assert!(day.vdv.is_some_and(|(_, v)| v.is_finite()));
    let sp = day.spine.unwrap();
    assert!(sp.dzd.is_finite(), "{}", sp.dzd);
}

#[test]
fn a_record_takes_its_rate_and_its_mean_removed() {
    let d = parse(&one(
        "hours = 1\nrecord = \"r.csv\"\nfs = 1000\nremove_mean = true",
    ))
    .unwrap();
    let Source::Record(r) = &d.operations[0].source else {
        panic!("record")
    };
    assert_eq!((r.fs, r.remove_mean), (Some(1000.0), true));
    let text = d.to_toml();
    assert!(text.contains("fs = 1000.0\nremove_mean = true\n"), "{text}");
    assert_eq!(
        DayFile::parse(&text, "back", Path::new("/site")).unwrap(),
        DayFile {
            origin: "back".into(),
            ..d.clone()
        }
    );
    // Left out: no rate, the mean kept; `remove_mean = false` is not written.
    let d = parse(&one("hours = 1\nrecord = \"r.csv\"\nremove_mean = false")).unwrap();
    let Source::Record(r) = &d.operations[0].source else {
        panic!("record")
    };
    assert_eq!((r.fs, r.remove_mean), (None, false));
    assert!(!d.to_toml().contains("remove_mean"));
    for bad in ["0", "-1", "1e7", "nan", "inf"] {
        let m = refused(&one(&format!("hours = 1\nrecord = \"r.csv\"\nfs = {bad}")));
        assert!(
            m.contains("fs = ") && m.contains("at most 1e6 Hz, e.g. fs = 1000"),
            "{m}"
        );
    }
    let m = refused(&one("hours = 1\nrecord = \"r.csv\"\nremove_mean = \"yes\""));
    assert!(m.contains("remove_mean") || m.contains("bool"), "{m}");
    for extra in ["fs = 1000", "remove_mean = true"] {
        let m = refused(&one(&format!(
            "hours = 1\naw_m_s2 = {{ z = 0.5 }}\n{extra}"
        )));
        assert!(m.contains("an operation with aw_m_s2 has no record"), "{m}");
    }
}

#[test]
fn the_report_table_is_read_checked_and_saved() {
    let text = format!(
        "[report]\nsite = \"North quarry\"\ndate = 2026-12-05\nnotes = \"wet day\"\n\n{}",
        one("hours = 1\naw_m_s2 = { z = 0.5 }")
    );
    let d = parse(&text).unwrap();
    assert_eq!(
        d.report.iter().collect::<Vec<_>>(),
        [
            ("site", "North quarry"),
            ("date", "2026-12-05"),
            ("notes", "wet day")
        ]
    );
    let back = DayFile::parse(&d.to_toml(), "day.toml", Path::new("/site")).unwrap();
    assert_eq!(back, d);
    // No table, nothing written.
    let plain = parse(&one("hours = 1\naw_m_s2 = { z = 0.5 }")).unwrap();
    assert_eq!(plain.report, Meta::default());
    assert!(!plain.to_toml().contains("[report]"));

    let m = refused(&format!(
        "[report]\nsight = \"x\"\n{}",
        one("hours = 1\naw_m_s2 = { z = 0.5 }")
    ));
    assert!(
        m.starts_with("day.toml:2:") && m.contains("sight") && m.contains("calibrated"),
        "{m}"
    );
    let m = refused(&format!(
        "[report]\nworker = \"a\\u001bb\"\n{}",
        one("hours = 1\naw_m_s2 = { z = 0.5 }")
    ));
    assert!(m.starts_with("day.toml:2: report.worker: "), "{m}");
}
