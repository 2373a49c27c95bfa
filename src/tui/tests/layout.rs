//! The layout check every snapshot passes (`screen` and `frame` in this
//! folder's `mod.rs` run it on each frame they draw). Four rules:
//!
//! - (a) labels: no axis title covers a cell its chart plotted (a curve, the
//!   cursor, a peak mark), by the chart's own record of both (`view::probe`);
//! - (b) units: no line of a box ends in a number whose unit starts the
//!   box's next line;
//! - (c) room: no line of a box is clipped at its right edge ("…" in its last
//!   cell) while the box's bottom rows are blank;
//! - (d) dialogs: every cell of a dialog's claimed rectangle is drawn by the
//!   dialog, none left from the layer below (`view::probe::dialog`).
//!
//! A "box" is a bordered block found in the buffer: a `┌` (or `+`) whose
//! left side runs down to a `└`, whose bottom runs right to a `┘`, whose
//! right side runs back up to a `┐`.

use crate::view::probe::{Marks, UNDRAWN};
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;

/// One broken rule: which, where, and what is there.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Fault {
    pub rule: char,
    pub at: (u16, u16),
    pub what: String,
}

impl std::fmt::Display for Fault {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let name = match self.rule {
            'a' => "a label over plotted cells",
            'b' => "a number split from its unit",
            'c' => "clipped while rows are free",
            _ => "a dialog with the layer below showing through",
        };
        write!(
            f,
            "({}) {name} at column {}, row {}: {}",
            self.rule, self.at.0, self.at.1, self.what
        )
    }
}

/// Units a number may be followed by on screen.
const UNITS: &[&str] = &[
    "%", "Hz", "kg", "g", "s", "ms", "h", "min", "m", "mm", "m/s", "m/s²", "m/s^2", "m/s^1.75",
    "m/s^1.5", "mm/s²", "N", "N/m", "N·s/m", "N.s/m", "°", "deg", "rad", "rad/s", "/s", "dB",
    "MPa", "kPa",
];

/// Every rule over `buf` and what the frame recorded; cells a dialog left
/// undrawn are put back from the layer below (the screen as a terminal
/// shows it), so the text of a failing frame reads as the user sees it.
pub fn check(buf: &mut Buffer, marks: &Marks) -> Vec<Fault> {
    let mut out = labels(marks);
    out.extend(dialogs(buf, marks));
    let boxes = boxes(buf);
    out.extend(units(buf, &boxes));
    out.extend(room(buf, &boxes));
    out
}

fn sym(buf: &Buffer, x: u16, y: u16) -> &str {
    buf.cell((x, y)).map_or("", |c| c.symbol())
}

/// (a): the titles' cells against the plotted cells, chart by chart.
pub fn labels(marks: &Marks) -> Vec<Fault> {
    let mut out = Vec::new();
    for c in &marks.charts {
        for r in &c.labels {
            for y in r.top()..r.bottom() {
                for x in r.left()..r.right() {
                    if c.plotted.contains(&(x, y)) {
                        out.push(Fault {
                            rule: 'a',
                            at: (x, y),
                            what: format!(
                                "an axis title over a plotted cell of the plot {:?}",
                                c.plot
                            ),
                        });
                    }
                }
            }
        }
    }
    out
}

/// (d): a dialog's cells still holding `UNDRAWN`; each is put back.
pub fn dialogs(buf: &mut Buffer, marks: &Marks) -> Vec<Fault> {
    let mut out = Vec::new();
    for d in marks.dialogs.iter().rev() {
        let mut below = d.below.iter();
        for y in d.rect.top()..d.rect.bottom() {
            for x in d.rect.left()..d.rect.right() {
                let was = below.next();
                let Some(cell) = buf.cell_mut((x, y)) else {
                    continue;
                };
                if cell.symbol() == UNDRAWN {
                    if let Some(was) = was {
                        *cell = was.clone();
                    }
                    out.push(Fault {
                        rule: 'd',
                        at: (x, y),
                        what: format!(
                            "'{}' of the layer below inside the dialog {:?}",
                            cell.symbol(),
                            d.rect
                        ),
                    });
                }
            }
        }
    }
    out
}

/// The bordered boxes in `buf` (their outer rectangles).
pub fn boxes(buf: &Buffer) -> Vec<Rect> {
    let a = buf.area;
    let is = |x: u16, y: u16, set: &[&str]| set.contains(&sym(buf, x, y));
    let (vert, horiz) = (["│", "|"], ["─", "-"]);
    let mut out = Vec::new();
    for y0 in a.top()..a.bottom() {
        for x0 in a.left()..a.right() {
            if !is(x0, y0, &["┌", "+"]) {
                continue;
            }
            let mut y1 = y0 + 1;
            while y1 < a.bottom() && is(x0, y1, &vert) {
                y1 += 1;
            }
            if y1 >= a.bottom() || y1 == y0 + 1 || !is(x0, y1, &["└", "+"]) {
                continue;
            }
            let mut x1 = x0 + 1;
            while x1 < a.right() && is(x1, y1, &horiz) {
                x1 += 1;
            }
            if x1 >= a.right() || x1 == x0 + 1 || !is(x1, y1, &["┘", "+"]) {
                continue;
            }
            if is(x1, y0, &["┐", "+"]) && (y0 + 1..y1).all(|y| is(x1, y, &vert)) {
                out.push(Rect::new(x0, y0, x1 - x0 + 1, y1 - y0 + 1));
            }
        }
    }
    out
}

