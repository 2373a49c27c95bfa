//! Big models through the real binary: chain presets of 400 and 1000
//! segments written to a temporary folder, then `response`, `peaks` and
//! `modes`, checked against computations written here: the uniform chain's
//! closed-form modes and a head-down shooting recurrence (independent of the
//! library's leaf elimination). No timing is asserted.

use serde_json::Value;
use std::f64::consts::PI;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

const K: f64 = 1e6;
const C: f64 = 50.0;
const M: f64 = 1.0;

fn run(args: &[&str]) -> (Option<i32>, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_biodyn"))
        .args(args)
        .stdin(Stdio::null())
        .output()
        .expect("biodyn runs");
    (
        out.status.code(),
        String::from_utf8(out.stdout).expect("UTF-8"),
        String::from_utf8(out.stderr).expect("UTF-8"),
    )
}

fn ok(args: &[&str]) -> String {
    let (code, out, err) = run(args);
    assert_eq!(code, Some(0), "{args:?}: {err}");
    out
}

/// A preset of `n` one-kilogram segments in a line, s0 the head at the top.
pub(crate) fn chain_preset(dir: &Path, n: usize) -> PathBuf {
    let mut t = format!(
        "schema = 1\nname = \"chain{n}\"\ndescription = \"{n} segments in a line\"\nhead = \"s0\"\n\n"
    );
    for i in 0..n {
        t += &format!("[[segment]]\nname = \"s{i}\"\nmass_kg = {M:?}\n\n");
    }
    for i in 0..n {
        let lower = if i + 1 < n {
            format!("s{}", i + 1)
        } else {
            "seat".into()
        };
        t += &format!(
            "[[link]]\nname = \"l{i}\"\nupper = \"s{i}\"\nlower = \"{lower}\"\nk_n_per_m = {K:?}\nc_ns_per_m = {C:?}\n\n"
        );
    }
    let path = dir.join(format!("chain{n}.toml"));
    std::fs::write(&path, t).expect("write preset");
    path
}

type Cx = (f64, f64);

fn div(a: Cx, b: Cx) -> Cx {
    let d = b.0 * b.0 + b.1 * b.1;
    ((a.0 * b.0 + a.1 * b.1) / d, (a.1 * b.0 - a.0 * b.1) / d)
}

fn norm(a: Cx) -> f64 {
    a.0.hypot(a.1)
}

/// (|STHT|, |APMS|) of the uniform chain by shooting from the head down:
/// with X_head = 1, the link below segment i carries ω²·Σ_{j≤i} m X_j, so
/// X_{i+1} = X_i − that / z; the seat's X0 comes out last. Below the chain's
/// cut-off (2√(k/m)/2π ≈ 318 Hz) nothing grows, so f64 holds.
fn shoot(n: usize, f: f64) -> (f64, f64) {
    let w = 2.0 * PI * f;
    let z = (K, w * C);
    let mut x: Cx = (1.0, 0.0);
    let mut sum: Cx = (0.0, 0.0);
    for _ in 0..n {
        sum = (sum.0 + M * x.0, sum.1 + M * x.1);
        let d = div((w * w * sum.0, w * w * sum.1), z);
        x = (x.0 - d.0, x.1 - d.1);
    }
    let one = (1.0, 0.0);
    (norm(div(one, x)), norm(div(sum, x)))
}

