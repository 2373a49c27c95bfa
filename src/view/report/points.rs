//! Comfort at the other points (ISO 2631-1 §8.2.2–8.2.3) in a report: the
//! table block and the JSON under `comfort`, written only when the record
//! has a backrest, feet or rotation column.

use super::table::{fx, table};
use biodyn::iso2631::{PointComfort, PointsComfort};
use biodyn::time::Point;
use serde_json::{Value, json};

/// The headings of the table of comfort at other points, as text and in
/// the report's page.
pub const POINT_HEADINGS: [&str; 7] = [
    "point",
    "channel",
    "weighting",
    "k",
    "a_w",
    "k·a_w m/s²",
    "a_v m/s²",
];

/// The unit of a point's a_w: rad/s² for the rotations.
fn aw_unit(p: Point) -> &'static str {
    if p.is_angular() { "rad/s²" } else { "m/s²" }
}

/// The JSON key of a point's a_w.
fn aw_key(p: Point) -> &'static str {
    if p.is_angular() {
        "aw_rad_s2"
    } else {
        "aw_m_s2"
    }
}

fn point_json(p: &PointComfort) -> Value {
    let mut o = serde_json::Map::new();
    for a in &p.axes {
        o.insert(
            a.rule.channel.axis.name().into(),
            json!({
                "channel": a.rule.channel.name(),
                "weighting": a.rule.weighting.name(),
                aw_key(p.point): a.aw,
                "k": a.rule.k,
                "weighted_m_s2": a.weighted(),
            }),
        );
    }
    o.insert("total_m_s2".into(), json!(p.total));
    Value::Object(o)
}

/// Adds `points`, `overall_m_s2` and `overall_words` to a report's
/// `comfort` object.
pub fn comfort_json(comfort: &mut Value, c: &PointsComfort) {
    let mut points = serde_json::Map::new();
    for p in &c.points {
        points.insert(p.point.name().into(), point_json(p));
    }
    if let Value::Object(o) = comfort {
        o.insert("points".into(), Value::Object(points));
        o.insert("overall_m_s2".into(), json!(c.overall));
        o.insert("overall_words".into(), json!(c.words));
    }
}

/// The table block: each channel's a_w, k and k·a_w, each point's total,
/// and the overall value in words.
pub fn comfort_table(c: &PointsComfort) -> String {
    let mut rows: Vec<Vec<String>> = Vec::new();
    for p in &c.points {
        for a in &p.axes {
            rows.push(vec![
                p.point.name().to_string(),
                a.rule.channel.name().to_string(),
                a.rule.weighting.name().to_string(),
                format!("{}", a.rule.k),
                format!("{} {}", fx(a.aw, 3), aw_unit(p.point)),
                fx(a.weighted(), 3),
                String::new(),
            ]);
        }
        if let Some(last) = rows.last_mut() {
            last[6] = fx(p.total, 3);
        }
    }
    let mut s = String::from(
        "\nComfort at other points (ISO 2631-1 §8.2.2-8.2.3; a_v = √Σ(k·a_w)² per point):\n",
    );
    s.push_str(&table(&POINT_HEADINGS, &rows));
    s.push_str(&format!(
        "overall vibration total value (seat {:.3} and the points, root-sum-of-squares): {:.3} m/s²: {}\n",
        c.seat,
        c.overall,
        c.words.join(" / ")
    ));
    s
}
