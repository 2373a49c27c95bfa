//! The real `biodyn` binary as a process: outputs against the reference
//! tables, and every bad input of issue 2 as a clean error.

use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

// ---- helpers ---------------------------------------------------------------

const HEADER: &str = "f_hz,stht_mag,stht_phase_deg,dpmi_mag,dpmi_phase_deg,apms_mag,apms_phase_deg";

use crate::common::{fails, ok, root, run};

/// Runs and expects a clap usage error: status 2, empty stdout. Returns stderr.
fn usage(args: &[&str]) -> String {
    let (code, out, err) = run(args);
    assert_eq!(code, Some(2), "{args:?}: status {code:?}, stderr: {err}");
    assert!(out.is_empty(), "{args:?}: stdout not empty: {out}");
    assert!(err.contains("error:"), "{args:?}: {err}");
    assert!(!err.contains("panicked"), "{args:?}: {err}");
    err
}

fn has(haystack: &str, needles: &[&str]) {
    for n in needles {
        assert!(haystack.contains(n), "'{n}' missing from:\n{haystack}");
    }
}

/// Parses a response CSV: checks the header, returns rows of (text, value).
fn parse_csv(text: &str) -> Vec<Vec<(String, f64)>> {
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some(HEADER));
    lines
        .map(|l| {
            let cells: Vec<(String, f64)> = l
                .split(',')
                .map(|c| {
                    let v: f64 = c.parse().unwrap_or_else(|_| panic!("not a number: {c}"));
                    (c.to_string(), v)
                })
                .collect();
            assert_eq!(cells.len(), 7, "row: {l}");
            cells
        })
        .collect()
}

fn values(rows: &[Vec<(String, f64)>]) -> Vec<Vec<f64>> {
    rows.iter()
        .map(|r| r.iter().map(|c| c.1).collect())
        .collect()
}

fn reference(name: &str) -> Vec<Vec<f64>> {
    let p = root().join(format!("tests/data/reference/{name}.csv"));
    values(&parse_csv(&std::fs::read_to_string(p).unwrap()))
}

fn close(a: f64, b: f64, rel: f64) -> bool {
    a == b || (a - b).abs() <= rel * a.abs().max(b.abs())
}

fn assert_rows_close(got: &[Vec<f64>], want: &[Vec<f64>], rel: f64, what: &str) {
    assert_eq!(got.len(), want.len(), "{what}: row count");
    for (i, (g, w)) in got.iter().zip(want).enumerate() {
        assert_eq!(g[0], w[0], "{what}: frequency of row {i}");
        for (j, (a, b)) in g.iter().zip(w).enumerate() {
            assert!(
                close(*a, *b, rel),
                "{what}: row {i} (f = {}) column {j}: {a} vs {b}",
                g[0]
            );
        }
    }
}

fn temp_file(dir: &Path, name: &str, bytes: impl AsRef<[u8]>) -> String {
    let p = dir.join(name);
    std::fs::write(&p, bytes).unwrap();
    p.to_str().unwrap().to_string()
}

fn tempdir() -> tempfile::TempDir {
    tempfile::tempdir().unwrap()
}

// ---- response ----------------------------------------------------------------

#[test]
fn response_csv_matches_the_reference_tables() {
    for (args, name) in [
        (vec![], "paper-75kg"),
        (
            vec!["--preset", "boileau-rakheja-1998"],
            "boileau-rakheja-1998",
        ),
        (vec!["--body-mass", "65"], "paper-65kg"),
        (vec!["--body-mass", "85"], "paper-85kg"),
        (vec!["--preset", "paper-85kg"], "paper-85kg"),
        (
            vec!["--preset", "presets/boileau-rakheja-1998.toml"],
            "boileau-rakheja-1998",
        ),
    ] {
        let mut a = vec!["response", "--format", "csv"];
        a.extend(&args);
        let out = ok(&a);
        let rows = parse_csv(&out);
        assert_eq!(rows.len(), 196, "{args:?}");
        assert_eq!(rows[0][0].0, "0.5");
        assert_eq!(rows[195][0].0, "20");
        assert_rows_close(&values(&rows), &reference(name), 1e-9, name);
    }
}

#[test]
fn response_csv_numbers_are_shortest_round_trip_and_phases_in_range() {
    let rows = parse_csv(&ok(&["response", "--format", "csv", "--step", "0.05"]));
    assert_eq!(rows.len(), 391);
    for r in &rows {
        for (text, v) in r {
            assert!(v.is_finite(), "{text}");
            assert_eq!(&format!("{v}"), text, "not shortest round trip");
        }
        for j in [2, 4, 6] {
            let p = r[j].1;
            assert!(p > -180.0 && p <= 180.0, "phase {p} at f = {}", r[0].1);
        }
    }
    // Frequencies on the grid print cleanly: 0.55, not 0.5500000000000002.
    assert!(rows.iter().all(|r| r[0].0.len() <= 5), "{:?}", rows[1][0]);
}

#[test]
fn response_low_frequency_limits_hold() {
    // DPMI phase near +90°, STHT near 1, APMS near the seated mass 0.781 × 75.
    let rows = values(&parse_csv(&ok(&[
        "response", "--format", "csv", "--from", "0.01", "--to", "0.02", "--step", "0.01",
    ])));
    let r = &rows[0];
    assert!((r[1] - 1.0).abs() < 1e-4, "{r:?}");
    assert!((r[4] - 90.0).abs() < 0.01, "{r:?}");
    assert!((r[5] - 0.781 * 75.0).abs() < 1e-2, "{r:?}");
}

#[test]
fn response_json_matches_csv() {
    let csv = values(&parse_csv(&ok(&["response", "--format", "csv"])));
    let json: serde_json::Value = serde_json::from_str(&ok(&["response", "--format", "json"]))
        .expect("response --format json parses");
    let arr = json.as_array().expect("a JSON array");
    assert_eq!(arr.len(), csv.len());
    let keys: Vec<&str> = HEADER.split(',').collect();
    for (obj, row) in arr.iter().zip(&csv) {
        let obj = obj.as_object().unwrap();
        assert_eq!(obj.len(), 7, "{obj:?}");
        for (k, want) in keys.iter().zip(row) {
            let got = obj[*k]
                .as_f64()
                .unwrap_or_else(|| panic!("{k} not a number"));
            assert!(close(got, *want, 1e-15), "{k}: {got} vs {want}");
        }
    }
}

