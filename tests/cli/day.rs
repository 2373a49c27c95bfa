//! `biodyn day` as a real process: the sheet, the JSON keys of issue 16
//! with numbers worked by hand, the week, and every refusal as one error
//! line plus a hint with a non-zero exit and no verdict.

use crate::common::{fails, ok, run};
use serde_json::Value;
use std::path::Path;

fn close(a: &Value, b: f64, tol: f64) {
    let a = a.as_f64().unwrap_or_else(|| panic!("not a number: {a}"));
    assert!((a - b).abs() <= tol, "{a} vs {b}");
}

/// `text` as a day file in a fresh folder.
fn day_file(text: &str) -> (tempfile::TempDir, String) {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("day.toml");
    std::fs::write(&p, text).unwrap();
    let shown = p.display().to_string();
    (dir, shown)
}

/// examples/day.toml, z: (0.52²·3.25 + 0.80²·2.5 + 0.38²·1)/8
/// = (0.8788 + 1.6 + 0.1444)/8 = 2.6232/8 = 0.3279; √ = 0.572626…;
/// points 100·0.3279/0.25 = 131.16. x: 1.4² (0.36²·3.25 + 0.30²·2.5 +
/// 0.45²·1)/8 = 1.96·(0.4212 + 0.225 + 0.2025)/8 = 1.96·0.8487/8 = 0.20793150;
/// √ = 0.455995…
#[test]
fn the_example_day_in_json() {
    let out = ok(&["day", "examples/day.toml", "--format", "json"]);
    let v: Value = serde_json::from_str(&out).unwrap();
    let d = &v["daily"];
    close(&d["axes"]["z"]["a8_m_s2"], 0.3279f64.sqrt(), 1e-12);
    close(&d["axes"]["z"]["points"], 131.16, 1e-9);
    close(&d["axes"]["x"]["a8_m_s2"], 0.207_931_5f64.sqrt(), 1e-12);
    assert_eq!(d["a8_axis"], "z");
    close(&d["a8_m_s2"], 0.3279f64.sqrt(), 1e-12);
    close(&d["points"], 131.16, 1e-9);
    assert_eq!(d["eu_a8"], "above action value");
    // z VDV: (7.0·19.5^¼)⁴ + (11.5·15^¼)⁴ + (5.2·6^¼)⁴
    // = 7⁴·19.5 + 11.5⁴·15 + 5.2⁴·6 = 46819.5 + 262350.9375 + 4386.9696 = 313557.4071; ^¼ = 23.6635
    close(&d["vdv_exposure_m_s175"], 313_557.407_1f64.powf(0.25), 1e-9);
    assert_eq!(d["vdv_axis"], "z");
    assert_eq!(d["eu_vdv"], "above limit value");
    let op = &v["operations"][0];
    assert_eq!(op["name"], "haul road");
    close(&op["hours"], 3.25, 0.0);
    let x = &op["axes"]["x"];
    // 1.4·0.36 = 0.504; A(8) 0.504·√(3.25/8) = 0.321238…; 8·(0.5/0.504)² = 7.87352…
    close(&x["kaw_m_s2"], 0.504, 1e-12);
    close(&x["a8_m_s2"], 0.504 * 0.40625f64.sqrt(), 1e-12);
    close(&x["points"], 41.2776, 1e-9);
    close(&x["hours_to_eav"], 7.873_519_778, 1e-8);
    close(&x["hours_to_elv"], 41.650_919_627, 1e-8);
    close(&op["axes"]["z"]["a8_m_s2"], 0.331_436_268, 1e-9);
    close(&op["axes"]["z"]["points"], 43.94, 1e-9);
}

#[test]
fn the_example_day_as_a_sheet() {
    let out = ok(&["day", "examples/day.toml"]);
    assert!(
        out.starts_with("examples/day.toml: 3 operations, 6 h 45 min\n"),
        "{out}"
    );
    for row in [
        "haul road  3 h 15 min     x       0.504      0.321    41.3      7.87     41.65         15.00",
        "z (vertical)          0.573   131.2         23.66",
        "Daily exposure (EU 2002/44/EC, the highest axis): z (vertical)",
        "A(8) 0.573 m/s², 131 points: above action value (action 0.5, limit 1.15)",
        "VDV 23.66 m/s^1.75 on z: above limit value (action 9.1, limit 21)",
    ] {
        assert!(out.contains(row), "missing {row:?} in\n{out}");
    }
}

