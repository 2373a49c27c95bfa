//! A report to hand over, as real processes: `--meta FILE.toml` and a day
//! file's `[report]` (the table's first lines, the JSON's `meta`, the
//! page's first section), `--no-model`, `--exposure` as people write
//! hours, and the day's hours, caps and `fs` key.

use crate::common::{fails, ok, root, run};
use serde_json::Value;
use std::path::Path;

const SIG: [&str; 3] = ["assess", "--signal", "sine:freq=5,amp=1"];

fn s(p: &Path) -> String {
    p.display().to_string()
}

fn json(args: &[&str]) -> Value {
    let mut a = args.to_vec();
    a.extend(["--format", "json"]);
    serde_json::from_str(&ok(&a)).unwrap()
}

const META: &str = "site = \"North <quarry> & 'pit'\"\nworker = \"J. Smith\"\ndate = 2026-12-05\ninstrument = \"SV 106\"\ncalibrated = \"2026-06-01\"\nnotes = \"wet\\nwindy\"\n";

#[test]
fn exposure_takes_hours_as_people_write_them() {
    let decimal = json(&[&SIG[..], &["--exposure", "6.5"]].concat());
    for form in ["6:30", "6h30", "6h30min", "390min"] {
        let v = json(&[&SIG[..], &["--exposure", form]].concat());
        assert_eq!(v, decimal, "--exposure {form}");
    }
    assert_eq!(
        json(&[&SIG[..], &["--exposure", "45min"]].concat())["exposure_h"],
        0.75
    );
    // A bad value: biodyn's own words with the forms, one line, status 2.
    for (bad, words) in [
        (
            "abc",
            "not hours; write 6.5, 6:30, 6h30, 6h or 45min, e.g. --exposure 6:30",
        ),
        (
            "6:75",
            "minutes past the hour are 0 to 59; write e.g. --exposure 7:15",
        ),
        (
            "25h",
            "25 h: the exposure must be over 0 and at most 24 h a day",
        ),
        ("-1", "not hours"),
    ] {
        let (code, out, err) = run(&[&SIG[..], &["--exposure", bad]].concat());
        assert_eq!(code, Some(2), "{bad}: {err}");
        assert!(out.is_empty());
        let first = err.lines().next().unwrap();
        assert!(
            first.contains(&format!("'{bad}' for '--exposure <HOURS>': {words}")),
            "{bad}: {err}"
        );
        assert!(!err.contains("invalid float literal"), "{err}");
    }
}

#[test]
fn meta_is_on_top_of_the_table_in_the_json_and_on_the_page() {
    let dir = tempfile::tempdir().unwrap();
    let meta = dir.path().join("meta.toml");
    std::fs::write(&meta, META).unwrap();
    let page = dir.path().join("r.html");
    let meta_s = s(&meta);
    let args = [&SIG[..], &["--meta", &meta_s]].concat();
    let table = ok(&args);
    assert!(
        table.starts_with(
            "site: North <quarry> & 'pit'; worker: J. Smith; date: 2026-12-05\ninstrument: SV 106 (calibrated 2026-06-01)\nnotes: wet\n       windy\n\n"
        ),
        "{table}"
    );
    // The rest is the table without --meta.
    assert!(table.ends_with(&ok(&SIG)));
    let v = json(&args);
    let m = v["meta"].as_object().unwrap();
    assert_eq!(
        m.keys().collect::<Vec<_>>(),
        [
            "calibrated",
            "date",
            "instrument",
            "notes",
            "site",
            "worker"
        ],
        "only the keys given"
    );
    assert_eq!(m["date"], "2026-12-05");
    assert!(json(&SIG).get("meta").is_none());
    let (code, _, err) = run(&[&args[..], &["--report", &s(&page)]].concat());
    assert_eq!(code, Some(0), "{err}");
    let html = std::fs::read_to_string(&page).unwrap();
    let first = html.find("<section").unwrap();
    assert!(
        html[first..].starts_with("<section id=\"meta\">"),
        "the details come first"
    );
    assert!(
        html.contains("<td data-key=\"/meta/site\">North &lt;quarry&gt; &amp; &#39;pit&#39;</td>")
    );
    assert!(html.contains("<td data-key=\"/meta/notes\">wet<br>windy</td>"));
    assert!(!html.contains("<quarry>"));
}

#[test]
fn a_bad_meta_file_is_refused_before_the_work() {
    let dir = tempfile::tempdir().unwrap();
    let meta = dir.path().join("meta.toml");
    std::fs::write(&meta, "site = \"A\"\nsight = \"B\"\n").unwrap();
    let err = fails(&[&SIG[..], &["--meta", &s(&meta)]].concat());
    assert!(
        err.contains("meta.toml:2:1: unknown field `sight`, expected one of `site`, `worker`"),
        "{err}"
    );
    assert!(
        err.contains("hint: the keys are site, worker, machine"),
        "{err}"
    );
    std::fs::write(&meta, "worker = \"a\\u0007b\"\n").unwrap();
    let err = fails(&[&SIG[..], &["--meta", &s(&meta)]].concat());
    assert!(
        err.contains("meta.toml:1: worker: \"a\\u{7}b\": give one line"),
        "{err}"
    );
    let err = fails(&[&SIG[..], &["--meta", &s(&dir.path().join("none.toml"))]].concat());
    assert!(err.contains("none.toml"), "{err}");
    let err = fails(&[&SIG[..], &["--meta", &s(dir.path())]].concat());
    assert!(err.contains("directory"), "{err}");
}

