//! The JSON writer: pretty-printed, one trailing newline, numbers in
//! shortest round-trip form; response curves keyed like the CSV columns.

use biodyn::{Function, Response};
use serde::Serialize;

/// `value` as pretty JSON ending in a newline.
pub fn pretty<T: Serialize + ?Sized>(value: &T) -> Result<String, serde_json::Error> {
    Ok(serde_json::to_string_pretty(value)? + "\n")
}

/// One object per frequency, keyed like the CSV columns (`f_hz`,
/// `stht_mag`, `stht_phase_deg`, …).
pub fn curve_rows(curve: &[Response]) -> Vec<serde_json::Value> {
    curve_rows_of(curve, &Function::ALL)
}

/// As `curve_rows`, with the keys of `functions`.
pub fn curve_rows_of(curve: &[Response], functions: &[Function]) -> Vec<serde_json::Value> {
    curve
        .iter()
        .map(|r| {
            let mut m = serde_json::Map::new();
            m.insert("f_hz".into(), r.f_hz.into());
            for &f in functions {
                m.insert(f.mag_column().into(), r.mag(f).into());
                m.insert(f.phase_column().into(), r.phase_deg(f).into());
            }
            serde_json::Value::Object(m)
        })
        .collect()
}
