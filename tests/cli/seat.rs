//! `biodyn seat` and a seat model through `response` and `plot`, as real
//! processes: the figures against independent checks (a rigid seat, a PSD
//! file tabulating a class, a fine grid computed here through the library,
//! the library's Solver), and every bad input as one line and a hint.

use crate::common::{fails, ok, run};
use biodyn::seat::{FloorPsd, SeatGrid};
use biodyn::time::{CLASSES, InputClass};
use biodyn::{Function, Preset, Solver};
use serde_json::Value;

const SUSPENSION: &str = "paper-75kg-suspension-seat";
const RIGID: &str = "paper-75kg-rigid-seat";

fn json(args: &[&str]) -> Value {
    let mut a = args.to_vec();
    a.extend(["--format", "json"]);
    serde_json::from_str(&ok(&a)).expect("JSON")
}

fn num(v: &Value, key: &str) -> f64 {
    v[key]
        .as_f64()
        .unwrap_or_else(|| panic!("{key} missing in {v}"))
}

fn has(haystack: &str, needles: &[&str]) {
    for n in needles {
        assert!(haystack.contains(n), "'{n}' missing from:\n{haystack}");
    }
}

fn body(name: &str) -> biodyn::Body {
    Preset::open(name).expect("a shipped preset").body
}

// ---- the figures -------------------------------------------------------------

/// A rigid seat passes the floor to the pan: SEAT 100 % and no travel, under
/// every class (the CSV of the all-classes view).
#[test]
fn a_rigid_seat_gives_seat_100_and_no_stroke_under_every_class() {
    let text = ok(&["seat", "--preset", RIGID, "--format", "csv"]);
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some("class,standard,seat_pct,pan_aw_m_s2,floor_aw_m_s2,stroke_rms_m,stroke_available_m")
    );
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), CLASSES.len());
    for (r, c) in rows.iter().zip(&CLASSES) {
        assert_eq!(r[0], c.name);
        let seat: f64 = r[2].parse().unwrap();
        let stroke: f64 = r[5].parse().unwrap();
        assert!((seat - 100.0).abs() < 0.1, "{}: SEAT {seat} %", c.name);
        assert!(stroke < 1e-5, "{}: stroke {stroke} m", c.name);
    }
    let em6 = json(&["seat", "--preset", RIGID, "--class", "em6"]);
    assert_eq!(em6["input"], "EM6");
    assert_eq!(em6["model"], RIGID);
    assert!((num(&em6, "seat_pct") - 100.0).abs() < 0.1, "{em6}");
    assert!(num(&em6, "stroke_rms_m") < 1e-5, "{em6}");
    assert_eq!(num(&em6, "stroke_available_m"), 0.10);
    // SEAT is the ratio of the two a_w.
    let ratio = 100.0 * num(&em6, "pan_aw_m_s2") / num(&em6, "floor_aw_m_s2");
    assert!((ratio - num(&em6, "seat_pct")).abs() < 1e-9);
}

/// The class's formula tabulated every 0.05 Hz in a PSD file gives the
/// class's SEAT within 0.5 %, and the table names its inputs.
#[test]
fn a_psd_file_tabulating_em6_gives_the_class_figures() {
    let d = tempfile::tempdir().unwrap();
    let path = d.path().join("em6.csv");
    let em6 = InputClass::parse("EM6").unwrap();
    let mut text = String::from("# EM6 every 0.05 Hz\nf_hz,psd_m2_s4_hz\n");
    for i in 2..=2000 {
        let f = 0.05 * f64::from(i);
        text += &format!("{f},{}\n", em6.psd(f));
    }
    std::fs::write(&path, text).unwrap();
    let p = path.to_str().unwrap();
    let file = json(&["seat", "--preset", SUSPENSION, "--psd", p]);
    let class = json(&["seat", "--preset", SUSPENSION, "--class", "EM6"]);
    assert_eq!(file["input"], p);
    for key in ["seat_pct", "pan_aw_m_s2", "floor_aw_m_s2", "stroke_rms_m"] {
        let (a, b) = (num(&file, key), num(&class, key));
        assert!((a / b - 1.0).abs() < 0.005, "{key}: file {a}, class {b}");
    }
    // A suspension seat isolates EM6's 6.5–9 Hz: well under 100 %.
    assert!(num(&class, "seat_pct") < 50.0, "{class}");
    let table = ok(&["seat", "--preset", SUSPENSION, "--psd", p]);
    has(&table, &[SUSPENSION, "em6.csv", "1999 rows", "SEAT %"]);
    let csv = ok(&[
        "seat", "--preset", SUSPENSION, "--class", "EM6", "--format", "csv",
    ]);
    assert!(csv.starts_with(
        "model,input,seat_pct,pan_aw_m_s2,floor_aw_m_s2,stroke_rms_m,stroke_available_m\n"
    ));
}

