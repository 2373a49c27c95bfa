//! Records shaped as instruments and loggers write them (issue 30): a
//! gravity offset, a clock in ms, units in brackets or none, no header.
//! Each was a wrong EU verdict with exit 0; each is now read right or
//! refused with the reason, the bug planted once per test.

use super::common::{fails, ok, run};
use serde_json::Value;
use std::f64::consts::PI;
use std::path::{Path, PathBuf};

/// Writes `header` and `seconds` of rows at `fs`: the time by `t` (s) and
/// the values by `v`.
fn record(
    dir: &Path,
    name: &str,
    header: &str,
    fs: f64,
    seconds: f64,
    t: impl Fn(f64) -> String,
    v: impl Fn(f64) -> String,
) -> PathBuf {
    let mut s = format!("{header}\n");
    for k in 0..(fs * seconds) as usize {
        let time = k as f64 / fs;
        s.push_str(&format!("{},{}\n", t(time), v(time)));
    }
    let p = dir.join(name);
    std::fs::write(&p, s).unwrap();
    p
}

fn json(args: &[&str]) -> Value {
    let mut a = args.to_vec();
    a.extend(["--format", "json"]);
    serde_json::from_str(&ok(&a)).unwrap()
}

fn verdicts(v: &Value) -> (String, String) {
    let s = |k: &str| v["eu"][k].as_str().unwrap().to_string();
    (s("a8"), s("vdv"))
}

/// The record: 1 + 0.05·sin(2π·5t) g on a DC-coupled z, 10 s and
/// 120 s. It judged A(8) 0.761 "above action value" and VDV 26.25 "above
/// limit value" with exit 0; now it is refused with the way out, and with
/// --remove-mean judged as the vibration alone, the mean named.
#[test]
fn a_gravity_offset_is_refused_or_removed_and_said() {
    let d = tempfile::tempdir().unwrap();
    for seconds in [10.0, 120.0] {
        let g = record(
            d.path(),
            "g.csv",
            "t_s,az_g",
            500.0,
            seconds,
            |t| t.to_string(),
            |t| (1.0 + 0.05 * (2.0 * PI * 5.0 * t).sin()).to_string(),
        );
        let g = g.to_str().unwrap();
        let (code, _, err) = run(&["assess", "--input", g]);
        assert_eq!(code, Some(1), "{err}");
        assert!(
            err.contains("the z axis carries a level of 9.8066 m/s² (1.0000 g)")
                && err.contains("--remove-mean"),
            "{err}"
        );
        let removed = json(&["assess", "--input", g, "--remove-mean"]);
        let clean = record(
            d.path(),
            "c.csv",
            "t_s,az_g",
            500.0,
            seconds,
            |t| t.to_string(),
            |t| (0.05 * (2.0 * PI * 5.0 * t).sin()).to_string(),
        );
        let clean = json(&["assess", "--input", clean.to_str().unwrap()]);
        assert_eq!(verdicts(&removed), verdicts(&clean));
        assert_eq!(verdicts(&removed).0, "below action value");
        let (a, b) = (&removed["seat"]["aw_m_s2"], &clean["seat"]["aw_m_s2"]);
        assert!(
            (a.as_f64().unwrap() / b.as_f64().unwrap() - 1.0).abs() < 1e-9,
            "{a} {b}"
        );
        let m = removed["input"]["axes"]["z"]["mean_removed"]
            .as_f64()
            .unwrap();
        assert!((m - 9.80665).abs() < 1e-9, "{m}");
        let text = ok(&["assess", "--input", g, "--remove-mean"]);
        let first = text.lines().next().unwrap();
        assert!(
            first.contains("mean removed: z 9.807 m/s² (1 g)"),
            "{first}"
        );
    }
}