#[test]
fn response_table_has_a_header() {
    let out = ok(&["response"]);
    let lines: Vec<&str> = out.lines().collect();
    has(lines[0], &["f Hz", "STHT", "DPMI", "APMS"]);
    // header, rule, 196 rows
    assert_eq!(lines.len(), 198, "{}", &out[..300]);
    assert!(lines[1].chars().all(|c| c == '-'), "{}", lines[1]);
    assert!(lines[2].trim_start().starts_with("0.5"), "{}", lines[2]);
    assert!(
        lines[197].trim_start().starts_with("20.0"),
        "{}",
        lines[197]
    );
}

#[test]
fn response_band_options_give_exact_grid() {
    let rows = parse_csv(&ok(&[
        "response", "--format", "csv", "--from", "1", "--to", "2", "--step", "0.25",
    ]));
    let f: Vec<&str> = rows.iter().map(|r| r[0].0.as_str()).collect();
    assert_eq!(f, ["1", "1.25", "1.5", "1.75", "2"]);
    // 'to' off the grid is not included.
    let rows = parse_csv(&ok(&[
        "response", "--format", "csv", "--from", "1", "--to", "2.05", "--step", "0.1",
    ]));
    assert_eq!(rows.len(), 11);
    assert_eq!(rows[10][0].0, "2");
    // The fine grid of the speed target.
    let rows = parse_csv(&ok(&["response", "--format", "csv", "--step", "0.01"]));
    assert_eq!(rows.len(), 1951);
    assert_eq!(rows[1950][0].0, "20");
}

#[test]
fn set_k4_changes_output_and_equals_study() {
    let base = ok(&["response", "--format", "csv"]);
    let set = ok(&["response", "--format", "csv", "--set", "k4=54000"]);
    assert_ne!(base, set);
    let study = ok(&["study", "k4", "54000", "--format", "csv"]);
    let mut lines = study.lines();
    assert_eq!(
        lines.next(),
        Some(format!("variant,value,{HEADER}").as_str())
    );
    let study_rows: Vec<&str> = lines
        .map(|l| {
            // "label",value,f,...
            let rest = l.split_once("\",").unwrap().1;
            let (value, row) = rest.split_once(',').unwrap();
            assert_eq!(value, "54000");
            row
        })
        .collect();
    let set_rows: Vec<&str> = set.lines().skip(1).collect();
    assert_eq!(study_rows, set_rows);
    // The same by name.
    assert_eq!(
        ok(&[
            "response",
            "--format",
            "csv",
            "--set",
            "pelvis-seat.k=54000"
        ]),
        set
    );
}

#[test]
fn set_body_mass_name_and_segment_name_work() {
    assert_eq!(
        ok(&["response", "--format", "csv", "--set", "body_mass=85"]),
        ok(&["response", "--format", "csv", "--body-mass", "85"])
    );
    let chest = ok(&["response", "--format", "csv", "--set", "chest=30"]);
    assert_eq!(
        chest,
        ok(&["response", "--format", "csv", "--set", "m2=30"])
    );
    assert_ne!(chest, ok(&["response", "--format", "csv"]));
}

#[test]
fn preset_file_equals_body_mass() {
    assert_eq!(
        ok(&[
            "response",
            "--format",
            "csv",
            "--preset",
            "presets/paper-85kg.toml"
        ]),
        ok(&["response", "--format", "csv", "--body-mass", "85"])
    );
}

// ---- modes and peaks -------------------------------------------------------

#[test]
fn modes_of_boileau_rakheja_match_the_reference() {
    let out = ok(&["modes", "--preset", "boileau-rakheja-1998"]);
    has(&out, &["oscillatory", "overdamped", "Undamped"]);
    assert_eq!(
        out.lines().filter(|l| l.contains("oscillatory")).count(),
        2,
        "{out}"
    );
    assert_eq!(
        out.lines().filter(|l| l.contains("overdamped")).count(),
        4,
        "{out}"
    );
    let json: serde_json::Value = serde_json::from_str(&ok(&[
        "modes",
        "--preset",
        "boileau-rakheja-1998",
        "--format",
        "json",
    ]))
    .unwrap();
    let damped = json["damped"].as_array().unwrap();
    let kind =
        |k: &str| -> Vec<&serde_json::Value> { damped.iter().filter(|m| m["kind"] == k).collect() };
    let osc = kind("oscillatory");
    assert_eq!(osc.len(), 2, "{json}");
    let mut fz: Vec<(f64, f64)> = osc
        .iter()
        .map(|m| {
            (
                m["natural_hz"].as_f64().unwrap(),
                m["damping_ratio"].as_f64().unwrap(),
            )
        })
        .collect();
    fz.sort_by(|a, b| a.0.total_cmp(&b.0));
    assert!(
        (fz[0].0 - 5.13).abs() < 0.01 && (fz[0].1 - 0.394).abs() < 0.001,
        "{fz:?}"
    );
    assert!(
        (fz[1].0 - 41.1).abs() < 0.1 && (fz[1].1 - 0.186).abs() < 0.001,
        "{fz:?}"
    );
    for m in &osc {
        // damped = natural × sqrt(1 − ζ²)
        let (wn, wd, z) = (
            m["natural_hz"].as_f64().unwrap(),
            m["damped_hz"].as_f64().unwrap(),
            m["damping_ratio"].as_f64().unwrap(),
        );
        assert!(close(wd, wn * (1.0 - z * z).sqrt(), 1e-9), "{m}");
    }
    let mut rates: Vec<f64> = kind("overdamped")
        .iter()
        .map(|m| m["rate_per_s"].as_f64().unwrap().abs())
        .collect();
    rates.sort_by(f64::total_cmp);
    let want = [37.8, 45.5, 311.7, 1342.9];
    assert_eq!(rates.len(), 4, "{json}");
    for (r, w) in rates.iter().zip(want) {
        assert!((r - w).abs() < 0.1, "{rates:?}");
    }
    let mut undamped: Vec<f64> = json["undamped"]
        .as_array()
        .unwrap()
        .iter()
        .map(|m| m["natural_hz"].as_f64().unwrap())
        .collect();
    undamped.sort_by(f64::total_cmp);
    // A zip stops at the shorter side: without the count an empty list passes.
    assert_eq!(undamped.len(), 4, "{json}");
    for (u, w) in undamped.iter().zip([5.11, 18.61, 35.42, 42.52]) {
        assert!((u - w).abs() < 0.01, "{undamped:?}");
    }
}

/// (function, f, magnitude) of the biggest peak of each function.
fn main_peaks(json: &serde_json::Value) -> Vec<(String, f64, f64)> {
    let mut best: Vec<(String, f64, f64)> = Vec::new();
    for p in json.as_array().unwrap() {
        let f = p["function"].as_str().unwrap().to_ascii_uppercase();
        let (hz, mag) = (p["f_hz"].as_f64().unwrap(), p["mag"].as_f64().unwrap());
        match best.iter_mut().find(|b| b.0 == f) {
            Some(b) if b.2 < mag => *b = (f, hz, mag),
            Some(_) => {}
            None => best.push((f, hz, mag)),
        }
    }
    best
}