#[test]
fn the_meta_file_is_an_input_no_output_replaces() {
    let dir = tempfile::tempdir().unwrap();
    let meta = dir.path().join("meta.toml");
    std::fs::write(&meta, META).unwrap();
    let other = format!("{}/./meta.toml", s(dir.path()));
    let meta_s = s(&meta);
    for out in ["--report", "--plot"] {
        let mut args = [&SIG[..], &["--meta", &meta_s]].concat();
        // --plot's name must end in .svg: a link to the meta file with one.
        let target = if out == "--plot" {
            let link = dir.path().join("meta.svg");
            let _ = std::fs::remove_file(&link);
            std::os::unix::fs::symlink(&meta, &link).unwrap();
            s(&link)
        } else {
            other.clone()
        };
        args.extend([out, &target]);
        let err = fails(&args);
        assert!(err.contains("is the input"), "{out}: {err}");
        let day = [
            "day",
            "examples/day.toml",
            "--meta",
            &s(&meta),
            out,
            &target,
        ];
        let err = fails(&day);
        assert!(err.contains("is the input"), "day {out}: {err}");
    }
    assert_eq!(std::fs::read_to_string(&meta).unwrap(), META, "touched");
}

#[test]
fn no_model_leaves_the_body_model_out_of_the_page() {
    let dir = tempfile::tempdir().unwrap();
    let (full, lean) = (dir.path().join("full.html"), dir.path().join("lean.html"));
    ok_report(&[&SIG[..], &["--report", &s(&full)]].concat());
    ok_report(&[&SIG[..], &["--report", &s(&lean), "--no-model"]].concat());
    let (full, lean) = (
        std::fs::read_to_string(full).unwrap(),
        std::fs::read_to_string(lean).unwrap(),
    );
    for model in [
        "id=\"prediction\"",
        "data-key=\"/head/",
        "data-key=\"/segments/",
        "/head_m_s2\"",
        "At the head",
        "model (the body)",
        "(model)",
    ] {
        assert!(full.contains(model), "the full page lacks {model}");
        assert!(!lean.contains(model), "--no-model kept {model}");
    }
    // What was measured stays: the verdicts, the seat's numbers and bands.
    for kept in [
        "id=\"verdicts\"",
        "data-key=\"/health/a8_m_s2\"",
        "/seat_m_s2\"",
        "<svg",
    ] {
        assert!(lean.contains(kept), "--no-model dropped {kept}");
    }
    assert!(
        lean.len() < full.len() * 3 / 4,
        "{} of {}",
        lean.len(),
        full.len()
    );
    // Only for the page.
    let (code, _, err) = run(&[&SIG[..], &["--no-model"]].concat());
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("--report"), "{err}");
}

fn ok_report(args: &[&str]) {
    let (code, _, err) = run(args);
    assert_eq!(code, Some(0), "{args:?}: {err}");
}

#[test]
fn a_day_files_report_table_and_meta_merge_the_flag_winning() {
    let dir = tempfile::tempdir().unwrap();
    let day = dir.path().join("day.toml");
    let text = std::fs::read_to_string(root().join("examples/day.toml")).unwrap();
    std::fs::write(
        &day,
        format!("[report]\nsite = \"From the file\"\nworker = \"W\"\n\n{text}"),
    )
    .unwrap();
    let v = json(&["day", &s(&day)]);
    assert_eq!(
        v["meta"],
        serde_json::json!({"site": "From the file", "worker": "W"})
    );
    let meta = dir.path().join("meta.toml");
    std::fs::write(&meta, "site = \"From the flag\"\nassessor = \"A\"\n").unwrap();
    let v = json(&["day", &s(&day), "--meta", &s(&meta)]);
    assert_eq!(
        v["meta"],
        serde_json::json!({"site": "From the flag", "worker": "W", "assessor": "A"})
    );
    let table = ok(&["day", &s(&day), "--meta", &s(&meta)]);
    assert!(
        table.starts_with("site: From the flag; worker: W\nassessor: A\n\n"),
        "{table}"
    );
    // A week: each day keeps its own, --meta is the week's.
    let v = json(&[
        "day",
        &s(&day),
        "examples/day.toml",
        "--week",
        "--meta",
        &s(&meta),
    ]);
    assert_eq!(
        v["meta"],
        serde_json::json!({"site": "From the flag", "assessor": "A"})
    );
    assert_eq!(v["days"][0]["meta"]["site"], "From the file");
    assert!(v["days"][1].get("meta").is_none());
    let page = dir.path().join("w.html");
    ok_report(&[
        "day",
        &s(&day),
        "examples/day.toml",
        "--week",
        "--meta",
        &s(&meta),
        "--report",
        &s(&page),
    ]);
    let html = std::fs::read_to_string(&page).unwrap();
    assert!(html.contains("<td data-key=\"/meta/site\">From the flag</td>"));
    assert!(html.contains("<td data-key=\"/days/0/meta/site\">From the file</td>"));
}

