//! `biodyn simulate` and `biodyn assess` as real processes: the exact CSV
//! header and JSON keys, results against independent formulas, a closed
//! pipe, and every bad input of issue 9 as one error line plus a hint.

use std::io::{BufRead, BufReader};
use std::path::Path;
use std::process::{Command, Stdio};

use crate::common::{fails, ok, run};

const HEADER: &str = "t_s,seat_acc_m_s2,head_acc_m_s2,seat_force_n,acc_head-neck_m_s2,acc_chest_m_s2,acc_lower-torso_m_s2,acc_pelvis_m_s2,defl_head-neck-chest_m,defl_chest-lower-torso_m,defl_lower-torso-pelvis_m,defl_pelvis-seat_m";

/// |Wk(f)| from SPEC §7, written out here (complex numbers as (re, im)).
fn wk(f: f64) -> f64 {
    use std::f64::consts::PI;
    type C = (f64, f64);
    let mul = |a: C, b: C| (a.0 * b.0 - a.1 * b.1, a.0 * b.1 + a.1 * b.0);
    let div = |a: C, b: C| {
        let d = b.0 * b.0 + b.1 * b.1;
        ((a.0 * b.0 + a.1 * b.1) / d, (a.1 * b.0 - a.0 * b.1) / d)
    };
    let w = 2.0 * PI * f;
    // (n0 + n1 s + n2 s²)/(d0 + d1 s + d2 s²) at s = jw.
    let sec = |n: [f64; 3], d: [f64; 3]| {
        div(
            (n[0] - n[2] * w * w, n[1] * w),
            (d[0] - d[2] * w * w, d[1] * w),
        )
    };
    let o = |f: f64| 2.0 * PI * f;
    let q = 1.0 / 2f64.sqrt();
    let g = (o(2.37) / o(3.35)).powi(2);
    let h = [
        sec([0.0, 0.0, 1.0], [o(0.4).powi(2), o(0.4) / q, 1.0]),
        sec(
            [1.0, 0.0, 0.0],
            [1.0, 1.0 / (q * o(100.0)), 1.0 / o(100.0).powi(2)],
        ),
        sec(
            [1.0, 1.0 / o(12.5), 0.0],
            [1.0, 1.0 / (0.63 * o(12.5)), 1.0 / o(12.5).powi(2)],
        ),
        sec(
            [g, g / (0.91 * o(2.37)), g / o(2.37).powi(2)],
            [1.0, 1.0 / (0.91 * o(3.35)), 1.0 / o(3.35).powi(2)],
        ),
    ]
    .into_iter()
    .fold((1.0, 0.0), mul);
    (h.0 * h.0 + h.1 * h.1).sqrt()
}

#[test]
fn simulate_csv_has_the_exact_header_and_one_row_per_sample() {
    let out = ok(&[
        "simulate",
        "--signal",
        "sine:freq=5,amp=5",
        "--format",
        "csv",
        "--duration",
        "2",
        "--fs",
        "500",
    ]);
    let mut lines = out.lines();
    assert_eq!(lines.next(), Some(HEADER));
    let rows: Vec<Vec<f64>> = lines
        .map(|l| {
            l.split(',')
                .map(|v| v.parse::<f64>().expect("a number"))
                .collect()
        })
        .collect();
    assert_eq!(rows.len(), 1000);
    assert!(rows.iter().all(|r| r.len() == 12));
    assert_eq!(rows[0], vec![0.0; 12]);
    assert_eq!(rows[250][0], 0.5);
    // The seat column is the signal: 5 sin(2π·5 t).
    let t = rows[13][0];
    assert!((rows[13][1] - 5.0 * (2.0 * std::f64::consts::PI * 5.0 * t).sin()).abs() < 1e-12);
    // Head column = the head segment's column; force = Σ m a (paper-75kg masses).
    let m = [0.075, 0.402, 0.122, 0.182].map(|s| s * 75.0);
    for r in &rows {
        assert_eq!(r[2], r[4]);
        let newton: f64 = (0..4).map(|i| m[i] * r[4 + i]).sum();
        assert!((newton - r[3]).abs() < 1e-9 * (1.0 + r[3].abs()));
    }
}

