//! Comfort at other points (ISO 2631-1:1997 §8.2.2–8.2.3, Table 1) through
//! `biodyn assess` as a real process: a record with the seat's three axes,
//! the backrest's three, the feet's z and the seat's roll, its JSON checked
//! against a hand computation from the standard's weightings and factors,
//! and every refusal one line and a hint.

use super::axes::{json, num, wd, weighting, wk, write};
use super::common::{fails, ok};

/// Wc (f3 = f4 = 8 Hz) and We (f3 = f4 = 1 Hz), Q4 0.63, no step
/// (ISO 2631-1 Table A.2), by the formula of `axes::weighting`.
fn wc(f: f64) -> f64 {
    weighting(f, 8.0, 8.0, 0.63, None)
}

fn we(f: f64) -> f64 {
    weighting(f, 1.0, 1.0, 0.63, None)
}

/// |W(f)| for a weighting name.
fn w(name: &str, f: f64) -> f64 {
    match name {
        "Wc" => wc(f),
        "Wd" => wd(f),
        "We" => we(f),
        "Wk" => wk(f),
        other => panic!("no weighting {other}"),
    }
}

/// The eight acceleration columns beside t_s: (header, amplitude, frequency
/// Hz, point, axis key, the standard's weighting, k).
const EIGHT: [(&str, f64, f64, &str, &str, &str, f64); 8] = [
    ("ax", 0.2, 1.0, "seat", "x", "Wd", 1.0),
    ("ay", 0.1, 1.6, "seat", "y", "Wd", 1.0),
    ("az", 0.8, 5.0, "seat", "z", "Wk", 1.0),
    ("backrest_x", 0.6, 4.0, "backrest", "x", "Wc", 0.8),
    ("backrest_y", 0.4, 2.0, "backrest", "y", "Wd", 0.5),
    ("backrest_z", 0.5, 3.0, "backrest", "z", "Wd", 0.4),
    ("feet_z", 1.2, 8.0, "feet", "z", "Wk", 0.4),
    ("rx_rad_s2", 0.9, 1.25, "rotation", "x", "We", 0.63),
];

/// a_w of a sine is A/√2·|W(f)|; k·a_w; a_v per point = √Σ(k·a_w)²; the
/// overall value √Σ a_v² over seat, backrest, feet and rotation.
#[test]
fn a_nine_column_record_gets_comfort_at_every_point() {
    let d = tempfile::tempdir().unwrap();
    let cols = &EIGHT;
    let header: Vec<&str> = cols.iter().map(|c| c.0).collect();
    let sines: Vec<(f64, f64)> = cols.iter().map(|c| (c.1, c.2)).collect();
    let p = write(d.path(), "nine.csv", &header, &sines, 1.0);
    let v = json(&["assess", "--input", p.to_str().unwrap()]);
    let c = &v["comfort"];
    let mut totals: std::collections::BTreeMap<&str, f64> = Default::default();
    for &(col, amp, f, point, axis, wname, k) in cols {
        let want = amp / 2f64.sqrt() * w(wname, f);
        let (aw, weighted) = if point == "seat" {
            (
                num(&v["axes"][axis]["aw_m_s2"]),
                num(&v["axes"][axis]["aw_m_s2"]),
            )
        } else {
            let a = &c["points"][point][axis];
            assert_eq!(a["weighting"], wname, "{col}");
            assert_eq!(num(&a["k"]), k, "{col}");
            let key = if point == "rotation" {
                "aw_rad_s2"
            } else {
                "aw_m_s2"
            };
            let aw = num(&a[key]);
            assert_eq!(num(&a["weighted_m_s2"]), k * aw, "{col}");
            (aw, k * aw)
        };
        assert!((aw / want - 1.0).abs() < 0.01, "{col}: a_w {aw} vs {want}");
        *totals.entry(point).or_default() += weighted * weighted;
    }
    for (point, sq) in &totals {
        let got = if *point == "seat" {
            num(&c["vector_sum_m_s2"])
        } else {
            num(&c["points"][*point]["total_m_s2"])
        };
        assert!(
            (got - sq.sqrt()).abs() < 1e-12,
            "{point}: {got} vs {}",
            sq.sqrt()
        );
    }
    let overall = totals.values().sum::<f64>().sqrt();
    assert!((num(&c["overall_m_s2"]) - overall).abs() < 1e-12);
    // And from the weightings alone, within their 1 %.
    let by_hand: f64 = cols
        .iter()
        .map(|&(_, amp, f, _, _, wname, k)| (k * amp / 2f64.sqrt() * w(wname, f)).powi(2))
        .sum::<f64>()
        .sqrt();
    assert!((num(&c["overall_m_s2"]) / by_hand - 1.0).abs() < 0.01);
    let words: Vec<&str> = c["overall_words"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| w.as_str().unwrap())
        .collect();
    assert!(!words.is_empty() && words.iter().all(|w| w.contains("uncomfortable")));
    let keys: Vec<&String> = c["points"].as_object().unwrap().keys().collect();
    assert_eq!(keys, ["backrest", "feet", "rotation"]);
    assert_eq!(v["input"]["points"]["rx"]["unit"], "rad/s2");
    assert_eq!(v["input"]["points"]["feet_z"]["column"], "feet_z");
    // The table has the block, its rows and the overall value.
    let t = ok(&["assess", "--input", p.to_str().unwrap()]);
    assert!(
        t.contains("Comfort at other points (ISO 2631-1 §8.2.2-8.2.3"),
        "{t}"
    );
    assert!(t.contains("overall vibration total value"), "{t}");
    for ch in ["backrest_x", "backrest_y", "backrest_z", "feet_z", "rx"] {
        let unit = if ch == "rx" { "rad/s²" } else { "m/s²" };
        assert!(
            t.lines().any(|l| l.contains(ch) && l.contains(unit)),
            "{ch}: {t}"
        );
    }
    // A seat-only record has neither block nor keys.
    let seat = write(d.path(), "seat.csv", &header[..3], &sines[..3], 1.0);
    let s = json(&["assess", "--input", seat.to_str().unwrap()]);
    assert!(s["comfort"].get("points").is_none() && s["comfort"].get("overall_m_s2").is_none());
    assert!(!ok(&["assess", "--input", seat.to_str().unwrap()]).contains("other points"));
}