/// ω_r of a uniform chain fixed at the seat and free at the head.
fn undamped_w(n: usize, r: usize) -> f64 {
    2.0 * (K / M).sqrt() * ((2 * r - 1) as f64 * PI / (2.0 * (2 * n + 1) as f64)).sin()
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

#[test]
fn a_thousand_segment_chain_answers_response_and_peaks() {
    let dir = tempfile::tempdir().expect("tempdir");
    let preset = chain_preset(dir.path(), 1000);
    let p = preset.to_str().expect("path");
    let csv = ok(&["response", "--preset", p, "--format", "csv"]);
    let rows: Vec<Vec<f64>> = csv
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|x| x.parse().expect("number")).collect())
        .collect();
    assert_eq!(rows.len(), 196);
    for row in rows.iter().step_by(13) {
        let (stht, apms) = shoot(1000, row[0]);
        assert!(rel(row[1], stht) < 1e-7, "{}: {} vs {stht}", row[0], row[1]);
        assert!(rel(row[5], apms) < 1e-7, "{}: {} vs {apms}", row[0], row[5]);
        assert!(rel(row[3], 2.0 * PI * row[0] * apms) < 1e-7);
    }

    let json = ok(&["peaks", "--preset", p, "--format", "json"]);
    let peaks: Vec<Value> = serde_json::from_str(&json).expect("JSON");
    let stht: Vec<&Value> = peaks.iter().filter(|v| v["function"] == "stht").collect();
    // Lightly damped (ζ_r = c ω_r / 2k): one STHT peak per mode in the band.
    let in_band = (1..)
        .map(|r| undamped_w(1000, r) / (2.0 * PI))
        .take_while(|&f| f < 20.0)
        .filter(|&f| f > 0.5)
        .count();
    assert_eq!(stht.len(), in_band, "{json}");
    for (r, p) in stht.iter().enumerate() {
        let f = p["f_hz"].as_f64().expect("f_hz");
        let mag = p["mag"].as_f64().expect("mag");
        assert_eq!(p["unbounded"], false);
        let fr = undamped_w(1000, r + 2) / (2.0 * PI);
        assert!(rel(f, fr) < 1e-3, "peak {f} vs mode {fr}");
        assert!(rel(mag, shoot(1000, f).0) < 1e-7, "{f}");
        // A maximum: the shooting recurrence is lower on either side.
        assert!(shoot(1000, f - 1e-4).0 < mag && shoot(1000, f + 1e-4).0 < mag);
    }
}

#[test]
fn a_chain_answers_modes_or_refuses_above_the_limit() {
    let dir = tempfile::tempdir().expect("tempdir");
    // Modes at 400 segments take seconds in a release build but minutes in
    // a debug one: `cargo test --release` runs the full size.
    let n = if cfg!(debug_assertions) { 120 } else { 400 };
    let preset = chain_preset(dir.path(), n);
    let json = ok(&[
        "modes",
        "--preset",
        preset.to_str().expect("path"),
        "--format",
        "json",
    ]);
    let modes: Value = serde_json::from_str(&json).expect("JSON");
    let damped = modes["damped"].as_array().expect("damped");
    let undamped = modes["undamped"].as_array().expect("undamped");
    assert_eq!((damped.len(), undamped.len()), (n, n));
    // C = (c/k)·K: proportional damping, so the damped modes share the
    // undamped ω_r and have ζ_r = c·ω_r / 2k.
    for r in 1..=n {
        let w = undamped_w(n, r);
        let u = undamped[r - 1]["natural_hz"].as_f64().expect("hz");
        assert!(rel(u, w / (2.0 * PI)) < 1e-9, "undamped {r}: {u}");
        let d = &damped[r - 1];
        assert_eq!(d["kind"], "oscillatory");
        let nat = d["natural_hz"].as_f64().expect("hz");
        let zeta = d["damping_ratio"].as_f64().expect("zeta");
        assert!(rel(nat, w / (2.0 * PI)) < 1e-9, "damped {r}: {nat}");
        assert!(rel(zeta, C * w / (2.0 * K)) < 1e-6, "zeta {r}: {zeta}");
    }

    let big = chain_preset(dir.path(), 1000);
    let (code, out, err) = run(&["modes", "--preset", big.to_str().expect("path")]);
    assert_eq!(code, Some(1), "{out}");
    assert!(out.is_empty());
    assert!(err.contains("1000-segment") && err.contains("500"), "{err}");
}

#[test]
fn an_oversized_study_is_refused_before_allocating() {
    let values: Vec<String> = (0..1000).map(|i| (50_000 + 10 * i).to_string()).collect();
    let (code, out, err) = run(&[
        "study",
        "k4",
        &values.join(","),
        "--from",
        "1",
        "--to",
        "62500.9375",
        "--step",
        "0.0625",
    ]);
    assert_eq!(code, Some(1), "{out}");
    assert!(
        err.contains("1000 values") && err.contains("1000000 frequency points"),
        "{err}"
    );
}

#[test]
fn undamped_peaks_say_unbounded_in_json() {
    let json = ok(&[
        "peaks", "--set", "c1=0", "--set", "c2=0", "--set", "c3=0", "--set", "c4=0", "--to", "60",
        "--format", "json",
    ]);
    let peaks: Vec<Value> = serde_json::from_str(&json).expect("JSON");
    assert!(!peaks.is_empty());
    assert!(peaks.iter().all(|p| p["unbounded"] == true), "{json}");
    let json = ok(&["peaks", "--format", "json"]);
    let peaks: Vec<Value> = serde_json::from_str(&json).expect("JSON");
    assert!(peaks.iter().all(|p| p["unbounded"] == false), "{json}");
}