#[test]
fn simulate_json_and_table_say_the_same() {
    let out = ok(&[
        "simulate",
        "--signal",
        "sine:freq=5,amp=5",
        "--format",
        "json",
        "--duration",
        "0.1",
    ]);
    let v: serde_json::Value = serde_json::from_str(&out).expect("valid JSON");
    assert_eq!(v["columns"].as_array().unwrap().len(), 12);
    assert_eq!(v["rows"].as_array().unwrap().len(), 100);
    assert_eq!(v["fs_hz"], 1000.0);
    let table = ok(&[
        "simulate",
        "--signal",
        "sine:freq=5,amp=5",
        "--duration",
        "0.1",
    ]);
    assert_eq!(table.lines().count(), 101);
    assert!(table.lines().next().unwrap().contains("head-neck m/s²"));
}

#[test]
fn a_closed_pipe_ends_simulate_quietly() {
    let mut child = Command::new(env!("CARGO_BIN_EXE_biodyn"))
        .args([
            "simulate",
            "--signal",
            "random:rms=1,band=1-20,seed=3",
            "--duration",
            "3000",
            "--format",
            "csv",
        ])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = String::new();
    BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut first)
        .unwrap();
    assert_eq!(first.trim_end(), HEADER);
    // The reader is dropped here: the pipe closes mid-stream.
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert!(
        out.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn assess_json_has_exactly_the_keys_and_the_weighted_rms_of_a_sine() {
    let out = ok(&[
        "assess",
        "--signal",
        "sine:freq=4,amp=2",
        "--duration",
        "60",
        "--format",
        "json",
    ]);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let mut keys: Vec<&str> = v.as_object().unwrap().keys().map(String::as_str).collect();
    keys.sort();
    assert_eq!(
        keys,
        [
            "axes",
            "bands",
            "comfort",
            "duration_s",
            "eu",
            "exposure_h",
            "fs_hz",
            "head",
            "health",
            "input",
            "model",
            "seat",
            "segments",
            "spine",
            "warnings"
        ]
    );
    // No --spine: the key is there, null.
    assert!(v["spine"].is_null());
    let metric_keys = [
        "a8_m_s2",
        "aw_m_s2",
        "awf_m_s2",
        "crest_factor",
        "msdv_exposure_m_s15",
        "msdv_m_s15",
        "mtvv_m_s2",
        "peak_m_s2",
        "vdv_exposure_m_s175",
        "vdv_m_s175",
        "vomit_beyond_annex_d",
        "vomit_pct",
        "vomit_words",
    ];
    for m in [&v["seat"], &v["head"]] {
        let mut k: Vec<&str> = m.as_object().unwrap().keys().map(String::as_str).collect();
        k.sort();
        assert_eq!(k, metric_keys);
    }
    let segs = v["segments"].as_array().unwrap();
    assert_eq!(segs.len(), 4);
    assert_eq!(segs[0]["name"], "head-neck");
    assert_eq!(
        (
            v["model"].as_str(),
            v["fs_hz"].as_f64(),
            v["duration_s"].as_f64(),
            v["exposure_h"].as_f64()
        ),
        (Some("paper-75kg"), Some(1000.0), Some(60.0), Some(8.0))
    );
    // a_w of a sine is amp/√2 · |Wk(f)| (the 0.4 Hz high-pass settles in a few seconds).
    let aw = v["seat"]["aw_m_s2"].as_f64().unwrap();
    let want = 2.0 / 2f64.sqrt() * wk(4.0);
    assert!((aw / want - 1.0).abs() < 0.01, "{aw} vs {want}");
    // A(8) over 8 h is a_w; the EU words follow from it.
    assert_eq!(v["seat"]["a8_m_s2"].as_f64(), Some(aw));
    let word = if aw > 1.15 {
        "above limit value"
    } else if aw > 0.5 {
        "above action value"
    } else {
        "below action value"
    };
    assert_eq!(v["eu"]["a8"], word);
    assert!(v["eu"]["vdv"].is_string());
    assert!(
        v["comfort"]["seat"]
            .as_array()
            .is_some_and(|a| !a.is_empty())
    );
    assert_eq!(v["bands"].as_array().unwrap().len(), 23);
    // The body amplifies 4 Hz: the head moves more than the seat.
    assert!(v["head"]["aw_m_s2"].as_f64().unwrap() > aw);
}

#[test]
fn assess_table_puts_seat_and_head_side_by_side_in_words() {
    let out = ok(&["assess", "--signal", "sine:freq=5,amp=5", "--exposure", "2"]);
    for w in [
        "seat",
        "head (head-neck)",
        "weighted r.m.s. a_w",
        "MTVV",
        "VDV over 2 h",
        "A(8)",
        "EU 2002/44/EC",
        "comfort",
        "One-third-octave",
    ] {
        assert!(out.contains(w), "missing {w:?}:\n{out}");
    }
    assert!(out.contains("above limit value"), "{out}");
}

#[test]
fn a_record_from_csv_assesses_like_the_same_signal_generated() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("seat.csv");
    let sim = ok(&[
        "simulate",
        "--signal",
        "sine:freq=6,amp=1.5+shock:peak=8,width=0.2,at=3",
        "--duration",
        "20",
        "--format",
        "csv",
    ]);
    // Keep t_s and the seat column, and a column to ignore.
    let mut csv = String::from("t_s,z_m_s2,other\n");
    for l in sim.lines().skip(1) {
        let f: Vec<&str> = l.split(',').collect();
        csv.push_str(&format!("{},{},7\n", f[0], f[1]));
    }
    std::fs::write(&p, csv).unwrap();
    let from_file = ok(&[
        "assess",
        "--input",
        p.to_str().unwrap(),
        "--column",
        "z_m_s2",
        "--format",
        "json",
    ]);
    let generated = ok(&[
        "assess",
        "--signal",
        "sine:freq=6,amp=1.5+shock:peak=8,width=0.2,at=3",
        "--duration",
        "20",
        "--format",
        "json",
    ]);
    let (a, b): (serde_json::Value, serde_json::Value) = (
        serde_json::from_str(&from_file).unwrap(),
        serde_json::from_str(&generated).unwrap(),
    );
    assert_eq!(a["seat"], b["seat"]);
    assert_eq!(a["head"], b["head"]);
    // Without --column the extra column makes the record ambiguous: refused,
    // never judged on the first column.
    let err = fails(&["assess", "--input", p.to_str().unwrap()]);
    assert!(
        err.contains("no axis in the name of other") && err.contains("--axes"),
        "{err}"
    );
    // --duration reads a prefix.
    let short = ok(&[
        "assess",
        "--input",
        p.to_str().unwrap(),
        "--column",
        "z_m_s2",
        "--duration",
        "5",
        "--format",
        "json",
    ]);
    let s: serde_json::Value = serde_json::from_str(&short).unwrap();
    assert_eq!(s["duration_s"], 5.0);
}

