//! Tri-axial records through `biodyn assess` and `simulate` as real
//! processes: columns mapped to axes by header or `--axes`, units, the
//! Directive's highest-axis rule (ISO 2631-1 §7.2.3, 2002/44/EC Annex B),
//! and every refusal of an ambiguous record.

use super::common::{fails, ok};
use serde_json::Value;
use std::f64::consts::PI;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// |W(f)| of ISO 2631-1 Annex A, written here from the standard's formula
/// (band limits f1 0.4 Hz, f2 100 Hz, Q 1/√2; a-v transition f3, f4, Q4;
/// the optional upward step f5, Q5, f6, Q6).
pub(super) fn weighting(f: f64, f3: f64, f4: f64, q4: f64, step: Option<[f64; 4]>) -> f64 {
    let s = |x: f64| (0.0, 2.0 * PI * x); // j·2πx
    let w = |x: f64| 2.0 * PI * x;
    let (sr, si) = s(f);
    let cm = |a: (f64, f64), b: (f64, f64)| (a.0 * b.0 - a.1 * b.1, a.0 * b.1 + a.1 * b.0);
    let abs = |a: (f64, f64)| (a.0 * a.0 + a.1 * a.1).sqrt();
    let sc = |k: f64| (sr * k, si * k);
    let add = |a: (f64, f64), b: (f64, f64)| (a.0 + b.0, a.1 + b.1);
    let s2 = cm((sr, si), (sr, si));
    // 1 + s/(Q ω) + (s/ω)²
    let quad = |q: f64, om: f64| {
        add(
            add((1.0, 0.0), sc(1.0 / (q * om))),
            (s2.0 / om / om, s2.1 / om / om),
        )
    };
    let q12 = 1.0 / 2f64.sqrt();
    // High-pass: s²/(ω1² (1 + s/(Q ω1) + (s/ω1)²)) has |·| = |s/ω1|² / |quad|.
    let hp = (f / 0.4).powi(2) / abs(quad(q12, w(0.4)));
    let lp = 1.0 / abs(quad(q12, w(100.0)));
    let t = abs(add((1.0, 0.0), sc(1.0 / w(f3)))) / abs(quad(q4, w(f4)));
    let st = step.map_or(1.0, |[f5, q5, f6, q6]| {
        abs(quad(q5, w(f5))) / abs(quad(q6, w(f6))) * (f5 / f6).powi(2)
    });
    hp * lp * t * st
}

pub(super) fn wk(f: f64) -> f64 {
    weighting(f, 12.5, 12.5, 0.63, Some([2.37, 0.91, 3.35, 0.91]))
}

pub(super) fn wd(f: f64) -> f64 {
    weighting(f, 2.0, 2.0, 0.63, None)
}

/// One sine per axis: (header, amplitude m/s², frequency Hz); 30 s at 1 kHz.
pub(super) fn write(
    dir: &Path,
    name: &str,
    header: &[&str],
    sines: &[(f64, f64)],
    scale: f64,
) -> PathBuf {
    let mut s = format!("t_s,{}\n", header.join(","));
    for k in 0..30_000 {
        let t = k as f64 / 1000.0;
        write!(s, "{t}").unwrap();
        for &(amp, f) in sines {
            write!(s, ",{}", amp * (2.0 * PI * f * t).sin() / scale).unwrap();
        }
        s.push('\n');
    }
    let p = dir.join(name);
    std::fs::write(&p, s).unwrap();
    p
}

pub(super) fn json(args: &[&str]) -> Value {
    let mut a = args.to_vec();
    a.extend(["--format", "json"]);
    serde_json::from_str(&ok(&a)).unwrap()
}

