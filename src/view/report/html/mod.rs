//! The HTML report a hygienist hands over: one self-contained, printable
//! page per `assess` or `day` (`--report FILE.html`).
//!
//! Why it is built from the JSON document and not from the library's
//! structs: the page must say exactly what `--format json` says, and the
//! only way that cannot drift is to read the same `Value`. Every number on
//! the page is rounded for eyes, and also carried exactly in its element's
//! `data-value` (serde_json's shortest round-trip text, the JSON's own
//! digits) beside `data-key`, the RFC 6901 pointer to it in the JSON
//! document, so a test (or a reader's script) can check one against the
//! other.
//!
//! The page has no script and no external resource (an inline `<style>`,
//! fonts by generic family; figures are inline SVG), so it opens offline,
//! archives as one file, and prints on A4 as it looks (`style.rs`). It has
//! no date: the same command gives the same bytes.

pub mod assess;
pub mod day;
pub mod meta;
mod predicted;
mod style;

use super::table::fx;
use serde_json::Value;

/// `Doc::num`'s decimals for a value shown as typed (`8`, `0.25`, `31.5`):
/// hours, seconds, rates and band centres, which rounding would only pad.
pub const AS_TYPED: usize = usize::MAX;

/// `Doc::num`'s decimals for three significant digits: values spanning
/// decades (the bands), which fixed decimals would show as 0.0000.
pub const SIG3: usize = usize::MAX - 3;

/// `Doc::num`'s decimals for hours as people say them (`6 h 45 min`, as the
/// day's table and the command line print them): a page read beside the
/// terminal must not say 6.75 where the terminal says 6 h 45 min.
pub const HOURS: usize = usize::MAX - 4;

/// The program and its version, as the page's footer names them.
pub const PROGRAM: &str = concat!("biodyn ", env!("CARGO_PKG_VERSION"));

/// `s` safe in HTML text and in a double- or single-quoted attribute.
pub fn esc(s: &str) -> String {
    let mut o = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => o.push_str("&amp;"),
            '<' => o.push_str("&lt;"),
            '>' => o.push_str("&gt;"),
            '"' => o.push_str("&quot;"),
            '\'' => o.push_str("&#39;"),
            // ESC, BEL and the like from a file or column name: shown as
            // text (`\u{1b}`), as the terminal shows them, never raw.
            c if c.is_control() && c != '\n' && c != '\t' => {
                o.push_str(&format!("\\u{{{:x}}}", c as u32))
            }
            c => o.push(c),
        }
    }
    o
}

/// One JSON pointer segment (RFC 6901: `~` is `~0`, `/` is `~1`).
pub fn seg(s: &str) -> String {
    s.replace('~', "~0").replace('/', "~1")
}

/// Reads a JSON document for the page: numbers as tagged spans, strings
/// escaped.
pub struct Doc<'a> {
    pub root: &'a Value,
}

impl<'a> Doc<'a> {
    pub fn new(root: &'a Value) -> Self {
        Doc { root }
    }

    pub fn get(&self, key: &str) -> Option<&'a Value> {
        self.root.pointer(key).filter(|v| !v.is_null())
    }

    pub fn f(&self, key: &str) -> Option<f64> {
        self.get(key).and_then(Value::as_f64)
    }

    /// The number at `key` with `decimals` for eyes (an integer as it is),
    /// in a span carrying the exact value and its pointer; "–" when the
    /// document has none there.
    pub fn num(&self, key: &str, decimals: usize) -> String {
        match self.get(key) {
            Some(v @ Value::Number(n)) => {
                let shown = if n.is_f64() {
                    n.as_f64().map_or_else(String::new, |x| {
                        if decimals == AS_TYPED {
                            crate::view::format::typed(x)
                        } else if decimals == SIG3 {
                            crate::view::format::num(x, 3)
                        } else if decimals == HOURS {
                            biodyn::exposure::hours_text(x)
                        } else {
                            fx(x, decimals)
                        }
                    })
                } else {
                    n.to_string()
                };
                format!(
                    "<span class=\"n\" data-key=\"{}\" data-value=\"{}\">{}</span>",
                    esc(key),
                    esc(&v.to_string()),
                    esc(&shown)
                )
            }
            _ => "–".into(),
        }
    }

    /// The text at `key`, escaped ("" when there is none); a number as its
    /// JSON text.
    pub fn text(&self, key: &str) -> String {
        match self.get(key) {
            Some(Value::String(s)) => esc(s),
            Some(v) => esc(&v.to_string()),
            None => String::new(),
        }
    }

    /// The strings of the array at `key`.
    pub fn strings(&self, key: &str) -> Vec<String> {
        self.get(key)
            .and_then(Value::as_array)
            .map(|a| a.iter().filter_map(Value::as_str).map(esc).collect())
            .unwrap_or_default()
    }

    /// The length of the array at `key` (0 when it is not one).
    pub fn len(&self, key: &str) -> usize {
        self.get(key)
            .and_then(Value::as_array)
            .map_or(0, |a| a.len())
    }

    /// The object keys at `key`, in the document's order.
    pub fn keys(&self, key: &str) -> Vec<String> {
        self.get(key)
            .and_then(Value::as_object)
            .map(|o| o.keys().cloned().collect())
            .unwrap_or_default()
    }
}

