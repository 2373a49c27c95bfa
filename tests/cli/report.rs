//! `assess --report` and `day --report` as real processes: every number on
//! the page is the JSON's for the same command (by its `data-key` pointer,
//! to the last digit), the page is self-contained and printable, what the
//! user named is escaped, stdout still prints, and every bad report path
//! is refused with one error line before anything is written or printed.

use crate::common::{fails, root, run};
use biodyn_app::view::figure::read::unescape;
use serde_json::Value;
use std::collections::BTreeSet;
use std::path::Path;

/// The value of attribute `name` in the tag text `tag`.
fn attr<'a>(tag: &'a str, name: &str) -> Option<&'a str> {
    let at = tag.find(&format!(" {name}=\""))? + name.len() + 3;
    let end = tag[at..].find('"')?;
    Some(&tag[at..at + end])
}

/// Every (data-key, data-value, shown text) on the page, from a scan of
/// its tags.
fn numbers(html: &str) -> Vec<(String, String, String)> {
    let mut out = Vec::new();
    let mut rest = html;
    while let Some(i) = rest.find("<span ") {
        rest = &rest[i..];
        let Some(end) = rest.find('>') else { break };
        let tag = &rest[..end];
        if let (Some(k), Some(v)) = (attr(tag, "data-key"), attr(tag, "data-value")) {
            let close = rest.find("</span>").expect("a number's span closes");
            out.push((unescape(k), unescape(v), rest[end + 1..close].to_string()));
        }
        rest = &rest[end..];
    }
    out
}

/// Hours as the page says them ("6 h 45 min", "3 h", "45 min"), in hours;
/// None for a plain number.
fn said_hours(shown: &str) -> Option<f64> {
    let (h, m) = match shown.split_once(" h") {
        Some((h, rest)) => (h, rest.trim().strip_suffix(" min").unwrap_or("0")),
        None => ("0", shown.strip_suffix(" min")?),
    };
    Some(h.trim().parse::<f64>().ok()? + m.trim().parse::<f64>().ok()? / 60.0)
}

/// Asserts each number on the page is the JSON's at its pointer, in the
/// JSON's own shortest round-trip digits, and that the page shows it
/// rounded (its text parses to within half a unit of its last digit);
/// returns the pointers seen.
fn same_numbers(html: &str, json: &Value) -> BTreeSet<String> {
    let nums = numbers(html);
    assert!(
        nums.len() > 20,
        "too few numbers on the page: {}",
        nums.len()
    );
    let mut seen = BTreeSet::new();
    for (key, value, shown) in nums {
        let j = json
            .pointer(&key)
            .unwrap_or_else(|| panic!("{key} is on the page but not in the JSON"));
        assert!(j.is_number(), "{key}: {j} is not a number");
        assert_eq!(
            j.to_string(),
            value,
            "{key}: the page carries {value}, the JSON {j}"
        );
        let exact: f64 = value.parse().unwrap();
        assert_eq!(exact.to_bits(), j.as_f64().unwrap().to_bits(), "{key}");
        let (eyes, half) = match said_hours(&shown) {
            // Hours said as people say them: to the minute.
            Some(h) => (h, 0.5 / 60.0 * (1.0 + 1e-9)),
            None => {
                let eyes: f64 = shown
                    .parse()
                    .unwrap_or_else(|_| panic!("{key}: shown as {shown:?}"));
                let decimals = shown.split_once('.').map_or(0, |(_, d)| d.len());
                (eyes, 0.5 * 10f64.powi(-(decimals as i32)) * (1.0 + 1e-9))
            }
        };
        assert!(
            (eyes - exact).abs() <= half,
            "{key}: shown {shown} for {exact}"
        );
        seen.insert(key);
    }
    seen
}

/// Every numeric leaf of `json` under `prefix`, as pointers.
fn leaves(json: &Value, prefix: &str) -> Vec<String> {
    fn walk(v: &Value, at: String, out: &mut Vec<String>) {
        match v {
            Value::Number(_) => out.push(at),
            Value::Object(o) => {
                for (k, v) in o {
                    walk(
                        v,
                        format!("{at}/{}", k.replace('~', "~0").replace('/', "~1")),
                        out,
                    )
                }
            }
            Value::Array(a) => {
                for (i, v) in a.iter().enumerate() {
                    walk(v, format!("{at}/{i}"), out)
                }
            }
            _ => {}
        }
    }
    let mut out = Vec::new();
    if let Some(v) = json.pointer(prefix) {
        walk(v, prefix.to_string(), &mut out);
    }
    out
}