/// A horizontal axis wins through k: x 0.4·1.4 = 0.56 > z 0.5, 8 h.
/// No VDVs: none judged, the operation named. k·a_w = 0 never reaches a value.
#[test]
fn the_highest_axis_may_be_horizontal_and_missing_vdvs_are_named() {
    let (_dir, p) = day_file(
        "[[operation]]\nname = \"grader\"\nhours = 8\naw_m_s2 = { x = 0.4, y = 0, z = 0.5 }\n",
    );
    let v: Value = serde_json::from_str(&ok(&["day", &p, "--format", "json"])).unwrap();
    assert_eq!(v["daily"]["a8_axis"], "x");
    close(&v["daily"]["a8_m_s2"], 0.56, 1e-12);
    // 100·(0.56/0.5)² = 125.44
    close(&v["daily"]["points"], 125.44, 1e-9);
    assert!(v["daily"].get("eu_vdv").is_none(), "{v}");
    assert!(v["operations"][0]["axes"]["y"]["hours_to_eav"].is_null());
    let t = ok(&["day", &p]);
    assert!(t.contains("VDV not judged: operations without a measured VDV (x: 'grader'; y: 'grader'; z: 'grader')"), "{t}");
    assert!(t.contains("never"), "{t}");
}

/// Two days at z 1.0 for 8 h: A(8)week = √(2·1/5) = 0.632456…, 160 points.
#[test]
fn a_week_of_days() {
    let (_d, p) = day_file("[[operation]]\nname = \"d\"\nhours = 8\naw_m_s2 = { z = 1.0 }\n");
    let v: Value =
        serde_json::from_str(&ok(&["day", &p, &p, "--week", "--format", "json"])).unwrap();
    assert_eq!(v["days"].as_array().unwrap().len(), 2);
    close(&v["week"]["a8_m_s2"], 0.4f64.sqrt(), 1e-12);
    close(&v["week"]["points"], 160.0, 1e-9);
    assert_eq!(v["week"]["eu_a8"], "above action value");
    let t = ok(&["day", &p, &p, "--week"]);
    assert!(
        t.contains(
            "Weekly exposure: z (vertical), A(8) 0.632 m/s², 160 points: above action value"
        ),
        "{t}"
    );
    let e = fails(&["day", &p, &p]);
    assert!(
        e.contains("2 day files given; one day file, or --week"),
        "{e}"
    );
    let eight: Vec<&str> = std::iter::once("day")
        .chain(std::iter::repeat_n(p.as_str(), 8))
        .chain(["--week"])
        .collect();
    let e = fails(&eight);
    assert!(e.contains("at most 7 days"), "{e}");
}

