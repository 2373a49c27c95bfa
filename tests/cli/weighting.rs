//! `biodyn weighting` as a real process: every format read back and its
//! numbers equal to the library's, the list, and every refusal as one error
//! line plus a hint.

use crate::common::{fails, ok, run};
use biodyn::iso2631::Weighting;
use serde_json::Value;

#[test]
fn json_rows_are_the_librarys_analog_and_digital_response() {
    for w in Weighting::ALL {
        let out = ok(&[
            "weighting",
            w.name(),
            "--format",
            "json",
            "--digital",
            "1000",
        ]);
        let v: Value = serde_json::from_str(&out).unwrap();
        assert_eq!(v["name"], w.name());
        assert_eq!(v["purpose"], w.purpose());
        assert_eq!(v["unit"], w.quantity().unit());
        let (lo, hi) = w.band();
        assert_eq!(v["band_hz"][0].as_f64(), Some(lo));
        assert_eq!(v["band_hz"][1].as_f64(), Some(hi));
        assert_eq!(v["params"]["f1_hz"].as_f64(), Some(w.params().f1));
        assert_eq!(v["params"]["k"].as_f64(), Some(w.params().k));
        let rows = v["rows"].as_array().unwrap();
        let centres: Vec<f64> = w.centres().collect();
        assert_eq!(rows.len(), centres.len(), "{}", w.name());
        let d = w.digital(1000.0);
        for (r, f) in rows.iter().zip(centres) {
            let n = |k: &str| r[k].as_f64().unwrap();
            assert_eq!(n("f_hz"), f);
            assert_eq!(n("mag"), w.analog(f).norm());
            assert_eq!(n("phase_deg"), w.analog(f).arg().to_degrees());
            assert_eq!(n("mag_digital"), d.response(f).norm());
            assert_eq!(n("phase_digital_deg"), d.response(f).arg().to_degrees());
        }
    }
}

#[test]
fn csv_has_the_definition_as_comments_then_the_rows() {
    let out = ok(&["weighting", "wm", "--format", "csv"]);
    let (comments, data): (Vec<&str>, Vec<&str>) = out.lines().partition(|l| l.starts_with('#'));
    assert!(
        comments[0].starts_with("# Wm: people in buildings"),
        "{out}"
    );
    assert!(comments.iter().any(|l| l.contains("Q4 0.5")), "{out}");
    assert_eq!(data[0], "f_hz,mag,phase_deg");
    assert_eq!(data.len() - 1, Weighting::Wm.centres().count());
    for (line, f) in data[1..].iter().zip(Weighting::Wm.centres()) {
        let v: Vec<f64> = line.split(',').map(|c| c.parse().unwrap()).collect();
        assert_eq!(
            v,
            [
                f,
                Weighting::Wm.analog(f).norm(),
                Weighting::Wm.analog(f).arg().to_degrees()
            ]
        );
    }
}

#[test]
fn a_linear_grid_from_the_band_flags() {
    let out = ok(&[
        "weighting",
        "Wd",
        "--from",
        "1",
        "--to",
        "2",
        "--step",
        "0.25",
        "--format",
        "csv",
    ]);
    let f: Vec<f64> = out
        .lines()
        .filter(|l| !l.starts_with('#'))
        .skip(1)
        .map(|l| l.split(',').next().unwrap().parse().unwrap())
        .collect();
    assert_eq!(f, [1.0, 1.25, 1.5, 1.75, 2.0]);
}

#[test]
fn the_table_shows_the_definition_and_rounded_rows() {
    let out = ok(&["weighting", "Wk"]);
    for want in [
        "Wk: vertical (z), seated",
        "band       0.5–80 Hz",
        "transition f3 12.5 Hz  f4 12.5 Hz  Q4 0.63",
        "step       f5 2.37 Hz  Q5 0.91  f6 3.35 Hz  Q6 0.91",
        "gain       K 1",
    ] {
        assert!(out.contains(want), "missing {want:?} in\n{out}");
    }
    // |Wk(10 Hz)| = 0.9884 (SPEC §7), four figures.
    let row: Vec<&str> = out
        .lines()
        .find(|l| l.starts_with("10 "))
        .unwrap()
        .split_whitespace()
        .collect();
    assert_eq!(row[..2], ["10", "0.9884"], "{out}");
    let wj = ok(&["weighting", "Wj"]);
    assert!(wj.contains("transition none (f3 = f4 = ∞)"), "{wj}");
}

#[test]
fn no_name_lists_the_eight() {
    let out = ok(&["weighting"]);
    for w in Weighting::ALL {
        assert!(
            out.lines()
                .any(|l| l.starts_with(w.name()) && l.contains(w.purpose())),
            "{} not listed:\n{out}",
            w.name()
        );
    }
    let v: Value = serde_json::from_str(&ok(&["weighting", "--format", "json"])).unwrap();
    assert_eq!(v.as_array().unwrap().len(), 8);
    assert_eq!(v[3]["unit"], "rad/s²");
}

#[test]
fn bad_input_is_one_line_and_a_hint() {
    let e = fails(&["weighting", "Wz"]);
    assert!(
        e.contains("'Wz'") && e.contains("Wb, Wc, Wd, We, Wf, Wj, Wk, Wm"),
        "{e}"
    );
    for (args, says) in [
        (&["weighting", "Wk", "--step", "0"][..], "step"),
        (&["weighting", "Wk", "--step", "-1"], "step"),
        (&["weighting", "Wk", "--step", "nan"], "step"),
        (&["weighting", "Wk", "--from", "10", "--to", "1"], "below"),
        (&["weighting", "Wk", "--step", "1e-9"], "points"),
        (&["weighting", "Wk", "--from", "0"], "from"),
        (&["weighting", "Wk", "--to", "1e300"], "--to"),
        (
            &["weighting", "Wk", "--from", "1.1", "--to", "1.2"],
            "no one-third-octave",
        ),
        (&["weighting", "Wk", "--digital", "0"], "--digital"),
        (&["weighting", "Wk", "--digital", "inf"], "--digital"),
        (&["weighting", "Wk", "--digital", "150"], "fs/2"),
        (&["weighting", "--from", "1"], "need a weighting"),
    ] {
        let e = fails(args);
        assert!(e.contains(says), "{args:?}: {e}");
    }
    // A usage error is clap's, status 2.
    let (code, _, _) = run(&["weighting", "Wk", "--step"]);
    assert_eq!(code, Some(2));
}