/// The all-classes table's rows equal the library's figures for each class.
#[test]
fn the_class_table_is_the_librarys_figures_per_class() {
    let v = json(&["seat", "--preset", SUSPENSION]);
    let b = body(SUSPENSION);
    let classes = v["classes"].as_array().unwrap();
    assert_eq!(classes.len(), CLASSES.len());
    for (row, c) in classes.iter().zip(&CLASSES) {
        let f = SeatGrid::new(&FloorPsd::Class(c))
            .unwrap()
            .figures(&b)
            .unwrap();
        assert_eq!(row["class"], c.name);
        assert_eq!(row["standard"], c.standard);
        assert_eq!(num(row, "seat_pct"), f.seat_pct);
        assert_eq!(num(row, "stroke_rms_m"), f.stroke_rms_m);
    }
    let table = ok(&["seat", "--preset", SUSPENSION]);
    has(
        &table,
        &[
            "SEAT % per input class",
            "EM6",
            "ISO 7096:2000",
            "AG3",
            "IT4",
        ],
    );
}

// ---- the design search -------------------------------------------------------

/// The lowest feasible SEAT on a fine grid of `n` points per axis (log-even,
/// as the box is searched), through the library.
fn fine_grid_best(class: &str, vary: &[(&str, f64, f64)], n: usize, limit: f64) -> f64 {
    let b = body(SUSPENSION);
    let grid = SeatGrid::new(&FloorPsd::Class(InputClass::parse(class).unwrap())).unwrap();
    let at =
        |(_, lo, hi): (&str, f64, f64), i: usize| lo * (hi / lo).powf(i as f64 / (n - 1) as f64);
    let mut best = f64::INFINITY;
    let cols = if vary.len() == 2 { n } else { 1 };
    for i in 0..n {
        for j in 0..cols {
            let mut m = b.clone();
            m.set(m.param(vary[0].0).unwrap(), at(vary[0], i)).unwrap();
            if vary.len() == 2 {
                m.set(m.param(vary[1].0).unwrap(), at(vary[1], j)).unwrap();
            }
            let f = grid.figures(&m).unwrap();
            if f.stroke_rms_m <= limit {
                best = best.min(f.seat_pct);
            }
        }
    }
    best
}

/// The best point's own figures, recomputed here from its parameters.
fn recompute(class: &str, params: &Value) -> biodyn::seat::SeatFigures {
    let mut b = body(SUSPENSION);
    for (name, v) in params.as_object().unwrap() {
        let p = b.param(name).unwrap();
        b.set(p, v.as_f64().unwrap()).unwrap();
    }
    let grid = SeatGrid::new(&FloorPsd::Class(InputClass::parse(class).unwrap())).unwrap();
    grid.figures(&b).unwrap()
}

