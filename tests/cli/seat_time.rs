//! `assess` and `simulate` with a seat under the body: the pan judged, the
//! floor beside it, SEAT, the travel and its end-stop hits, and the refusals.

use crate::common::{fails, ok};
use serde_json::Value;

fn json(args: &[&str]) -> Value {
    serde_json::from_str(&ok(args)).expect("JSON")
}

const SEAT: &str = "paper-75kg-suspension-seat";

#[test]
fn assess_judges_the_pan_and_reports_the_floor_beside_it() {
    let v = json(&[
        "assess",
        "--preset",
        SEAT,
        "--signal",
        "class:EM6,seed=3",
        "--duration",
        "300",
        "--fs",
        "200",
        "--format",
        "json",
    ]);
    let (pan, floor) = (
        v["seat"]["aw_m_s2"].as_f64().unwrap(),
        v["floor"]["aw_m_s2"].as_f64().unwrap(),
    );
    let seat_pct = v["seat_value"]["seat_pct"].as_f64().unwrap();
    assert!((seat_pct - 100.0 * pan / floor).abs() < 1e-9);
    // EM6 through the suspension seat: the frequency domain says 20.7 %.
    assert!((seat_pct - 20.7).abs() < 2.0, "{seat_pct}");
    // The floor keeps every metric the seat has.
    for k in [
        "aw_m_s2",
        "peak_m_s2",
        "crest_factor",
        "mtvv_m_s2",
        "vdv_m_s175",
        "a8_m_s2",
    ] {
        assert!(v["floor"][k].is_f64(), "floor.{k}");
    }
    assert!(v["seat_value"]["vdv_pct"].as_f64().unwrap() > 0.0);
    let st = &v["stroke"];
    assert_eq!(st["available_m"].as_f64(), Some(0.10));
    assert_eq!(st["hits"].as_u64(), Some(0));
    assert!(st["peak_m"].as_f64().unwrap() >= st["rms_m"].as_f64().unwrap());
    // The EU verdict is the pan's: below the action value, while the floor's
    // a_w (1.64 m/s²) alone would be over the limit.
    assert_eq!(v["eu"]["a8"].as_str(), Some("below action value"));
    assert!(floor > 1.15);
    // Without a seat there is no floor block.
    let plain = json(&[
        "assess",
        "--signal",
        "class:EM6,seed=3",
        "--duration",
        "300",
        "--fs",
        "200",
        "--format",
        "json",
    ]);
    assert!(plain.get("floor").is_none() && plain.get("stroke").is_none());
    assert!((plain["seat"]["aw_m_s2"].as_f64().unwrap() - floor).abs() < 1e-12);
}

#[test]
fn a_shock_past_the_end_stops_is_counted_and_said() {
    let text = ok(&[
        "assess",
        "--preset",
        SEAT,
        "--signal",
        "shock:peak=60,width=0.2,at=2",
        "--duration",
        "10",
        "--fs",
        "500",
    ]);
    assert!(text.contains("past an end-stop"), "{text}");
    let v = json(&[
        "assess",
        "--preset",
        SEAT,
        "--signal",
        "shock:peak=60,width=0.2,at=2",
        "--duration",
        "10",
        "--fs",
        "500",
        "--format",
        "json",
    ]);
    let st = &v["stroke"];
    assert!(st["hits"].as_u64().unwrap() >= 1);
    assert!(st["peak_m"].as_f64().unwrap() > 0.05);
}

#[test]
fn a_seat_model_refuses_horizontal_axes() {
    let dir = tempfile::tempdir().unwrap();
    let rec = dir.path().join("xyz.csv");
    let mut s = String::from("t_s,x,y,z\n");
    for i in 0..5000 {
        let t = i as f64 / 500.0;
        s.push_str(&format!(
            "{t},{},{},{}\n",
            (t * 3.0).sin(),
            (t * 2.0).cos(),
            (t * 5.0).sin()
        ));
    }
    std::fs::write(&rec, s).unwrap();
    let e = fails(&["assess", "--preset", SEAT, "--input", rec.to_str().unwrap()]);
    assert!(
        e.contains("the seat model is vertical") && e.contains("--axes z=COL"),
        "{e}"
    );
    // z alone is judged.
    let t = ok(&[
        "assess",
        "--preset",
        SEAT,
        "--input",
        rec.to_str().unwrap(),
        "--axes",
        "z=z",
    ]);
    assert!(t.contains("SEAT"), "{t}");
}

#[test]
fn simulate_names_the_floor_under_a_seat() {
    let out = ok(&[
        "simulate",
        "--preset",
        SEAT,
        "--signal",
        "class:IT2,seed=1",
        "--duration",
        "2",
        "--fs",
        "200",
        "--format",
        "csv",
    ]);
    let header = out.lines().find(|l| !l.starts_with('#')).unwrap();
    assert!(
        header.starts_with("t_s,floor_acc_m_s2,head_acc_m_s2,floor_force_n,"),
        "{header}"
    );
    assert!(header.contains("acc_pad_m_s2") && header.contains("defl_suspension_m"));
    let table = ok(&[
        "simulate",
        "--preset",
        SEAT,
        "--signal",
        "sine:freq=2,amp=1",
        "--duration",
        "2",
    ]);
    assert!(
        table.lines().next().unwrap().contains("floor m/s²"),
        "{table}"
    );
    // A class needs 100 Hz at least.
    let e = fails(&[
        "simulate",
        "--signal",
        "class:EM6,seed=1",
        "--duration",
        "2",
        "--fs",
        "50",
    ]);
    assert!(e.contains("at least 100 Hz"), "{e}");
    let e = fails(&[
        "simulate",
        "--signal",
        "class:EM10,seed=1",
        "--duration",
        "2",
    ]);
    assert!(e.contains("EM1, EM2") && e.contains("AG3"), "{e}");
    let e = fails(&["simulate", "--signal", "class:EM6", "--duration", "2"]);
    assert!(e.contains("missing key 'seed'"), "{e}");
}