/// `time_ms,az`: read as seconds it was "60000 s at 0.5 Hz", A(8) 0.000
/// "below action value". Now the name's unit is read: the same as `t_s`.
/// A clock in ms under a bare `t` is refused by the rate rule.
#[test]
fn a_clock_in_ms_is_read_in_ms_and_a_bare_one_is_refused() {
    let d = tempfile::tempdir().unwrap();
    let v = |t: f64| (2.0 * (2.0 * PI * 5.0 * t).sin()).to_string();
    let ms = record(
        d.path(),
        "ms.csv",
        "time_ms,az",
        500.0,
        60.0,
        |t| format!("{}", t * 1e3),
        v,
    );
    let s = record(
        d.path(),
        "s.csv",
        "t_s,az",
        500.0,
        60.0,
        |t| t.to_string(),
        v,
    );
    let a = json(&["assess", "--input", ms.to_str().unwrap()]);
    let b = json(&["assess", "--input", s.to_str().unwrap()]);
    assert_eq!(a["fs_hz"], b["fs_hz"]);
    let (x, y) = (
        a["seat"]["a8_m_s2"].as_f64().unwrap(),
        b["seat"]["a8_m_s2"].as_f64().unwrap(),
    );
    assert!((x / y - 1.0).abs() < 1e-6 && x > 1.15, "{x} {y}");
    assert_eq!(verdicts(&a), verdicts(&b));
    assert_eq!(a["input"]["time_unit"], "ms");
    let bare = record(
        d.path(),
        "bare.csv",
        "t,az",
        500.0,
        60.0,
        |t| format!("{}", t * 1e3),
        v,
    );
    let e = fails(&["assess", "--input", bare.to_str().unwrap()]);
    assert!(
        e.contains("sampling rate 0.5 Hz") && e.contains("t_ms"),
        "{e}"
    );
    // The day refuses it too, naming the operation.
    let day = d.path().join("day.toml");
    std::fs::write(
        &day,
        "[[operation]]\nname = \"haul\"\nhours = 2\nrecord = \"bare.csv\"\n",
    )
    .unwrap();
    let e = fails(&["day", day.to_str().unwrap()]);
    assert!(
        e.contains("operation 1 ('haul')") && e.contains("more than 160 Hz"),
        "{e}"
    );
}

/// `Acc Z [g]` was read as m/s² (9.81× low), and so was a g record with
/// headers `X,Y,Z`. Brackets are read; no unit is assumed m/s² and said.
#[test]
fn units_in_brackets_are_read_and_none_is_said() {
    let d = tempfile::tempdir().unwrap();
    let v = |t: f64| format!("{0},{0},{0}", 0.1 * (2.0 * PI * 5.0 * t).sin());
    let named = record(
        d.path(),
        "n.csv",
        "t_s,ax_g,ay_g,az_g",
        500.0,
        10.0,
        |t| t.to_string(),
        v,
    );
    let n = json(&["assess", "--input", named.to_str().unwrap()]);
    for header in [
        "Time [s],Acc X [g],Acc Y [g],Acc Z [g]",
        "t,X (g),Y (g),Z (g)",
        "t,x in g,y in g,z in g",
    ] {
        let p = record(d.path(), "b.csv", header, 500.0, 10.0, |t| t.to_string(), v);
        let b = json(&["assess", "--input", p.to_str().unwrap()]);
        assert_eq!(b["axes"], n["axes"], "{header}");
        assert_eq!(b["input"]["axes"]["z"]["unit_from"], "header", "{header}");
    }
    let bare = record(
        d.path(),
        "xyz.csv",
        "t,X,Y,Z",
        500.0,
        10.0,
        |t| t.to_string(),
        v,
    );
    let bare = bare.to_str().unwrap();
    let text = ok(&["assess", "--input", bare]);
    let first = text.lines().next().unwrap();
    assert!(
        first.contains("m/s² assumed for X, Y, Z: the header gives no unit"),
        "{first}"
    );
    let j = json(&["assess", "--input", bare]);
    assert_eq!(j["input"]["axes"]["x"]["unit_from"], "assumed");
    let g = json(&["assess", "--input", bare, "--unit", "g"]);
    assert_eq!(g["axes"], n["axes"]);
    assert_eq!(g["input"]["axes"]["y"]["unit_from"], "given");
    let volts = record(
        d.path(),
        "v.csv",
        "t,Acc Z [V]",
        500.0,
        10.0,
        |t| t.to_string(),
        |t| t.to_string(),
    );
    let e = fails(&["assess", "--input", volts.to_str().unwrap()]);
    assert!(
        e.contains("'Acc Z [V]' is in 'V', which is not a unit of acceleration"),
        "{e}"
    );
}

/// A record without a header lost its first sample to a column named
/// `0.00000`; now it is refused, naming line 1 and the fix.
#[test]
fn a_record_without_a_header_is_refused() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path().join("nohead.csv");
    let rows: String = (0..5000)
        .map(|k| {
            let t = k as f64 / 500.0;
            format!("{t:.5},{:.6}\n", (2.0 * PI * 5.0 * t).sin())
        })
        .collect();
    std::fs::write(&p, rows).unwrap();
    let (code, out, err) = run(&["assess", "--input", p.to_str().unwrap()]);
    assert_eq!((code, out.as_str()), (Some(1), ""), "{err}");
    assert!(
        err.contains("line 1 is numbers (0.00000,0.000000), not a header"),
        "{err}"
    );
}

