//! `assess`'s HSE reading per axis: the points of the A(8) over the
//! exposure and the hours a day that reach the Directive's values
//! (2002/44/EC Art. 3: A(8) 0.5 and 1.15 m/s², VDV 9.1 and 21 m/s^1.75),
//! checked by assessing again for exactly those hours: the exposure then
//! meets the value.

use crate::common::ok;
use serde_json::Value;

fn json(args: &[&str]) -> Value {
    let mut a = args.to_vec();
    a.extend(["--format", "json"]);
    serde_json::from_str(&ok(&a)).expect("JSON")
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// A 5 Hz sine of 1 m/s² for 10 s: a_w about 0.75, so the action value
/// in about 3.6 h and the limit in about 19 h; its VDV reaches 9.1 in
/// about 4 h. Assessed for each of those hours, the A(8) or the VDV over
/// the exposure is the value (VDV ∝ T^¼, A(8) ∝ T^½).
#[test]
fn assessed_for_the_hours_it_gives_the_exposure_meets_the_value() {
    let sig = "sine:freq=5,amp=1";
    let v = json(&["assess", "--signal", sig, "--exposure", "6"]);
    let z = &v["axes"]["z"];
    // points = 100·(A(8)/0.5)² of the A(8) over the 6 h asked.
    let a8 = num(&z["a8_m_s2"]);
    assert!((num(&z["points"]) - 100.0 * (a8 / 0.5).powi(2)).abs() < 1e-9);
    for (key, value, field) in [
        ("hours_to_eav", 0.5, "/health/a8_m_s2"),
        ("hours_to_elv", 1.15, "/health/a8_m_s2"),
        ("hours_to_vdv_eav", 9.1, "/health/vdv_exposure_m_s175"),
    ] {
        let h = num(&z[key]);
        assert!(h > 0.5 && h < 24.0, "{key}: {h}");
        let again = json(&["assess", "--signal", sig, "--exposure", &h.to_string()]);
        let got = num(again.pointer(field).expect(field));
        assert!((got - value).abs() < 1e-9, "{key} {h} h: {field} {got}");
    }
    // To 21 takes longer than any day: given as the hours it takes.
    let h = num(&z["hours_to_vdv_elv"]);
    assert!(h > 24.0, "{h}");
    assert!((h - num(&z["hours_to_vdv_eav"]) * (21.0f64 / 9.1).powi(4)).abs() < 1e-9 * h);
}

/// On x, k = 1.4 (ISO 2631-1 §7.2.3) enters the hours as it enters the
/// A(8) and the VDV: assessed for x's hours, x's own A(8) is 0.5.
#[test]
fn a_horizontal_axis_carries_its_k_and_the_table_says_so() {
    let rec = "examples/tractor-seat-xyz-g.csv";
    let v = json(&["assess", "--input", rec]);
    let x = &v["axes"]["x"];
    let h = num(&x["hours_to_eav"]);
    let again = json(&["assess", "--input", rec, "--exposure", &h.to_string()]);
    assert!((num(&again["axes"]["x"]["a8_m_s2"]) - 0.5).abs() < 1e-9);
    let h = num(&x["hours_to_vdv_eav"]);
    let again = json(&["assess", "--input", rec, "--exposure", &h.to_string()]);
    assert!((num(&again["axes"]["x"]["vdv_exposure_m_s175"]) - 9.1).abs() < 1e-9);
    let t = ok(&["assess", "--input", rec]);
    for line in [
        "Hours a day of this vibration to reach each value (HSE points of the A(8) over 8 h):",
        "axis  points  to EAV h  to ELV h  to VDV EAV h  to VDV ELV h",
        &format!(
            "x *    {:.1}      {:.2}     {:.2}          {:.2}        {:.2}",
            num(&x["points"]),
            num(&x["hours_to_eav"]),
            num(&x["hours_to_elv"]),
            num(&x["hours_to_vdv_eav"]),
            num(&x["hours_to_vdv_elv"])
        ),
    ] {
        assert!(t.contains(line), "{line:?} not in\n{t}");
    }
}
