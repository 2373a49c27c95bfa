//! The report's details at the top of the page: who, where, when, with
//! what, read from the JSON's `meta` (only the keys given), every value
//! escaped and tagged with its JSON pointer in `data-key`.

use super::{Doc, esc, section};

/// Each key's words on the page.
const LABELS: [(&str, &str); 9] = [
    ("site", "site"),
    ("worker", "worker"),
    ("machine", "machine"),
    ("task", "task"),
    ("date", "date"),
    ("instrument", "instrument"),
    ("calibrated", "instrument last calibrated"),
    ("assessor", "assessor"),
    ("notes", "notes"),
];

/// The details at `at` (a JSON pointer, e.g. `/meta`) as a table of
/// facts; "" when the document has none there.
pub fn facts(d: &Doc, at: &str) -> String {
    let rows: Vec<String> = LABELS
        .iter()
        .filter_map(|(key, label)| {
            let k = format!("{at}/{key}");
            let v = d.get(&k)?.as_str()?;
            Some(format!(
                "<tr><th>{label}</th><td data-key=\"{}\">{}</td></tr>\n",
                esc(&k),
                esc(v).replace('\n', "<br>")
            ))
        })
        .collect();
    if rows.is_empty() {
        return String::new();
    }
    format!(
        "<table class=\"facts meta\">\n<tbody>\n{}</tbody>\n</table>\n",
        rows.concat()
    )
}

/// The details as the page's first section; "" when there are none.
pub fn block(d: &Doc, at: &str) -> String {
    let t = facts(d, at);
    if t.is_empty() {
        return t;
    }
    section("meta", "Site, worker and instrument", &t)
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn only_the_keys_given_escaped_and_tagged() {
        let v = json!({"meta": {"site": "<b>Q & A</b>", "notes": "a\nb", "calibrated": "2026"}});
        let b = block(&Doc::new(&v), "/meta");
        assert!(b.starts_with("<section id=\"meta\">"), "{b}");
        assert!(
            b.contains("<tr><th>site</th><td data-key=\"/meta/site\">&lt;b&gt;Q &amp; A&lt;/b&gt;</td></tr>"),
            "{b}"
        );
        assert!(b.contains(">a<br>b</td>"), "{b}");
        assert!(b.contains("<th>instrument last calibrated</th>"), "{b}");
        assert!(!b.contains("/meta/worker"), "{b}");
        // The order is the keys', not the document's.
        assert!(b.find("/meta/site").unwrap() < b.find("/meta/calibrated").unwrap());
        assert_eq!(block(&Doc::new(&json!({})), "/meta"), "");
    }
}
