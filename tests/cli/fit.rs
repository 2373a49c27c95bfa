//! `biodyn fit` as a real process: a fit through the binary recovers a model
//! from `biodyn response --format csv` output, the JSON has its stated shape,
//! `--save` writes a preset, and every bad input is one error line plus a hint.

use std::path::Path;
use std::process::Command;

use crate::common::{ok, root, run};

/// `common::fails` with a hint of more than a few words.
fn fails(args: &[&str]) -> String {
    let err = crate::common::fails(args);
    let hint = err.lines().nth(1).unwrap_or("");
    assert!(hint.len() > 20, "{args:?}: {err}");
    err
}

fn has(haystack: &str, needles: &[&str]) {
    for n in needles {
        assert!(haystack.contains(n), "'{n}' missing from:\n{haystack}");
    }
}

fn write(dir: &Path, name: &str, bytes: impl AsRef<[u8]>) -> String {
    let p = dir.join(name);
    std::fs::write(&p, bytes).unwrap();
    p.to_str().unwrap().to_string()
}

fn json(text: &str) -> serde_json::Value {
    serde_json::from_str(text).unwrap_or_else(|e| panic!("not JSON ({e}): {text}"))
}

const EXAMPLE: &str = "examples/synthetic-stht-apms-3pct-2deg.csv";

#[test]
fn response_csv_is_valid_data_and_the_fit_recovers_its_model() {
    let dir = tempfile::tempdir().unwrap();
    let csv = ok(&[
        "response",
        "--format",
        "csv",
        "--set",
        "k4=150000",
        "--set",
        "c4=3000",
        "--set",
        "k2=200000",
    ]);
    let data = write(dir.path(), "r.csv", csv);
    let out = ok(&[
        "fit", "--data", &data, "--free", "k2,k4,c4", "--format", "json",
    ]);
    let v = json(&out);
    let obj = v.as_object().unwrap();
    for key in [
        "model",
        "data",
        "columns",
        "points",
        "starts",
        "seconds",
        "cost",
        "converged_starts",
        "parameters",
        "correlations",
        "residual_rms",
    ] {
        assert!(obj.contains_key(key), "no {key} in {out}");
    }
    assert_eq!(v["model"], "paper-75kg");
    assert_eq!(v["data"], data.as_str());
    assert_eq!(v["points"], 196);
    assert_eq!(v["starts"], 8);
    assert_eq!(
        v["columns"],
        serde_json::json!([
            "stht_mag",
            "stht_phase_deg",
            "dpmi_mag",
            "dpmi_phase_deg",
            "apms_mag",
            "apms_phase_deg"
        ])
    );
    let params = v["parameters"].as_array().unwrap();
    let want = [
        ("k2", 183000.0, 200000.0),
        ("k4", 90000.0, 150000.0),
        ("c4", 2064.0, 3000.0),
    ];
    assert_eq!(params.len(), 3);
    for (p, (name, start, value)) in params.iter().zip(want) {
        let keys: Vec<&str> = p.as_object().unwrap().keys().map(String::as_str).collect();
        let mut sorted = vec![
            "name",
            "start",
            "value",
            "ci95_low",
            "ci95_high",
            "ci95_pieces",
            "determined",
        ];
        sorted.sort();
        assert_eq!(keys, sorted, "{p}");
        assert_eq!(p["name"], name);
        assert_eq!(p["start"].as_f64().unwrap(), start);
        let got = p["value"].as_f64().unwrap();
        assert!(
            (got - value).abs() <= 1e-6 * value,
            "{name}: {got} vs {value}"
        );
        assert_eq!(p["determined"], true);
    }
    let corr = v["correlations"].as_array().unwrap();
    assert_eq!(corr.len(), 3);
    for (i, row) in corr.iter().enumerate() {
        assert_eq!(row.as_array().unwrap().len(), 3);
        assert_eq!(row[i].as_f64().unwrap(), 1.0);
    }
    let rms = v["residual_rms"].as_object().unwrap();
    assert_eq!(rms.len(), 6);
    assert!(rms["apms_mag"].as_f64().unwrap() < 1e-9, "{out}");
}