#[test]
fn every_bad_signal_or_number_is_one_line_and_a_hint() {
    let cases: &[(&[&str], &str)] = &[
        (&["--signal", "sine:freq=5,amp"], "'sine:freq=5,amp'"),
        (
            &["--signal", "sine:freq=5,amp=5+sine:freq=x,amp=1"],
            "'sine:freq=x,amp=1'",
        ),
        (&["--signal", "sine:freq=5"], "missing key 'amp'"),
        (&["--signal", "saw:freq=5,amp=1"], "unknown kind 'saw'"),
        (
            &["--signal", "sine:freq=5,amp=5,colour=red"],
            "unknown key 'colour'",
        ),
        (
            &["--signal", "sine:freq=5,amp=5", "--duration", "0"],
            "duration 0",
        ),
        (
            &["--signal", "sine:freq=5,amp=5", "--duration", "-3"],
            "duration -3",
        ),
        (
            &["--signal", "sine:freq=5,amp=5", "--fs", "0"],
            "sampling rate 0",
        ),
        (
            &["--signal", "sine:freq=5,amp=5", "--fs", "-1000"],
            "sampling rate -1000",
        ),
        (&["--signal", "shock:peak=10,width=0,at=1"], "width=0"),
        (&["--signal", "shock:peak=10,width=-0.1,at=1"], "width=-0.1"),
        (&["--signal", "random:rms=1,band=0-20,seed=1"], "band=0-20"),
        (
            &["--signal", "random:rms=1,band=-1-20,seed=1"],
            "band=-1-20",
        ),
        (&["--signal", "random:rms=1,band=20-2,seed=1"], "band=20-2"),
        (&["--signal", "random:rms=1,band=1-600,seed=1"], "fs/2"),
        (&["--signal", "random:rms=1,band=1-20,seed=x"], "seed=x"),
        (
            &["--signal", "sine:freq=5,amp=5", "--duration", "1e6"],
            "over the cap",
        ),
        (
            &["--signal", "shock:peak=10,width=0.1,at=30"],
            "past the end",
        ),
    ];
    for (args, want) in cases {
        for cmd in ["simulate", "assess"] {
            let mut a = vec![cmd];
            a.extend_from_slice(args);
            let err = fails(&a);
            assert!(err.contains(want), "{a:?}: {err}");
        }
    }
    // --exposure is read as hours by its own parser (status 2, as clap's
    // usage errors), in biodyn's words.
    for (bad, want) in [
        (
            "0",
            "'0' for '--exposure <HOURS>': 0 h: the exposure must be over 0",
        ),
        (
            "-8",
            "'-8' for '--exposure <HOURS>': not hours; write 6.5, 6:30",
        ),
    ] {
        let (code, _, err) = run(&["assess", "--signal", "sine:freq=5,amp=5", "--exposure", bad]);
        assert_eq!(code, Some(2), "{err}");
        assert!(err.contains(want), "{err}");
    }
}