#[test]
fn two_parameter_search_beats_a_fine_grid_and_keeps_the_limit() {
    // EM2 excites the suspension's resonance: the limit binds.
    let limit = 0.012;
    let v = json(&[
        "seat",
        "--preset",
        SUSPENSION,
        "--class",
        "EM2",
        "--vary",
        "suspension.k=4000..20000",
        "--vary",
        "suspension.c=200..4000",
        "--stroke-rms-max",
        "0.012",
    ]);
    let best = &v["best"];
    let seat = num(best, "seat_pct");
    let stroke = num(best, "stroke_rms_m");
    assert!(stroke <= limit, "{best}");
    let fine = fine_grid_best(
        "EM2",
        &[
            ("suspension.k", 4000.0, 20000.0),
            ("suspension.c", 200.0, 4000.0),
        ],
        81,
        limit,
    );
    assert!(seat <= fine + 1e-9, "search {seat} %, fine grid {fine} %");
    // The reported point is what its parameters give.
    let f = recompute("EM2", &best["params"]);
    assert!((f.seat_pct - seat).abs() < 1e-9 && (f.stroke_rms_m - stroke).abs() < 1e-12);
    assert_eq!(num(best, "pan_aw_m_s2"), f.pan_aw_m_s2);
    // The map: 21 × 21, rows the first parameter.
    let map = &v["map"];
    assert_eq!(
        map["params"],
        serde_json::json!(["suspension.k", "suspension.c"])
    );
    assert_eq!(map["axes"]["suspension.k"].as_array().unwrap().len(), 21);
    let rows = map["seat_pct"].as_array().unwrap();
    assert_eq!(rows.len(), 21);
    assert_eq!(rows[0].as_array().unwrap().len(), 21);
    assert_eq!(map["stroke_rms_m"].as_array().unwrap().len(), 21);
    assert!(v["evaluations"].as_u64().unwrap() >= 441);
    assert_eq!(num(&v, "stroke_rms_max_m"), limit);
    // The limit binds here: the free optimum travels more.
    let free = fine_grid_best(
        "EM2",
        &[
            ("suspension.k", 4000.0, 20000.0),
            ("suspension.c", 200.0, 4000.0),
        ],
        21,
        f64::INFINITY,
    );
    assert!(free < seat, "the limit does not bind: {free} vs {seat}");
}

#[test]
fn one_parameter_search_beats_a_fine_line_and_prints_its_map() {
    let args = [
        "seat",
        "--preset",
        SUSPENSION,
        "--class",
        "EM2",
        "--vary",
        "suspension.c=200..4000",
        "--stroke-rms-max",
        "0.015",
    ];
    let v = json(&args);
    let seat = num(&v["best"], "seat_pct");
    assert!(num(&v["best"], "stroke_rms_m") <= 0.015);
    let fine = fine_grid_best("EM2", &[("suspension.c", 200.0, 4000.0)], 2001, 0.015);
    assert!(seat <= fine + 1e-9, "search {seat} %, fine line {fine} %");
    assert_eq!(v["map"]["seat_pct"].as_array().unwrap().len(), 41);
    let table = ok(&args);
    has(
        &table,
        &[
            "best: suspension.c = ",
            "SEAT ",
            "keeps the limit",
            "figures computed",
        ],
    );
    let csv = ok(&[&args[..], &["--format", "csv"]].concat());
    let mut lines = csv.lines();
    assert_eq!(
        lines.next(),
        Some("suspension.c,seat_pct,stroke_rms_m,feasible")
    );
    assert_eq!(lines.count(), 41);
}

#[test]
fn the_two_parameter_table_marks_infeasible_cells() {
    let table = ok(&[
        "seat",
        "--preset",
        SUSPENSION,
        "--class",
        "EM2",
        "--vary",
        "suspension.k=4000..20000",
        "--vary",
        "suspension.c=200..4000",
        "--stroke-rms-max",
        "0.012",
    ]);
    has(
        &table,
        &["suspension.k \\ suspension.c", "rows suspension.k N/m"],
    );
    // Lightly damped cells travel past 12 mm, well-damped ones do not:
    // both kinds are in the grid, an infeasible cell ends in x.
    let body = table.split("-----\n").last().unwrap();
    let cells: Vec<&str> = body
        .lines()
        .flat_map(|l| l.split_whitespace().skip(1))
        .collect();
    assert_eq!(cells.len(), 11 * 11, "{table}");
    let over = cells.iter().filter(|c| c.ends_with('x')).count();
    assert!(
        over > 0 && over < cells.len(),
        "{over} of {}:\n{table}",
        cells.len()
    );
    // The infeasible cells are the map's: stroke over the limit.
    let v = json(&[
        "seat",
        "--preset",
        SUSPENSION,
        "--class",
        "EM2",
        "--vary",
        "suspension.k=4000..20000",
        "--vary",
        "suspension.c=200..4000",
        "--stroke-rms-max",
        "0.012",
    ]);
    let strokes = v["map"]["stroke_rms_m"].as_array().unwrap();
    let want = (0..21)
        .step_by(2)
        .flat_map(|i| (0..21).step_by(2).map(move |j| (i, j)))
        .filter(|&(i, j)| strokes[i][j].as_f64().unwrap() > 0.012)
        .count();
    assert_eq!(over, want);
}

