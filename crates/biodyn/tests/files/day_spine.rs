//! Day files that carry ISO 2631-5: the person at the top, each operation's
//! z dose (`dz_m_s2` over `measured_s`, or a record's), the day's daily dose
//! by Formula 5 and Annex C by hand; the round trip; every refusal.

use biodyn::exposure::{DayError, DayFile, EvalError, Measured, Source, measure_record};
use biodyn::iso2631::spine::{Person, Sex, SpineAccumulator};
use biodyn::time::{Axis, PerAxis};
use std::f64::consts::PI;
use std::path::Path;

const DAY: &str = r#"
spine = "age=25,years=10,days=220,sex=male"

[[operation]]
name = "loaded on track"
hours = 4
aw_m_s2 = { x = 0.42, z = 0.61 }
vdv_m_s175 = { z = 11.9 }
dz_m_s2 = 24.5
measured_s = 900

[[operation]]
name = "crane work"
hours = 2.5
aw_m_s2 = { z = 0.31 }
dz_m_s2 = 8.2
measured_s = 600
"#;

fn parse(text: &str) -> Result<DayFile, DayError> {
    DayFile::parse(text, "day.toml", Path::new("/site"))
}

fn no_records(_: &biodyn::exposure::RecordSource) -> Result<PerAxis<Measured>, String> {
    Err("no records here".into())
}

#[test]
fn the_day_dose_is_formula_5_and_annex_c_by_hand() {
    let d = parse(DAY).unwrap();
    assert_eq!(
        d.spine,
        Some(Person::new(25.0, 10, 220, Sex::Male).unwrap())
    );
    let Source::Measured { dz, .. } = &d.operations[1].source else {
        panic!("measured")
    };
    assert_eq!(*dz, Some(8.2));
    let day = d.evaluate(no_records).unwrap();
    let sp = day.spine.expect("the day's spine");
    // Formula 5: (24.5⁶·4 h/900 s + 8.2⁶·2.5 h/600 s)^⅙.
    let hand =
        (24.5f64.powi(6) * 14400.0 / 900.0 + 8.2f64.powi(6) * 9000.0 / 600.0).powf(1.0 / 6.0);
    assert!((sp.dzd - hand).abs() < 1e-9 * hand, "{} vs {hand}", sp.dzd);
    assert!((sp.parts[0].dzd - 24.5 * 16f64.powf(1.0 / 6.0)).abs() < 1e-9);
    // Annex C for a man: Sd = 0.029·Dzd; R over ages 26..35; P Weibull.
    let sd = 0.029 * hand;
    let r = (1..=10)
        .map(|i| {
            (sd * 220f64.powf(1.0 / 6.0) / (6.75 - 0.052 * (25.0 + f64::from(i)) - 0.029 * 9.81))
                .powi(6)
        })
        .sum::<f64>()
        .powf(1.0 / 6.0);
    assert!((sp.risk.r - r).abs() < 1e-12, "{} vs {r}", sp.risk.r);
    assert!((sp.risk.probability - (1.0 - (-(r / 1.613).powf(2.799)).exp())).abs() < 1e-12);
    // Without a person the day has no spine, whatever the doses.
    let plain = parse(&DAY.replace("spine = \"age=25,years=10,days=220,sex=male\"", "")).unwrap();
    assert!(plain.evaluate(no_records).unwrap().spine.is_none());
}

#[test]
fn the_person_and_the_doses_round_trip() {
    let dir = tempfile::tempdir().unwrap();
    let d = parse(DAY).unwrap();
    let p = dir.path().join("day.toml");
    d.save(&p).unwrap();
    let back = DayFile::load(&p).unwrap();
    assert_eq!((back.spine, &back.operations), (d.spine, &d.operations));
    assert_eq!(back.to_toml(), d.to_toml());
    assert!(
        back.to_toml()
            .contains("spine = \"age=25,years=10,days=220,sex=male\"")
    );
}