#[test]
fn every_refusal_is_one_line_with_the_file_and_no_verdict() {
    let op = |extra: &str| format!("[[operation]]\nname = \"drive\"\n{extra}\n");
    for (text, says) in [
        (
            op("hours = 2\naw_m_s2 = { z = 0.5 }\nspeed = 3"),
            "unknown field `speed`",
        ),
        (
            op("hours = -2\naw_m_s2 = { z = 0.5 }"),
            "operation 1 ('drive'): hours = -2",
        ),
        (
            op("hours = 13\naw_m_s2 = { z = 0.5 }").repeat(2),
            "add up to 26 h",
        ),
        (op("hours = 2"), "aw_m_s2: missing, and no record either"),
        (op("hours = 2\naw_m_s2 = { z = -0.5 }"), "aw_m_s2.z = -0.5"),
        (
            op("hours = 2\naw_m_s2 = { z = 0.5 }\nvdv_m_s175 = { z = 7 }"),
            "needs measured_s",
        ),
        (
            op("hours = 2\nrecord = \"a.csv\"\nunit = \"furlong\""),
            "unit = \"furlong\"",
        ),
        (
            op("hours = 2\nrecord = \"a.csv\"\naxes = \"q=a\""),
            "axes = \"q=a\"",
        ),
        (String::new(), "no [[operation]] tables"),
        (
            op("hours = 2\nrecord = \"loading.csv\""),
            "operation 1 ('drive'): record = \"loading.csv\": ",
        ),
    ] {
        let (_dir, p) = day_file(&text);
        let e = fails(&["day", &p]);
        assert!(e.contains(&format!("biodyn: error: {p}")), "{e}");
        assert!(e.contains(says), "{says:?} not in {e}");
        assert!(!e.contains("value"), "no verdict on a refused file: {e}");
    }
    let e = fails(&["day", "no-such-day.toml"]);
    assert!(
        e.contains("no-such-day.toml: cannot read the day file"),
        "{e}"
    );
    // clap's own refusals: status 2.
    let (code, _, _) = run(&["day"]);
    assert_eq!(code, Some(2));
    let (code, _, _) = run(&["day", "examples/day.toml", "--format", "xml"]);
    assert_eq!(code, Some(2));
    // CSV is one day's sheet: a week's is refused, with no output.
    let e = fails(&[
        "day",
        "examples/day.toml",
        "examples/day.toml",
        "--week",
        "--format",
        "csv",
    ]);
    assert!(e.contains("--format csv is one day's sheet"), "{e}");
    assert!(Path::new("examples/day.toml").is_relative());
}

/// A record operation is read on its axes and weighted as `assess` does:
/// its k·a_w is 1.4 (x) or 1.0 (z) times assess's a_w of the same record,
/// its VDV over the operation k·VDV·(T/T_rec)^¼; a g record with its unit
/// named gives the same day; an ambiguous record is refused with the
/// day file, the operation and how to name the axes.
#[test]
fn a_record_operation_is_measured_on_its_axes() {
    let dir = tempfile::tempdir().unwrap();
    let mut ms2 = String::from("t_s,ax,az\n");
    let mut g = String::from("t_s,ax,az\n");
    for k in 0..20_000 {
        let t = k as f64 / 1000.0;
        let (x, z) = (
            0.4 * (2.0 * std::f64::consts::PI * 1.5 * t).sin(),
            0.9 * (2.0 * std::f64::consts::PI * 5.0 * t).sin(),
        );
        ms2.push_str(&format!("{t},{x},{z}\n"));
        g.push_str(&format!("{t},{},{}\n", x / 9.80665, z / 9.80665));
    }
    std::fs::write(dir.path().join("r.csv"), ms2).unwrap();
    std::fs::write(dir.path().join("g.csv"), g).unwrap();
    let amb: String = std::iter::once("t_s,a,b\n".to_string())
        .chain((0..3000).map(|k| {
            let t = k as f64 / 1000.0;
            let v = (2.0 * std::f64::consts::PI * 4.0 * t).sin();
            format!("{t},{v},{v}\n")
        }))
        .collect();
    std::fs::write(dir.path().join("amb.csv"), amb).unwrap();
    std::fs::write(dir.path().join("short.csv"), "t_s,az\n0,1\n0.001,1\n").unwrap();
    let day = |rec: &str, extra: &str| {
        let p = dir.path().join(format!("{rec}.toml"));
        std::fs::write(
            &p,
            format!(
                "[[operation]]\nname = \"loading\"\nhours = 2\nrecord = \"{rec}.csv\"\n{extra}"
            ),
        )
        .unwrap();
        p.display().to_string()
    };
    let r = day("r", "");
    let v: Value = serde_json::from_str(&ok(&["day", &r, "--format", "json"])).unwrap();
    let a: Value = serde_json::from_str(&ok(&[
        "assess",
        "--input",
        dir.path().join("r.csv").to_str().unwrap(),
        "--format",
        "json",
    ]))
    .unwrap();
    let op = &v["operations"][0]["axes"];
    for (axis, k) in [("x", 1.4), ("z", 1.0)] {
        let aw = a["axes"][axis]["aw_m_s2"].as_f64().unwrap();
        close(&op[axis]["kaw_m_s2"], k * aw, 1e-12);
        // Partial A(8) = k·a_w·√(2/8) = k·a_w/2.
        close(&op[axis]["a8_m_s2"], k * aw / 2.0, 1e-12);
        let vdv = a["axes"][axis]["vdv_m_s175"].as_f64().unwrap();
        close(
            &op[axis]["vdv_exposure_m_s175"],
            k * vdv * (2.0 * 3600.0 / 20.0f64).powf(0.25),
            1e-9,
        );
    }
    assert!(op["y"].is_null());
    let gv: Value = serde_json::from_str(&ok(&[
        "day",
        &day("g", "unit = \"g\"\n"),
        "--format",
        "json",
    ]))
    .unwrap();
    for axis in ["x", "z"] {
        close(
            &gv["operations"][0]["axes"][axis]["kaw_m_s2"],
            op[axis]["kaw_m_s2"].as_f64().unwrap(),
            1e-6,
        );
    }
    let e = fails(&["day", &day("amb", "")]);
    assert!(
        e.contains("operation 1 ('loading')") && e.contains("amb.csv") && e.contains("axes = "),
        "{e}"
    );
    let named = day("amb", "axes = \"z=a\"\n");
    assert!(ok(&["day", &named]).contains("loading"));
    // Too short to judge: the day has no verdict (issue 19 item 12).
    let e = fails(&["day", &day("short", "")]);
    assert!(
        e.contains("short.csv") && e.contains("too short to judge"),
        "{e}"
    );
}