/// The inner rows of box `b`, as text.
fn rows(buf: &Buffer, b: Rect) -> Vec<String> {
    (b.top() + 1..b.bottom() - 1)
        .map(|y| {
            (b.left() + 1..b.right() - 1)
                .map(|x| sym(buf, x, y))
                .collect()
        })
        .collect()
}

/// A number as it is printed: digits with a sign, a decimal point or an
/// exponent ("1.213", "-20", "1e-3").
fn is_number(t: &str) -> bool {
    let t = t.trim_start_matches(['(', '≈', '~', '<', '>', '=']);
    let t = t.strip_prefix(['-', '+', '−']).unwrap_or(t);
    t.starts_with(|c: char| c.is_ascii_digit())
        && t.ends_with(|c: char| c.is_ascii_digit())
        && t.chars()
            .all(|c| c.is_ascii_digit() || matches!(c, '.' | 'e' | 'E' | '-' | '+'))
}

/// (b): a box's line ending in a number and its next line starting with a unit.
pub fn units(buf: &Buffer, boxes: &[Rect]) -> Vec<Fault> {
    let mut out = Vec::new();
    for &b in boxes {
        let lines = rows(buf, b);
        for (i, w) in lines.windows(2).enumerate() {
            let Some(last) = w[0].split_whitespace().last() else {
                continue;
            };
            let Some(first) = w[1].split_whitespace().next() else {
                continue;
            };
            let unit = first.trim_end_matches([',', ';', ':', '.', ')']);
            // Rows that both start with a one-cell mark ("#", "%": ASCII
            // series glyphs) are a list, not a line and its wrap.
            let mark = |l: &str| {
                l.split_whitespace().next().is_some_and(|t| {
                    t.chars().count() == 1 && !t.chars().all(char::is_alphanumeric)
                })
            };
            if is_number(last) && UNITS.contains(&unit) && !(mark(&w[0]) && mark(&w[1])) {
                out.push(Fault {
                    rule: 'b',
                    at: (b.x + 1, b.y + 2 + i as u16),
                    what: format!("'{}' / '{}'", w[0].trim(), w[1].trim()),
                });
            }
        }
    }
    out
}

/// (c): a box's line with "…" in its last cell, above blank bottom rows.
pub fn room(buf: &Buffer, boxes: &[Rect]) -> Vec<Fault> {
    let mut out = Vec::new();
    for &b in boxes {
        let lines = rows(buf, b);
        let free = lines
            .iter()
            .rev()
            .take_while(|l| l.trim().is_empty())
            .count();
        if free == 0 {
            continue;
        }
        for (i, l) in lines.iter().enumerate().take(lines.len() - free) {
            if l.ends_with('…') {
                out.push(Fault {
                    rule: 'c',
                    at: (b.right() - 2, b.y + 1 + i as u16),
                    what: format!("'{}' with {free} blank rows below", l.trim()),
                });
            }
        }
    }
    out
}

mod tests {
    use super::*;
    use crate::view::probe::ChartMark;

    /// A buffer holding `lines`.
    fn screen(lines: &[&str]) -> Buffer {
        let w = lines.iter().map(|l| l.chars().count()).max().unwrap_or(0) as u16;
        let mut buf = Buffer::empty(Rect::new(0, 0, w, lines.len() as u16));
        for (y, l) in lines.iter().enumerate() {
            for (x, ch) in l.chars().enumerate() {
                buf[(x as u16, y as u16)].set_char(ch);
            }
        }
        buf
    }

    fn rules(buf: &mut Buffer, marks: &Marks) -> Vec<char> {
        check(buf, marks).iter().map(|f| f.rule).collect()
    }

    #[test]
    fn boxes_are_found_with_titles_on_their_top_and_nested() {
        let buf = screen(&[
            "┌ run ───┐ ┌─┐",
            "│a ┌──┐  │ │x│",
            "│  │  │  │ └─┘",
            "│  └──┘  │    ",
            "└────────┘    ",
            "+-a-+  ┌──    ",
            "|   |  │      ",
            "+---+  └──┘   ",
        ]);
        let b = boxes(&buf);
        assert!(b.contains(&Rect::new(0, 0, 10, 5)), "{b:?}");
        assert!(b.contains(&Rect::new(3, 1, 4, 3)), "{b:?}");
        assert!(b.contains(&Rect::new(11, 0, 3, 3)), "{b:?}");
        assert!(b.contains(&Rect::new(0, 5, 5, 3)), "{b:?}");
        assert_eq!(b.len(), 4, "{b:?}");
    }