#[test]
fn table_reports_every_section_and_says_what_is_not_determined() {
    let out = ok(&["fit", "--data", EXAMPLE]);
    has(
        &out,
        &[
            "fit of paper-75kg to examples/synthetic-stht-apms-3pct-2deg.csv",
            "196 frequencies",
            "8 free parameters, 8 starts (seed 1)",
            "reached the best cost",
            "parameter",
            "95% low",
            "determined",
            "correlations",
            "residual r.m.s. per column",
            "stht_phase_deg",
            "main peaks, data and fitted model",
            "Not determined by these data:",
        ],
    );
    // The same seed gives the same numbers (all but the time).
    let strip = |s: &str| {
        let mut v = json(s);
        v.as_object_mut().unwrap().remove("seconds");
        v
    };
    let a = ok(&[
        "fit", "--data", EXAMPLE, "--format", "json", "--seed", "4", "--starts", "3",
    ]);
    let b = ok(&[
        "fit", "--data", EXAMPLE, "--format", "json", "--seed", "4", "--starts", "3",
    ]);
    assert_eq!(strip(&a), strip(&b));
}

#[test]
fn apms_magnitude_alone_leaves_the_head_neck_link_undetermined() {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(root().join(EXAMPLE)).unwrap();
    let apms: String = text
        .lines()
        .map(|l| {
            let c: Vec<&str> = l.split(',').collect();
            format!("{},{}\n", c[0], c[3])
        })
        .collect();
    assert!(apms.starts_with("f_hz,apms_mag\n"));
    let data = write(dir.path(), "apms.csv", apms);
    let v = json(&ok(&["fit", "--data", &data, "--format", "json"]));
    let mut head_neck = 0;
    for p in v["parameters"].as_array().unwrap() {
        if p["name"] == "k1" || p["name"] == "c1" {
            head_neck += 1;
            assert_eq!(p["determined"], false, "{p}");
        }
    }
    // Both are free in the default fit: a report without them checks nothing.
    assert_eq!(head_neck, 2, "{v}");
    let table = ok(&["fit", "--data", &data]);
    has(&table, &["Not determined by these data:", "k1", "c1"]);
}

#[test]
fn save_writes_a_preset_that_records_the_fit() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("fitted.toml");
    let (code, stdout, err) = run(&[
        "fit",
        "--data",
        EXAMPLE,
        "--free",
        "k4,c4",
        "--save",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert!(stdout.contains("k4"), "{stdout}");
    assert!(err.contains("saved the fitted model"), "{err}");
    let text = std::fs::read_to_string(&out).unwrap();
    has(
        &text,
        &[
            "fitted by biodyn fit to examples/synthetic-stht-apms-3pct-2deg.csv",
            "free k4, c4",
            "seed 1",
        ],
    );
    ok(&["preset", "check", out.to_str().unwrap()]);
    // The saved model is the fitted one.
    let v = json(&ok(&[
        "fit", "--data", EXAMPLE, "--free", "k4,c4", "--format", "json",
    ]));
    let k4 = v["parameters"][0]["value"].as_f64().unwrap();
    let saved = ok(&[
        "response",
        "--preset",
        out.to_str().unwrap(),
        "--format",
        "csv",
        "--from",
        "1",
        "--to",
        "2",
    ]);
    let direct = ok(&[
        "response",
        "--set",
        &format!("k4={k4}"),
        "--set",
        &format!("c4={}", v["parameters"][1]["value"]),
        "--format",
        "csv",
        "--from",
        "1",
        "--to",
        "2",
    ]);
    assert_eq!(saved, direct);
}

#[test]
fn every_bad_data_file_is_one_line_naming_line_and_column() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let cases: Vec<(&str, &str, Vec<&str>)> = vec![
        (
            "text.csv",
            "f_hz,apms_mag\n1,58\n2,lots\n",
            vec!["line 3, column 2 (apms_mag): 'lots' is not a finite number"],
        ),
        (
            "fzero.csv",
            "f_hz,apms_mag\n0,58\n",
            vec!["line 2, column 1 (f_hz): 0 Hz"],
        ),
        (
            "fneg.csv",
            "f_hz,apms_mag\n-1,58\n",
            vec!["line 2, column 1 (f_hz): -1 Hz"],
        ),
        (
            "order.csv",
            "f_hz,apms_mag\n1,58\n3,60\n2,61\n",
            vec!["line 4, column 1 (f_hz): 2 Hz does not exceed the previous row's 3 Hz"],
        ),
        (
            "negmag.csv",
            "f_hz,stht_mag,apms_mag\n1,1.1,58\n2,-1.2,60\n",
            vec!["line 3, column 2 (stht_mag): magnitude -1.2"],
        ),
        (
            "zeromag.csv",
            "f_hz,apms_mag\n1,0\n",
            vec!["line 2, column 2 (apms_mag): magnitude 0"],
        ),
        (
            "nocol.csv",
            "f_hz,apms_mag\n1,\n2,\n",
            vec!["no usable column"],
        ),
        ("onlyf.csv", "f_hz\n1\n2\n", vec!["no usable column"]),
        (
            "unknown.csv",
            "f_hz,apms_mg\n1,58\n",
            vec!["line 1, column 2: unknown column 'apms_mg'"],
        ),
        (
            "few.csv",
            "f_hz,apms_mag\n1,58\n2,60\n3,66\n",
            vec!["3 measured values for 8 free parameters"],
        ),
        ("empty.csv", "", vec!["the file is empty"]),
        ("ragged.csv", "f_hz,apms_mag\n1,58,3\n", vec!["line 2"]),
        (
            "binary.csv",
            "f_hz,apms_mag\n1,\u{0}\u{1}\n",
            vec!["line 2, column 2"],
        ),
    ];
    for (name, text, want) in cases {
        let p = write(d, name, text);
        let err = fails(&["fit", "--data", &p]);
        let mut want = want;
        want.push(name);
        has(&err, &want);
    }
    // Not UTF-8.
    let p = write(d, "latin1.csv", b"f_hz,apms_mag\n1,5\xe9\n");
    has(&fails(&["fit", "--data", &p]), &["not UTF-8"]);
    // Missing, a directory, over the cap.
    has(
        &fails(&["fit", "--data", "no-such-file.csv"]),
        &["no-such-file.csv"],
    );
    has(
        &fails(&["fit", "--data", d.to_str().unwrap()]),
        &["is a directory, not a regular file"],
    );
    let big = d.join("big.csv");
    std::fs::File::create(&big)
        .unwrap()
        .set_len((16 << 20) + 1)
        .unwrap();
    has(
        &fails(&["fit", "--data", big.to_str().unwrap()]),
        &["over the", "cap"],
    );
}