/// A table: `head` cells (already HTML) and rows of cells (already HTML);
/// a cell that is a number is set right, and so is its column's title.
/// One weighted channel's metrics, as the JSON names them, their column
/// headings and decimals: the columns of the per-axis and per-segment tables.
pub const METRICS: [(&str, &str, usize); 7] = [
    ("aw_m_s2", "a_w m/s²", 3),
    ("peak_m_s2", "peak m/s²", 3),
    ("crest_factor", "crest", 2),
    ("mtvv_m_s2", "MTVV m/s²", 3),
    ("vdv_m_s175", "VDV m/s^1.75", 2),
    ("a8_m_s2", "A(8) m/s²", 3),
    ("vdv_exposure_m_s175", "VDV day m/s^1.75", 2),
];

/// The cells of `METRICS` under JSON pointer `at`.
pub fn metric_cells(d: &Doc, at: &str) -> Vec<String> {
    METRICS
        .iter()
        .map(|(key, _, dec)| d.num(&format!("{at}/{key}"), *dec))
        .collect()
}

/// `first` headings, then `METRICS`'.
pub fn metric_head<'a>(first: &[&'a str]) -> Vec<&'a str> {
    first
        .iter()
        .copied()
        .chain(METRICS.iter().map(|m| m.1))
        .collect()
}

pub fn table(class: &str, head: &[&str], rows: &[Vec<String>]) -> String {
    let mut s = format!("<table class=\"{class}\">\n<thead><tr>");
    for (i, h) in head.iter().enumerate() {
        // A column of numbers has its title over them, on the right.
        let numeric = rows
            .iter()
            .filter_map(|r| r.get(i))
            .find(|c| !c.is_empty())
            .is_some_and(|c| is_num(c));
        if numeric {
            s.push_str(&format!("<th class=\"num\">{h}</th>"));
        } else {
            s.push_str(&format!("<th>{h}</th>"));
        }
    }
    s.push_str("</tr></thead>\n<tbody>\n");
    for r in rows {
        s.push_str("<tr>");
        for c in r {
            if is_num(c) {
                s.push_str(&format!("<td class=\"num\">{c}</td>"));
            } else {
                s.push_str(&format!("<td>{c}</td>"));
            }
        }
        s.push_str("</tr>\n");
    }
    s.push_str("</tbody>\n</table>\n");
    s
}

/// Whether a cell is a number (set right): a number span, "–" or "never".
fn is_num(c: &str) -> bool {
    c.starts_with("<span class=\"n\"") || c == "–" || c == "never"
}

/// The EU 2002/44/EC verdict's words in a box whose class follows it
/// (colour as a second cue: the words say it).
pub fn verdict_class(words: &str) -> &'static str {
    if words.contains("limit") {
        "limit"
    } else if words.contains("above") {
        "action"
    } else {
        "below"
    }
}

/// What a verdict asks of the employer under Directive 2002/44/EC.
pub fn verdict_meaning(words: &str) -> &'static str {
    match verdict_class(words) {
        "limit" => {
            "The exposure limit value is exceeded: the Directive (Art. 5(3)) requires immediate action to bring the exposure below it, finding why it was exceeded and changing the protection and prevention measures so that it is not exceeded again."
        }
        "action" => {
            "The exposure action value is exceeded: the Directive (Art. 5(2)) requires a programme of technical and/or organisational measures to reduce the exposure to a minimum; the worker is entitled to health surveillance (Art. 7)."
        }
        _ => {
            "Below the exposure action value: the Directive requires no programme of measures for this exposure; the risk is still to be reduced to a minimum where it reasonably can be (Art. 5(1))."
        }
    }
}