/// examples/day-shocks.toml: the day's spine block, Formula 5 and Annex C by
/// hand in the JSON, the same numbers in the sheet; a day without the
/// person has no block.
#[test]
fn the_shocks_example_carries_the_spine() {
    let v: Value = serde_json::from_str(&ok(&[
        "day",
        "examples/day-shocks.toml",
        "--format",
        "json",
    ]))
    .unwrap();
    let s = &v["spine"];
    let dzd = (24.5f64.powi(6) * 14400.0 / 900.0 + 8.2f64.powi(6) * 9000.0 / 900.0).powf(1.0 / 6.0);
    close(&s["dzd_m_s2"], dzd, 1e-9 * dzd);
    close(&s["sd_mpa"], 0.029 * dzd, 1e-12);
    let r = (1..=10)
        .map(|i| {
            (0.029 * dzd * 220f64.powf(1.0 / 6.0)
                / (6.75 - 0.052 * (25.0 + f64::from(i)) - 0.029 * 9.81))
                .powi(6)
        })
        .sum::<f64>()
        .powf(1.0 / 6.0);
    close(&s["r"], r, 1e-12);
    close(
        &s["probability"],
        1.0 - (-(r / 1.613).powf(2.799)).exp(),
        1e-12,
    );
    assert_eq!(s["operations"][1]["operation"], "crane work");
    assert_eq!(s["band"], "moderate");
    let t = ok(&["day", "examples/day-shocks.toml"]);
    assert!(
        t.contains(&format!("Dzd = (Σ Dz⁶·t_d/t_m)^⅙ = {dzd:.2} m/s²")),
        "{t}"
    );
    assert!(t.contains(&format!("R {r:.2}")), "{t}");
    let plain = ok(&["day", "examples/day.toml", "--format", "json"]);
    assert!(!plain.contains("\"spine\""));
}

/// Issue 30's day: the known VDVs x 1.4·19.921428… = 27.89 and z 35.41,
/// each measured over the whole hour it lasts, are both over the limit
/// value 21 m/s^1.75 (Directive 2002/44/EC Art. 3); "idle" has none. A
/// missing VDV only raises (Σ VDV_i⁴)^¼, so the day is above the limit.
/// Its x A(8): √((0.42²·1 + 0.14²·4)/8) = √0.03185 = 0.1785, 12.74 points.
const ISSUE_30: &str = "[[operation]]\nname = \"rough track\"\nhours = 1\naw_m_s2 = { x = 0.3, z = 0.5 }\nvdv_m_s175 = { x = 19.921428571428571, z = 35.41 }\nmeasured_s = 3600\n\n[[operation]]\nname = \"idle\"\nhours = 4\naw_m_s2 = { x = 0.1, z = 0.2 }\n";