pub(super) fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// The report: a t_s,ax,ay,az record was judged on ax with Wk. Now
/// each axis gets its weighting and k, and the day is the highest axis's:
/// here z (0.75 m/s²: above the action value), with x small.
#[test]
fn a_tri_axial_record_is_judged_per_axis_and_on_its_highest() {
    let d = tempfile::tempdir().unwrap();
    let sines = [(0.1, 1.0), (0.05, 1.6), (1.0, 5.0)];
    let p = write(d.path(), "seat.csv", &["ax", "ay", "az"], &sines, 1.0);
    let v = json(&["assess", "--input", p.to_str().unwrap(), "--exposure", "8"]);
    let mut keys: Vec<&str> = v["axes"]
        .as_object()
        .unwrap()
        .keys()
        .map(String::as_str)
        .collect();
    keys.sort();
    assert_eq!(keys, ["x", "y", "z"]);
    let per_axis_keys = [
        "a8_m_s2",
        "aw_m_s2",
        "crest_factor",
        "hours_to_eav",
        "hours_to_elv",
        "hours_to_vdv_eav",
        "hours_to_vdv_elv",
        "k_comfort",
        "k_health",
        "mtvv_m_s2",
        "peak_m_s2",
        "points",
        "vdv_exposure_m_s175",
        "vdv_m_s175",
        "weighting",
    ];
    for (axis, (amp, _), w, k, name) in [
        ("x", sines[0], wd(sines[0].1), 1.4, "Wd"),
        ("y", sines[1], wd(sines[1].1), 1.4, "Wd"),
        ("z", sines[2], wk(sines[2].1), 1.0, "Wk"),
    ] {
        let a = &v["axes"][axis];
        let mut ks: Vec<&str> = a.as_object().unwrap().keys().map(String::as_str).collect();
        ks.sort();
        assert_eq!(ks, per_axis_keys, "{axis}");
        assert_eq!(
            (
                a["weighting"].as_str(),
                num(&a["k_health"]),
                num(&a["k_comfort"])
            ),
            (Some(name), k, 1.0)
        );
        // a_w of a sine: amp/√2·|W(f)|; the high-pass settles within the first seconds.
        let want = amp / 2f64.sqrt() * w;
        let aw = num(&a["aw_m_s2"]);
        assert!((aw / want - 1.0).abs() < 0.01, "{axis}: a_w {aw} vs {want}");
        // A(8) over 8 h is k·a_w; the VDV over 8 h is k·VDV·(8 h / 30 s)^¼.
        assert!((num(&a["a8_m_s2"]) - k * aw).abs() < 1e-12, "{axis}");
        let vdv = num(&a["vdv_m_s175"]);
        let want_vdv = k * vdv * (8.0 * 3600.0 / 30.0f64).powf(0.25);
        assert!(
            (num(&a["vdv_exposure_m_s175"]) / want_vdv - 1.0).abs() < 1e-12,
            "{axis}"
        );
    }
    let h = &v["health"];
    assert_eq!(h["a8_axis"], "z");
    assert_eq!(h["a8_m_s2"], v["axes"]["z"]["a8_m_s2"]);
    assert_eq!(h["eu_a8"], "above action value");
    assert_eq!(v["eu"]["a8"], h["eu_a8"]);
    // The body is driven by z: its seat channel is the z axis.
    assert_eq!(v["seat"]["aw_m_s2"], v["axes"]["z"]["aw_m_s2"]);
    // Comfort: √Σ a_w² (k = 1 on every axis).
    let sum: f64 = ["x", "y", "z"]
        .iter()
        .map(|a| num(&v["axes"][*a]["aw_m_s2"]).powi(2))
        .sum();
    assert!((num(&v["comfort"]["vector_sum_m_s2"]) - sum.sqrt()).abs() < 1e-12);
    // The input block names the file, each axis's column and unit.
    let i = &v["input"];
    assert_eq!(i["file"], p.to_str().unwrap());
    assert_eq!(i["time_column"], "t_s");
    for (a, c) in [("x", "ax"), ("y", "ay"), ("z", "az")] {
        assert_eq!(i["axes"][a]["column"], c);
        assert_eq!(i["axes"][a]["unit"], "m/s2");
        assert_eq!(i["axes"][a]["named_by"], "header");
    }
}

/// 1.4·a_wx over a_wz: x rules the day. x 0.6 m/s² at 1.5 Hz gives
/// a_w ≈ 0.42, 1.4·0.42 = 0.59 > 0.5 (action); z alone (0.5 m/s² at 5 Hz,
/// a_w ≈ 0.37) would read "below action value".
#[test]
fn the_fore_and_aft_axis_rules_when_its_k_weighted_value_is_highest() {
    let d = tempfile::tempdir().unwrap();
    let p = write(
        d.path(),
        "x.csv",
        &["seat_x_m_s2", "seat_z_m_s2"],
        &[(0.6, 1.5), (0.5, 5.0)],
        1.0,
    );
    let v = json(&["assess", "--input", p.to_str().unwrap()]);
    let x = num(&v["axes"]["x"]["aw_m_s2"]);
    let z = num(&v["axes"]["z"]["aw_m_s2"]);
    assert!(1.4 * x > 0.5 && z < 0.5, "x {x}, z {z}");
    assert_eq!(v["health"]["a8_axis"], "x");
    assert!((num(&v["health"]["a8_m_s2"]) - 1.4 * x).abs() < 1e-12);
    assert_eq!(v["health"]["eu_a8"], "above action value");
    assert!(v["axes"]["y"].is_null());
    let table = ok(&["assess", "--input", p.to_str().unwrap()]);
    assert!(table.contains("x *"), "{table}");
    assert!(
        table.contains(&format!("A(8) {:.3} m/s² (x): above action value", 1.4 * x)),
        "{table}"
    );
}