#[test]
fn the_days_hours_as_written_summed_and_printed() {
    let dir = tempfile::tempdir().unwrap();
    let day = dir.path().join("day.toml");
    // 0.1 + 16.1 + 7.8 = 24.000000000000004 in floats: still a day.
    let op = |h: &str| format!("[[operation]]\nname = \"op\"\n{h}\naw_m_s2 = {{ z = 0.5 }}\n");
    std::fs::write(
        &day,
        [op("hours = 0.1"), op("hours = 16.1"), op("hours = 7.8")].concat(),
    )
    .unwrap();
    let table = ok(&["day", &s(&day)]);
    assert!(table.contains(": 3 operations, 24 h\n"), "{table}");
    for h in [" 6 min ", " 16 h 6 min ", " 7 h 48 min "] {
        assert!(
            table.lines().any(|l| l.starts_with("op ") && l.contains(h)),
            "{h}: {table}"
        );
    }
    std::fs::write(
        &day,
        [
            op("hours = \"3:15\""),
            op("minutes = 150"),
            op("hours = \"1h\""),
        ]
        .concat(),
    )
    .unwrap();
    let v = json(&["day", &s(&day)]);
    assert_eq!(v["operations"][0]["hours"], 3.25);
    assert_eq!(v["operations"][1]["hours"], 2.5);
    assert_eq!(v["hours"], 6.75);
    assert!(ok(&["day", &s(&day)]).contains(": 3 operations, 6 h 45 min\n"));
    // The page says the hours as the table does, not as the JSON stores them.
    let page = dir.path().join("day.html");
    ok(&["day", &s(&day), "--report", &s(&page), "-q"]);
    let html = std::fs::read_to_string(&page).unwrap();
    for h in ["6 h 45 min", ">3 h 15 min<", ">2 h 30 min<", ">1 h<"] {
        assert!(html.contains(h), "{h} is not on the page");
    }
    assert!(!html.contains(">6.75<") && !html.contains(">3.25<"));
    std::fs::write(&day, [op("hours = 20"), op("hours = \"4:30\"")].concat()).unwrap();
    let err = fails(&["day", &s(&day)]);
    assert!(
        err.contains("add up to 24 h 30 min, more than the 24 h of a day"),
        "{err}"
    );
}

#[test]
fn a_days_values_are_capped_as_records_are() {
    let dir = tempfile::tempdir().unwrap();
    let day = dir.path().join("day.toml");
    std::fs::write(
        &day,
        "[[operation]]\nname = \"op\"\nhours = 1\naw_m_s2 = { z = 1e308 }\n",
    )
    .unwrap();
    let err = fails(&["day", &s(&day)]);
    assert!(
        err.contains(
            "day.toml:4: operation 1 ('op'): aw_m_s2.z = 1e308: is over the cap of 1e4 m/s²"
        ),
        "{err}"
    );
}

#[test]
fn a_day_record_without_a_time_column_takes_the_fs_key() {
    let dir = tempfile::tempdir().unwrap();
    // 10 s of a 5 Hz sine at 500 Hz, the same samples with and without t_s.
    let (mut timed, mut bare) = (String::from("t_s,az\n"), String::from("az\n"));
    for i in 0..5000 {
        let t = i as f64 / 500.0;
        let a = (2.0 * std::f64::consts::PI * 5.0 * t).sin();
        timed += &format!("{t},{a}\n");
        bare += &format!("{a}\n");
    }
    std::fs::write(dir.path().join("timed.csv"), timed).unwrap();
    std::fs::write(dir.path().join("bare.csv"), bare).unwrap();
    let day = dir.path().join("day.toml");
    let op = |rec: &str, extra: &str| {
        format!("[[operation]]\nname = \"ride\"\nhours = 2\nrecord = \"{rec}\"\n{extra}\n")
    };
    std::fs::write(&day, op("bare.csv", "")).unwrap();
    let err = fails(&["day", &s(&day)]);
    assert!(
        err.contains("bare.csv: no time column (t_s, t_ms, t, time …): give the record's sampling rate in the operation, e.g. fs = 1000 (Hz)"),
        "{err}"
    );
    assert!(!err.contains("--fs"), "{err}");
    std::fs::write(&day, op("bare.csv", "fs = 500")).unwrap();
    let bare = json(&["day", &s(&day)]);
    std::fs::write(&day, op("timed.csv", "")).unwrap();
    let timed = json(&["day", &s(&day)]);
    assert_eq!(
        bare["daily"], timed["daily"],
        "fs = 500 reads as the t_s column does"
    );
    // A rate the time column contradicts is refused.
    std::fs::write(&day, op("timed.csv", "fs = 50")).unwrap();
    let err = fails(&["day", &s(&day)]);
    assert!(err.contains("500 Hz") && err.contains("50 Hz"), "{err}");
}