fn all_on_page(seen: &BTreeSet<String>, json: &Value, prefixes: &[&str]) {
    for p in prefixes {
        let l = leaves(json, p);
        assert!(!l.is_empty(), "the JSON has no numbers under {p}");
        for k in l {
            assert!(seen.contains(&k), "{k} is in the JSON but not on the page");
        }
    }
}

/// No script, nothing fetched; the print stylesheet is there.
fn self_contained(html: &str) {
    let lower = html.to_ascii_lowercase();
    for bad in [
        "<script", "src=", "href=", "url(", "@import", "<link", "<iframe", "<img", "http:",
        "https:",
    ] {
        assert!(!lower.contains(bad), "the page has {bad:?}");
    }
    for want in [
        "<!doctype html>",
        "<meta charset=\"utf-8\">",
        "@media print",
        "@page { size: a4",
        "break-inside: avoid",
    ] {
        assert!(lower.contains(want), "the page lacks {want:?}");
    }
    assert!(
        html.contains(concat!("biodyn ", env!("CARGO_PKG_VERSION"))),
        "no program version"
    );
    // assess's page carries its figure (the --plot figure: tests/cli/figures.rs).
    if html.contains("<h2>Figures</h2>") {
        assert!(
            html.contains("<svg version=\"1.1\""),
            "a Figures heading with no figure"
        );
    }
}

/// Runs `args` twice: once with `--format json`, once with `--report` to a
/// temp file; returns (stdout with --report, the page, the JSON), having
/// checked the table still prints the same with the report as without.
fn report_and_json(args: &[&str]) -> (String, String, Value) {
    let dir = tempfile::tempdir().unwrap();
    let page = dir.path().join("r.html");
    let page_s = page.display().to_string();
    let mut with: Vec<&str> = args.to_vec();
    with.extend(["--report", &page_s]);
    let (code, out, err) = run(&with);
    assert_eq!(code, Some(0), "{with:?}: {err}");
    assert_eq!(err, format!("wrote the report to {page_s}\n"));
    let (code, plain, _) = run(args);
    assert_eq!(code, Some(0));
    assert_eq!(out, plain, "--report changed what stdout prints");
    let html = std::fs::read_to_string(&page).unwrap();
    // Reproducible: the same command, the same bytes (no clock in it).
    let again = dir.path().join("again.html");
    let mut twice: Vec<&str> = args.to_vec();
    let again_s = again.display().to_string();
    twice.extend(["--format", "json", "--report", &again_s]);
    let (code, json, _) = run(&twice);
    assert_eq!(code, Some(0));
    assert_eq!(
        std::fs::read_to_string(&again).unwrap(),
        html,
        "not the same bytes twice"
    );
    (out, html, serde_json::from_str(&json).unwrap())
}

#[test]
fn assess_on_a_signal_reports_the_json_numbers() {
    let (_, html, json) =
        report_and_json(&["assess", "--signal", "sine:freq=5,amp=1", "--exposure", "6"]);
    self_contained(&html);
    let seen = same_numbers(&html, &json);
    all_on_page(
        &seen,
        &json,
        &[
            "/axes",
            "/health",
            "/seat",
            "/head",
            "/comfort",
            "/segments",
            "/bands",
        ],
    );
    for k in ["/duration_s", "/fs_hz", "/exposure_h"] {
        assert!(seen.contains(k), "{k}");
    }
    assert!(
        html.contains("generated signal <code>sine:freq=5,amp=1"),
        "what was measured"
    );
    // The verdicts in words, and the head labelled as the model's.
    let words = json["health"]["eu_a8"].as_str().unwrap();
    assert!(
        html.contains(&format!("<div class=\"words\">{words}</div>")),
        "{words}"
    );
    assert!(html.contains("the model's prediction, not a measurement"));
    for w in json["comfort"]["seat"].as_array().unwrap() {
        assert!(html.contains(w.as_str().unwrap()), "comfort words {w}");
    }
    assert!(
        !html.contains("ISO 2631-5"),
        "no spine block without --spine"
    );
}

