//! `biodyn assess --spine`: ISO 2631-5:2018's block in the table and the
//! JSON, equal to the library's stream and to Annex C by hand; motion
//! sickness (MSDV) beside seat and head; every refusal in one line.

use super::common::{fails, ok, run};
use biodyn::iso2631::spine::{Person, Sex, SpineAccumulator};
use serde_json::Value;
use std::f64::consts::PI;
use std::fmt::Write;
use std::path::{Path, PathBuf};

/// Five shocks with a rebound as deep (a whole cycle: no mean), 40 m/s²
/// up, at 1 kHz over 20 s.
fn shocks() -> Vec<f64> {
    let fs = 1000.0;
    let mut z = vec![0.0; 20_000];
    for i in 0..5 {
        let k0 = ((2.0 + 3.5 * i as f64) * fs) as usize;
        let m = (0.07 * fs) as usize;
        for j in 0..2 * m {
            let u = j as f64 / m as f64;
            z[k0 + j] = 40.0 * (PI * u).sin();
        }
    }
    z
}

fn write(dir: &Path, z: &[f64]) -> PathBuf {
    let mut s = String::from("t_s,az_m_s2\n");
    for (k, v) in z.iter().enumerate() {
        writeln!(s, "{},{v}", k as f64 / 1000.0).unwrap();
    }
    let p = dir.join("ride.csv");
    std::fs::write(&p, s).unwrap();
    p
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

const WHO: &str = "age=25,years=10,days=240,sex=male";

#[test]
fn the_spine_block_is_the_librarys_and_annex_c_by_hand() {
    let d = tempfile::tempdir().unwrap();
    let z = shocks();
    let p = write(d.path(), &z);
    let path = p.to_str().unwrap();
    let args = ["assess", "--input", path, "--exposure", "4", "--spine", WHO];
    let j: Value = serde_json::from_str(&ok(&[&args[..], &["--format", "json"]].concat())).unwrap();
    let s = &j["spine"];
    let mut acc = SpineAccumulator::new(1000.0);
    z.iter().for_each(|&a| acc.push(a));
    let lib = acc
        .finish(&Person::new(25.0, 10, 240, Sex::Male).unwrap(), 4.0)
        .unwrap();
    assert_eq!(num(&s["dz_m_s2"]), lib.dose.dz);
    assert_eq!(s["peaks"].as_u64(), Some(lib.dose.count));
    assert!(lib.dose.count >= 5);
    // Formula 4 and Annex C by hand from the printed Dz.
    let dz = num(&s["dz_m_s2"]);
    let dzd = dz * (4.0 * 3600.0 / 20.0f64).powf(1.0 / 6.0);
    assert!((num(&s["dzd_m_s2"]) - dzd).abs() < 1e-9 * dzd);
    let sd = 0.029 * dzd;
    assert!((num(&s["sd_mpa"]) - sd).abs() < 1e-12);
    let r = (1..=10)
        .map(|i| {
            (sd * 240f64.powf(1.0 / 6.0) / (6.75 - 0.052 * (25.0 + i as f64) - 0.029 * 9.81))
                .powi(6)
        })
        .sum::<f64>()
        .powf(1.0 / 6.0);
    assert!((num(&s["r"]) - r).abs() < 1e-12, "{} vs {r}", s["r"]);
    let p = 1.0 - (-(r / 1.613).powf(2.799)).exp();
    assert!((num(&s["probability"]) - p).abs() < 1e-12);
    let band = if r < 0.72 {
        "low"
    } else if r < 1.42 {
        "moderate"
    } else if r < 2.17 {
        "high"
    } else {
        "very high"
    };
    assert_eq!(s["band"], band);
    assert_eq!(s["person"]["sex"], "male");
    assert_eq!(s["largest_peaks"].as_array().map(Vec::len), Some(5));
    // The table says the same, in words.
    let t = ok(&args);
    assert!(
        t.contains("Multiple shocks, the spine (ISO 2631-5:2018"),
        "{t}"
    );
    assert!(
        t.contains(&format!("risk factor R                        {r:.2}")),
        "{t}"
    );
    assert!(t.contains("probability of an adverse health effect"), "{t}");
    assert!(t.contains("largest peaks: "), "{t}");
    assert!(
        !t.contains("--spine"),
        "no advice to add what is there: {t}"
    );
}

/// MSDV of seat and head: (∫ a_wf² dt)^½ = a_wf·√T over the record, a_wf·√T0
/// over the exposure, and a third of that in per cent.
#[test]
fn motion_sickness_is_reported_for_seat_and_head() {
    let j: Value = serde_json::from_str(&ok(&[
        "assess",
        "--signal",
        "sine:freq=0.2,amp=1",
        "--duration",
        "100",
        "--fs",
        "200",
        "--exposure",
        "2",
        "--format",
        "json",
    ]))
    .unwrap();
    for who in ["seat", "head"] {
        let c = &j[who];
        let awf = num(&c["awf_m_s2"]);
        assert!((num(&c["msdv_m_s15"]) - awf * 10.0).abs() < 1e-9, "{who}");
        assert!((num(&c["msdv_exposure_m_s15"]) - awf * 7200f64.sqrt()).abs() < 1e-9);
        assert!((num(&c["vomit_pct"]) - num(&c["msdv_exposure_m_s15"]) / 3.0).abs() < 1e-12);
    }
    // A 1 m/s² sine: a_wf = |Wf(0.2 Hz)|/√2, less a little for the start-up.
    let awf = num(&j["seat"]["awf_m_s2"]);
    let want = biodyn::iso2631::Weighting::Wf.analog(0.2).norm() / 2f64.sqrt();
    assert!((awf / want - 1.0).abs() < 0.02, "{awf} vs {want}");
    assert!(j["spine"].is_null());
}

/// ISO 2631-1 Annex D's estimate rests on up to about 70 % vomiting: past it
/// the table, the JSON (beside the number, kept) and the report say "more
/// than 70 %", never "136.4 % may vomit"; under it the number as before.
#[test]
fn motion_sickness_past_70_percent_is_words_in_every_output() {
    let dir = tempfile::tempdir().unwrap();
    let report = dir.path().join("r.html");
    let args = |amp: &'static str, more: &[&'static str]| -> Vec<&'static str> {
        let sig: &'static str = if amp == "4" {
            "sine:freq=0.25,amp=4"
        } else {
            "sine:freq=0.25,amp=1"
        };
        let mut a = vec![
            "assess",
            "--signal",
            sig,
            "--duration",
            "600",
            "--fs",
            "200",
            "--exposure",
            "8",
        ];
        a.extend_from_slice(more);
        a
    };
    let words =
        "more than 70 % of unadapted adults may vomit: beyond the range of Annex D's estimate";
    let j: Value = serde_json::from_str(&ok(&args("4", &["--format", "json"]))).unwrap();
    for who in ["seat", "head"] {
        let c = &j[who];
        assert!(num(&c["vomit_pct"]) > 100.0, "{c}");
        assert_eq!(c["vomit_beyond_annex_d"], true);
        assert_eq!(c["vomit_words"], words);
    }
    let mut a = args("4", &["--report"]);
    let r = report.to_str().unwrap().to_string();
    a.push(&r);
    let (code, t, _) = run(&a);
    assert_eq!(code, Some(0));
    assert_eq!(t.matches(words).count(), 2, "{t}");
    let html = std::fs::read_to_string(&report).unwrap();
    // (the apostrophe is escaped in HTML)
    let head = "more than 70 % of unadapted adults may vomit: beyond the range of Annex D";
    assert_eq!(html.matches(head).count(), 2, "{html}");
    // Under the range: the number, as before.
    let t = ok(&args("1", &[]));
    assert!(
        t.contains(": about ") && t.contains("% of unadapted adults may vomit\n"),
        "{t}"
    );
    assert!(!t.contains("beyond the range"), "{t}");
}