    #[test]
    fn a_title_over_a_plotted_cell_fails_and_beside_it_passes() {
        let plot = Rect::new(2, 1, 10, 4);
        let over = Marks {
            charts: vec![ChartMark {
                plot,
                plotted: vec![(8, 4), (9, 4)],
                labels: vec![Rect::new(7, 4, 4, 1)],
            }],
            dialogs: vec![],
        };
        let mut buf = screen(&["            "; 6]);
        assert_eq!(rules(&mut buf, &over), ['a', 'a']);
        let beside = Marks {
            charts: vec![ChartMark {
                plot,
                plotted: vec![(8, 4), (9, 4)],
                labels: vec![Rect::new(7, 3, 4, 1)],
            }],
            dialogs: vec![],
        };
        assert!(rules(&mut buf, &beside).is_empty());
    }

    #[test]
    fn a_number_split_from_its_unit_fails_and_a_whole_one_passes() {
        let split = [
            "┌ run ──────────────┐",
            "│paper: MPRE 1.213  │",
            "│%, RMS 0.0015      │",
            "└───────────────────┘",
        ];
        assert_eq!(rules(&mut screen(&split), &Marks::default()), ['b']);
        let whole = [
            "┌ run ──────────────┐",
            "│paper: MPRE        │",
            "│1.213 %, RMS 0.0015│",
            "└───────────────────┘",
        ];
        assert!(rules(&mut screen(&whole), &Marks::default()).is_empty());
        // ASCII series marks starting two rows: a list, fine.
        let marks = [
            "┌────────────────┐",
            "│# 70 kg    89.34│",
            "│% 75 kg    97.63│",
            "└────────────────┘",
        ];
        assert!(rules(&mut screen(&marks), &Marks::default()).is_empty());
        // A number and a word that is no unit: fine.
        let word = [
            "┌───────────┐",
            "│epoch 45931│",
            "│stopped    │",
            "└───────────┘",
        ];
        assert!(rules(&mut screen(&word), &Marks::default()).is_empty());
        for unit in ["Hz", "kg", "m/s²", "N/m", "s"] {
            let l2 = format!("│{unit:<11}│");
            let s = [
                "┌───────────┐",
                "│f at 4.56  │",
                l2.as_str(),
                "└───────────┘",
            ];
            assert_eq!(rules(&mut screen(&s), &Marks::default()), ['b'], "{unit}");
        }
    }

    #[test]
    fn a_line_clipped_above_blank_rows_fails_and_a_full_box_passes() {
        let clipped = [
            "┌ model ──────────┐",
            "│about: Boileau &…│",
            "│                 │",
            "└─────────────────┘",
        ];
        assert_eq!(rules(&mut screen(&clipped), &Marks::default()), ['c']);
        let full = [
            "┌ model ──────────┐",
            "│about: Boileau &…│",
            "│m1 head-neck     │",
            "└─────────────────┘",
        ];
        assert!(rules(&mut screen(&full), &Marks::default()).is_empty());
        let wrapped = [
            "┌ model ──────────┐",
            "│about: Boileau & │",
            "│Rakheja          │",
            "└─────────────────┘",
        ];
        assert!(rules(&mut screen(&wrapped), &Marks::default()).is_empty());
    }

    #[test]
    fn a_dialog_that_leaves_cells_undrawn_fails_and_they_are_put_back() {
        let mut buf = screen(&["0 5 10 15 20", "0 5 10 15 20", "0 5 10 15 20"]);
        let rect = Rect::new(0, 0, 12, 2);
        crate::view::probe::take();
        crate::view::probe::dialog(rect, &mut buf);
        // The dialog draws its first row only (no Clear).
        for x in 0..12 {
            buf[(x, 0)].set_char('#');
        }
        let marks = crate::view::probe::take();
        assert_eq!(marks.dialogs.len(), 1);
        let faults = check(&mut buf, &marks);
        assert_eq!(faults.len(), 12, "{faults:?}");
        assert!(faults.iter().all(|f| f.rule == 'd' && f.at.1 == 1));
        assert_eq!(crate::view::chart::buffer_text(&buf)[1], "0 5 10 15 20");
        // A dialog that clears its rectangle passes.
        let mut buf = screen(&["0 5 10 15 20"; 3]);
        crate::view::probe::dialog(rect, &mut buf);
        ratatui::widgets::Widget::render(ratatui::widgets::Clear, rect, &mut buf);
        let marks = crate::view::probe::take();
        assert!(check(&mut buf, &marks).is_empty());
    }
}