#[test]
fn peaks_of_boileau_rakheja_match_the_reference() {
    let json: serde_json::Value = serde_json::from_str(&ok(&[
        "peaks",
        "--preset",
        "boileau-rakheja-1998",
        "--format",
        "json",
    ]))
    .unwrap();
    let best = main_peaks(&json);
    for (name, f, mag, tol) in [
        ("STHT", 4.676, 1.7807, 1e-4),
        ("DPMI", 5.462, 2847.1, 0.1),
        ("APMS", 4.570, 90.48, 0.01),
    ] {
        let b = best
            .iter()
            .find(|b| b.0 == name)
            .unwrap_or_else(|| panic!("no {name} peak in {json}"));
        assert!((b.1 - f).abs() < 0.01, "{name} at {} Hz, want {f}", b.1);
        assert!((b.2 - mag).abs() <= tol, "{name} peak {}, want {mag}", b.2);
    }
    // The table: "function  f Hz  magnitude  unit" rows, parsed back.
    let table = ok(&["peaks", "--preset", "boileau-rakheja-1998"]);
    for (name, f, mag) in [
        ("STHT", 4.676, 1.7807),
        ("DPMI", 5.462, 2847.1),
        ("APMS", 4.570, 90.48),
    ] {
        let hit = table.lines().any(|l| {
            let c: Vec<&str> = l.split_whitespace().collect();
            c.len() >= 3
                && c[0] == name
                && c[1].parse::<f64>().is_ok_and(|x| (x - f).abs() < 0.01)
                && c[2].parse::<f64>().is_ok_and(|x| close(x, mag, 1e-4))
        });
        assert!(hit, "no {name} row near {f} Hz, {mag}:\n{table}");
    }
}

#[test]
fn peaks_refine_off_the_grid() {
    // On a coarse 0.5 Hz grid the refined peak is still within 0.01 Hz.
    let json: serde_json::Value = serde_json::from_str(&ok(&[
        "peaks",
        "--preset",
        "boileau-rakheja-1998",
        "--step",
        "0.5",
        "--format",
        "json",
    ]))
    .unwrap();
    let best = main_peaks(&json);
    let stht = best.iter().find(|b| b.0 == "STHT").unwrap();
    assert!((stht.1 - 4.676).abs() < 0.01, "{stht:?}");
}

// ---- study -------------------------------------------------------------------

#[test]
fn study_mass_table_csv_json() {
    let table = ok(&["study", "mass", "65,75,85"]);
    has(&table, &["65", "75", "85", "STHT", "DPMI", "APMS"]);
    let csv = ok(&["study", "mass", "65,75,85", "--format", "csv"]);
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(lines[0], format!("variant,value,{HEADER}"));
    assert_eq!(lines.len(), 1 + 3 * 196);
    // The 85 kg curve equals the 85 kg reference.
    let rows: Vec<Vec<f64>> = lines[1..]
        .iter()
        .filter(|l| l.contains("\",85,"))
        .map(|l| {
            l.split_once("\",85,")
                .unwrap()
                .1
                .split(',')
                .map(|c| c.parse().unwrap())
                .collect()
        })
        .collect();
    assert_rows_close(&rows, &reference("paper-85kg"), 1e-9, "study 85 kg");
    let json: serde_json::Value =
        serde_json::from_str(&ok(&["study", "mass", "65,75,85", "--format", "json"])).unwrap();
    assert_eq!(json["variants"].as_array().unwrap().len(), 3, "{json}");
    assert_eq!(json["trends"].as_array().unwrap().len(), 3);
    for v in json["variants"].as_array().unwrap() {
        assert_eq!(v["points"].as_array().unwrap().len(), 196);
    }
}

#[test]
fn study_k4_percent_lists_three_variants() {
    let table = ok(&["study", "k4", "-40%,0%,+40%"]);
    // Base value and the ±40 % variants are named.
    has(&table, &["k4", "-40%", "+40%", "54000", "90000", "126000"]);
    let variant_rows = table
        .lines()
        .filter(|l| l.trim_start().starts_with("k4 "))
        .count();
    assert_eq!(variant_rows, 3, "{table}");
    let csv = ok(&["study", "k4", "-40%,0%,+40%", "--format", "csv"]);
    assert_eq!(csv.lines().count(), 1 + 3 * 196);
    let json: serde_json::Value =
        serde_json::from_str(&ok(&["study", "k4", "-40%,0%,+40%", "--format", "json"])).unwrap();
    let vals: Vec<f64> = json["variants"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v["value"].as_f64().unwrap())
        .collect();
    assert_eq!(vals.len(), 3);
    assert!(
        close(vals[0], 54000.0, 1e-12) && vals[1] == 90000.0 && close(vals[2], 126000.0, 1e-12)
    );
    assert_eq!(json["trends"].as_array().unwrap().len(), 3);
}

// ---- plot --------------------------------------------------------------------

#[test]
fn plot_has_the_requested_size() {
    let out = ok(&["plot", "stht", "--width", "80", "--height", "24"]);
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines.len(), 24, "{out}");
    for l in &lines {
        assert!(
            l.chars().count() <= 80,
            "{} columns: {l}",
            l.chars().count()
        );
    }
    has(&out, &["STHT"]);
}

#[test]
fn plot_ascii_is_pure_ascii() {
    for f in ["stht", "dpmi", "apms"] {
        let out = ok(&["plot", f, "--ascii", "--width", "80", "--height", "24"]);
        let bad: Vec<char> = out.chars().filter(|c| !c.is_ascii()).collect();
        assert!(bad.is_empty(), "{f}: non-ASCII {bad:?}\n{out}");
        assert_eq!(out.lines().count(), 24);
    }
}

#[test]
fn plot_study_shows_a_legend_of_three() {
    let out = ok(&[
        "plot",
        "apms",
        "--study",
        "mass=65,75,85",
        "--width",
        "100",
        "--height",
        "30",
    ]);
    assert_eq!(out.lines().count(), 30);
    for kg in ["65", "75", "85"] {
        assert!(
            out.lines().any(|l| l.contains("mass") && l.contains(kg)),
            "no legend entry for {kg} kg:\n{out}"
        );
    }
}