// ---- response and plot with a seat -----------------------------------------

#[test]
fn response_prints_the_seats_columns_as_the_library_computes_them() {
    let csv = ok(&[
        "response", "--preset", SUSPENSION, "--at", "1,4.5,12", "--format", "csv",
    ]);
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let mut want = vec!["f_hz"];
    for f in Function::EVERY {
        want.extend([f.mag_column(), f.phase_column()]);
    }
    assert_eq!(header, want);
    assert_eq!(
        &header[7..],
        [
            "seat_tr_mag",
            "seat_tr_phase_deg",
            "floor_head_mag",
            "floor_head_phase_deg"
        ]
    );
    let solver = Solver::new(&body(SUSPENSION));
    for line in lines {
        let cells: Vec<f64> = line.split(',').map(|c| c.parse().unwrap()).collect();
        let r = solver.at(cells[0]);
        for (i, f) in Function::EVERY.into_iter().enumerate() {
            assert_eq!(cells[1 + 2 * i], r.mag(f), "{} at {} Hz", f.key(), cells[0]);
            assert_eq!(
                cells[2 + 2 * i],
                r.phase_deg(f),
                "{} at {} Hz",
                f.key(),
                cells[0]
            );
        }
    }
    let v = json(&["response", "--preset", SUSPENSION, "--at", "4.5"]);
    let r = solver.at(4.5);
    assert_eq!(num(&v[0], "seat_tr_mag"), r.mag(Function::SeatTr));
    assert_eq!(
        num(&v[0], "floor_head_phase_deg"),
        r.phase_deg(Function::FloorHead)
    );
    let table = ok(&["response", "--preset", SUSPENSION, "--at", "4.5"]);
    has(&table, &["|SEAT T|", "SEAT T deg", "|floor-head|"]);
    // Without a seat: the body's three only.
    let plain = ok(&["response", "--at", "4.5", "--format", "csv"]);
    assert!(!plain.contains("seat_tr"), "{plain}");
    assert!(!ok(&["response", "--at", "4.5", "--format", "json"]).contains("seat_tr"));
    assert!(!ok(&["response", "--at", "4.5"]).contains("SEAT T"));
}

#[test]
fn plot_draws_a_seats_functions_on_a_seat_model_only() {
    for f in ["seat_tr", "floor_head"] {
        let chart = ok(&[
            "plot", f, "--preset", SUSPENSION, "--width", "60", "--height", "12",
        ]);
        let title = Function::parse(f).unwrap().name();
        assert!(chart.contains(title), "{chart}");
        let err = fails(&["plot", f]);
        has(
            &err,
            &[f, "has no seat", "--preset paper-75kg-suspension-seat"],
        );
    }
    let help = ok(&["plot", "--help"]);
    has(&help, &["seat_tr", "floor_head"]);
}

// ---- bad input -----------------------------------------------------------------

fn seat_fails(extra: &[&str]) -> String {
    fails(&[&["seat", "--preset", SUSPENSION][..], extra].concat())
}

const BOX: [&str; 4] = ["--class", "EM6", "--vary", "suspension.k=4000..20000"];