#[test]
fn assess_with_the_spine_reports_its_block() {
    let (_, html, json) = report_and_json(&[
        "assess",
        "--signal",
        "random:rms=0.8,band=1-20,seed=1+shock:peak=15,width=0.1,at=30",
        "--duration",
        "60",
        "--spine",
        "age=25,years=10,days=240,sex=male",
    ]);
    self_contained(&html);
    let seen = same_numbers(&html, &json);
    for k in [
        "peaks",
        "dz_m_s2",
        "dzd_m_s2",
        "sd_mpa",
        "static_mpa",
        "r",
        "probability",
        "largest_peaks/0/m_s2",
        "largest_peaks/0/t_s",
    ] {
        assert!(
            seen.contains(&format!("/spine/{k}")),
            "/spine/{k} not on the page"
        );
    }
    let words = json["spine"]["words"].as_str().unwrap();
    assert!(
        words.contains('<'),
        "the words hold a '<' to escape: {words}"
    );
    assert!(html.contains(&words.replace('<', "&lt;")), "{words}");
    assert!(html.contains("ISO 2631-5:2018"));
}

#[test]
fn assess_on_three_axes_reports_each_axis() {
    let (out, html, json) = report_and_json(&[
        "assess",
        "--input",
        "examples/tractor-seat-xyz-g.csv",
        "--axes",
        "x=ax_g,y=ay_g,z=az_g",
    ]);
    assert!(
        out.contains("At the seat, per axis"),
        "the table still prints"
    );
    self_contained(&html);
    let seen = same_numbers(&html, &json);
    all_on_page(
        &seen,
        &json,
        &[
            "/axes/x",
            "/axes/y",
            "/axes/z",
            "/health",
            "/fs_hz",
            "/duration_s",
        ],
    );
    for col in ["ax_g", "ay_g", "az_g"] {
        assert!(html.contains(&format!("<code>{col}</code>")), "{col}");
    }
    assert!(html.contains("<code>examples/tractor-seat-xyz-g.csv</code>"));
    // The highest axis is the bold row.
    let top = json["health"]["a8_axis"].as_str().unwrap();
    assert!(
        html.contains(&format!("<tr class=\"top\"><td>{top} (")),
        "{top}"
    );
}

#[test]
fn the_example_day_and_week_report_the_json_numbers() {
    for args in [
        &["day", "examples/day.toml"][..],
        &["day", "examples/day-shocks.toml"],
        &[
            "day",
            "examples/day.toml",
            "examples/day-shocks.toml",
            "--week",
        ],
    ] {
        let (_, html, json) = report_and_json(args);
        self_contained(&html);
        let seen = same_numbers(&html, &json);
        if json.get("week").is_some() {
            all_on_page(
                &seen,
                &json,
                &[
                    "/week",
                    "/days/0/operations",
                    "/days/1/daily",
                    "/days/1/spine",
                ],
            );
        } else {
            all_on_page(&seen, &json, &["/operations", "/daily", "/hours"]);
            let words = json["daily"]["eu_a8"].as_str().unwrap();
            assert!(
                html.contains(&format!("<div class=\"words\">{words}</div>")),
                "{words}"
            );
        }
    }
}

#[test]
fn what_the_user_named_is_escaped() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let preset = d.join("p.toml");
    let (code, _, err) = run(&["preset", "save", &preset.display().to_string()]);
    assert_eq!(code, Some(0), "{err}");
    let text = std::fs::read_to_string(&preset).unwrap();
    std::fs::write(
        &preset,
        text.replace("name = \"paper-75kg\"", "name = \"<b>bold</b>\""),
    )
    .unwrap();
    let record = d.join("a<i>&.csv");
    std::fs::copy(root().join("examples/tractor-seat-xyz-g.csv"), &record).unwrap();
    let page = d.join("r.html");
    let (code, _, err) = run(&[
        "assess",
        "--preset",
        &preset.display().to_string(),
        "--input",
        &record.display().to_string(),
        "--axes",
        "x=ax_g,y=ay_g,z=az_g",
        "--report",
        &page.display().to_string(),
    ]);
    assert_eq!(code, Some(0), "{err}");
    let html = std::fs::read_to_string(&page).unwrap();
    assert!(
        !html.contains("<b>") && !html.contains("<i>"),
        "user text not escaped"
    );
    assert!(html.contains("&lt;b&gt;bold&lt;/b&gt;"));
    assert!(html.contains("a&lt;i&gt;&amp;.csv"));

    let day = d.join("day.toml");
    let text = std::fs::read_to_string(root().join("examples/day.toml")).unwrap();
    std::fs::write(
        &day,
        text.replace("\"haul road\"", "\"<b>haul</b> & 'road'\""),
    )
    .unwrap();
    let (code, _, err) = run(&[
        "day",
        &day.display().to_string(),
        "--report",
        &page.display().to_string(),
    ]);
    assert_eq!(code, Some(0), "{err}");
    let html = std::fs::read_to_string(&page).unwrap();
    assert!(!html.contains("<b>"), "a segment of user text not escaped");
    assert!(html.contains("&lt;b&gt;haul&lt;/b&gt; &amp; &#39;road&#39;"));
}