fn write(dir: &Path, name: &str, text: &str) -> String {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.to_str().unwrap().to_string()
}

#[test]
fn every_bad_record_names_file_line_and_column() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // 100 rows at 1 kHz; `bad` rewrites row k (line k + 2).
    let record = |bad: &dyn Fn(usize) -> Option<String>| {
        let mut text = String::from("t_s,acc\n");
        for k in 0..100 {
            let row = bad(k)
                .unwrap_or_else(|| format!("{},{}", k as f64 / 1000.0, (k as f64 * 0.3).sin()));
            text.push_str(&row);
            text.push('\n');
        }
        text
    };
    let good = record(&|_| None);
    let cases = [
        (
            write(
                d,
                "text.csv",
                &record(&|k| (k == 50).then(|| "0.05,abc".into())),
            ),
            "line 52, column 'acc': 'abc' is not a number",
        ),
        (
            write(
                d,
                "nan.csv",
                &record(&|k| (k == 1).then(|| "0.001,NaN".into())),
            ),
            "line 3, column 'acc': NaN is not a finite number",
        ),
        (
            write(
                d,
                "nan2.csv",
                &record(&|k| (k == 60).then(|| "0.06,nan".into())),
            ),
            "line 62, column 'acc': nan is not a finite",
        ),
        (write(d, "one.csv", "t_s,acc\n0,1\n"), "1 data row(s)"),
        (write(d, "none.csv", "t_s,acc\n"), "0 data row(s)"),
        (
            write(
                d,
                "uneven.csv",
                &record(&|k| (k == 70).then(|| "0.0705,1".into())),
            ),
            "line 72: time step",
        ),
        (write(d, "empty.csv", ""), "empty"),
    ];
    for (path, want) in &cases {
        for cmd in ["assess", "simulate"] {
            if cmd == "simulate"
                && (want.contains("line 52")
                    || want.contains("line 62")
                    || want.contains("line 72"))
            {
                continue; // simulate streams: rows before the bad line are already out.
            }
            let err = fails(&[cmd, "--input", path]);
            assert!(
                err.contains(want)
                    && err.contains(Path::new(path).file_name().unwrap().to_str().unwrap()),
                "{path}: {err}"
            );
        }
    }
    let p = write(d, "good.csv", &good);
    let err = fails(&["assess", "--input", &p, "--column", "z"]);
    assert!(
        err.contains("no column named 'z'") && err.contains("t_s, acc"),
        "{err}"
    );
    let single = write(d, "single.csv", "acc\n1\n2\n3\n");
    assert!(fails(&["assess", "--input", &single]).contains("--fs"));
    // Read with --fs, and then too short to judge (issue 19 item 12): no verdict.
    let short = fails(&["assess", "--input", &single, "--fs", "1000"]);
    assert!(
        short.contains("3 samples (0.003 s) long: too short to judge"),
        "{short}"
    );
    assert!(!short.contains("action value"), "{short}");
    let rows: String = (0..3000)
        .map(|k| format!("{}\n", (k as f64 * 0.03).sin()))
        .collect();
    let long = write(d, "long.csv", &format!("acc\n{rows}"));
    ok(&["assess", "--input", &long, "--fs", "1000"]);
    // A rate that cannot carry Wk's band to 80 Hz is refused, never judged.
    let low = fails(&["assess", "--input", &long, "--fs", "100"]);
    assert!(low.contains("needs more than 160 Hz"), "{low}");
    // Not a regular file, missing, or over the cap (a sparse file past 2 GiB).
    assert!(fails(&["assess", "--input", d.to_str().unwrap()]).contains("directory"));
    assert!(
        fails(&["assess", "--input", &format!("{}/nope.csv", d.display())]).contains("nope.csv")
    );
    let big = d.join("big.csv");
    std::fs::File::create(&big)
        .unwrap()
        .set_len((2u64 << 30) + 1)
        .unwrap();
    assert!(fails(&["simulate", "--input", big.to_str().unwrap()]).contains("cap"));
}