#[test]
fn a_model_without_a_seat_or_with_no_stroke_is_refused() {
    let err = fails(&["seat"]);
    has(
        &err,
        &[
            "has no seat",
            "hint: `biodyn seat --preset paper-75kg-suspension-seat`",
        ],
    );
    let d = tempfile::tempdir().unwrap();
    let text = ok(&["preset", "show", SUSPENSION]).replace("stroke_m = 0.10", "stroke_m = 0");
    assert!(text.contains("stroke_m = 0\n"));
    let p = d.path().join("s0.toml");
    std::fs::write(&p, text).unwrap();
    let err = fails(&["seat", "--preset", p.to_str().unwrap(), "--class", "EM6"]);
    has(
        &err,
        &[
            "[seat] stroke_m = 0",
            "must be > 0",
            "hint: `biodyn preset show paper-75kg-suspension-seat`",
        ],
    );
}

#[test]
fn bad_psd_files_are_refused_naming_the_line() {
    let d = tempfile::tempdir().unwrap();
    let write = |name: &str, text: &str| {
        let p = d.path().join(name);
        std::fs::write(&p, text).unwrap();
        p.to_str().unwrap().to_string()
    };
    let cases = [
        (
            write("neg.csv", "f_hz,psd_m2_s4_hz\n1,1\n2,-1\n"),
            "line 3: psd_m2_s4_hz = '-1'",
        ),
        (
            write("uns.csv", "f_hz,psd_m2_s4_hz\n2,1\n1,1\n"),
            "line 3: f_hz = 1 is not above",
        ),
        (
            write("head.csv", "1,1\n2,1\n"),
            "line 1: the header is '1,1'",
        ),
    ];
    for (p, want) in &cases {
        let err = seat_fails(&["--psd", p]);
        has(
            &err,
            &[
                want,
                "hint: a PSD file is a regular CSV file: the header f_hz,psd_m2_s4_hz",
            ],
        );
    }
    let dir = d.path().join("dir");
    std::fs::create_dir(&dir).unwrap();
    let err = seat_fails(&["--psd", dir.to_str().unwrap()]);
    has(&err, &["--psd ", "is a directory", "hint: a PSD file"]);
    let fifo = d.path().join("fifo");
    match std::process::Command::new("mkfifo").arg(&fifo).status() {
        Ok(s) if s.success() => {
            let err = seat_fails(&["--psd", fifo.to_str().unwrap()]);
            has(&err, &["--psd ", "FIFO", "hint: a PSD file"]);
        }
        _ => crate::common::skip("mkfifo"),
    }
}