/// The x axis of a (Unicode) `biodyn plot`: (first plot column, last plot column,
/// tick-mark columns, labels as (centre column, value)).
fn x_axis(out: &str) -> (usize, usize, Vec<usize>, Vec<(usize, f64)>) {
    let lines: Vec<Vec<char>> = out.lines().map(|l| l.chars().collect()).collect();
    let ai = lines
        .iter()
        .position(|l| l.contains(&'└') && l.contains(&'┬'))
        .expect("an axis row");
    let axis = &lines[ai];
    let corner = axis.iter().position(|&c| c == '└').expect("corner");
    let left = corner + 1;
    let right = (left..axis.len())
        .take_while(|&i| matches!(axis[i], '─' | '┬'))
        .last()
        .expect("axis line");
    let ticks: Vec<usize> = (left..=right)
        .filter(|&i| matches!(axis[i], '┬' | '+'))
        .collect();
    let row = &lines[ai + 1];
    let mut labels = Vec::new();
    let mut i = 1;
    while i + 1 < row.len() {
        if row[i].is_ascii_digit() || row[i] == '.' || row[i] == '-' {
            let start = i;
            while i < row.len() && !row[i].is_whitespace() && row[i] != '│' {
                i += 1;
            }
            let text: String = row[start..i].iter().collect();
            let v: f64 = text.parse().unwrap_or_else(|_| panic!("label {text:?}"));
            labels.push((start + (i - start) / 2, v));
        }
        i += 1;
    }
    (left, right, ticks, labels)
}

#[test]
fn plot_x_labels_sit_under_their_frequency() {
    for (w, h, log) in [
        ("80", "20", false),
        ("80", "24", true),
        ("200", "60", false),
        ("200", "60", true),
        ("60", "16", false),
    ] {
        let mut args = vec!["plot", "stht", "--width", w, "--height", h];
        if log {
            args.push("--log-x");
        }
        let out = ok(&args);
        let (left, right, ticks, labels) = x_axis(&out);
        assert!(labels.len() >= 3, "{w}x{h}:\n{out}");
        // A tick mark over every label, and no other.
        let at: Vec<usize> = labels.iter().map(|l| l.0).collect();
        assert_eq!(ticks, at, "{w}x{h} log {log}:\n{out}");
        // Each label where its value lies between the plot's ends (the
        // band 0.5..20 Hz: linear axes run 0..20, log axes 0.5..20).
        let (lo, hi) = if log { (0.5f64, 20.0f64) } else { (0.0, 20.0) };
        for &(col, v) in &labels {
            let t = if log {
                (v / lo).ln() / (hi / lo).ln()
            } else {
                (v - lo) / (hi - lo)
            };
            let want = left as f64 + t * (right - left) as f64;
            assert!(
                (col as f64 - want).abs() <= 1.0,
                "{w}x{h} log {log}: label {v} at column {col}, its value at {want:.1}\n{out}"
            );
        }
    }
}

#[test]
fn plot_magnitude_axes_start_at_zero() {
    for (w, h) in [("80", "20"), ("200", "60"), ("60", "12")] {
        let out = ok(&[
            "plot",
            "dpmi",
            "--study",
            "mass=65,75,85",
            "--width",
            w,
            "--height",
            h,
        ]);
        // The y labels: the numbers left of the y axis.
        let ys: Vec<f64> = out
            .lines()
            .filter_map(|l| {
                let l = l.trim_start_matches(['│', '|', ' ']);
                let (num, _) = l.split_once(['┤', '+'])?;
                num.trim().parse().ok()
            })
            .collect();
        assert!(ys.len() >= 2, "{w}x{h}:\n{out}");
        assert_eq!(ys.last(), Some(&0.0), "{w}x{h}:\n{out}");
        assert!(ys.iter().all(|&y| y >= 0.0), "{w}x{h}: {ys:?}\n{out}");
        assert!(ys.windows(2).all(|p| p[0] > p[1]), "{ys:?}");
        if h != "12" {
            assert!(ys.len() >= 4, "{w}x{h}: {ys:?}\n{out}");
        }
    }
}

#[test]
fn plot_ascii_gives_each_series_its_own_glyph() {
    let out = ok(&[
        "plot",
        "stht",
        "--study",
        "mass=65,75,85",
        "--ascii",
        "--width",
        "80",
        "--height",
        "20",
    ]);
    for entry in [
        "* body mass = 65 kg",
        "+ body mass = 75 kg",
        "o body mass = 85 kg",
        "^ peak",
    ] {
        assert!(out.contains(entry), "{entry}:\n{out}");
    }
    // Inside the plot (between the y axis and the frame) all three glyphs.
    let plot: String = out
        .lines()
        .skip(5)
        .filter_map(|l| l.split_once('|').map(|(_, r)| r.to_string()))
        .collect();
    for g in ['*', '+', 'o', '^'] {
        assert!(plot.contains(g), "{g}:\n{out}");
    }
}

// ---- presets -------------------------------------------------------------------

#[test]
fn preset_list_shows_the_six_builtins() {
    let out = ok(&["preset", "list"]);
    let builtins: Vec<&str> = out.lines().filter(|l| l.contains("built-in")).collect();
    assert_eq!(builtins.len(), 6, "{out}");
    for name in [
        "paper-75kg",
        "paper-65kg",
        "paper-85kg",
        "boileau-rakheja-1998",
        "paper-75kg-suspension-seat",
        "paper-75kg-rigid-seat",
    ] {
        assert!(
            builtins.iter().any(|l| l.starts_with(name)),
            "{name}: {out}"
        );
    }
    assert!(!out.contains("BROKEN"), "{out}");
}

#[test]
fn preset_show_is_valid_toml_that_check_accepts() {
    let dir = tempdir();
    for name in ["paper-75kg", "boileau-rakheja-1998"] {
        let shown = ok(&["preset", "show", name]);
        let path = temp_file(dir.path(), &format!("{name}-copy.toml"), &shown);
        let checked = ok(&["preset", "check", &path]);
        assert!(checked.starts_with("ok: "), "{checked}");
        assert_eq!(
            ok(&["response", "--format", "csv", "--preset", &path]),
            ok(&["response", "--format", "csv", "--preset", name])
        );
    }
    // show of a file prints it as loaded, which also checks.
    let shown = ok(&["preset", "show", "presets/paper-65kg.toml"]);
    let path = temp_file(dir.path(), "65.toml", &shown);
    ok(&["preset", "check", &path]);
}

#[test]
fn preset_check_accepts_each_shipped_file() {
    for name in [
        "paper-75kg",
        "paper-65kg",
        "paper-85kg",
        "boileau-rakheja-1998",
    ] {
        let file = format!("presets/{name}.toml");
        let out = ok(&["preset", "check", &file]);
        assert!(out.starts_with(&format!("ok: {file}")), "{out}");
        has(&out, &["4 segments", "4 links"]);
    }
}