#[test]
fn a_record_beyond_the_sample_cap_is_refused() {
    // duration × fs over 10^8 samples.
    let err = fails(&[
        "assess",
        "--signal",
        "sine:freq=5,amp=1",
        "--duration",
        "200000",
        "--fs",
        "1000",
    ]);
    assert!(
        err.contains("2e8 samples") && err.contains("cap of 100000000"),
        "{err}"
    );
}

#[test]
fn a_low_rate_is_warned_about_and_its_bands_left_out() {
    // At or under twice the band's top (80 Hz) no verdict (issue 30 item 2).
    let e = fails(&["assess", "--signal", "sine:freq=5,amp=1", "--fs", "160"]);
    assert!(
        e.contains("sampling rate 160 Hz cannot carry Wk's band to 80 Hz"),
        "{e}"
    );
    let out = ok(&[
        "assess",
        "--signal",
        "sine:freq=5,amp=1",
        "--fs",
        "170",
        "--format",
        "json",
    ]);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let warnings: Vec<&str> = v["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|w| w.as_str())
        .collect();
    assert!(
        warnings.iter().any(|w| w.contains("is low for Wk")),
        "{warnings:?}"
    );
    assert!(
        warnings.iter().any(|w| w.contains("not computed")),
        "{warnings:?}"
    );
    let bands = v["bands"].as_array().unwrap();
    assert!(bands.last().unwrap()["seat_m_s2"].is_null());
    assert!(bands[0]["seat_m_s2"].is_number());
    // At 1000 Hz there is nothing to warn about for a steady sine.
    let out = ok(&[
        "assess",
        "--signal",
        "sine:freq=5,amp=1",
        "--format",
        "json",
    ]);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(
        v["warnings"].as_array().unwrap().len(),
        0,
        "{}",
        v["warnings"]
    );
}

/// Regression (fuzz): inputs that printed NaN or inf with status 0 are
/// refused with status 1, in one short printable line with short numbers.
#[test]
fn signals_and_records_that_would_print_nan_or_inf_are_refused() {
    for spec in [
        "random:rms=0.01,band=1e-300-1e-299,seed=0",
        "sine:freq=1,amp=1e308+sine:freq=1,amp=1e308",
        "shock:peak=1e308,width=0.1,at=0",
    ] {
        for cmd in ["simulate", "assess"] {
            let err = fails(&[cmd, "--signal", spec, "--fs", "2", "--duration", "1"]);
            assert!(!err.contains("000000"), "{cmd} {spec}: {err}");
        }
    }
    let dir = tempfile::tempdir().expect("temp dir");
    let big = dir.path().join("big.csv");
    std::fs::write(&big, "t_s,acc\n0,1\n0.01,1e308\n0.02,1\n").expect("write");
    let err = fails(&["simulate", "--input", big.to_str().expect("utf-8")]);
    assert!(err.contains("line 3") && err.contains("cap"), "{err}");
    // Control characters in a column name never reach stderr.
    let ctl = dir.path().join("ctl.csv");
    std::fs::write(&ctl, "t_s,\"acc\x1b[31mred\x07\nsplit\"\n0,1\n0.01,1\n").expect("write");
    let args = [
        "simulate",
        "--input",
        ctl.to_str().expect("utf-8"),
        "--column",
        "acc",
    ];
    let err = fails(&args);
    assert!(!err.contains('\x1b') && !err.contains('\x07'), "{err:?}");
}

/// Regression: an error with stderr unwritable (a full disk here) exits 1,
/// not 101 from a panicking eprintln!.
#[test]
fn an_error_with_stderr_unwritable_still_exits_1() {
    for args in [
        &["simulate", "--input", "/nonexistent/no.csv"][..],
        &["simulate", "--signal", "bogus"][..],
        &["fit", "--data", "/nonexistent/no.csv"][..],
    ] {
        let full = std::fs::File::create("/dev/full").expect("/dev/full");
        let status = Command::new(env!("CARGO_BIN_EXE_biodyn"))
            .args(args)
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::from(full))
            .status()
            .expect("biodyn runs");
        assert_eq!(status.code(), Some(1), "{args:?}");
    }
}

