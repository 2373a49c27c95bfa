//! The glyphs and colours of chart series, the cursor and the peaks, in
//! Unicode and in plain ASCII (one table each, so the chart and every
//! legend drawn outside it agree), and the ASCII transliteration of a
//! rendered area.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Color, Style};
use ratatui::symbols::Marker;

/// Colours of the series, in order; markers differ too (see `MARKERS`).
const COLORS: [Color; 6] = [
    Color::Cyan,
    Color::Yellow,
    Color::Magenta,
    Color::Green,
    Color::Red,
    Color::Blue,
];
/// Markers of the series, in order, so that NO_COLOR still tells eleven
/// series apart. No whole-cell block: it would hide the others.
const MARKERS: [Marker; 11] = [
    Marker::Braille,
    Marker::Dot,
    Marker::Quadrant,
    Marker::Custom('×'),
    Marker::Custom('○'),
    Marker::Custom('□'),
    Marker::Custom('△'),
    Marker::Custom('+'),
    Marker::Custom('▽'),
    Marker::Custom('◇'),
    Marker::Custom('∗'),
];
/// The same in plain ASCII; none is the cursor's `|` or the peaks' `^`.
const ASCII_MARKERS: [Marker; 11] = [
    Marker::Custom('*'),
    Marker::Custom('+'),
    Marker::Custom('o'),
    Marker::Custom('x'),
    Marker::Custom('#'),
    Marker::Custom('%'),
    Marker::Custom('@'),
    Marker::Custom('='),
    Marker::Custom('~'),
    Marker::Custom('&'),
    Marker::Custom('$'),
];
/// Peaks and the frequency cursor, (unicode, ascii).
pub(super) const PEAK: (char, char) = ('◆', '^');
pub(super) const CURSOR: (char, char) = ('│', '|');
/// A dimmed series (a compared model), (unicode, ascii): a light glyph
/// none of the markers, the cursor or the peaks use, so it reads as the
/// background curve also without colour.
pub(super) const DIM: (char, char) = ('·', '.');

/// The marker of a dimmed series.
pub(super) fn dim_marker(ascii: bool) -> Marker {
    Marker::Custom(if ascii { DIM.1 } else { DIM.0 })
}

/// The glyph of a dimmed series, for legends drawn outside the chart.
pub fn dim_glyph(ascii: bool) -> &'static str {
    if ascii { "." } else { "·" }
}

/// The colour of a dimmed series: dark grey (none when `mono`: the glyph
/// alone tells it apart, and a DIM attribute fades to nothing on some
/// terminals).
pub fn dim_style(mono: bool) -> Style {
    if mono {
        Style::default()
    } else {
        Style::default().fg(Color::DarkGray)
    }
}

pub(super) fn marker(i: usize, ascii: bool) -> Marker {
    if ascii {
        ASCII_MARKERS[i % ASCII_MARKERS.len()]
    } else {
        MARKERS[i % MARKERS.len()]
    }
}

/// Dots per cell (across, down) of a marker's grid in ratatui's Canvas.
pub(super) fn dots(m: Marker) -> (u16, u16) {
    match m {
        Marker::Braille | Marker::Octant => (2, 4),
        Marker::Quadrant => (2, 2),
        Marker::Sextant => (2, 3),
        Marker::HalfBlock => (1, 2),
        _ => (1, 1),
    }
}

/// The glyph series `i` is drawn with, for legends drawn outside the chart
/// (a short chart hides its own). The chart's own legend uses the same.
pub fn legend_glyph(i: usize, ascii: bool) -> &'static str {
    glyph_of(marker(i, ascii))
}

fn glyph_of(m: Marker) -> &'static str {
    match m {
        Marker::Braille => "⣿",
        Marker::Dot => "•",
        Marker::Quadrant => "▚",
        Marker::Block => "█",
        Marker::Bar => "▄",
        Marker::Custom(c) => {
            let all = MARKERS.iter().chain(ASCII_MARKERS.iter());
            for (k, mk) in all.enumerate() {
                if *mk == Marker::Custom(c) {
                    return CUSTOM_TEXT[k];
                }
            }
            "*"
        }
        _ => "*",
    }
}

/// Texts of `MARKERS` then `ASCII_MARKERS` (a `char` cannot lend a `&str`).
const CUSTOM_TEXT: [&str; 22] = [
    "⣿", "•", "▚", "×", "○", "□", "△", "+", "▽", "◇", "∗", "*", "+", "o", "x", "#", "%", "@", "=",
    "~", "&", "$",
];

/// The glyph of the peak marks, for legends drawn outside the chart.
pub fn peak_glyph(ascii: bool) -> &'static str {
    if ascii { "^" } else { "◆" }
}

/// The glyph of the frequency cursor.
pub fn cursor_glyph(ascii: bool) -> &'static str {
    if ascii { "|" } else { "│" }
}

/// The colour of series `i` (none when `mono`).
pub fn series_style(i: usize, mono: bool) -> Style {
    if mono {
        Style::default()
    } else {
        Style::default().fg(COLORS[i % COLORS.len()])
    }
}

/// Replaces every non-ASCII glyph in `area` by an ASCII look-alike: each
/// marker glyph maps to its own character, so series stay distinct.
pub fn asciify(area: Rect, buf: &mut Buffer) {
    for y in area.top()..area.bottom() {
        for x in area.left()..area.right() {
            let Some(cell) = buf.cell_mut((x, y)) else {
                continue;
            };
            let sym = cell.symbol();
            if sym.is_ascii() {
                continue;
            }
            let c = sym.chars().next().unwrap_or(' ');
            let rep = match c {
                '•' | '∗' => "*",
                '◆' => "^",
                '×' => "x",
                '○' => "o",
                '□' => "#",
                '△' => "A",
                '▽' => "V",
                '◇' => "<",
                '█' => "#",
                '▄' | '▀' => "o",
                '─' | '━' | '═' | '—' | '–' | '−' => "-",
                'Δ' => "d",
                '│' | '┃' | '║' => "|",
                '┌' | '┐' | '└' | '┘' | '├' | '┤' | '┬' | '┴' | '┼' | '╭' | '╮' | '╯' | '╰' => {
                    "+"
                }
                '\u{2800}' => " ",
                '\u{2801}'..='\u{28FF}' => ".",
                '▖' | '▗' | '▘' | '▝' | '▙' | '▚' | '▛' | '▜' | '▞' | '▟' | '▌' | '▐' => {
                    "+"
                }
                '·' => ".",
                '◀' | '←' | '∠' | '≤' => "<",
                '▶' | '→' | '≥' => ">",
                '↑' => "^",
                '↓' => "v",
                '…' => "~",
                '°' => "o",
                'ζ' => "z",
                '§' => "S",
                'µ' => "u",
                '²' => "2",
                '›' => ">",
                '÷' => "/",
                'λ' => "l",
                _ => "?",
            };
            cell.set_symbol(rep);
        }
    }
}
