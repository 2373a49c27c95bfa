//! `biodyn fit`'s intervals and what it refuses or writes (issue 19): few
//! degrees of freedom widen the interval, an end never reaches 0 or below
//! the model's floor, `--intervals` picks the method and JSON says which; a
//! data row outside the band's limits is refused with its line; a data
//! file named with control characters still saves a preset that loads.

use crate::common::{fails, ok, run};
use std::path::Path;

fn write(dir: &Path, name: &str, text: &str) -> String {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.to_str().unwrap().to_string()
}

fn json(text: &str) -> serde_json::Value {
    serde_json::from_str(text).unwrap_or_else(|e| panic!("not JSON ({e}): {text}"))
}

/// APMS of paper-75kg at 3, 5 and 7 Hz, ±2 %.
const THREE: &str = "f_hz,apms_mag\n3,79.4887\n5,95.971\n7,56.5444\n";

/// 3 values for 2 parameters: 1 degree of freedom, t = 12.7 and F = 161,
/// not 1.96 and 3.84. The old z interval said "determined" at ±10 %.
#[test]
fn three_points_for_two_parameters_determine_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let data = write(dir.path(), "three.csv", THREE);
    let v = json(&ok(&[
        "fit", "--data", &data, "--free", "k4,c4", "--format", "json",
    ]));
    assert_eq!(v["intervals"], "profile", "{v}");
    assert!(
        (v["interval_threshold"].as_f64().unwrap() - 161.45).abs() < 0.01,
        "{v}"
    );
    for p in v["parameters"].as_array().unwrap() {
        assert_eq!(p["determined"], false, "{p}");
        let (lo, val) = (
            p["ci95_low"].as_f64().unwrap(),
            p["value"].as_f64().unwrap(),
        );
        assert!(lo < 0.6 * val, "{p}");
    }
    let table = ok(&["fit", "--data", &data, "--free", "k4,c4"]);
    assert!(table.contains("F(0.95; 1, 1) = 161.448"), "{table}");
    // The curvature interval, asked for, says so; its t is 12.706.
    let v = json(&ok(&[
        "fit",
        "--data",
        &data,
        "--free",
        "k4,c4",
        "--intervals",
        "curvature",
        "--format",
        "json",
    ]));
    assert_eq!(v["intervals"], "curvature", "{v}");
    let k4 = &v["parameters"][0];
    let (lo, val) = (
        k4["ci95_low"].as_f64().unwrap(),
        k4["value"].as_f64().unwrap(),
    );
    assert!(lo < 0.6 * val, "{k4}");
    let (code, _, e) = run(&["fit", "--data", &data, "--intervals", "exact"]);
    assert_eq!(code, Some(2), "{e}");
    assert!(e.contains("profile") && e.contains("curvature"), "{e}");
}

/// `--free all` printed ends of 0 and 1.455e-15 kg: now every end is null
/// (the interval reaches the box) or inside the box, above the 1 g floor.
#[test]
fn free_all_gives_no_end_at_zero_or_below_the_floor() {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(
        crate::common::root().join("examples/synthetic-stht-apms-3pct-2deg.csv"),
    )
    .unwrap();
    // Every fourth row: the same shape of problem in a quarter of the time.
    let thin: String = text
        .lines()
        .enumerate()
        .filter(|(i, _)| i % 4 == 0)
        .map(|(_, l)| format!("{l}\n"))
        .collect();
    let data = write(dir.path(), "thin.csv", &thin);
    let out = ok(&[
        "fit", "--data", &data, "--free", "all", "--starts", "2", "--format", "json",
    ]);
    let v = json(&out);
    let mut open = 0;
    for p in v["parameters"].as_array().unwrap() {
        let start = p["start"].as_f64().unwrap();
        for key in ["ci95_low", "ci95_high"] {
            match p[key].as_f64() {
                None => {
                    assert!(p[key].is_null(), "{p}");
                    open += 1;
                }
                Some(end) => {
                    assert!(end >= start / 1000.0 * (1.0 - 1e-12), "{key} {p}");
                    assert!(end <= start * 1000.0 * (1.0 + 1e-12), "{key} {p}");
                    if p["name"].as_str().is_some_and(|n| n.starts_with('m')) {
                        assert!(end >= 1e-3, "{key} below a gram: {p}");
                    }
                }
            }
        }
        for piece in p["ci95_pieces"].as_array().unwrap() {
            assert_eq!(piece.as_array().unwrap().len(), 2, "{p}");
        }
    }
    assert!(
        open > 0,
        "twelve free parameters on two functions: some end is open: {v}"
    );
    let table = ok(&["fit", "--data", &data, "--free", "all", "--starts", "2"]);
    assert!(
        table.contains("unbounded: the interval reaches the parameter's box"),
        "{table}"
    );
}

#[test]
fn a_row_outside_the_band_limits_is_refused_with_its_line() {
    let dir = tempfile::tempdir().unwrap();
    let data = write(
        dir.path(),
        "far.csv",
        "f_hz,apms_mag\n1,58\n3,70\n1e300,60\n",
    );
    let e = fails(&["fit", "--data", &data]);
    assert!(
        e.contains(
            "far.csv: line 4, column 1 (f_hz): 1e300 Hz; a frequency must be from 1e-3 to 1e5 Hz"
        ),
        "{e}"
    );
    assert!(!e.contains("undamped"), "{e}");
}

/// The data file's name goes into the preset's description: control
/// characters in it made the save fail after the fit ("it would not load
/// back"). They are written escaped, and the preset loads.
#[test]
fn a_data_name_with_control_characters_saves_a_preset_that_loads() {
    let dir = tempfile::tempdir().unwrap();
    let data = write(dir.path(), "bad\tname\u{1}.csv", THREE);
    let out = dir.path().join("fitted\u{2}.toml");
    let out = out.to_str().unwrap();
    let (code, _, err) = run(&["fit", "--data", &data, "--free", "k4", "--save", out]);
    assert_eq!(code, Some(0), "{err}");
    let text = std::fs::read_to_string(out).unwrap();
    assert!(text.contains(r"bad\tname\u{1}.csv"), "{text}");
    assert!(!text.chars().any(|c| c.is_control() && c != '\n'), "{text}");
    ok(&["preset", "check", out]);
}
