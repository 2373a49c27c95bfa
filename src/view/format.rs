//! Number and label formatting for eyes, shared by both fronts: tables round;
//! files and edit fields keep every digit.

/// Past these magnitudes plain digits stop being readable (`1000000000000`,
/// `0.00000015`): `num` switches to scientific form, `1e12`, `1.5e-7`.
pub const PLAIN_BELOW: f64 = 1e7;
pub const PLAIN_FROM: f64 = 1e-4;

/// `v` with `sig` significant digits, trailing zeros trimmed; thousands
/// stay whole (310000, not 3.1e5) because that is how Table 1 reads. From
/// 1e7 up and below 1e-4, scientific: `1e12`, `1.5e-7` (so `1e30 kg` is not
/// 31 digits long).
pub fn num(v: f64, sig: usize) -> String {
    if !v.is_finite() {
        return format!("{v}");
    }
    let a = v.abs();
    if a != 0.0 && !(PLAIN_FROM..PLAIN_BELOW).contains(&a) {
        return sci(v, sig);
    }
    plain(v, sig)
}

/// A value the user typed, as typed for ordinary magnitudes (`8`, `0.25`,
/// `54000`), in short scientific form past them (`1e-300`, not 300 zeros:
/// Rust's `{}` never uses an exponent).
pub fn typed(v: f64) -> String {
    let a = v.abs();
    if v == 0.0 || !v.is_finite() || (PLAIN_FROM..PLAIN_BELOW).contains(&a) {
        format!("{v}")
    } else {
        format!("{v:e}")
    }
}