/// The same record in m/s², g and mm/s², by suffix or by --unit: the same
/// numbers (1 g = 9.80665 m/s²).
#[test]
fn units_by_suffix_or_flag_give_the_same_assessment() {
    let d = tempfile::tempdir().unwrap();
    let sines = [(0.3, 1.5), (1.0, 5.0)];
    let base = write(d.path(), "ms2.csv", &["ax", "az"], &sines, 1.0);
    let g = write(d.path(), "g.csv", &["ax_g", "az_g"], &sines, 9.80665);
    let bare_g = write(d.path(), "bare_g.csv", &["ax", "az"], &sines, 9.80665);
    let mm = write(d.path(), "mm.csv", &["ax_mm_s2", "az_mm_s2"], &sines, 1e-3);
    let want = json(&["assess", "--input", base.to_str().unwrap()]);
    for (p, extra) in [
        (&g, None),
        (&bare_g, Some("g")),
        (&mm, None),
        (&base, Some("m/s2")),
    ] {
        let mut args = vec!["assess", "--input", p.to_str().unwrap()];
        if let Some(u) = extra {
            args.extend(["--unit", u]);
        }
        let v = json(&args);
        for a in ["x", "z"] {
            let (got, w) = (
                num(&v["axes"][a]["aw_m_s2"]),
                num(&want["axes"][a]["aw_m_s2"]),
            );
            assert!((got / w - 1.0).abs() < 1e-5, "{p:?} {a}: {got} vs {w}");
        }
    }
    let v = json(&["assess", "--input", g.to_str().unwrap()]);
    assert_eq!(v["input"]["axes"]["z"]["unit"], "g");
    // Read as m/s² the g record is 9.81 times too low: the reason units matter.
    let v = json(&["assess", "--input", bare_g.to_str().unwrap()]);
    let ratio = num(&want["axes"]["z"]["aw_m_s2"]) / num(&v["axes"]["z"]["aw_m_s2"]);
    assert!((ratio - 9.80665).abs() < 1e-3, "{ratio}");
}

/// One acceleration column with no axis in its name is z, and the output
/// says so; `--column C` is `--axes z=C`.
#[test]
fn one_unnamed_column_is_vertical_and_said_to_be() {
    let d = tempfile::tempdir().unwrap();
    let p = write(d.path(), "one.csv", &["acc"], &[(1.0, 5.0)], 1.0);
    let t = ok(&["assess", "--input", p.to_str().unwrap()]);
    assert!(
        t.contains("z = acc (m/s2), the only acceleration column, taken as vertical"),
        "{t}"
    );
    let v = json(&["assess", "--input", p.to_str().unwrap()]);
    assert_eq!(v["input"]["axes"]["z"]["named_by"], "only column");
    let c = json(&["assess", "--input", p.to_str().unwrap(), "--column", "acc"]);
    let a = json(&["assess", "--input", p.to_str().unwrap(), "--axes", "z=acc"]);
    assert_eq!(c["axes"], a["axes"]);
    assert_eq!(c["input"]["axes"]["z"]["named_by"], "given");
    assert_eq!(c["axes"]["z"], v["axes"]["z"]);
}