#[test]
fn a_known_vdv_over_the_limit_is_judged_as_the_lower_bound_it_is() {
    let (_d, p) = day_file(ISSUE_30);
    let t = ok(&["day", &p]);
    for line in [
        "  VDV at least 35.41 m/s^1.75 on z: above limit value (action 9.1, limit 21)",
        "a missing VDV only raises the day's; without a measured VDV: x: 'idle'; z: 'idle'",
        "x (fore-and-aft)      0.178    12.7       ≥ 27.89",
    ] {
        assert!(t.contains(line), "{line:?} not in\n{t}");
    }
    assert!(!t.contains("not judged"), "{t}");
    let v: Value = serde_json::from_str(&ok(&["day", &p, "--format", "json"])).unwrap();
    let d = &v["daily"];
    close(&d["vdv_at_least_m_s175"], 35.41, 1e-12);
    assert_eq!(d["vdv_axis"], "z");
    assert_eq!(d["eu_vdv"], "above limit value");
    assert_eq!(d["eu_vdv_at_least"], "above limit value");
    // Never the exact key for a bound.
    assert!(d.get("vdv_exposure_m_s175").is_none(), "{d}");
    close(&d["axes"]["x"]["vdv_at_least_m_s175"], 27.89, 1e-12);
    assert_eq!(d["axes"]["z"]["vdv_lacking"], serde_json::json!(["idle"]));
    // idle's hours to the VDV values are not judged: no key, never 0.
    let idle = &v["operations"][1]["axes"]["z"];
    assert!(idle.get("hours_to_vdv_eav").is_none(), "{idle}");
    assert!(idle.get("hours_to_vdv_elv").is_none(), "{idle}");
    // rough track's z: 1 h·(9.1/35.41)⁴ = 0.0043617 h, under 0.01: shown so.
    close(
        &v["operations"][0]["axes"]["z"]["hours_to_vdv_eav"],
        (9.1f64 / 35.41).powi(4),
        1e-15,
    );
    assert!(t.contains("  <0.01 "), "{t}");
    // The report: the bound judged, "idle" named, the tiny hour said so.
    let page = Path::new(&p).with_extension("html");
    let (code, _, err) = run(&["day", &p, "--report", page.to_str().unwrap()]);
    assert_eq!(code, Some(0), "{err}");
    let html = std::fs::read_to_string(&page).unwrap();
    assert!(html.contains("VDV ≥ <span"), "{html}");
    assert!(html.contains("<div class=\"words\">above limit value</div>"));
    assert!(html.contains("Without a measured VDV: x: idle; z: idle."));
    assert!(html.contains(">&lt;0.01</span>"));
}

/// The known part above the action value only: the day is above it
/// whatever the missing VDVs are, and the limit is open. Below it: not
/// judged, the bound said.
#[test]
fn below_the_limit_a_known_part_leaves_the_verdict_open() {
    let (_d, p) = day_file(
        &ISSUE_30
            .replace("35.41", "12.5")
            .replace("19.921428571428571", "5"),
    );
    let t = ok(&["day", &p]);
    assert!(
        t.contains("  VDV at least 12.50 m/s^1.75 on z: above action value; above limit value open (action 9.1, limit 21)"),
        "{t}"
    );
    let v: Value = serde_json::from_str(&ok(&["day", &p, "--format", "json"])).unwrap();
    assert!(v["daily"].get("eu_vdv").is_none(), "{v}");
    assert_eq!(v["daily"]["eu_vdv_at_least"], "above action value");
    let (_d, p) = day_file(
        &ISSUE_30
            .replace("35.41", "8.5")
            .replace("19.921428571428571", "5"),
    );
    let t = ok(&["day", &p]);
    assert!(
        t.contains("  VDV not judged: at least 8.50 m/s^1.75 on z, below the action value so far (action 9.1, limit 21)"),
        "{t}"
    );
    let v: Value = serde_json::from_str(&ok(&["day", &p, "--format", "json"])).unwrap();
    assert!(v["daily"].get("eu_vdv").is_none(), "{v}");
    assert_eq!(v["daily"]["eu_vdv_at_least"], "below action value");
}