#[test]
fn bad_vary_and_limits_are_refused_with_the_flag() {
    let cases: [(&[&str], &[&str]); 13] = [
        (
            &[
                "--class",
                "EM6",
                "--vary",
                "nope.k=1..2",
                "--stroke-rms-max",
                "0.01",
            ],
            &[
                "--vary nope.k=1..2",
                "unknown parameter",
                "hint: vary a seat link's k or c",
            ],
        ),
        (
            &[
                "--class",
                "EM6",
                "--vary",
                "suspension.k=5..2",
                "--stroke-rms-max",
                "0.01",
            ],
            &["from 5 to 2", "0 < LO < HI", "hint: write NAME=LO..HI"],
        ),
        (
            &[
                "--class",
                "EM6",
                "--vary",
                "suspension.k=5..5",
                "--stroke-rms-max",
                "0.01",
            ],
            &["from 5 to 5", "hint: write NAME=LO..HI"],
        ),
        (
            &[
                "--class",
                "EM6",
                "--vary",
                "k=5",
                "--stroke-rms-max",
                "0.01",
            ],
            &[
                "--vary k=5: the range '5' is not LO..HI",
                "hint: write NAME=LO..HI",
            ],
        ),
        (
            &[
                "--class",
                "EM6",
                "--vary",
                "k=a..b",
                "--stroke-rms-max",
                "0.01",
            ],
            &["--vary k=a..b: 'a' is not a finite number"],
        ),
        (
            &[
                "--class",
                "EM6",
                "--vary",
                "suspension.k",
                "--stroke-rms-max",
                "0.01",
            ],
            &["expected NAME=LO..HI"],
        ),
        (
            &[
                "--class",
                "EM6",
                "--vary",
                "suspension.k=1e3..2e3",
                "--vary",
                "suspension.c=100..200",
                "--vary",
                "cushion.k=1e3..5e4",
                "--stroke-rms-max",
                "0.01",
            ],
            &[
                "--vary is given 3 times",
                "one or two",
                "hint: give --vary once or twice",
            ],
        ),
        (
            &[
                "--class",
                "EM6",
                "--vary",
                "suspension.k=1e3..2e3",
                "--vary",
                "suspension.k=3e3..4e3",
                "--stroke-rms-max",
                "0.01",
            ],
            &["varied twice"],
        ),
        (
            &[&BOX[..], &["--stroke-rms-max", "0"]].concat(),
            &[
                "--stroke-rms-max 0: ",
                "finite and > 0",
                "hint: e.g. --stroke-rms-max 0.015",
            ],
        ),
        (
            &[&BOX[..], &["--stroke-rms-max", "-0.01"]].concat(),
            &["--stroke-rms-max -0.01: "],
        ),
        (
            &[&BOX[..], &["--stroke-rms-max", "NaN"]].concat(),
            &["--stroke-rms-max NaN: "],
        ),
        (
            &[
                "--class",
                "EM1",
                "--vary",
                "suspension.k=1000..2000",
                "--stroke-rms-max",
                "0.001",
            ],
            &[
                "no point of the --vary box keeps the r.m.s. stroke within 1e-3 m",
                "raise --stroke-rms-max",
                "hint: a stiffer or more damped",
            ],
        ),
        (
            &[
                "--class",
                "EM6",
                "--vary",
                "body_mass=50..90",
                "--stroke-rms-max",
                "0.01",
            ],
            &["the person is not the seat's to choose"],
        ),
    ];
    for (args, want) in cases {
        has(&seat_fails(args), want);
    }
}

#[test]
fn a_limit_without_a_box_a_box_without_a_limit_or_a_floor_and_an_unknown_class_are_refused() {
    has(
        &seat_fails(&BOX),
        &[
            "--vary: the search needs a limit",
            "--stroke-rms-max M",
            "hint: e.g. --vary",
        ],
    );
    has(
        &seat_fails(&["--class", "EM6", "--stroke-rms-max", "0.01"]),
        &[
            "--stroke-rms-max 0.01: the limit is the design search's, and nothing is varied",
            "hint: search a box with it",
        ],
    );
    has(
        &seat_fails(&[
            "--vary",
            "suspension.k=4000..20000",
            "--stroke-rms-max",
            "0.01",
        ]),
        &["give --class NAME or --psd FILE"],
    );
    let err = seat_fails(&["--class", "EM10"]);
    has(
        &err,
        &[
            "--class EM10: not an input spectral class",
            "EM1, EM2",
            "AG3",
            "hint: e.g. --class EM6",
        ],
    );
    // --psd and --class together: clap's usage error.
    let (code, _, err) = run(&[
        "seat", "--preset", SUSPENSION, "--class", "EM6", "--psd", "x.csv",
    ]);
    assert_eq!(code, Some(2), "{err}");
}

/// A class signal below its sampling-rate floor, or an unknown class, in
/// the time domain: the flag and a class example.
#[test]
fn a_class_signal_names_fs_and_the_classes() {
    let err = fails(&[
        "assess",
        "--preset",
        SUSPENSION,
        "--signal",
        "class:EM6,seed=1",
        "--fs",
        "50",
        "--duration",
        "10",
    ]);
    has(
        &err,
        &[
            "at least 100 Hz (now 50): raise --fs, e.g. --fs 200",
            "hint: e.g. --signal class:EM6,seed=1 --fs 200",
        ],
    );
    let err = fails(&[
        "simulate",
        "--preset",
        SUSPENSION,
        "--signal",
        "class:EM16,seed=1",
    ]);
    has(
        &err,
        &[
            "EM16 is not an input spectral class",
            "AG3",
            "hint: e.g. --signal class:EM6,seed=1",
        ],
    );
}