#[cfg(unix)]
#[test]
fn a_fifo_is_refused_without_blocking() {
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("pipe.csv");
    let made = Command::new("mkfifo").arg(&fifo).status();
    if !matches!(made, Ok(s) if s.success()) {
        crate::common::skip("mkfifo unavailable");
        return;
    }
    has(
        &fails(&["fit", "--data", fifo.to_str().unwrap()]),
        &["FIFO"],
    );
}

#[test]
fn bad_free_bound_and_starts_are_one_line_each() {
    let cases: Vec<(Vec<&str>, Vec<&str>)> = vec![
        (vec!["--free", "k9"], vec!["--free k9", "unknown parameter"]),
        (vec!["--free", " , "], vec!["--free: the list is empty"]),
        (
            vec!["--free", "body-mass,m2"],
            vec!["body-mass and m2 are both free"],
        ),
        (
            vec!["--free", "c1", "--set", "c1=0"],
            vec!["--free c1: it is 0 in the start model", "ln c1"],
        ),
        (
            vec!["--bound", "k4=5..2"],
            vec!["--bound k4=5..2", "lower bound must be below"],
        ),
        (
            vec!["--bound", "k4"],
            vec!["--bound k4: expected NAME=LO..HI"],
        ),
        (vec!["--bound", "k4=-1..2"], vec!["not a number > 0"]),
        (vec!["--bound", "k4=1..x"], vec!["upper bound 'x'"]),
        (
            vec!["--free", "k4", "--bound", "k1=1..2"],
            vec!["k1 is not a free parameter"],
        ),
        (
            vec!["--bound", "k4=1..1e13"],
            vec!["above the model's limit"],
        ),
        (
            vec!["--bound", "k4=1..2", "--bound", "k4=3..4"],
            vec!["bounded twice"],
        ),
        (vec!["--bound", "zz=1..2"], vec!["unknown parameter 'zz'"]),
        (vec!["--starts", "0"], vec!["--starts 0"]),
        (vec!["--starts", "1001"], vec!["--starts 1001"]),
    ];
    for (extra, want) in cases {
        let mut args = vec!["fit", "--data", EXAMPLE];
        args.extend(extra.iter().copied());
        has(&fails(&args), &want);
    }
}

#[test]
fn help_has_examples_and_describes_the_data() {
    let out = ok(&["fit", "--help"]);
    has(
        &out,
        &[
            "Examples:",
            "biodyn fit --data",
            "<column>_sd",
            "--free",
            "--bound",
            "[default: links]",
            "[default: 8]",
        ],
    );
    has(&ok(&["--help"]), &["fit"]);
}