#[test]
fn every_refusal_names_the_line_and_the_fix() {
    let bad = |from: &str, to: &str| {
        let m = parse(&DAY.replacen(from, to, 1)).expect_err(to).to_string();
        assert!(m.starts_with("day.toml:"), "{m}");
        assert!(!m.contains('\n') && !m.contains("--"), "{m}");
        m
    };
    let m = bad("age=25,years=10", "age=-3,years=10");
    assert!(
        m.starts_with("day.toml:2: spine: age -3 is out of range"),
        "{m}"
    );
    let m = bad("sex=male", "sex=robot");
    assert!(m.contains("sex 'robot'"), "{m}");
    let m = bad("dz_m_s2 = 24.5", "dz_m_s2 = -1");
    assert!(
        m.contains("dz_m_s2 = -1: ISO 2631-5's acceleration dose"),
        "{m}"
    );
    let m = bad("dz_m_s2 = 24.5", "dz_m_s2 = nan");
    assert!(m.contains("dz_m_s2 = NaN"), "{m}");
    let m = bad("aw_m_s2 = { z = 0.31 }", "aw_m_s2 = { x = 0.31 }");
    assert!(m.contains("aw_m_s2 has no z"), "{m}");
    let m = bad("dz_m_s2 = 8.2\nmeasured_s = 600", "dz_m_s2 = 8.2");
    assert!(m.contains("dz_m_s2: needs measured_s"), "{m}");
    let m = bad(
        "aw_m_s2 = { z = 0.31 }\ndz_m_s2 = 8.2",
        "record = \"r.csv\"\ndz_m_s2 = 8.2",
    );
    assert!(m.contains("given with record"), "{m}");
    let m = bad("spine = \"age=25,years=10,days=220,sex=male\"", "spine = 3");
    assert!(m.contains("day.toml:2"), "{m}");
    // A day with a person and an operation without a dose: evaluated, refused.
    let d = parse(&DAY.replacen("dz_m_s2 = 8.2\nmeasured_s = 600", "", 1)).unwrap();
    let e = d.evaluate(no_records).unwrap_err();
    assert!(matches!(e, EvalError::Day(_)));
    let m = e.to_string();
    assert!(
        m.contains("operation 2 ('crane work'): dz_m_s2: missing; the day's spine"),
        "{m}"
    );
}

/// A record operation's dose is the record's own, through the resolver that
/// reads it: the same Dz as the spine's stream over its z column.
#[test]
fn a_record_brings_its_own_dose() {
    let dir = tempfile::tempdir().unwrap();
    let fs = 500.0;
    let z: Vec<f64> = (0..5000)
        .map(|k| {
            let t = k as f64 / fs;
            let shock = if (3.0..3.1).contains(&t) {
                30.0 * (2.0 * PI * (t - 3.0) / 0.1).sin()
            } else {
                0.0
            };
            0.5 * (2.0 * PI * 4.0 * t).sin() + shock
        })
        .collect();
    let mut csv = String::from("t_s,az\n");
    for (k, v) in z.iter().enumerate() {
        csv.push_str(&format!("{},{v}\n", k as f64 / fs));
    }
    std::fs::write(dir.path().join("track.csv"), csv).unwrap();
    let text = "spine = \"age=30,years=5,days=200,sex=female\"\n[[operation]]\nname = \"track\"\nhours = 2\nrecord = \"track.csv\"\n";
    let d = DayFile::parse(text, "day.toml", dir.path()).unwrap();
    let day = d.evaluate(measure_record).unwrap();
    let sp = day.spine.unwrap();
    let mut acc = SpineAccumulator::new(fs);
    z.iter().for_each(|&a| acc.push(a));
    let m = acc.measure().unwrap();
    assert_eq!(sp.parts[0].dz, m.dose.dz);
    assert_eq!(sp.parts[0].measured_s, 10.0);
    assert!((sp.dzd - m.dose.dz * 720f64.powf(1.0 / 6.0)).abs() < 1e-9 * sp.dzd);
    let Some(Measured { dz: Some(_), .. }) = measure_record(match &d.operations[0].source {
        Source::Record(r) => r,
        _ => unreachable!(),
    })
    .unwrap()
    .get(Axis::Z)
    .copied() else {
        panic!("the record's z carries its dose")
    };
    // A record with a gravity offset is judged by neither method: the day
    // is refused, naming the operation, the record and the way out.
    let g: String = std::iter::once("t_s,az\n".to_string())
        .chain(
            z.iter()
                .enumerate()
                .map(|(k, v)| format!("{},{}\n", k as f64 / fs, v + 9.81)),
        )
        .collect();
    std::fs::write(dir.path().join("track.csv"), g).unwrap();
    let m = d.evaluate(measure_record).unwrap_err().to_string();
    assert!(
        m.contains("operation 1 ('track'): record = \"track.csv\"")
            && m.contains("the z axis carries a level of 9.8100 m/s²")
            && m.contains("(remove_mean)"),
        "{m}"
    );
}

/// A resolver's dose is held to the same rules as its a_w: a NaN dose is
/// refused, naming the operation, never summed into the day.
#[test]
fn a_resolvers_bad_dose_is_refused() {
    let text = "spine = \"age=30,years=5,days=200,sex=male\"\n[[operation]]\nname = \"track\"\nhours = 2\nrecord = \"track.csv\"\n";
    let d = parse(text).unwrap();
    let e = d
        .evaluate(|_| {
            let mut m = PerAxis::default();
            m.set(
                Axis::Z,
                Measured {
                    aw: 0.5,
                    vdv: Some(5.0),
                    measured_s: Some(60.0),
                    dz: Some(f64::NAN),
                },
            );
            Ok::<_, String>(m)
        })
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("operation 1 ('track'): record") && e.contains("dose NaN"),
        "{e}"
    );
}