#[test]
fn preset_save_then_load_back() {
    let dir = tempdir();
    let out = dir.path().join("stiff.toml");
    let o = out.to_str().unwrap();
    let (code, stdout, stderr) = run(&["preset", "save", o, "--set", "k4=1e5"]);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(stdout.is_empty(), "{stdout}");
    assert!(stderr.contains("saved"), "{stderr}");
    let p = biodyn::Preset::load(&out).unwrap();
    assert_eq!(p.body.links[3].k, 1e5);
    assert_eq!(
        ok(&["response", "--format", "csv", "--preset", o]),
        ok(&["response", "--format", "csv", "--set", "k4=1e5"])
    );
    // Only the file, no temp leftovers.
    let names: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
    assert_eq!(names.len(), 1);
}

// ---- bad input: preset files ---------------------------------------------------

#[test]
fn malformed_toml_preset_is_an_error_with_line_and_column() {
    let dir = tempdir();
    let p = temp_file(dir.path(), "broken.toml", "schema = 1\nname = = 3\n");
    for cmd in [
        &["response"][..],
        &["modes"],
        &["peaks"],
        &["study", "k4", "1,2"],
    ] {
        let mut a = cmd.to_vec();
        a.extend(["--preset", &p]);
        let err = fails(&a);
        has(&err, &[&format!("{p}:2:")]);
    }
    let err = fails(&["preset", "check", &p]);
    has(&err, &[&format!("{p}:2:")]);
}

#[test]
fn empty_and_binary_files_are_errors() {
    let dir = tempdir();
    let empty = temp_file(dir.path(), "empty.toml", "");
    has(
        &fails(&["response", "--preset", &empty]),
        &[&empty, "empty"],
    );
    let blank = temp_file(dir.path(), "blank.toml", "  \n\n");
    has(
        &fails(&["response", "--preset", &blank]),
        &[&blank, "empty"],
    );
    let bin = temp_file(
        dir.path(),
        "bin.toml",
        [0x7fu8, b'E', b'L', b'F', 0, 0, 1, 2],
    );
    has(
        &fails(&["response", "--preset", &bin]),
        &[&bin, "not a text file"],
    );
    let latin1 = temp_file(dir.path(), "latin1.toml", b"name = \"caf\xe9\"\n");
    has(
        &fails(&["preset", "check", &latin1]),
        &[&latin1, "not a text file"],
    );
}

#[test]
fn directory_and_missing_path_are_errors() {
    let dir = tempdir();
    let d = dir.path().to_str().unwrap();
    has(&fails(&["response", "--preset", d]), &[d, "directory"]);
    has(&fails(&["preset", "check", d]), &["directory"]);
    let missing = dir.path().join("nope.toml");
    let m = missing.to_str().unwrap();
    has(&fails(&["response", "--preset", m]), &["nope.toml"]);
    has(
        &fails(&["response", "--preset", "nosuchpreset"]),
        &["nosuchpreset", "paper-75kg"],
    );
    has(
        &fails(&["preset", "show", "nosuchpreset"]),
        &["nosuchpreset"],
    );
}

/// A valid preset text to break one field of.
fn good_preset() -> String {
    let (_, out, _) = run(&["preset", "show", "boileau-rakheja-1998"]);
    out
}

#[test]
fn wrong_type_missing_and_unknown_fields_are_errors() {
    let dir = tempdir();
    let text = good_preset();
    let cases = [
        (
            "type.toml",
            text.replacen("mass_kg = 5.31", "mass_kg = \"heavy\"", 1),
            "\"heavy\"",
        ),
        (
            "missing.toml",
            text.replacen("k_n_per_m = 90000.0\n", "", 1),
            "k_n_per_m",
        ),
        (
            "unknown.toml",
            text.replacen("mass_kg = 5.31", "mas_kg = 5.31", 1),
            "mas_kg",
        ),
    ];
    for (name, t, word) in cases {
        assert_ne!(t, text, "{name}: replacement did not apply");
        let p = temp_file(dir.path(), name, &t);
        let err = fails(&["response", "--preset", &p]);
        has(&err, &[&p, word]);
        // path:line:col
        let after = &err[err.find(&p).unwrap() + p.len()..];
        let mut parts = after.split(':');
        assert_eq!(parts.next(), Some(""));
        assert!(parts.next().unwrap().parse::<usize>().is_ok(), "{err}");
    }
}

#[test]
fn floating_segment_preset_is_an_error() {
    let dir = tempdir();
    let text = good_preset() + "\n[[segment]]\nname = \"loose\"\nmass_kg = 2.0\n";
    let p = temp_file(dir.path(), "floating.toml", text);
    has(&fails(&["response", "--preset", &p]), &["loose", "seat"]);
    has(&fails(&["preset", "check", &p]), &["loose"]);
}

#[test]
fn body_mass_on_a_model_without_shares_is_an_error() {
    let err = fails(&[
        "response",
        "--preset",
        "boileau-rakheja-1998",
        "--body-mass",
        "70",
    ]);
    has(&err, &["--body-mass", "share", "--set m1"]);
}

#[test]
fn bad_body_mass_is_an_error() {
    for v in ["-5", "0", "nan", "inf"] {
        has(
            &fails(&["response", "--body-mass", v]),
            &["--body-mass", "body mass"],
        );
    }
    usage(&["response", "--body-mass", "heavy"]);
}

// ---- bad input: --set ------------------------------------------------------------

#[test]
fn bad_masses_via_set_are_errors() {
    for v in ["-1", "0", "nan", "inf", "-inf"] {
        let arg = format!("m1={v}");
        let err = fails(&["response", "--set", &arg]);
        has(&err, &[&format!("--set {arg}")]);
    }
    has(
        &fails(&["response", "--set", "m1=-1"]),
        &["head-neck", "> 0"],
    );
    has(&fails(&["response", "--set", "m1=0"]), &["head-neck"]);
    has(&fails(&["response", "--set", "m1=nan"]), &["finite"]);
    has(&fails(&["response", "--set", "m1=inf"]), &["finite"]);
}

