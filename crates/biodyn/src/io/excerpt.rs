//! Quoting user content in error messages: short, on one line, printable.
//!
//! A message must never grow with the input (a 20 MB JSON string, a 100 000
//! deep array, a 300-digit number) and must never carry a control character
//! (a newline splits the line, an escape sequence reaches the terminal).

/// The most characters of user text an error quotes.
pub const MAX_QUOTE: usize = 60;

/// The most characters of a whole message built from a parser's words.
pub const MAX_MESSAGE: usize = 240;

/// `s` for an error message: control and bidi/zero-width characters escaped
/// (`\n`, `\u{1b}`), cut with "…" where the escaped text would pass `max`
/// characters (an escape counts as the characters it prints: 57 escape
/// characters are not 57 characters of message but 342).
pub fn excerpt(s: &str, max: usize) -> String {
    let mut out = String::new();
    let mut shown = 0usize;
    for c in s.chars() {
        let escaped = c.is_control() || is_invisible(c);
        let width = if escaped { c.escape_debug().count() } else { 1 };
        if shown.saturating_add(width) > max {
            out.push('…');
            return out;
        }
        shown += width;
        if escaped {
            out.extend(c.escape_debug());
        } else {
            out.push(c);
        }
    }
    out
}

/// A name or short value quoted with [`MAX_QUOTE`].
pub fn quote(s: &str) -> String {
    excerpt(s, MAX_QUOTE)
}

/// The most characters a short quote takes, "…" included (a setting's
/// text, a `NAME=VALUE` argument, an unknown case name).
pub const SHORT_QUOTE: usize = 40;

/// `s` quoted in at most `SHORT_QUOTE` (40) characters, "…" included, control
/// characters escaped: an error names what was typed, it does not echo a
/// whole file back.
pub fn short_quote(s: &str) -> String {
    let whole = excerpt(s, SHORT_QUOTE);
    if whole.ends_with('…') {
        excerpt(s, SHORT_QUOTE - 1)
    } else {
        whole
    }
}

/// A number for a message: shortest round-trip form while it is short,
/// scientific beyond (1e300, not 301 digits).
pub struct Short(pub f64);

impl std::fmt::Display for Short {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let v = self.0;
        let a = v.abs();
        if a.is_finite() && a != 0.0 && !(1e-6..1e16).contains(&a) {
            write!(f, "{v:e}")
        } else {
            write!(f, "{v}")
        }
    }
}

/// Characters that are not control codes but still hide or reorder text on
/// a terminal: zero-width marks, bidi embeddings and isolates, the BOM.
pub fn is_invisible(c: char) -> bool {
    matches!(c,
        '\u{200B}'..='\u{200F}' | '\u{202A}'..='\u{202E}' | '\u{2060}'..='\u{2069}' | '\u{FEFF}')
}

/// A number in short form, still exact: the shorter of Rust's shortest
/// round trip (`0.075`, `54000`) and its scientific form (`1e7`, `4.02e6`,
/// `1e-300`), the plain one on a tie.
pub fn num(v: f64) -> String {
    let plain = format!("{v}");
    let sci = format!("{v:e}");
    if sci.len() < plain.len() { sci } else { plain }
}

/// 1-based line and column of a byte offset.
pub(crate) fn line_col(text: &str, offset: usize) -> (usize, usize) {
    let offset = offset.min(text.len());
    let before = &text[..offset];
    let line = before.matches('\n').count() + 1;
    // Columns count characters, as an editor shows them, not bytes.
    let line_start = before.rfind('\n').map_or(0, |p| p + 1);
    let col = before[line_start..].chars().count() + 1;
    (line, col)
}

/// Where a file parser's error sits and what it says: the 1-based line and
/// column of byte offset `at` (1, 1 without one), the message made safe
/// ([`message`]) and the offending line quoted after it, so the user sees
/// what was written.
pub(crate) fn located(text: &str, at: Option<usize>, raw: &str) -> (usize, usize, String) {
    let (line, col) = at.map_or((1, 1), |o| line_col(text, o));
    let source_line = text.lines().nth(line - 1).unwrap_or("").trim();
    let mut m = message(raw.trim());
    if !source_line.is_empty() {
        m = format!("{m} (in `{}`)", excerpt(source_line, MAX_QUOTE));
    }
    (line, col, m)
}