/// One refusal: exit 1, nothing printed, error + hint naming `what`, and
/// `path`'s contents (if a file) untouched.
fn refused(args: &[&str], what: &str) {
    let err = fails(args);
    assert!(err.contains(what), "{what:?} not in {err}");
    assert!(!err.contains("wrote the report"), "{err}");
}

#[cfg(unix)]
#[test]
fn bad_report_paths_are_refused_before_the_work() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let s = |p: &Path| p.display().to_string();
    let sig = ["assess", "--signal", "sine:freq=5,amp=1", "--report"];
    // A directory, a missing folder.
    refused(&[&sig[..], &[&s(d)]].concat(), "is a directory");
    refused(
        &[&sig[..], &[&s(&d.join("no/r.html"))]].concat(),
        "does not exist",
    );
    // A FIFO: refused, not opened (opening would hang).
    let fifo = d.join("fifo");
    let made = std::process::Command::new("mkfifo").arg(&fifo).status();
    if made.is_ok_and(|s| s.success()) {
        refused(&[&sig[..], &[&s(&fifo)]].concat(), "FIFO");
    } else {
        crate::common::skip("mkfifo");
    }
    // Its own input, by another path to it: the record, the preset, the day file.
    let record = d.join("seat.csv");
    std::fs::copy(root().join("examples/tractor-seat-xyz-g.csv"), &record).unwrap();
    let before = std::fs::read(&record).unwrap();
    let other = format!("{}/./seat.csv", s(d));
    refused(
        &[
            "assess",
            "--input",
            &s(&record),
            "--axes",
            "x=ax_g,y=ay_g,z=az_g",
            "--report",
            &other,
        ],
        "is the input",
    );
    assert_eq!(
        std::fs::read(&record).unwrap(),
        before,
        "the input was touched"
    );
    let preset = d.join("p.toml");
    run(&["preset", "save", &s(&preset)]);
    refused(
        &[
            "assess",
            "--preset",
            &s(&preset),
            "--signal",
            "sine:freq=5,amp=1",
            "--report",
            &s(&preset),
        ],
        "is the input",
    );
    let day = d.join("day.toml");
    std::fs::copy(root().join("examples/day.toml"), &day).unwrap();
    refused(&["day", &s(&day), "--report", &s(&day)], "is the input");
    // A record the day file reads is the day's input too.
    std::fs::write(
        d.join("rec.toml"),
        "[[operation]]\nname = \"ride\"\nhours = 2\nrecord = \"seat.csv\"\naxes = \"x=ax_g,y=ay_g,z=az_g\"\n",
    )
    .unwrap();
    refused(
        &["day", &s(&d.join("rec.toml")), "--report", &s(&record)],
        "is the input",
    );
    assert_eq!(
        std::fs::read(&record).unwrap(),
        before,
        "the record was touched"
    );
    // A read-only page is replaced only with --force, its mode kept.
    use std::os::unix::fs::PermissionsExt;
    let old = d.join("old.html");
    std::fs::write(&old, "old").unwrap();
    std::fs::set_permissions(&old, std::fs::Permissions::from_mode(0o444)).unwrap();
    refused(&[&sig[..], &[&s(&old)]].concat(), "read-only");
    assert_eq!(std::fs::read_to_string(&old).unwrap(), "old");
    let (code, out, err) = run(&[&sig[..], &[&s(&old), "--force"]].concat());
    assert_eq!(code, Some(0), "{err}");
    assert!(!out.is_empty(), "the table prints");
    assert!(
        std::fs::read_to_string(&old)
            .unwrap()
            .starts_with("<!DOCTYPE html>")
    );
    let mode = std::fs::metadata(&old).unwrap().permissions().mode() & 0o777;
    assert_eq!(mode, 0o444);
}