/// `v` in plain digits with `sig` significant digits (whole numbers keep
/// all their digits), trailing zeros trimmed.
fn plain(v: f64, sig: usize) -> String {
    if v == 0.0 {
        return "0".into();
    }
    let mag = v.abs().log10().floor() as i32;
    let decimals = (sig as i32 - 1 - mag).max(0) as usize;
    let s = format!("{v:.decimals$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// `v` in scientific form with `sig` significant digits, trailing zeros of
/// the mantissa trimmed: `1e12`, `1.5e-7`, `-2.06e3`.
pub fn sci(v: f64, sig: usize) -> String {
    if !v.is_finite() {
        return format!("{v}");
    }
    if v == 0.0 {
        return "0".into();
    }
    let p = sig.clamp(1, 17) - 1;
    let s = format!("{v:.p$e}");
    match s.split_once('e') {
        Some((m, e)) if m.contains('.') => {
            format!("{}e{e}", m.trim_end_matches('0').trim_end_matches('.'))
        }
        _ => s,
    }
}

/// `v` for a table column `width` characters wide: `num(v, sig)` when it
/// fits, else the form that keeps the most significant digits within the
/// width (fewer decimals, or scientific: 2064 in 3 columns is `2e3`).
/// Never cut: when not even one digit fits, the shortest form (`-2e-308`
/// is the longest of those, 7 characters).
pub fn fit(v: f64, sig: usize, width: usize) -> String {
    let first = num(v, sig);
    if first.chars().count() <= width || !v.is_finite() {
        return first;
    }
    let plain_ok = v == 0.0 || (PLAIN_FROM..PLAIN_BELOW).contains(&v.abs());
    for d in (1..=sig.max(1)).rev() {
        if plain_ok {
            let s = plain(v, d);
            if s.chars().count() <= width {
                return s;
            }
        }
        let s = sci(v, d);
        if s.chars().count() <= width {
            return s;
        }
    }
    sci(v, 1)
}

/// Unit of a function's magnitude for labels; STHT is a plain ratio.
pub fn unit(f: biodyn::Function) -> &'static str {
    f.unit_label()
}

/// A chart's y-axis title: `|STHT|`, `|DPMI| (N·s/m)`, or `STHT phase (deg)`.
pub fn axis_title(f: biodyn::Function, phase: bool) -> String {
    if phase {
        format!("{} phase (deg)", f.name())
    } else {
        match unit(f) {
            "" => format!("|{}|", f.name()),
            u => format!("|{}| ({u})", f.name()),
        }
    }
}

/// The exact value for an edit field: Rust's shortest round-trip form.
pub fn exact(v: f64) -> String {
    format!("{v}")
}

/// A model value for its edit field: 12 significant digits, so that
/// 0.402 × 75 reads 30.15, not 30.150000000000002; outside the plain range
/// (as `num`) scientific, so 1e-320 is `1e-320`, not 330 zeros. Committing
/// the pre-filled text unchanged leaves the exact value alone.
pub fn for_edit(v: f64) -> String {
    if !v.is_finite() {
        return format!("{v}");
    }
    if v == 0.0 || (PLAIN_FROM..PLAIN_BELOW).contains(&v.abs()) {
        return plain(v, 12);
    }
    // The shortest round-trip form when it is no longer than 12 digits
    // (`1e-320`, `1.05e30`), else 12 digits.
    let shortest = format!("{v:e}");
    let digits = shortest
        .split('e')
        .next()
        .map_or(0, |m| m.chars().filter(char::is_ascii_digit).count());
    if digits <= 12 { shortest } else { sci(v, 12) }
}

/// `s` cut to `w` characters, with an ellipsis when anything was cut.
pub fn clip(s: &str, w: usize) -> String {
    if s.chars().count() <= w {
        s.to_string()
    } else {
        let mut t: String = s.chars().take(w.saturating_sub(1)).collect();
        t.push('…');
        t
    }
}

/// `s` cut to `w` characters from the front, keeping its end after an
/// ellipsis: the file name of a long path matters most.
pub fn clip_start(s: &str, w: usize) -> String {
    let n = s.chars().count();
    if n <= w {
        s.to_string()
    } else if w < 2 {
        String::new()
    } else {
        let tail: String = s.chars().skip(n - (w - 1)).collect();
        format!("…{tail}")
    }
}

/// The space between a number and its unit: `wrap` (as ratatui) never
/// breaks a row there; a view that wraps with it shows a plain space in
/// its place once the rows are cut.
pub const NBSP: char = '\u{a0}';

/// The units a number is printed with: `glue_units` keeps each on the
/// number's row.
const UNITS: &[&str] = &[
    "%", "Hz", "kg", "g", "s", "ms", "h", "min", "m", "mm", "m/s", "m/s²", "m/s^2", "m/s^1.75",
    "m/s^1.5", "mm/s²", "N", "N/m", "N·s/m", "N.s/m", "°", "rad/s", "/s", "dB", "MPa",
];

/// A number as printed, alone or as a range or ratio: "1.213", "-20",
/// "0.5–20", "0.5/1.15".
fn numeric(word: &str) -> bool {
    word.ends_with(|c: char| c.is_ascii_digit())
        && word.starts_with(|c: char| c.is_ascii_digit() || matches!(c, '-' | '−' | '+' | '('))
        && word.chars().all(|c| {
            c.is_ascii_digit() || matches!(c, '.' | '-' | '–' | '−' | '+' | '/' | 'e' | '(')
        })
}

/// `text` with the space between a number and the unit after it made
/// `NBSP`, so a wrap keeps "1.213 %" on one row.
pub fn glue_units(text: &str) -> String {
    let words: Vec<&str> = text.split(' ').collect();
    let mut out = String::with_capacity(text.len());
    for (i, w) in words.iter().enumerate() {
        out.push_str(w);
        if let Some(next) = words.get(i + 1) {
            let unit = next.trim_end_matches([',', ';', ':', '.', ')']);
            out.push(if numeric(w) && UNITS.contains(&unit) {
                NBSP
            } else {
                ' '
            });
        }
    }
    out
}

/// `text` word-wrapped to `width` columns the way ratatui's
/// `Paragraph::wrap(Wrap { trim })` draws it, one string per screen row:
/// rows break after the last word that fits, a word wider than a row is
/// broken inside, `trim` drops the spaces that start a wrapped row. Every
/// row count and pre-wrapped list in the TUI comes from here, so a popup's
/// height is the height its paragraph takes (a test renders both).
pub fn wrap(text: &str, width: usize, trim: bool) -> Vec<String> {
    let mut out = Vec::new();
    if width == 0 {
        return out;
    }
    for line in text.split('\n') {
        wrap_line(
            line.strip_suffix('\r').unwrap_or(line),
            width,
            trim,
            &mut out,
        );
    }
    out
}

/// Rows `text` takes in `width` columns (`wrap`'s length).
pub fn wrapped_rows(text: &str, width: usize, trim: bool) -> usize {
    wrap(text, width, trim).len()
}

/// The cells a character takes on a terminal, as ratatui counts them.
fn cell_width(c: char) -> usize {
    use ratatui::buffer::CellWidth;
    let mut b = [0u8; 4];
    usize::from(c.encode_utf8(&mut b).cell_width())
}

/// ratatui's `WordWrapper::process_input` (0.30) for one line of text,
/// over characters (not graphemes): words and the whitespace before them are held back
/// until the next word starts or the row is full.
fn wrap_line(line: &str, max: usize, trim: bool, out: &mut Vec<String>) {
    use std::collections::VecDeque;
    let start = out.len();
    let mut pending = String::new();
    let mut word = String::new();
    let mut space: VecDeque<(char, usize)> = VecDeque::new();
    let (mut line_w, mut word_w, mut space_w) = (0usize, 0usize, 0usize);
    let mut after_word = false;
    // Control characters are not drawn (ratatui drops them).
    for c in line.chars().filter(|c| !c.is_control()) {
        let blank = c == '\u{200B}' || (c.is_whitespace() && c != '\u{00A0}');
        let w = cell_width(c);
        if w > max {
            continue;
        }
        let first = pending.is_empty();
        let overflow = first
            && if trim {
                word_w + w > max || space_w + w > max
            } else {
                word_w + space_w + w > max
            };
        if (after_word && blank) || overflow {
            if !first || !trim {
                pending.extend(space.drain(..).map(|(c, _)| c));
                line_w += space_w;
            }
            pending.push_str(&std::mem::take(&mut word));
            line_w += word_w;
            space.clear();
            (space_w, word_w) = (0, 0);
        }
        if line_w >= max || (w > 0 && line_w + space_w + word_w >= max) {
            let mut room = max.saturating_sub(line_w);
            out.push(std::mem::take(&mut pending));
            line_w = 0;
            while let Some(&(_, sw)) = space.front() {
                if sw > room {
                    break;
                }
                space_w -= sw;
                room -= sw;
                space.pop_front();
            }
            if blank && space.is_empty() {
                continue;
            }
        }
        if blank {
            space_w += w;
            space.push_back((c, w));
        } else {
            word_w += w;
            word.push(c);
        }
        after_word = !blank;
    }
    if pending.is_empty() && word.is_empty() && !space.is_empty() && trim {
        out.push(String::new());
    }
    if !pending.is_empty() || !trim {
        pending.extend(space.drain(..).map(|(c, _)| c));
    }
    pending.push_str(&word);
    if !pending.is_empty() {
        out.push(pending);
    }
    if out.len() == start {
        out.push(String::new());
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounding_for_tables() {
        assert_eq!(num(5.625, 4), "5.625");
        assert_eq!(num(310_000.0, 4), "310000");
        assert_eq!(num(0.123456, 3), "0.123");
        assert_eq!(num(30.15, 3), "30.1");
        assert_eq!(num(0.0, 3), "0");
        assert_eq!(exact(0.1 + 0.2), "0.30000000000000004");
        assert_eq!(for_edit(0.402 * 75.0), "30.15");
        assert_eq!(for_edit(310_000.0), "310000");
        assert_eq!(for_edit(1.5e-7), "1.5e-7");
        assert_eq!(for_edit(1e-320), "1e-320");
        assert_eq!(for_edit(1e30), "1e30");
        assert_eq!(for_edit(1e30 * 1.05), "1.05e30");
        assert_eq!(for_edit(1e30 / 3.0), "3.33333333333e29");
        assert_eq!(for_edit(75.0 / 1.05), "71.4285714286");
    }

    #[test]
    fn extreme_values_use_scientific_form() {
        assert_eq!(num(1e12, 4), "1e12");
        assert_eq!(num(1e15, 6), "1e15");
        assert_eq!(num(1e30, 4), "1e30");
        assert_eq!(num(1.5e-7, 3), "1.5e-7");
        assert_eq!(num(-2.5e9, 4), "-2.5e9");
        assert_eq!(num(1.23456e8, 3), "1.23e8");
        // Ordinary values as before: the edges of the plain range.
        assert_eq!(num(9_999_999.0, 4), "9999999");
        assert_eq!(num(1e7, 4), "1e7");
        assert_eq!(num(0.0001, 3), "0.0001");
        assert_eq!(num(0.00009, 3), "9e-5");
        assert_eq!(num(f64::INFINITY, 3), "inf");
        assert_eq!(sci(9.9999, 2), "1e1");
        assert_eq!(sci(0.0, 2), "0");
    }

    #[test]
    fn fit_stays_within_the_width_and_never_cuts() {
        assert_eq!(fit(2064.0, 4, 4), "2064");
        assert_eq!(fit(2064.0, 4, 3), "2e3");
        assert_eq!(fit(2064.0, 4, 5), "2064");
        assert_eq!(fit(1e12, 6, 12), "1e12");
        assert_eq!(fit(0.000123, 3, 6), "1.2e-4");
        assert_eq!(fit(30.1536, 6, 5), "30.15");
        assert_eq!(fit(123456.0, 4, 5), "1.2e5");
        // Too narrow for anything: the shortest form, whole.
        assert_eq!(fit(-1.5e-300, 3, 2), "-2e-300");
        // Every value within 7 columns, and each one reads back close.
        let mut v = 1.234_567e-300_f64;
        while v < 1e300 {
            for x in [v, -v] {
                for w in 7..12 {
                    let s = fit(x, 6, w);
                    assert!(s.chars().count() <= w, "{x} in {w}: {s}");
                    let back: f64 = s.parse().unwrap();
                    // At worst one significant digit: within half a unit of it.
                    assert!(((back - x) / x).abs() <= 0.5, "{x} in {w}: {s}");
                }
            }
            v *= 37.7;
        }
    }

    #[test]
    fn words_wrap_within_the_width() {
        let l = wrap("aaa bbb ccc dddddddddddddddddd e", 8, true);
        assert!(l.iter().all(|x| x.chars().count() <= 8), "{l:?}");
        assert_eq!(l.join(" ").replace(' ', ""), "aaabbbcccdddddddddddddddddde");
    }

    #[test]
    fn a_number_is_glued_to_its_unit_and_to_nothing_else() {
        let g = |t: &str| glue_units(t).replace(NBSP, "_");
        assert_eq!(g("MPRE 1.213 %, RMS 0.0015"), "MPRE 1.213_%, RMS 0.0015");
        assert_eq!(g("shares x 75 kg body mass"), "shares x 75_kg body mass");
        assert_eq!(
            g("0.5–20 Hz, A(8) 0.5/1.15 m/s², 1e9 N/m)"),
            "0.5–20_Hz, A(8) 0.5/1.15_m/s², 1e9_N/m)"
        );
        assert_eq!(
            g("MSDV 32.14 m/s^1.5 over 8 h, about"),
            "MSDV 32.14_m/s^1.5 over 8_h, about"
        );
        assert_eq!(g("! 3 warnings: s shows"), "! 3 warnings: s shows");
        assert_eq!(g("seed 1 · 8 starts"), "seed 1 · 8 starts");
        // Wrapped, "1.213 %" stays on one row.
        let rows = wrap(
            &glue_units("paper: 45931 epochs, MPRE 1.213 %, RMS 0.0015"),
            31,
            true,
        );
        assert_eq!(
            rows[1].replace(NBSP, " "),
            "1.213 %, RMS 0.0015",
            "{rows:?}"
        );
    }

    /// `wrap` against what ratatui draws: each string rendered by a
    /// wrapping `Paragraph` on a TestBackend, row by row.
    #[test]
    fn wrap_is_what_a_wrapping_paragraph_draws() {
        use ratatui::Terminal;
        use ratatui::backend::TestBackend;
        use ratatui::text::Line;
        use ratatui::widgets::{Paragraph, Wrap};
        let texts = [
            "",
            " ",
            "   ",
            "a",
            "one two three four five six seven eight nine ten",
            "exactly ten",
            "exactlyten",
            "exactlyten and more",
            "ten chars. ten chars. ten chars.",
            "double  spaces  between  words",
            "  leading spaces then words",
            "trailing spaces   ",
            "averyveryverylongwordthatneedsbreaking in the middle",
            "short averyveryverylongwordthatneedsbreaking end",
            "a b c d e f g h i j k l m n o p q r s t u v w x y z",
            "refused: k4 of link 'pelvis-to-torso' = -1 N/m: stiffness must be in [0, 1e9] N/m",
            "presets/a/very/long/path/to/some/preset/file/name.toml (built-in)",
            "m2 · 30.15 kg — the torso → head link ≤ 5 Hz",
            "word\u{00A0}with\u{00A0}no-break spaces that stay together",
            "first line\nsecond line that is longer than the width\n\nafter a blank",
            "x         y",
            "tab\tseparated\twords",
        ];
        for width in [1usize, 2, 3, 5, 8, 10, 11, 17, 30, 80] {
            for trim in [true, false] {
                for text in texts {
                    let ours = wrap(text, width, trim);
                    let h = u16::try_from(ours.len() + 2).unwrap_or(u16::MAX);
                    let w = u16::try_from(width).unwrap_or(u16::MAX);
                    // Each line of `text`, then a sentinel row: where it lands
                    // is the number of rows the text took.
                    let lines: Vec<Line> = text
                        .split('\n')
                        .map(Line::raw)
                        .chain([Line::raw("|")])
                        .collect();
                    let mut t = Terminal::new(TestBackend::new(w, h)).expect("backend");
                    t.draw(|f| {
                        // Cells the paragraph leaves alone stay '#', so a
                        // drawn trailing space shows.
                        let area = f.area();
                        for y in area.top()..area.bottom() {
                            f.buffer_mut().set_string(
                                0,
                                y,
                                "#".repeat(width),
                                ratatui::style::Style::default(),
                            );
                        }
                        f.render_widget(Paragraph::new(lines).wrap(Wrap { trim }), area)
                    })
                    .expect("draw");
                    let drawn = crate::view::chart::buffer_text(t.backend().buffer());
                    let mut want: Vec<String> = ours
                        .iter()
                        .map(|r| format!("{r:#<width$}").trim_end().to_string())
                        .collect();
                    want.push(format!("{:#<width$}", "|"));
                    assert_eq!(
                        drawn[..want.len()],
                        want[..],
                        "{text:?} at width {width}, trim {trim}"
                    );
                    assert_eq!(wrapped_rows(text, width, trim), ours.len());
                }
            }
        }
    }
}