/// A parser's message made safe to print: one line, every run of more than
/// 20 digits (serde prints 1e300 in full) in short form, control characters
/// escaped, at most [`MAX_MESSAGE`] characters.
pub fn message(raw: &str) -> String {
    let one_line: String = raw
        .chars()
        .map(|c| if c == '\n' || c == '\r' { ' ' } else { c })
        .collect();
    excerpt(&shorten_numbers(&one_line), MAX_MESSAGE)
}

/// Rewrites each long decimal number in `s` (more than 20 digits) in short form.
fn shorten_numbers(s: &str) -> String {
    let b = s.as_bytes();
    let mut out = String::with_capacity(s.len().min(4096));
    let mut i = 0;
    while i < b.len() {
        if b[i].is_ascii_digit() {
            let start = i;
            while i < b.len() && (b[i].is_ascii_digit() || b[i] == b'.') {
                i += 1;
            }
            // Only ASCII was consumed, so these are char boundaries.
            let run = &s[start..i];
            let digits = run.bytes().filter(u8::is_ascii_digit).count();
            match run.trim_end_matches('.').parse::<f64>() {
                Ok(v) if digits > 20 => out.push_str(&num(v)),
                _ => out.push_str(run),
            }
        } else {
            // Copy one whole character.
            let len = s[i..].chars().next().map_or(1, char::len_utf8);
            out.push_str(&s[i..i + len]);
            i += len;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn excerpt_cuts_and_escapes() {
        assert_eq!(excerpt("head", 10), "head");
        assert_eq!(excerpt("head\nneck", 20), "head\\nneck");
        assert_eq!(excerpt("a\u{1b}[31m", 20), "a\\u{1b}[31m");
        assert_eq!(excerpt("abcdef", 3), "abc…");
        assert_eq!(excerpt("éééé", 2), "éé…");
        assert_eq!(excerpt("x\u{202e}y", 10), "x\\u{202e}y");
        // The limit is on what is printed: escapes count as their width.
        assert_eq!(excerpt("x\u{202e}y", 9), "x\\u{202e}…");
        assert!(quote(&"x".repeat(1_000_000)).chars().count() <= MAX_QUOTE + 1);
        assert!(quote(&"\u{1b}".repeat(1000)).chars().count() <= MAX_QUOTE + 1);
        assert!(short_quote(&"\u{1b}".repeat(30)).chars().count() <= SHORT_QUOTE);
    }

    #[test]
    fn short_quotes_fit_and_escape() {
        assert_eq!(short_quote(&"é".repeat(100)).chars().count(), SHORT_QUOTE);
        assert_eq!(short_quote(&"x".repeat(40)), "x".repeat(40));
        assert_eq!(short_quote("a\nb"), "a\\nb");
        assert_eq!(Short(1e300).to_string(), "1e300");
        assert_eq!(Short(-1e-300).to_string(), "-1e-300");
        assert_eq!(Short(54000.0).to_string(), "54000");
        assert_eq!(Short(0.0).to_string(), "0");
    }

    #[test]
    fn numbers_are_short() {
        assert_eq!(num(1e300), "1e300");
        assert_eq!(num(1e-300), "1e-300");
        assert_eq!(num(4_020_000.0), "4.02e6");
        assert_eq!(num(1e7), "1e7");
        assert_eq!(num(54_000.0), "54000");
        assert_eq!(num(75.0), "75");
        assert_eq!(num(0.001), "1e-3");
        assert_eq!(num(-1.5), "-1.5");
        assert_eq!(num(0.075), "0.075");
        assert_eq!(num(f64::NAN), "NaN");
    }

    #[test]
    fn messages_are_one_bounded_line_with_short_numbers() {
        let long = format!(
            "invalid value: floating point `1{}.0`, expected x",
            "0".repeat(300)
        );
        assert_eq!(
            message(&long),
            "invalid value: floating point `1e300`, expected x"
        );
        assert_eq!(message("a\nb 12.5 line 3"), "a b 12.5 line 3");
        let m = message(&"[".repeat(200_000));
        assert!(m.chars().count() <= MAX_MESSAGE + 1, "{}", m.len());
        assert_eq!(message("é1234"), "é1234");
    }
}