#[test]
fn negative_stiffness_and_damping_via_set_are_errors() {
    has(
        &fails(&["response", "--set", "k4=-1"]),
        &["--set k4=-1", "pelvis-seat", "[0, 1e12]"],
    );
    has(
        &fails(&["response", "--set", "c2=-0.5"]),
        &["--set c2=-0.5", "chest-lower-torso"],
    );
    has(&fails(&["response", "--set", "c1=nan"]), &["--set c1=nan"]);
    has(&fails(&["modes", "--set", "k1=-3"]), &["k1=-3"]);
    has(
        &fails(&[
            "preset",
            "save",
            "/tmp/never-written.toml",
            "--set",
            "k1=-3",
        ]),
        &["k1=-3"],
    );
    assert!(!Path::new("/tmp/never-written.toml").exists());
}

#[test]
fn unknown_set_names_are_errors() {
    for arg in ["k9=1", "x=1", "m0=1", "pelvis-seat.z=1", "k=1"] {
        let err = fails(&["response", "--set", arg]);
        has(
            &err,
            &[&format!("--set {arg}"), "unknown parameter", "k1..k4"],
        );
    }
}

#[test]
fn malformed_set_is_an_error() {
    has(
        &fails(&["response", "--set", "k4"]),
        &["--set k4", "NAME=VALUE"],
    );
    has(&fails(&["response", "--set", "=5"]), &["--set =5", "name"]);
    has(
        &fails(&["response", "--set", "k4=abc"]),
        &["--set k4=abc", "'abc'", "not a number"],
    );
    has(&fails(&["response", "--set", "k4="]), &["--set k4="]);
    // One bad --set among good ones still fails, and prints nothing.
    fails(&["response", "--set", "k4=54000", "--set", "k4=abc"]);
}

// ---- bad input: band, format, command --------------------------------------------

#[test]
fn bad_bands_are_errors() {
    for (a, word) in [
        (&["--from", "5", "--to", "5"][..], "from 5 Hz to 5 Hz"),
        (&["--from", "5", "--to", "1"], "from 5 Hz to 1 Hz"),
        (&["--step", "0"], "step = 0 Hz"),
        (&["--step", "-1"], "step = -1 Hz"),
        (&["--step", "nan"], "step = NaN Hz"),
        (&["--step", "1e-9"], "points"),
        (&["--from", "0"], "from = 0 Hz"),
        (&["--from", "-1"], "from = -1 Hz"),
        (&["--to", "inf"], "to = inf Hz"),
    ] {
        for cmd in ["response", "peaks"] {
            let mut args = vec![cmd];
            args.extend(a);
            let err = fails(&args);
            has(&err, &[word, "hint: e.g. --from"]);
        }
    }
    has(
        &fails(&["study", "mass", "65,75", "--step", "0"]),
        &["step"],
    );
    has(
        &fails(&["plot", "stht", "--from", "5", "--to", "1"]),
        &["from"],
    );
    has(
        &fails(&["response", "--step", "1e-9"]),
        &["10^6", "1000000"],
    );
}

#[test]
fn bad_format_and_command_are_usage_errors() {
    let err = usage(&["response", "--format", "xml"]);
    has(&err, &["xml", "table", "csv", "json"]);
    let err = usage(&["modes", "--format", "csv"]);
    has(&err, &["csv"]);
    let err = usage(&["frobnicate"]);
    has(&err, &["frobnicate"]);
    let err = usage(&["plot", "xyz"]);
    has(&err, &["xyz", "stht"]);
    let err = usage(&["response", "--from", "abc"]);
    has(&err, &["abc", "--from"]);
    // `study mass` alone takes the paper's list (papercuts.rs); no
    // parameter at all is still a usage error.
    let err = usage(&["study"]);
    has(&err, &["PARAM"]);
    usage(&["response", "--nosuch"]);
    usage(&["preset", "frob"]);
    usage(&["preset", "check"]);
}

#[test]
fn bad_study_values_are_errors() {
    has(
        &fails(&["study", "mass", "65,abc,85"]),
        &["'abc'", "entry 2", "hint: e.g. `biodyn study"],
    );
    has(&fails(&["study", "mass", "65,,85"]), &["entry 2", "empty"]);
    has(&fails(&["study", "mass", "65,75,"]), &["entry 3"]);
    has(&fails(&["study", "mass", ""]), &["study"]);
    has(
        &fails(&["study", "nosuch", "1,2"]),
        &["nosuch", "unknown parameter"],
    );
    has(&fails(&["study", "k4", "-100%,0%"]), &["-100"]);
    has(&fails(&["study", "mass", "65,-75"]), &["-75"]);
    has(&fails(&["study", "m1", "1,0"]), &["0"]);
    has(&fails(&["study", "mass", "65,nan"]), &["nan"]);
    has(
        &fails(&["study", "mass", "70", "--preset", "boileau-rakheja-1998"]),
        &["share"],
    );
    // plot --study goes through the same parser.
    has(
        &fails(&["plot", "stht", "--study", "mass=65,abc"]),
        &["'abc'"],
    );
    has(
        &fails(&["plot", "stht", "--study", "nosuch"]),
        &["nosuch", "unknown parameter"],
    );
    has(&fails(&["plot", "stht", "--width", "5"]), &["--width"]);
}

#[test]
fn save_to_unwritable_path_is_an_error() {
    let err = fails(&["preset", "save", "/nonexistent-dir/x.toml"]);
    has(
        &err,
        &[
            "/nonexistent-dir/x.toml",
            "the folder /nonexistent-dir does not exist",
            "hint: choose a file name in a folder you can write to",
        ],
    );
    assert!(!Path::new("/nonexistent-dir").exists());
}

#[test]
fn failing_save_leaves_existing_path_byte_identical() {
    let dir = tempdir();
    // The target is an existing directory: the rename must fail.
    let target: PathBuf = dir.path().join("taken.toml");
    std::fs::create_dir(&target).unwrap();
    std::fs::write(target.join("inside"), b"precious").unwrap();
    let t = target.to_str().unwrap();
    has(
        &fails(&["preset", "save", t]),
        &[
            "taken.toml",
            "is a directory; only a regular file is replaced",
        ],
    );
    assert!(target.is_dir());
    assert_eq!(std::fs::read(target.join("inside")).unwrap(), b"precious");
    let names: Vec<String> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(names, ["taken.toml"], "temp file left behind");

    // An existing file whose save fails for a bad --set stays byte-identical.
    let file = dir.path().join("keep.toml");
    let before = b"# not touched\nschema = 1\n";
    std::fs::write(&file, before).unwrap();
    fails(&["preset", "save", file.to_str().unwrap(), "--set", "m1=-1"]);
    assert_eq!(std::fs::read(&file).unwrap(), before);
}

// ---- pipes ---------------------------------------------------------------------

