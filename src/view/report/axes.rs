//! Each axis of the seat judged (ISO 2631-1 §7.2; Directive 2002/44/EC
//! Annex B): the per-axis table and JSON, the EU verdicts of the highest
//! axis, and the HSE calculator's points and hours, shared by the full
//! assessment and a record without z (no body to drive).

use super::day::hours_cell;
use super::table::{fx, table};
use biodyn::exposure::AxisReach;
use biodyn::iso2631::{A8_ACTION, A8_LIMIT, AxisResult, Health, VDV_ACTION, VDV_LIMIT};
use biodyn::time::PerAxis;
use serde_json::{Value, json};

fn hours(h: f64) -> String {
    crate::view::format::typed(h)
}

/// "At the seat, per axis …", the table, the EU verdicts of the highest
/// axis and the hours to each value; `at` names where ("At the seat").
pub fn text(axes: &PerAxis<AxisResult>, h: &Health, exposure_h: f64, at: &str) -> String {
    let mut s = String::new();
    s.push_str(&format!("{at}, per axis (ISO 2631-1 seated; a_w and VDV before k, A(8) and VDV over the exposure after it):\n"));
    let axis_rows: Vec<Vec<String>> = axes
        .iter()
        .map(|(a, x)| {
            let m = &x.metrics;
            let mark = if a == h.a8_axis { " *" } else { "" };
            vec![
                format!("{a}{mark}"),
                x.rule.weighting.name().to_string(),
                format!("{}", x.rule.k_health),
                fx(m.aw, 3),
                fx(m.peak, 3),
                fx(m.crest, 2),
                fx(m.mtvv, 3),
                fx(m.vdv, 2),
                fx(x.a8, 3),
                fx(x.vdv_exposure, 2),
            ]
        })
        .collect();
    let exp = format!("VDV {} h", hours(exposure_h));
    s.push_str(&table(
        &[
            "axis",
            "weighting",
            "k",
            "a_w m/s²",
            "peak m/s²",
            "crest",
            "MTVV m/s²",
            "VDV m/s^1.75",
            "A(8) m/s²",
            &exp,
        ],
        &axis_rows,
    ));
    s.push_str(&format!(
        "(* the highest A(8) after k: the day's exposure)\n\nEU 2002/44/EC, the highest axis at the seat:\n  A(8) {:.3} m/s² ({}): {} (action {A8_ACTION}, limit {A8_LIMIT})\n  VDV {:.2} m/s^1.75 ({}): {} (action {VDV_ACTION}, limit {VDV_LIMIT})\n",
        h.a8,
        h.a8_axis,
        h.eu.a8.words(),
        h.vdv_exposure,
        h.vdv_axis,
        h.eu.vdv.words()
    ));
    s.push_str(&reach_text(axes, h, exposure_h));
    s
}

/// Each axis's JSON object, by axis name.
pub fn json(axes: &PerAxis<AxisResult>) -> Value {
    let mut o = serde_json::Map::new();
    for (a, x) in axes.iter() {
        o.insert(a.name().into(), axis_json(x));
    }
    Value::Object(o)
}

/// The Directive's daily values: the highest axis's, named, and the verdicts.
pub fn health_json(h: &Health) -> Value {
    json!({
        "a8_m_s2": h.a8,
        "a8_axis": h.a8_axis.name(),
        "vdv_exposure_m_s175": h.vdv_exposure,
        "vdv_axis": h.vdv_axis.name(),
        "eu_a8": h.eu.a8.words(),
        "eu_vdv": h.eu.vdv.words(),
    })
}

/// One axis: its rule, its metrics before k, A(8) and VDV after it; the
/// HSE calculator's points and hours to each value (`exposure::AxisReach`,
/// as `biodyn day` gives them per operation; null: never reached).
fn axis_json(r: &AxisResult) -> Value {
    let m = &r.metrics;
    let h = AxisReach::of(r);
    json!({
        "weighting": r.rule.weighting.name(),
        "k_health": r.rule.k_health,
        "k_comfort": r.rule.k_comfort,
        "aw_m_s2": m.aw,
        "peak_m_s2": m.peak,
        "crest_factor": m.crest,
        "mtvv_m_s2": m.mtvv,
        "vdv_m_s175": m.vdv,
        "a8_m_s2": r.a8,
        "vdv_exposure_m_s175": r.vdv_exposure,
        "points": h.points,
        "hours_to_eav": h.hours_to_eav,
        "hours_to_elv": h.hours_to_elv,
        "hours_to_vdv_eav": h.vdv.to_eav,
        "hours_to_vdv_elv": h.vdv.to_elv,
    })
}

/// Per axis, the HSE calculator's reading: the points of the A(8) over the
/// exposure, and the hours a day of this vibration that reach the A(8)
/// values, 8 h·(V/(k·a_w))², and the VDV values, T·(V/(k·VDV))⁴ with T
/// the record's length (VDV grows as the fourth root of time).
fn reach_text(axes: &PerAxis<AxisResult>, health: &Health, exposure_h: f64) -> String {
    let rows: Vec<Vec<String>> = axes
        .iter()
        .map(|(a, x)| {
            let h = AxisReach::of(x);
            let mark = if a == health.a8_axis { " *" } else { "" };
            vec![
                format!("{a}{mark}"),
                fx(h.points, 1),
                hours_cell(h.hours_to_eav),
                hours_cell(h.hours_to_elv),
                hours_cell(h.vdv.to_eav),
                hours_cell(h.vdv.to_elv),
            ]
        })
        .collect();
    format!(
        "\nHours a day of this vibration to reach each value (HSE points of the A(8) over {} h):\n{}\n",
        hours(exposure_h),
        table(
            &[
                "axis",
                "points",
                "to EAV h",
                "to ELV h",
                "to VDV EAV h",
                "to VDV ELV h"
            ],
            &rows
        )
    )
}
