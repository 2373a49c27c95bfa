//! What `biodyn assess` prints for a record without a vertical axis: the
//! Directive on the axes it has, comfort, and why the body is not run (it
//! is driven vertically).

use super::axes;
use super::input::Source;
use super::table::fx;
use biodyn::iso2631::AxesAssessment;
use serde_json::{Value, json};

/// Why there is no body prediction, in every output.
pub const NO_BODY: &str = "the record has no z (vertical) axis: the body model is driven vertically and is not run; the Directive judges the axes the record has";

/// The table output.
pub fn text(r: &AxesAssessment, source: &Source) -> String {
    let mut s = format!(
        "{}\n{} s at {} Hz; exposure {} h a day\n{NO_BODY}\n\n",
        source.line(),
        fx(r.duration_s, 3)
            .trim_end_matches('0')
            .trim_end_matches('.'),
        r.fs,
        crate::view::format::typed(r.exposure_h)
    );
    s.push_str(&axes::text(&r.axes, &r.health, r.exposure_h, "At the seat"));
    s.push_str(&format!(
        "comfort (ISO 2631-1 Annex C): seat vector sum {:.3} m/s²: {}\n",
        r.comfort_vector,
        r.comfort_seat.join(" / ")
    ));
    if !r.warnings.is_empty() {
        s.push_str("\nwarnings:\n");
        for w in &r.warnings {
            s.push_str(&format!("  - {w}\n"));
        }
    }
    s
}

/// The JSON document: the full assessment's keys for what is judged,
/// `model`, `seat`, `head` and `segments` null, and `body` saying why.
pub fn json(r: &AxesAssessment, source: &Source) -> Value {
    json!({
        "model": null,
        "body": NO_BODY,
        "input": source.json(r.fs),
        "fs_hz": r.fs,
        "duration_s": r.duration_s,
        "exposure_h": r.exposure_h,
        "seat": null,
        "head": null,
        "segments": [],
        "axes": axes::json(&r.axes),
        "health": axes::health_json(&r.health),
        "eu": {"a8": r.health.eu.a8.words(), "vdv": r.health.eu.vdv.words()},
        "comfort": {"vector_sum_m_s2": r.comfort_vector, "seat": r.comfort_seat},
        "spine": null,
        "bands": [],
        "warnings": r.warnings,
    })
}