/// `--axes` names the points, and then only the named columns are read.
#[test]
fn axes_name_the_points_explicitly() {
    let d = tempfile::tempdir().unwrap();
    let p = write(
        d.path(),
        "r.csv",
        &["a1", "b1", "c1"],
        &[(1.0, 5.0), (0.5, 4.0), (2.0, 8.0)],
        1.0,
    );
    let v = json(&[
        "assess",
        "--input",
        p.to_str().unwrap(),
        "--axes",
        "z=a1,backrest_z=b1,feet_z=c1",
    ]);
    let c = &v["comfort"]["points"];
    assert_eq!(v["input"]["points"]["backrest_z"]["named_by"], "given");
    let bz = num(&c["backrest"]["z"]["aw_m_s2"]);
    assert!(
        (bz / (0.5 / 2f64.sqrt() * wd(4.0)) - 1.0).abs() < 0.01,
        "{bz}"
    );
    let fz = num(&c["feet"]["z"]["aw_m_s2"]);
    assert!(
        (fz / (2.0 / 2f64.sqrt() * wk(8.0)) - 1.0).abs() < 0.01,
        "{fz}"
    );
    assert!(v["axes"].get("x").is_none());
}

/// Every refusal: one line and a hint, naming the file, the columns and the fix.
#[test]
fn bad_point_columns_are_refused_with_a_hint() {
    let d = tempfile::tempdir().unwrap();
    let s = [(1.0, 5.0), (0.5, 4.0)];
    let f = |name: &str, h: [&str; 2]| write(d.path(), name, &h, &s, 1.0);
    let rot_g = f("rg.csv", ["az", "rx_g"]);
    let rad = f("rad.csv", ["az", "feet_z_rad_s2"]);
    let twice = f("tw.csv", ["backrest_x", "acc_backrest_x"]);
    let unnamed = f("un.csv", ["backrest_x", "speed"]);
    let two = f("two.csv", ["a1", "b1"]);
    let path = |p: &std::path::Path| p.to_str().unwrap().to_string();
    let cases: Vec<(Vec<String>, Vec<&str>)> = vec![
        (
            vec![path(&rot_g)],
            vec![
                "rg.csv",
                "'rx_g' is the rotation rx, in rad/s²",
                "name it rx_rad_s2",
            ],
        ),
        (
            vec![path(&rad)],
            vec![
                "'feet_z_rad_s2' is feet_z, a linear acceleration",
                "feet_z_m_s2",
            ],
        ),
        (
            vec![path(&twice)],
            vec![
                "'backrest_x' and 'acc_backrest_x' both name backrest_x",
                "with --axes backrest_x=COL",
            ],
        ),
        (
            vec![path(&unnamed)],
            vec!["no axis in the name of speed", "--axes"],
        ),
        (
            vec![path(&two), "--axes".into(), "z=a1,backrest_x=a1".into()],
            vec!["'a1' is given for both z and backrest_x"],
        ),
        (
            vec![path(&two), "--axes".into(), "z=a1,rx=t_s".into()],
            vec!["'t_s' is the time column: it cannot be the rx axis"],
        ),
        (
            vec![
                path(&two),
                "--axes".into(),
                "z=a1,feet_z=b1,feet_z=a1".into(),
            ],
            vec!["feet_z is named twice"],
        ),
        (
            vec![path(&two), "--axes".into(), "z=a1,backseat_x=b1".into()],
            vec!["'backseat_x' is not an axis", "backrest_x, feet_z, rx"],
        ),
        (
            vec![path(&two), "--axes".into(), "z=a1,feet_z=q".into()],
            vec!["no column named 'q'"],
        ),
    ];
    for (args, want) in cases {
        let mut a = vec!["assess", "--input"];
        a.extend(args.iter().map(String::as_str));
        let e = fails(&a);
        for w in &want {
            assert!(e.contains(w), "{a:?}: missing {w:?} in {e}");
        }
    }
}