/// A crest factor above 9 without --spine says that ISO 2631-5 applies.
#[test]
fn shocks_without_the_spine_say_that_it_applies() {
    let sig = "random:rms=0.3,band=1-20,seed=2+shock:peak=30,width=0.05,at=10";
    let t = ok(&["assess", "--signal", sig, "--duration", "30"]);
    assert!(
        t.contains("ISO 2631-5 (multiple shocks) applies; add --spine"),
        "{t}"
    );
    let calm = ok(&[
        "assess",
        "--signal",
        "sine:freq=5,amp=1",
        "--duration",
        "30",
    ]);
    assert!(!calm.contains("ISO 2631-5"), "{calm}");
}

/// Each bad person in one line naming the key and value; a record the
/// method cannot judge is an error, never a dose.
#[test]
fn bad_spines_are_refused_with_the_fix() {
    for (spec, says) in [
        (
            "age=-3,years=10,days=240,sex=male",
            "age -3 is out of range",
        ),
        ("age=25,years=0,days=240,sex=male", "years '0'"),
        (
            "age=25,years=10,days=240,sex=male,height=2",
            "unknown key 'height'",
        ),
        ("age=25,years=10", "days, sex are missing"),
        ("age=25,years=10,days=999,sex=male", "days '999'"),
        ("age=25,years=10,days=240,sex=robot", "sex 'robot'"),
        ("age=95,years=10,days=240,sex=male", "passes 100"),
    ] {
        let (code, out, err) = run(&["assess", "--signal", "sine:freq=5,amp=1", "--spine", spec]);
        assert_eq!(code, Some(2), "{spec}: {err}");
        assert!(out.is_empty());
        assert!(
            err.lines().next().is_some_and(|l| l.contains(says)),
            "{spec}: {err}"
        );
    }
    let short = fails(&[
        "assess",
        "--signal",
        "sine:freq=5,amp=1",
        "--duration",
        "0.5",
        "--spine",
        WHO,
    ]);
    // Too short for ISO 2631-1 (2 s) before it is too short for one shock
    // (1 s): no verdict of either.
    assert!(short.contains("too short to judge"), "{short}");
    let d = tempfile::tempdir().unwrap();
    let gravity: Vec<f64> = shocks().iter().map(|a| a + 9.81).collect();
    let p = write(d.path(), &gravity);
    let e = fails(&["assess", "--input", p.to_str().unwrap(), "--spine", WHO]);
    assert!(
        e.contains("level of 9.8") && e.contains("--remove-mean"),
        "{e}"
    );
}

