//! `assess`'s seat block, with a seat under the body: the floor beside the
//! pan, SEAT and the VDV ratio (ISO 10326-1), the suspension's travel.

use super::table::fx;
use biodyn::iso2631::{Assessment, Channel};
use serde_json::{Map, Value, json};

/// Adds `floor`, `seat_value` and `stroke` to the JSON document (`metrics`
/// writes a channel the way `seat` is written).
pub fn json(r: &Assessment, v: &mut Value, metrics: impl Fn(&Channel) -> Map<String, Value>) {
    let (Some(floor), Some(sv), Some(st)) = (&r.floor, &r.seat_value, &r.stroke) else {
        return;
    };
    v["floor"] = Value::Object(metrics(floor));
    v["seat_value"] = json!({"seat_pct": sv.seat_pct, "vdv_pct": sv.vdv_pct});
    v["stroke"] = json!({
        "peak_m": st.peak_m,
        "rms_m": st.rms_m,
        "available_m": st.available_m,
        "hits": st.hits,
    });
}

/// The text block, or nothing without a seat.
pub fn text(r: &Assessment) -> String {
    let (Some(floor), Some(sv), Some(st)) = (&r.floor, &r.seat_value, &r.stroke) else {
        return String::new();
    };
    let mm = |m: f64| fx(1000.0 * m, 1);
    let mut s = format!(
        "\nThe seat (the record is the floor; the verdicts above judge the pan):\n  SEAT {} % (a_w pan {} / floor {} m/s²), VDV pan/floor {} %\n  suspension travel: r.m.s. {} mm, peak {} mm, of ±{} mm to the end-stops\n",
        fx(sv.seat_pct, 1),
        fx(r.seat.metrics.aw, 3),
        fx(floor.metrics.aw, 3),
        fx(sv.vdv_pct, 1),
        mm(st.rms_m),
        mm(st.peak_m),
        mm(st.available_m / 2.0)
    );
    s.push_str(&match st.hits {
        0 => "  no excursion reached an end-stop\n".to_string(),
        n => format!(
            "  {n} excursion(s) past an end-stop: the model is linear and has no end-stop, so past it the pan's figures are not the seat's\n"
        ),
    });
    s
}
