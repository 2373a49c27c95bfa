//! A report's details (who, where, when, with what: `--meta FILE.toml`, a
//! day file's `[report]`) for every format: a line or two at the top of
//! the table, `meta` in the JSON with only the keys given. The HTML page
//! reads the JSON's (`html/meta.rs`).

use biodyn::exposure::Meta;
use serde_json::Value;

/// The details as the JSON's `meta` object; None when there are none.
pub fn json(meta: &Meta) -> Option<Value> {
    (!meta.is_empty())
        .then(|| serde_json::to_value(meta).ok())
        .flatten()
}

/// The details in words, a line or two (notes on lines of their own),
/// ending in a blank line; "" when there are none.
pub fn text(meta: &Meta) -> String {
    let pair = |k: &str| meta.get(k).map(|v| format!("{k}: {v}"));
    let who: Vec<String> = ["site", "worker", "machine", "task", "date"]
        .iter()
        .filter_map(|k| pair(k))
        .collect();
    let mut with: Vec<String> = Vec::new();
    match (meta.get("instrument"), meta.get("calibrated")) {
        (Some(i), Some(c)) => with.push(format!("instrument: {i} (calibrated {c})")),
        (Some(i), None) => with.push(format!("instrument: {i}")),
        (None, Some(c)) => with.push(format!("calibrated: {c}")),
        (None, None) => {}
    }
    with.extend(pair("assessor"));
    let mut s = String::new();
    for line in [who, with] {
        if !line.is_empty() {
            s.push_str(&line.join("; "));
            s.push('\n');
        }
    }
    if let Some(n) = meta.get("notes") {
        s.push_str(&format!("notes: {}\n", n.replace('\n', "\n       ")));
    }
    if !s.is_empty() {
        s.push('\n');
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_details_in_two_lines_and_only_the_keys_given() {
        let m = Meta::parse(
            "site = \"North quarry\"\nworker = \"J. Smith\"\ndate = 2026-12-05\ninstrument = \"SV 106\"\ncalibrated = \"2026-06-01\"\nnotes = \"wet\\nwindy\"",
            "m",
        )
        .unwrap();
        assert_eq!(
            text(&m),
            "site: North quarry; worker: J. Smith; date: 2026-12-05\ninstrument: SV 106 (calibrated 2026-06-01)\nnotes: wet\n       windy\n\n"
        );
        let j = json(&m).unwrap();
        assert_eq!(j.as_object().unwrap().len(), 6);
        assert_eq!(j["calibrated"], "2026-06-01");
        assert_eq!(text(&Meta::default()), "");
        assert_eq!(json(&Meta::default()), None);
    }
}