fn early_close(args: &[&str]) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_biodyn"))
        .args(args)
        .current_dir(root())
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = String::new();
    {
        let mut r = BufReader::new(child.stdout.take().unwrap());
        r.read_line(&mut first).unwrap();
    } // the read end closes here, like `| head -1`
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!first.is_empty(), "{args:?}: no first line");
    assert!(!err.contains("panicked"), "{args:?}: {err}");
    assert!(err.is_empty(), "{args:?}: stderr: {err}");
    assert!(out.status.success(), "{args:?}: {:?}", out.status);
}

#[test]
fn early_closed_pipe_is_not_an_error() {
    // Several MB of output: far more than a pipe buffer holds.
    early_close(&["response", "--format", "csv", "--step", "0.001"]);
    early_close(&["response", "--step", "0.001"]);
    early_close(&[
        "study", "mass", "65,75,85", "--format", "json", "--step", "0.005",
    ]);
}

#[test]
fn zeroed_seat_link_is_an_error() {
    has(
        &fails(&["response", "--set", "k4=0", "--set", "c4=0"]),
        &["seat"],
    );
    has(
        &fails(&["response", "--set", "k2=0", "--set", "c2=0"]),
        &["seat"],
    );
}

#[test]
fn huge_stiffness_is_refused_or_right() {
    let rigid = values(&parse_csv(&ok(&[
        "response", "--format", "csv", "--to", "0.6", "--set", "k1=1e10",
    ])));
    for k in ["k1=1e50", "k1=1e155"] {
        let (code, out, err) = run(&["response", "--format", "csv", "--to", "0.6", "--set", k]);
        if code == Some(0) {
            let got = values(&parse_csv(&out));
            assert!(
                close(got[0][1], rigid[0][1], 1e-3),
                "{k}: |STHT| {} vs {}",
                got[0][1],
                rigid[0][1]
            );
        } else {
            assert!(out.is_empty() && err.contains("error:"), "{k}: {err}");
        }
    }
}

#[test]
fn dpmi_is_j_omega_times_apms_in_the_output() {
    let rows = values(&parse_csv(&ok(&["response", "--format", "csv"])));
    for r in &rows {
        let w = 2.0 * std::f64::consts::PI * r[0];
        assert!(
            close(r[3], w * r[5], 1e-12),
            "f = {}: {} vs {}",
            r[0],
            r[3],
            w * r[5]
        );
        let d = (r[4] - r[6] - 90.0).rem_euclid(360.0);
        assert!(
            !(1e-9..=360.0 - 1e-9).contains(&d),
            "f = {}: phases {} {}",
            r[0],
            r[4],
            r[6]
        );
    }
}

#[test]
fn preset_show_of_a_builtin_prints_the_shipped_file() {
    for name in [
        "paper-75kg",
        "paper-65kg",
        "paper-85kg",
        "boileau-rakheja-1998",
    ] {
        let file = std::fs::read_to_string(root().join(format!("presets/{name}.toml"))).unwrap();
        assert_eq!(ok(&["preset", "show", name]), file, "{name}");
    }
    assert_eq!(
        ok(&["preset", "show"]),
        ok(&["preset", "show", "paper-75kg"])
    );
}

#[test]
fn plot_options_keep_the_size() {
    for extra in [
        &["--phase"][..],
        &["--log-x", "--log-y"],
        &["--study", "k4=-40%,0%,+40%", "--ascii"],
        &["--from", "4", "--to", "5", "--step", "0.5"],
    ] {
        let mut a = vec!["plot", "dpmi", "--width", "60", "--height", "20"];
        a.extend(extra);
        let out = ok(&a);
        assert_eq!(out.lines().count(), 20, "{extra:?}\n{out}");
        assert!(
            out.lines().all(|l| l.chars().count() <= 60),
            "{extra:?}\n{out}"
        );
    }
}

#[test]
fn plot_phase_on_a_short_chart_does_not_panic() {
    for h in ["8", "10", "12"] {
        let (code, out, err) = run(&["plot", "stht", "--phase", "--width", "80", "--height", h]);
        assert!(!err.contains("panicked"), "height {h}: {err}");
        assert_eq!(code, Some(0), "height {h}: {err}");
        assert_eq!(out.lines().count(), h.parse::<usize>().unwrap());
        assert!(!out.contains("inf") && !out.contains("NaN"), "{out}");
    }
}

/// A preset text: segments (name, kg) and links (upper, lower, k, c).
fn preset_text(segments: &[(String, f64)], links: &[(String, String, f64, f64)]) -> String {
    let mut s = String::from("schema = 1\n");
    for (name, m) in segments {
        s += &format!("\n[[segment]]\nname = \"{name}\"\nmass_kg = {m:?}\n");
    }
    for (u, l, k, c) in links {
        s += &format!(
            "\n[[link]]\nupper = \"{u}\"\nlower = \"{l}\"\nk_n_per_m = {k:?}\nc_ns_per_m = {c:?}\n"
        );
    }
    s
}

/// Low-frequency limits and the eigenvalue count hold for a model file.
fn check_model_file(path: &str, seated: f64, n: usize) {
    let rows = values(&parse_csv(&ok(&[
        "response", "--format", "csv", "--preset", path, "--from", "0.01", "--to", "0.02",
        "--step", "0.01",
    ])));
    let r = &rows[0];
    assert!((r[1] - 1.0).abs() < 1e-3, "{path}: STHT {r:?}");
    assert!((r[5] - seated).abs() < 1e-3 * seated, "{path}: APMS {r:?}");
    assert!((r[4] - 90.0).abs() < 0.1, "{path}: DPMI phase {r:?}");
    let json: serde_json::Value =
        serde_json::from_str(&ok(&["modes", "--preset", path, "--format", "json"])).unwrap();
    let damped = json["damped"].as_array().unwrap();
    let osc = damped.iter().filter(|m| m["kind"] == "oscillatory").count();
    let over = damped.iter().filter(|m| m["kind"] == "overdamped").count();
    assert_eq!(
        2 * osc + over,
        2 * n,
        "{path}: {osc} pairs + {over} real roots"
    );
    assert_eq!(json["undamped"].as_array().unwrap().len(), n);
    // A coarse band keeps the debug build fast on the general solve.
    ok(&["peaks", "--preset", path, "--step", "0.5"]);
    ok(&[
        "study",
        "k1",
        "-10%,0%,+10%",
        "--preset",
        path,
        "--step",
        "0.5",
    ]);
}