/// A record with x and y only is judged by the Directive on those axes
/// (the same numbers as beside z); the body, driven vertically, is not
/// run, and every output says so; --spine and --plot, which need z, are
/// refused with the reason.
#[test]
fn a_horizontal_record_is_judged_without_the_body() {
    let d = tempfile::tempdir().unwrap();
    let xy = |t: f64| {
        format!(
            "{},{}",
            0.6 * (2.0 * PI * 2.0 * t).sin(),
            0.2 * (2.0 * PI * 3.0 * t).sin()
        )
    };
    let p = record(
        d.path(),
        "xy.csv",
        "t_s,ax,ay",
        500.0,
        20.0,
        |t| t.to_string(),
        xy,
    );
    let full = record(
        d.path(),
        "xyz.csv",
        "t_s,ax,ay,az",
        500.0,
        20.0,
        |t| t.to_string(),
        |t| format!("{},{}", xy(t), 0.01 * (2.0 * PI * 5.0 * t).sin()),
    );
    let p = p.to_str().unwrap();
    let only = json(&["assess", "--input", p]);
    let with_z = json(&["assess", "--input", full.to_str().unwrap()]);
    for a in ["x", "y"] {
        assert_eq!(only["axes"][a], with_z["axes"][a], "{a}");
    }
    assert_eq!(only["health"]["a8_axis"], "x");
    assert_eq!(only["health"], with_z["health"]);
    assert!(only["body"].as_str().unwrap().contains("not run"));
    assert!(only["head"].is_null() && only["model"].is_null());
    let text = ok(&["assess", "--input", p]);
    assert!(text.contains("the record has no z (vertical) axis: the body model is driven vertically and is not run"), "{text}");
    assert!(
        text.contains("A(8) 0.528 m/s² (x): above action value"),
        "{text}"
    );
    let e = fails(&[
        "assess",
        "--input",
        p,
        "--spine",
        "age=25,years=10,days=240,sex=male",
    ]);
    assert!(e.contains("this record has none"), "{e}");
    let svg = d.path().join("f.svg");
    let e = fails(&["assess", "--input", p, "--plot", svg.to_str().unwrap()]);
    assert!(e.contains("has no z"), "{e}");
    assert!(!svg.exists());
    let page = d.path().join("r.html");
    let (code, _, err) = run(&["assess", "--input", p, "--report", page.to_str().unwrap()]);
    assert_eq!(code, Some(0), "{err}");
    let html = std::fs::read_to_string(&page).unwrap();
    assert!(
        html.contains("above action value"),
        "the page carries the verdict"
    );
}

/// A day's record read with `remove_mean = true` is judged as the
/// vibration alone, and the day says what was removed; a record whose
/// header gives no unit is said to be assumed in m/s² — in the table, the
/// JSON and the report (a hostile review found the day silent on both).
#[test]
fn a_day_says_what_its_records_assumed_and_removed() {
    let d = tempfile::tempdir().unwrap();
    let g = |t: f64| (1.0 + 0.05 * (2.0 * PI * 5.0 * t).sin()).to_string();
    record(
        d.path(),
        "g.csv",
        "t_s,az_g",
        500.0,
        20.0,
        |t| t.to_string(),
        g,
    );
    record(
        d.path(),
        "bare.csv",
        "t_s,az",
        500.0,
        20.0,
        |t| t.to_string(),
        |t| (0.5 * (2.0 * PI * 5.0 * t).sin()).to_string(),
    );
    let day = d.path().join("day.toml");
    let op = |name: &str, rec: &str, extra: &str| {
        format!("[[operation]]\nname = \"{name}\"\nhours = 2\nrecord = \"{rec}\"\n{extra}\n")
    };
    std::fs::write(&day, op("lift", "g.csv", "")).unwrap();
    let e = fails(&["day", day.to_str().unwrap()]);
    assert!(
        e.contains("operation 1 ('lift')") && e.contains("remove_mean = true"),
        "{e}"
    );
    std::fs::write(
        &day,
        op("lift", "g.csv", "remove_mean = true") + &op("haul", "bare.csv", ""),
    )
    .unwrap();
    let t = ok(&["day", day.to_str().unwrap()]);
    assert!(t.contains("g.csv: mean removed: z 9.8066 m/s²"), "{t}");
    assert!(t.contains("bare.csv: m/s² assumed for 'az'"), "{t}");
    let j: Value =
        serde_json::from_str(&ok(&["day", day.to_str().unwrap(), "--format", "json"])).unwrap();
    assert_eq!(j["notes"].as_array().unwrap().len(), 2, "{}", j["notes"]);
    let page = d.path().join("day.html");
    let (code, _, err) = run(&[
        "day",
        day.to_str().unwrap(),
        "--report",
        page.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        std::fs::read_to_string(&page)
            .unwrap()
            .contains("mean removed: z 9.8066")
    );
}