/// examples/day.toml's haul road on x: k·VDV = 1.4·5.1 = 7.14 over 600 s;
/// to 9.1 m/s^1.75: 600 s·(9.1/7.14)⁴ = 1583.157 s = 0.439766 h, to 21:
/// 600 s·(21/7.14)⁴ = 44898.9 s = 12.4719 h (VDV ∝ T^¼, SPEC §12).
#[test]
fn each_operation_has_the_hours_to_the_vdv_values() {
    let v: Value =
        serde_json::from_str(&ok(&["day", "examples/day.toml", "--format", "json"])).unwrap();
    let x = &v["operations"][0]["axes"]["x"];
    close(&x["hours_to_vdv_eav"], 0.439_766, 1e-6);
    close(&x["hours_to_vdv_elv"], 12.4719, 1e-4);
    let t = ok(&["day", "examples/day.toml"]);
    assert!(
        t.contains("VDV m/s^1.75  to VDV EAV h  to VDV ELV h"),
        "{t}"
    );
    assert!(
        t.contains("haul road  3 h 15 min     x       0.504      0.321    41.3      7.87     41.65         15.00          0.44         12.47"),
        "{t}"
    );
    // An operation without a VDV: "-" in both, as its VDV.
    let (_d, p) = day_file(ISSUE_30);
    let t = ok(&["day", &p]);
    assert!(
        t.contains("idle           4 h     x       0.140      0.099     3.9    102.04    539.80             -             -             -"),
        "{t}"
    );
}

/// `day --format csv`: the sheet, every number the JSON's.
#[test]
fn the_sheet_as_csv_carries_the_jsons_numbers() {
    let csv = ok(&["day", "examples/day.toml", "--format", "csv"]);
    let v: Value =
        serde_json::from_str(&ok(&["day", "examples/day.toml", "--format", "json"])).unwrap();
    let mut lines = csv.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let mut n = 0;
    for line in lines.clone().filter(|l| !l.starts_with("the day")) {
        let cells: Vec<&str> = line.split(',').collect();
        let o = v["operations"]
            .as_array()
            .unwrap()
            .iter()
            .find(|o| o["name"] == cells[0])
            .unwrap();
        for (i, key) in head.iter().enumerate().skip(3).take(8) {
            let want = o["axes"][cells[1]][key].as_f64().unwrap();
            assert_eq!(cells[i].parse::<f64>().unwrap(), want, "{line}: {key}");
        }
        n += 1;
    }
    assert_eq!(n, 9);
    let day: Vec<&str> = lines.filter(|l| l.starts_with("the day")).collect();
    assert_eq!(
        day.last().unwrap(),
        &format!(
            "the day,highest VDV: z,,,,,,,{},,,",
            v["daily"]["vdv_exposure_m_s175"]
        )
    );
}

/// The week names the days whose VDV passes a value: examples/day.toml's
/// z 23.66 > 21 exactly, issue 30's day by its known part.
#[test]
fn a_week_names_the_days_over_a_vdv_value() {
    let (_d, p) = day_file(ISSUE_30);
    let t = ok(&["day", "examples/day.toml", &p, "--week"]);
    assert!(
        t.contains("  day 1 (examples/day.toml): VDV 23.66 m/s^1.75 on z: above limit value"),
        "{t}"
    );
    assert!(
        t.contains(&format!(
            "  day 2 ({p}): VDV at least 35.41 m/s^1.75 on z: above limit value"
        )),
        "{t}"
    );
    let v: Value = serde_json::from_str(&ok(&[
        "day",
        "examples/day.toml",
        &p,
        "--week",
        "--format",
        "json",
    ]))
    .unwrap();
    let days = v["week"]["vdv_days"].as_array().unwrap();
    assert_eq!(days.len(), 2);
    assert_eq!(days[1]["day"], 2);
    close(&days[1]["vdv_at_least_m_s175"], 35.41, 1e-12);
    assert_eq!(days[1]["eu_vdv"], "above limit value");
    assert_eq!(v["week"]["vdv_open_days"], serde_json::json!([]));
}