/// A day's dose past what sixth powers hold (dz_m_s2 = 1e60) is a number,
/// or refused naming the field (a cap on day-file values may refuse it
/// first); never inf or null with exit 0. Past the largest float it is
/// refused, naming the operation and dz_m_s2.
#[test]
fn a_huge_day_dose_is_a_number_or_refused_never_inf() {
    let dir = tempfile::tempdir().unwrap();
    let day = |dz: &str, measured: &str| {
        let p = dir.path().join(format!("d{dz}.toml"));
        std::fs::write(
            &p,
            format!(
                "spine = \"age=25,years=10,days=220,sex=male\"\n[[operation]]\nname = \"big\"\nhours = 2\naw_m_s2 = {{ z = 0.5 }}\nmeasured_s = {measured}\ndz_m_s2 = {dz}\n"
            ),
        )
        .unwrap();
        p.display().to_string()
    };
    let p = day("1e60", "600");
    let (code, out, err) = run(&["day", &p, "--format", "json"]);
    if code == Some(0) {
        let v: Value = serde_json::from_str(&out).unwrap();
        let dzd = num(&v["spine"]["dzd_m_s2"]);
        assert!(
            (dzd / (1e60 * 12f64.powf(1.0 / 6.0)) - 1.0).abs() < 1e-12,
            "{dzd}"
        );
        assert!(num(&v["spine"]["r"]).is_finite() && num(&v["spine"]["sd_mpa"]).is_finite());
        let t = ok(&["day", &p]);
        assert!(t.contains("Dzd = (Σ Dz⁶·t_d/t_m)^⅙ = 1.513e60 m/s²"), "{t}");
    } else {
        assert_eq!(code, Some(1), "{err}");
        assert!(err.contains("dz_m_s2"), "{err}");
    }
    let e = fails(&["day", &day("1e308", "1")]);
    assert!(e.contains("operation 1 ('big'): dz_m_s2"), "{e}");
    assert!(!e.contains("inf"), "{e}");
}