/// `assess` wraps its input errors: the hint must still be about the input
/// (a record, a duration), not about `--exposure`.
#[test]
fn assess_input_errors_get_the_inputs_hint() {
    let dir = tempfile::tempdir().expect("tempdir");
    let uneven = dir.path().join("uneven.csv");
    std::fs::write(&uneven, "t_s,acc\n0,1\n0.001,2\n0.0025,3\n").expect("write");
    let err = fails(&["assess", "--input", uneven.to_str().expect("utf-8")]);
    assert!(err.contains("line 4"), "{err}");
    assert!(err.contains("hint: a CSV with a header"), "{err}");
    let err = fails(&[
        "assess",
        "--signal",
        "sine:freq=5,amp=5",
        "--duration",
        "1e12",
    ]);
    assert!(err.contains("hint: e.g. --duration"), "{err}");
    let (code, _, err) = run(&[
        "assess",
        "--signal",
        "sine:freq=5,amp=5",
        "--exposure",
        "30",
    ]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("at most 24 h a day, e.g. --exposure 8"),
        "{err}"
    );
}

/// Issue 19 item 12: the time step is the mean over the record's first
/// rows, not its first step. A 1 kHz clock starting at t = 1e9 s has
/// steps off by an ulp of 1e9 (1.2e-7 s): its first step alone gave
/// 999.953 Hz; the mean of 4095 steps is within 1e-7 of 1000 Hz.
#[test]
fn the_sampling_rate_comes_from_many_steps_not_the_first() {
    let dir = tempfile::tempdir().expect("tempdir");
    let mut s = String::from("t_s,az\n");
    for k in 0..6000 {
        let t = 1e9 + k as f64 * 1e-3;
        s.push_str(&format!("{t:.3},{}\n", (k as f64 * 0.0314).sin()));
    }
    let p = write(dir.path(), "epoch.csv", &s);
    let out = ok(&["assess", "--input", &p, "--format", "json"]);
    let v: serde_json::Value = serde_json::from_str(&out).expect("json");
    let fs = v["fs_hz"].as_f64().expect("fs_hz");
    assert!((fs - 1000.0).abs() < 1e-4, "fs {fs}");
    // The first step alone is as far off as the issue saw.
    let first = (1e9_f64 + 1e-3) - 1e9;
    assert!((1.0 / first - 1000.0).abs() > 1e-2, "{}", 1.0 / first);
}

/// Issue 19 item 23: a `;`- or tab-separated record is told its separator,
/// not "only one column".
#[test]
fn a_record_separated_otherwise_is_told_its_separator() {
    let dir = tempfile::tempdir().expect("tempdir");
    for (name, text, sep) in [
        ("semi.csv", "t_s;az\n0;1\n0.001;2\n", "no comma but ';'"),
        ("tab.csv", "t_s\taz\n0\t1\n0.001\t2\n", "no comma but tabs"),
        ("space.csv", "t_s az\n0 1\n0.001 2\n", "no comma but spaces"),
    ] {
        let p = write(dir.path(), name, text);
        let err = fails(&["assess", "--input", &p]);
        assert!(err.contains(sep), "{err}");
        assert!(!err.contains("only one column"), "{err}");
    }
    // One real column is still asked for its rate.
    let p = write(dir.path(), "one.csv", "az\n1\n2\n");
    assert!(fails(&["assess", "--input", &p]).contains("only one column"));
}
