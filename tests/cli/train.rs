//! `biodyn train` and `biodyn predict` as real processes.

use std::process::{Command, Output};

fn biodyn(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_biodyn"))
        .args(args)
        .output()
        .expect("run biodyn")
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

#[test]
fn train_json_is_one_array_with_the_documented_fields() {
    let out = biodyn(&[
        "train",
        "--case",
        "k4-stht",
        "--trainer",
        "backprop",
        "--epochs",
        "20",
        "--format",
        "json",
    ]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let arr = v.as_array().expect("a JSON array");
    assert_eq!(arr.len(), 1);
    let r = &arr[0];
    for field in [
        "case",
        "trainer",
        "epochs",
        "rms",
        "mpre_pct",
        "stop_reason",
        "train_seconds",
        "holdout",
    ] {
        assert!(r.get(field).is_some(), "missing {field}");
    }
    assert_eq!(r["case"], "k4-stht");
    assert_eq!(r["trainer"], "backprop");
    assert_eq!(r["epochs"], 20);
    assert_eq!(r["stop_reason"], "epoch-limit");
    let h = r["holdout"].as_array().unwrap();
    assert_eq!(h.len(), 4);
    for k in [
        "param",
        "value",
        "max_err_pct",
        "mean_err_pct",
        "extrapolation",
    ] {
        assert!(h[0].get(k).is_some(), "holdout lacks {k}");
    }
    assert_eq!(h[1]["value"], 72000.0);
    assert_eq!(h[1]["extrapolation"], false);
    // stderr is not a terminal here: no progress bar.
    assert!(
        !text(&out.stderr).contains('\r'),
        "progress bar on a pipe: {}",
        text(&out.stderr)
    );
}

#[test]
fn train_all_prints_six_cases_beside_table_5() {
    let out = biodyn(&["train", "--case", "all", "--epochs", "2", "--ensemble", "1"]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let t = text(&out.stdout);
    for c in [
        "mass-stht",
        "mass-dpmi",
        "mass-apms",
        "k4-stht",
        "k4-dpmi",
        "k4-apms",
    ] {
        assert!(t.contains(c), "{c} missing:\n{t}");
    }
    // The paper's epochs and MPRE sit beside ours.
    assert!(
        t.contains("45931") && t.contains("1.213") && t.contains("101463"),
        "{t}"
    );
}

#[test]
fn save_then_predict_csv_and_json() {
    let dir = tempfile::tempdir().unwrap();
    let net = dir.path().join("k4.json");
    let net_s = net.to_str().unwrap();
    let out = biodyn(&[
        "train",
        "--case",
        "k4-apms",
        "--epochs",
        "3",
        "--ensemble",
        "2",
        "--save",
        net_s,
    ]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert!(net.exists());

    let out = biodyn(&[
        "predict", "--net", net_s, "--set", "k4=72000", "--format", "csv",
    ]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let t = text(&out.stdout);
    let mut lines = t.lines();
    assert_eq!(lines.next(), Some("f_hz,predicted,analytic,err_pct"));
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|x| x.parse::<f64>().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 196);
    assert_eq!(rows[0][0], 0.5);
    assert_eq!(
        rows[2][0], 0.7,
        "frequencies print short, not 0.7000000000000001"
    );
    for r in &rows {
        let err = 100.0 * (r[1] - r[2]).abs() / r[2];
        assert!((err - r[3]).abs() < 1e-9 * err.max(1.0));
    }
    // An independent analytic value: APMS → seated mass at low frequency.
    assert!((rows[0][2] - 0.781 * 75.0).abs() / (0.781 * 75.0) < 0.05);

    let out = biodyn(&[
        "predict",
        "--net",
        net_s,
        "--set",
        "k4=200000",
        "--from",
        "1",
        "--to",
        "2",
        "--step",
        "0.5",
        "--format",
        "json",
    ]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["points"].as_array().unwrap().len(), 3);
    assert_eq!(v["extrapolation"], true);
    assert_eq!(v["inputs"]["k4"], 200000.0);
    assert!(text(&out.stderr).contains("extrapolation"));
}

#[test]
fn divergence_prints_no_nan() {
    let out = biodyn(&[
        "train",
        "--case",
        "mass-dpmi",
        "--trainer",
        "backprop",
        "--lr",
        "1e300",
        "--epochs",
        "50",
    ]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let t = text(&out.stdout);
    assert!(t.contains("diverged"), "{t}");
    assert!(
        !t.to_lowercase().contains("nan") && !t.contains("inf "),
        "{t}"
    );
    let out = biodyn(&[
        "train",
        "--case",
        "mass-dpmi",
        "--trainer",
        "backprop",
        "--lr",
        "1e300",
        "--epochs",
        "50",
        "--format",
        "json",
    ]);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v[0]["stop_reason"], "diverged");
    assert!(v[0]["rms"].is_null() && v[0]["mpre_pct"].is_null());
}

#[test]
fn bad_input_exits_non_zero_with_one_clear_line() {
    let dir = tempfile::tempdir().unwrap();
    let garbage = dir.path().join("garbage.json");
    std::fs::write(&garbage, "{ not json").unwrap();
    let g = garbage.to_str().unwrap();
    let missing = dir.path().join("missing.json");
    let m = missing.to_str().unwrap();
    let cases: &[(&[&str], &str)] = &[
        (
            &["train", "--case", "k4-stht", "--epochs", "0"],
            "epochs = 0",
        ),
        (
            &[
                "train",
                "--case",
                "k4-stht",
                "--trainer",
                "backprop",
                "--lr",
                "0",
            ],
            "learning rate = 0",
        ),
        (
            &[
                "train",
                "--case",
                "k4-stht",
                "--trainer",
                "backprop",
                "--lr",
                "NaN",
            ],
            "learning rate = NaN",
        ),
        (
            &[
                "train",
                "--case",
                "k4-stht",
                "--trainer",
                "backprop",
                "--momentum",
                "1",
            ],
            "momentum = 1",
        ),
        (
            &["train", "--case", "k4-stht", "--layers", "2-0-1"],
            "0 neurons",
        ),
        (
            &["train", "--case", "k4-stht", "--layers", "5-6-1"],
            "first layer must have 2",
        ),
        (
            &["train", "--case", "k4-stht", "--layers", "2--1"],
            "neuron counts like 5-6-4-1",
        ),
        (
            &[
                "train", "--case", "k4-stht", "--from", "20", "--to", "0.5", "--step", "0.5",
            ],
            "must be below",
        ),
        (&["predict", "--net", m], "cannot read"),
        (&["predict", "--net", g], "not a valid network file"),
    ];
    for (args, want) in cases {
        let out = biodyn(args);
        assert!(!out.status.success(), "{args:?} succeeded");
        let e = text(&out.stderr);
        assert!(e.contains(want), "{args:?}: expected '{want}' in: {e}");
        assert!(!e.contains("panicked"), "{args:?} panicked: {e}");
        assert!(out.stdout.is_empty(), "{args:?} wrote to stdout");
    }
    // Closed sets are clap value enums: a wrong value is a usage error
    // (status 2) that lists the right ones.
    let usage: &[(&[&str], &[&str])] = &[
        (
            &["train", "--case", "mass-xyz"],
            &["mass-xyz", "mass-stht", "k4-apms", "all"],
        ),
        (
            &["train", "--case", "k4-stht", "--trainer", "adam"],
            &["adam", "backprop", "lm"],
        ),
        (
            &["train", "--case", "k4-stht", "--grid", "0.5:20:0.5"],
            &["--grid"],
        ),
        (
            &["train", "--case", "k4-stht", "--activation", "relu"],
            &["relu", "logistic", "tanh"],
        ),
    ];
    for (args, want) in usage {
        let out = biodyn(args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let e = text(&out.stderr);
        for w in *want {
            assert!(e.contains(w), "{args:?}: expected '{w}' in: {e}");
        }
        assert!(out.stdout.is_empty(), "{args:?} wrote to stdout");
    }
}

#[test]
fn predict_refuses_a_mass_value_it_cannot_build() {
    let dir = tempfile::tempdir().unwrap();
    let net = dir.path().join("m.json");
    let n = net.to_str().unwrap();
    let out = biodyn(&[
        "train",
        "--case",
        "mass-stht",
        "--epochs",
        "2",
        "--ensemble",
        "1",
        "--save",
        n,
    ]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let out = biodyn(&["predict", "--net", n, "--body-mass", "-3"]);
    assert!(!out.status.success());
    assert!(text(&out.stderr).contains("-3"), "{}", text(&out.stderr));
    let out = biodyn(&["predict", "--net", n, "--body-mass", "70", "--set", "k4"]);
    assert!(!out.status.success());
    assert!(text(&out.stderr).contains("NAME=VALUE"));
}

/// Issue 19 item 8: a network file whose numbers overflow (every weight
/// 1e308, or only the linear output's bias raised to 1e308) makes no `inf`
/// table with exit 0: predict fails naming the file, in every format.
#[test]
fn a_network_that_predicts_no_number_is_an_error_naming_its_file() {
    let dir = tempfile::tempdir().unwrap();
    let net = dir.path().join("k4.json");
    let out = biodyn(&[
        "train",
        "--case",
        "k4-apms",
        "--epochs",
        "3",
        "--save",
        net.to_str().unwrap(),
    ]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let good: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&net).unwrap()).unwrap();
    type Edit = fn(&mut Vec<serde_json::Value>);
    let edits: [(&str, Edit); 2] = [
        ("all-huge.json", |p| {
            p.iter_mut().for_each(|v| *v = 1e308.into())
        }),
        ("output-bias.json", |p| {
            if let Some(v) = p.last_mut() {
                *v = 1e308.into();
            }
        }),
    ];
    for (name, edit) in edits {
        let mut v = good.clone();
        for m in v["network"]["members"].as_array_mut().unwrap() {
            edit(m["params"].as_array_mut().unwrap());
        }
        let bad = dir.path().join(name);
        std::fs::write(&bad, v.to_string()).unwrap();
        for format in ["table", "csv", "json"] {
            let out = biodyn(&[
                "predict",
                "--net",
                bad.to_str().unwrap(),
                "--format",
                format,
            ]);
            assert_eq!(
                out.status.code(),
                Some(1),
                "{name} {format}: {}",
                text(&out.stdout)
            );
            assert!(
                out.stdout.is_empty(),
                "{name} {format}: {}",
                text(&out.stdout)
            );
            let err = text(&out.stderr);
            assert!(
                err.contains(name) && err.contains("not a finite number"),
                "{err}"
            );
        }
    }
}