/// The axis names in order, and their directions (ISO 2631-1 Figure 1).
const AXES: [(&str, &str); 3] = [("x", "fore-and-aft"), ("y", "lateral"), ("z", "vertical")];

/// "fore-and-aft" for "x" ("" for a name that is not an axis).
pub fn direction(axis: &str) -> &'static str {
    AXES.iter().find(|(a, _)| *a == axis).map_or("", |(_, d)| d)
}

/// One verdict box: what is judged, its value, the words, what they ask.
pub fn verdict_box(what: &str, value: &str, words: &str) -> String {
    format!(
        "<div class=\"verdict {}\">\n<div class=\"what\">{what}</div>\n<div class=\"value\">{value}</div>\n<div class=\"words\">{}</div>\n<p>{}</p>\n</div>\n",
        verdict_class(words),
        esc(words),
        verdict_meaning(words)
    )
}

/// The whole page: `<head>` with the inline style, the title, `body`
/// (sections, already HTML), the figures (nothing at all when there are
/// none), the standards cited and the program.
pub fn page(title: &str, subtitle: &str, body: &str, figures: &[String], cited: &[&str]) -> String {
    let mut s = String::with_capacity(body.len() + 8192);
    s.push_str("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n");
    s.push_str("<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n");
    s.push_str(&format!(
        "<meta name=\"generator\" content=\"{PROGRAM}\">\n"
    ));
    s.push_str(&format!("<title>{}</title>\n", esc(title)));
    s.push_str("<style>\n");
    s.push_str(style::CSS);
    s.push_str("</style>\n</head>\n<body>\n<main>\n");
    s.push_str(&format!(
        "<header>\n<h1>{}</h1>\n<p class=\"sub\">{subtitle}</p>\n</header>\n",
        esc(title)
    ));
    s.push_str(body);
    if !figures.is_empty() {
        s.push_str("<section class=\"figures\">\n<h2>Figures</h2>\n");
        for f in figures {
            s.push_str("<figure>\n");
            s.push_str(f);
            s.push_str("\n</figure>\n");
        }
        s.push_str("</section>\n");
    }
    s.push_str("<footer>\n<h2>Standards and program</h2>\n<ul>\n");
    for c in cited {
        s.push_str(&format!("<li>{c}</li>\n"));
    }
    s.push_str(&format!(
        "</ul>\n<p>Computed with {PROGRAM}. Every number on this page is the one <code>--format json</code> prints for the same command, rounded for reading; the exact value is in its <code>data-value</code> attribute.</p>\n</footer>\n"
    ));
    s.push_str("</main>\n</body>\n</html>\n");
    s
}

/// A `<section>` with its heading and content.
pub fn section(id: &str, title: &str, content: &str) -> String {
    format!("<section id=\"{id}\">\n<h2>{title}</h2>\n{content}</section>\n")
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn user_text_is_escaped_in_text_and_attributes() {
        assert_eq!(
            esc("<b>\"a\" & 'b'</b>"),
            "&lt;b&gt;&quot;a&quot; &amp; &#39;b&#39;&lt;/b&gt;"
        );
        assert_eq!(esc("a\u{1b}]0;T\u{7}b"), "a\\u{1b}]0;T\\u{7}b");
        let v = json!({"m": "<b>x</b>"});
        assert_eq!(Doc::new(&v).text("/m"), "&lt;b&gt;x&lt;/b&gt;");
    }

    #[test]
    fn a_number_carries_its_json_text_and_pointer() {
        let v = json!({"a": {"b/c": 0.1 + 0.2}, "n": 632});
        let d = Doc::new(&v);
        let key = format!("/a/{}", seg("b/c"));
        assert_eq!(
            d.num(&key, 3),
            "<span class=\"n\" data-key=\"/a/b~1c\" data-value=\"0.30000000000000004\">0.300</span>"
        );
        assert!(d.num("/n", 3).ends_with(">632</span>"));
        assert_eq!(d.num("/missing", 3), "–");
    }

    #[test]
    fn no_figures_no_heading() {
        let p = page("t", "s", "", &[], &[]);
        assert!(!p.contains("Figures"));
        let p = page("t", "s", "", &["<svg></svg>".into()], &[]);
        assert!(p.contains("<h2>Figures</h2>\n<figure>\n<svg></svg>"));
    }
}
