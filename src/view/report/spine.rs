//! ISO 2631-5's Annex C in JSON, as `assess --spine` and `day` both give it:
//! the standard, the person, the daily dose and the risk.

use biodyn::iso2631::spine::{Person, Risk};
use serde_json::{Map, Value, json};

/// `{standard, person, dzd_m_s2, sd_mpa, static_mpa, r, probability, band,
/// words}`; the caller adds what its dose came from.
pub fn annex_c(person: &Person, dzd: f64, risk: &Risk) -> Map<String, Value> {
    let v = json!({
        "standard": "ISO 2631-5:2018",
        "person": {
            "age": person.age,
            "years": person.years,
            "days": person.days,
            "sex": person.sex.name(),
        },
        "dzd_m_s2": dzd,
        "sd_mpa": risk.sd,
        "static_mpa": risk.s_stat,
        "r": risk.r,
        "probability": risk.probability,
        "band": risk.band.name(),
        "words": risk.band.words(),
    });
    match v {
        Value::Object(m) => m,
        _ => Map::new(),
    }
}