/// Every ambiguous or contradictory record is refused with the reason and
/// the fix, exit 1, nothing on stdout.
#[test]
fn ambiguous_records_are_refused_with_the_fix() {
    let d = tempfile::tempdir().unwrap();
    let s = |n: usize| vec![(1.0, 5.0); n];
    let two = write(d.path(), "two.csv", &["acc1", "acc2"], &s(2), 1.0);
    let extra = write(
        d.path(),
        "extra.csv",
        &["ax", "ay", "az", "speed"],
        &s(4),
        1.0,
    );
    let same = write(d.path(), "same.csv", &["az", "acc_z"], &s(2), 1.0);
    let clash = write(d.path(), "clash.csv", &["az_g"], &s(1), 1.0);
    let xy = write(d.path(), "xy.csv", &["ax", "ay"], &s(2), 1.0);
    let path = |p: &PathBuf| p.to_str().unwrap().to_string();
    let cases: Vec<(Vec<String>, Vec<&str>)> = vec![
        (
            vec![path(&two)],
            vec!["acc1, acc2", "--axes x=COL,y=COL,z=COL"],
        ),
        (
            vec![path(&extra)],
            vec![
                "ax, ay, az, speed",
                "no axis in the name of speed",
                "--axes",
            ],
        ),
        (
            vec![path(&same)],
            vec!["'az' and 'acc_z' both name the z axis", "--axes z=COL"],
        ),
        (
            vec![path(&clash), "--unit".into(), "m/s2".into()],
            vec!["'az_g' is in g by its name", "--unit says m/s2"],
        ),
        (
            vec![path(&two), "--axes".into(), "z=acc3".into()],
            vec!["no column named 'acc3'", "acc1, acc2"],
        ),
        (
            vec![path(&two), "--axes".into(), "z=t_s".into()],
            vec!["'t_s' is the time column"],
        ),
        (
            vec![path(&two), "--axes".into(), "z=acc1,x=acc1".into()],
            vec!["'acc1' is given for both"],
        ),
        (
            vec![path(&two), "--axes".into(), "w=acc1".into()],
            vec!["--axes 'w=acc1'", "x, y or z"],
        ),
        (
            vec![path(&two), "--axes".into(), "z=acc1,z=acc2".into()],
            vec!["z is named twice"],
        ),
        (
            vec![path(&two), "--unit".into(), "ft/s2".into()],
            vec!["--unit 'ft/s2'", "m/s2, g"],
        ),
    ];
    // simulate drives the body and needs z; assess judges x and y alone
    // (tests/cli/instruments.rs).
    let e = fails(&["simulate", "--input", &path(&xy)]);
    assert!(
        e.contains("no z (vertical) column, only x = ax (m/s2), y = ay (m/s2)")
            && e.contains("--axes z=COL"),
        "{e}"
    );
    for (args, want) in cases {
        for cmd in ["assess", "simulate"] {
            let mut a = vec![cmd, "--input"];
            a.extend(args.iter().map(String::as_str));
            let e = fails(&a);
            for w in &want {
                assert!(e.contains(w), "{a:?}: missing {w:?} in {e}");
            }
        }
    }
}

/// simulate names the record's columns too: a comment line before the CSV
/// header, an input block in JSON; it is driven by z alone.
#[test]
fn simulate_names_the_columns_it_read() {
    let d = tempfile::tempdir().unwrap();
    let p = write(
        d.path(),
        "r.csv",
        &["ax", "az_g"],
        &[(5.0, 1.0), (1.0, 5.0)],
        1.0,
    );
    let csv = ok(&[
        "simulate",
        "--input",
        p.to_str().unwrap(),
        "--duration",
        "0.01",
        "--format",
        "csv",
    ]);
    let first = csv.lines().next().unwrap();
    assert_eq!(
        first,
        format!(
            "# input: {}: x = ax (m/s2), z = az_g (g); time t_s; m/s² assumed for ax: the header gives no unit (name it az_g or Acc Z [g], or give the unit)",
            p.display()
        )
    );
    // The seat column is z in m/s²: the second row's seat is sin(2π·5·0.001) g.
    let row: Vec<f64> = csv
        .lines()
        .nth(3)
        .unwrap()
        .split(',')
        .map(|c| c.parse().unwrap())
        .collect();
    let want = (2.0 * PI * 5.0 * 0.001).sin() * 9.80665;
    assert!((row[1] - want).abs() < 1e-9, "{row:?} vs {want}");
    let v: Value = serde_json::from_str(&ok(&[
        "simulate",
        "--input",
        p.to_str().unwrap(),
        "--duration",
        "0.01",
        "--format",
        "json",
    ]))
    .unwrap();
    assert_eq!(v["input"]["axes"]["z"]["column"], "az_g");
    assert_eq!(v["input"]["axes"]["x"]["unit"], "m/s2");
}

/// A hostile header or file name cannot drive the terminal: the table
/// names them with control characters escaped.
#[test]
fn control_characters_in_names_are_escaped() {
    let d = tempfile::tempdir().unwrap();
    let p = write(
        d.path(),
        "e\x1b[2J.csv",
        &["a\x1b[31mz"],
        &[(1.0, 5.0)],
        1.0,
    );
    let t = ok(&["assess", "--input", p.to_str().unwrap()]);
    assert!(!t.contains('\x1b'), "{t:?}");
    assert!(t.contains("z = a\\u{1b}[31mz (m/s2)"), "{t}");
    let csv = ok(&[
        "simulate",
        "--input",
        p.to_str().unwrap(),
        "--duration",
        "0.002",
        "--format",
        "csv",
    ]);
    assert!(!csv.contains('\x1b'), "{csv:?}");
}