#[test]
fn long_chain_and_branched_models_run_through_every_command() {
    let dir = tempdir();
    // 20 segments: beyond the stack-allocated tridiagonal path.
    let segs: Vec<(String, f64)> = (1..=20).map(|i| (format!("s{i}"), 2.0)).collect();
    let mut links: Vec<(String, String, f64, f64)> = (1..20)
        .map(|i| (format!("s{i}"), format!("s{}", i + 1), 1e5, 500.0))
        .collect();
    links.push(("s20".into(), "seat".into(), 1e5, 500.0));
    let chain = temp_file(dir.path(), "chain20.toml", preset_text(&segs, &links));
    check_model_file(&chain, 40.0, 20);

    // Branched: viscera hang off the torso, and the torso has its own seat link.
    let segs = vec![
        ("head".to_string(), 5.0),
        ("torso".to_string(), 30.0),
        ("viscera".to_string(), 6.0),
        ("pelvis".to_string(), 13.0),
    ];
    let links = vec![
        ("head".to_string(), "torso".to_string(), 3.1e5, 400.0),
        ("viscera".to_string(), "torso".to_string(), 5e4, 900.0),
        ("torso".to_string(), "pelvis".to_string(), 1.6e5, 4500.0),
        ("pelvis".to_string(), "seat".to_string(), 9e4, 2064.0),
        ("torso".to_string(), "seat".to_string(), 2e4, 300.0),
    ];
    let branched = temp_file(dir.path(), "branched.toml", preset_text(&segs, &links));
    check_model_file(&branched, 54.0, 4);
    // A branched model saved and reloaded gives the same response.
    let copy = dir.path().join("copy.toml");
    let (code, _, err) = run(&[
        "preset",
        "save",
        copy.to_str().unwrap(),
        "--preset",
        &branched,
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(
        ok(&[
            "response",
            "--format",
            "csv",
            "--preset",
            copy.to_str().unwrap()
        ]),
        ok(&["response", "--format", "csv", "--preset", &branched])
    );
}

fn help_has_example(cmd: &[&str]) {
    let mut a = cmd.to_vec();
    a.push("--help");
    let out = ok(&a);
    assert!(
        out.contains("Example"),
        "{cmd:?} --help has no example:\n{out}"
    );
    assert!(out.contains("biodyn "), "{cmd:?}: {out}");
}

#[test]
fn every_command_help_has_an_example() {
    for cmd in [
        &[][..],
        &["response"],
        &["modes"],
        &["peaks"],
        &["study"],
        &["plot"],
        &["tui"],
        &["preset", "show"],
        &["preset", "check"],
        &["preset", "save"],
    ] {
        help_has_example(cmd);
    }
    assert!(ok(&["--version"]).starts_with("biodyn "));
}

#[test]
fn preset_and_preset_list_help_have_an_example() {
    help_has_example(&["preset"]);
    help_has_example(&["preset", "list"]);
}

#[test]
fn grid_never_ends_past_to() {
    let rows = parse_csv(&ok(&[
        "response",
        "--format",
        "csv",
        "--from",
        "1",
        "--to",
        "1.2999999999",
        "--step",
        "0.1",
    ]));
    let last = rows.last().unwrap()[0].1;
    assert!(last <= 1.2999999999, "last f = {last}");
}

#[test]
fn grid_ends_on_to_when_it_is_on_the_grid() {
    for (from, to, step, n) in [
        ("0.5", "20", "0.1", 196),
        ("0.5", "20", "0.3", 66),
        ("1", "1.3", "0.1", 4),
        ("0.1", "0.7", "0.2", 4),
        ("2", "3", "0.001", 1001),
    ] {
        let rows = parse_csv(&ok(&[
            "response", "--format", "csv", "--from", from, "--to", to, "--step", step,
        ]));
        assert_eq!(rows.len(), n, "{from}..{to} step {step}");
        assert_eq!(rows[0][0].0, from);
        assert_eq!(rows.last().unwrap()[0].0, to, "{from}..{to} step {step}");
    }
}

#[test]
fn study_with_one_value_or_duplicates_says_nothing_to_compare() {
    for (values, why) in [
        ("5%", "one value: nothing to compare"),
        ("75", "one value: nothing to compare"),
        ("75,75", "the values are all the same: nothing to compare"),
        (
            "0%,0%,0%",
            "the values are all the same: nothing to compare",
        ),
    ] {
        let table = ok(&["study", "mass", values]);
        has(&table, &[why, "two or more different values"]);
        for trend in [
            "stays put",
            "rises over",
            "falls over",
            "As body mass rises",
        ] {
            assert!(!table.contains(trend), "{values}: {trend} in\n{table}");
        }
        // The peaks are still listed, one row per value.
        let rows = table
            .lines()
            .filter(|l| l.starts_with("body mass "))
            .count();
        assert_eq!(rows, values.split(',').count(), "{values}:\n{table}");
    }
    // Two different values: the trends, as before.
    has(&ok(&["study", "mass", "75,85"]), &["As body mass rises"]);
}

/// Issue 19 item 9: a band has physical limits, 0.001 Hz to 100 kHz, said
/// in the error (no NaN rows at 1e100 Hz, no `0.000` rows below 1e-12 Hz,
/// no trend sentences about NaN peaks); a fine step prints its
/// frequencies exactly in the table.
#[test]
fn bands_have_physical_limits_and_print_their_frequencies_exactly() {
    for args in [
        &[
            "response", "--from", "1e100", "--to", "1e101", "--step", "1e100",
        ][..],
        &[
            "response", "--from", "1e-13", "--to", "2e-13", "--step", "1e-13",
        ],
        &["response", "--to", "1e6"],
        &[
            "study", "k4", "-40%,0%", "--from", "1e100", "--to", "1e101", "--step", "1e100",
        ],
        &["plot", "stht", "--from", "0.0001", "--to", "1"],
    ] {
        let e = fails(args);
        assert!(
            e.contains("outside the band a model is computed over, 0.001 Hz to 100 kHz"),
            "{args:?}: {e}"
        );
        assert!(!e.contains("NaN"), "{e}");
    }
    let t = ok(&[
        "response", "--from", "0.001", "--to", "0.0016", "--step", "0.0001",
    ]);
    let f: Vec<&str> = t
        .lines()
        .skip(2)
        .filter_map(|l| l.split_whitespace().next())
        .collect();
    assert_eq!(
        f,
        [
            "0.0010", "0.0011", "0.0012", "0.0013", "0.0014", "0.0015", "0.0016"
        ],
        "{t}"
    );
    let edge = ok(&[
        "response", "--from", "99999", "--to", "100000", "--step", "1", "--format", "csv",
    ]);
    assert!(!edge.contains("NaN") && edge.lines().count() == 3, "{edge}");
    // The default band still prints three decimals.
    assert!(
        ok(&["response"])
            .lines()
            .nth(2)
            .is_some_and(|l| l.starts_with("0.500 "))
    );
}
