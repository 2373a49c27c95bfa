//! The Study tab's table: each variant's main peak per function (the
//! chart's legend, marker glyphs included) and the trends, in words.

use crate::tui::keys;
use crate::tui::theme::Theme;
use crate::tui::widgets::block;
use crate::view::chart;
use crate::view::trend::{self, sentence};
use crate::view::format::{clip, num, unit, wrap};
use biodyn::{Function, Response};
use biodyn::freq::{Study, Trend};
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget};

pub use crate::view::trend::comparable;

/// Why there are no trends (one value, or all the same), wrapped at
/// spaces to the table's inner width; empty when there is something to
/// compare.
pub fn nothing_to_compare(study: &Study, width: u16, framed: bool) -> Vec<String> {
    let Some(why) = trend::nothing_to_compare(study) else {
        return Vec::new();
    };
    let text =
        format!("{why}. Enter gives two or more different values, e.g. 65,75,85 or -40%,0%,+40%.");
    let inner = usize::from(width).saturating_sub(if framed { 2 } else { 0 });
    wrap(&text, inner.max(8), true)
}

/// The frequency cursor's columns of the legend.
pub struct Readout<'a> {
    pub f_hz: f64,
    /// The functions whose charts are shown: one column each.
    pub functions: Vec<Function>,
    /// Each variant's response at `f_hz` (`Cursor::at`).
    pub at: &'a [Option<Response>],
}

/// How the table is laid out.
pub struct Shape {
    /// The trends in sentences too (a tall tab).
    pub sentences: bool,
    /// The first variant row shown (the legend scrolls, ↑↓).
    pub top: usize,
    /// With its frame (a short tab drops it for two more rows).
    pub framed: bool,
}

/// One cursor column: "DPMI at 4.6 Hz, N·s/m" over each variant's
/// magnitude there. The first one's heading may reach left over the
/// names' column, whose heading it replaces.
struct CursorColumn {
    head: String,
    values: Vec<String>,
    width: usize,
}

/// The cursor's columns, the first `room` columns right of the names'
/// column start.
fn cursor_columns(r: &Readout, n: usize, room: usize) -> Vec<CursorColumn> {
    r.functions
        .iter()
        .enumerate()
        .map(|(k, &f)| {
            let head = match unit(f) {
                "" => format!("{} at {} Hz", f.name(), num(r.f_hz, 6)),
                u => format!("{} at {} Hz, {u}", f.name(), num(r.f_hz, 6)),
            };
            let values: Vec<String> = (0..n)
                .map(|i| match r.at.get(i).copied().flatten() {
                    Some(x) => num(x.mag(f), 4),
                    None => "-".into(),
                })
                .collect();
            let head_w = head.chars().count();
            let head_w = if k == 0 {
                head_w.saturating_sub(room)
            } else {
                head_w
            };
            let width = values
                .iter()
                .map(|v| v.chars().count())
                .chain([head_w, 6])
                .max()
                .unwrap_or(6);
            CursorColumn {
                head,
                values,
                width,
            }
        })
        .collect()
}

/// The columns of the table.
struct Widths {
    /// Below 100 columns "body mass = 65 kg" reads "65 kg".
    narrow: bool,
    /// "k4 B.V. -40% (54000)" reads "B.V. -40% (54000)" (only when the
    /// cursor's column would not fit beside the full names).
    bare: bool,
    /// The variants' glyph and name.
    label_w: usize,
    /// The trend rows' names: the name column and the cursor's columns.
    trend_w: usize,
    /// Each function's peak column.
    col_w: usize,
    /// The trend rows' names.
    names: [&'static str; 3],
    cursor: Vec<CursorColumn>,
}

impl Widths {
    /// The cursor's columns fit beside the peaks, whose columns must stay
    /// as wide as their headings ("STHT Hz, ratio").
    fn fit(&self, width: u16, framed: bool) -> bool {
        let inner = usize::from(width).saturating_sub(if framed { 2 } else { 0 });
        self.col_w >= 14 && self.trend_w + Function::ALL.len() * (self.col_w + 1) <= inner
    }
}

/// The widest layout in which the cursor's columns fit: the full names
/// and the first heading clear of the names' heading cell; else that
/// heading over the whole cell (framed: the scroll position is in the
/// frame's title); else the names without the parameter too.
fn widths(study: &Study, width: u16, framed: bool, readout: Option<&Readout>) -> Widths {
    let mut w = widths_with(study, width, framed, readout, (false, false));
    for squeeze in [(true, false), (true, true)] {
        if readout.is_none() || w.fit(width, framed) {
            break;
        }
        w = widths_with(study, width, framed, readout, squeeze);
    }
    w
}

/// `over`: the first cursor heading may reach over the names' heading
/// cell; `bare`: names without the parameter.
fn widths_with(
    study: &Study,
    width: u16,
    framed: bool,
    readout: Option<&Readout>,
    (over, bare): (bool, bool),
) -> Widths {
    // Below 100 columns "body mass = 65 kg" reads "65 kg": the heading
    // above names the parameter.
    let narrow = width < 100;
    let label_w = study
        .variants
        .iter()
        .map(|v| row_label(&v.label, &study.param_label, narrow, bare).chars().count())
        .max()
        .unwrap_or(10)
        .clamp(if narrow { 10 } else { 14 }, 26)
        + 2;
    let names = if width < 70 {
        ["  peak mag", "  peak f", "  up/down"]
    } else {
        ["  peak magnitude", "  peak frequency", "  band share up/down"]
    };
    let n = study.variants.len();
    // The first heading may take the names' heading cell but one column
    // (and the scroll position's, which only an unframed table has there:
    // see `render`).
    let keep = if framed && over { 1 } else { SCROLL_W + 1 };
    let cursor = readout.map_or(Vec::new(), |r| {
        cursor_columns(r, n, label_w.saturating_sub(keep))
    });
    let cursor_w: usize = cursor.iter().map(|c| c.width + 2).sum();
    // The trend rows' names share the first column with the variants, and
    // the cursor's columns, which they leave empty.
    let label_w = label_w.max((names[2].chars().count() + 1).saturating_sub(cursor_w));
    let trend_w = label_w + cursor_w;
    let inner = usize::from(width).saturating_sub(if framed { 2 } else { 0 });
    let nf = Function::ALL.len();
    let col_w = (inner.saturating_sub(trend_w) / nf)
        .saturating_sub(1)
        .clamp(12, 30);
    Widths {
        narrow,
        bare,
        label_w,
        trend_w,
        col_w,
        names,
        cursor,
    }
}

/// A variant's name in a row: below 100 columns (`narrow`) "65 kg" of
/// "body mass = 65 kg"; `bare`, "B.V. -40% (54000)" of "k4 B.V. -40%
/// (54000)". The header above names the parameter.
pub fn row_label<'a>(label: &'a str, param: &str, narrow: bool, bare: bool) -> &'a str {
    if let Some((_, v)) = label.split_once(" = ").filter(|_| narrow) {
        return v;
    }
    if !bare {
        return label;
    }
    label
        .strip_prefix(param)
        .and_then(|rest| rest.strip_prefix(' '))
        .filter(|rest| !rest.is_empty())
        .unwrap_or(label)
}

/// Room kept for the scroll position ("↑↓1–3/11") in the first heading.
const SCROLL_W: usize = 9;

/// Whether the cursor's columns fit in a table `width` wide beside the
/// peaks, whose columns must stay as wide as their headings ("STHT Hz,
/// ratio"); if not, the values at the cursor take a line of their own.
pub fn cursor_fits(study: &Study, width: u16, framed: bool, r: &Readout) -> bool {
    widths(study, width, framed, Some(r)).fit(width, framed)
}

/// The peak rows from variant `top` on, as many as fit (the legend
/// scrolls, ↑↓), each with its values at the cursor beside its name, then
/// the trends or why there are none.
pub fn render(
    study: &Study,
    area: Rect,
    buf: &mut Buffer,
    th: Theme,
    shape: Shape,
    readout: Option<Readout>,
) {
    let Shape {
        sentences,
        top,
        framed,
    } = shape;
    let compare = comparable(study);
    let n = study.variants.len();
    let Widths {
        narrow,
        bare,
        label_w,
        trend_w,
        col_w,
        names: [mag, freq, share],
        cursor,
    } = widths(study, area.width, framed, readout.as_ref());
    let label = |l: &str| row_label(l, &study.param_label, narrow, bare).to_string();
    let frame_rows = if framed { 2 } else { 0 };
    let nf = Function::ALL.len();
    let message = nothing_to_compare(study, area.width, framed);
    let below = if compare { 4 } else { message.len() } + if sentences && compare { 4 } else { 0 };
    let rows = (area.height as usize)
        .saturating_sub(1 + frame_rows + below)
        .max(1)
        .min(n);
    let top = top.min(n - rows.min(n));
    let scrolled = if rows < n {
        keys::arrows(&format!(" — {}–{}/{n} ↑↓", top + 1, top + rows), th.ascii)
    } else {
        String::new()
    };
    // Without a frame the scroll position goes in the first heading cell;
    // in ASCII the keys, spelt out, do not fit there (the hint bar names
    // them) and `^v` would read as keys.
    let first = if !framed && rows < n && th.ascii {
        format!("{}–{}/{n}", top + 1, top + rows)
    } else if !framed && rows < n {
        format!("↑↓{}–{}/{n}", top + 1, top + rows)
    } else {
        "peak".to_string()
    };
    let mut head = match cursor.first() {
        // The first cursor heading right-aligned over its column, reaching
        // left over the names' heading (the scroll position stays).
        Some(c) => {
            let lead = if first == "peak" { "" } else { first.as_str() };
            let lead = clip(lead, SCROLL_W);
            let seg = label_w + 2 + c.width - lead.chars().count();
            let room = if lead.is_empty() { seg } else { seg - 1 };
            vec![
                Span::styled(lead, th.heading()),
                Span::styled(format!("{:>seg$}", clip(&c.head, room)), th.key()),
            ]
        }
        None => vec![Span::styled(
            format!("{:<label_w$}", clip(&first, label_w)),
            th.heading(),
        )],
    };
    for c in cursor.iter().skip(1) {
        head.push(Span::styled(
            format!("  {:>w$}", c.head, w = c.width),
            th.key(),
        ));
    }
    for f in Function::ALL {
        let u = unit(f);
        let h = format!(
            "{} Hz, {}",
            f.name(),
            if u.is_empty() { "ratio" } else { u }
        );
        head.push(Span::styled(format!(" {h:>col_w$}"), th.heading()));
    }
    let mut lines = vec![Line::from(head)];
    for (i, v) in study.variants.iter().enumerate().skip(top).take(rows) {
        // The marker glyph makes this table the legend, also in NO_COLOR.
        let mut spans = vec![
            Span::styled(
                format!("{} ", chart::legend_glyph(i, th.ascii)),
                chart::series_style(i, th.mono),
            ),
            Span::raw(format!(
                "{:<w$}",
                clip(&label(&v.label), label_w - 2),
                w = label_w - 2
            )),
        ];
        for c in &cursor {
            let value = c.values.get(i).map_or("", |v| v.as_str());
            spans.push(Span::raw(format!("  {value:>w$}", w = c.width)));
        }
        for p in &v.peaks {
            let text = match p {
                Some(p) if p.at_edge => format!("edge {}", num(p.mag, 4)),
                Some(p) => format!("{} Hz {}", num(p.f_hz, 3), num(p.mag, 4)),
                None => "-".into(),
            };
            spans.push(Span::raw(format!(" {text:>col_w$}")));
        }
        lines.push(Line::from(spans));
    }
    if !compare {
        // Wrapped here, not by the paragraph: its trim would take the
        // right-aligned heading's leading spaces.
        lines.extend(message.into_iter().map(|m| Line::styled(m, th.error())));
        let p = Paragraph::new(lines);
        if framed {
            p.block(block(&format!("peaks{scrolled}"), th))
                .render(area, buf);
        } else {
            p.render(area, buf);
        }
        return;
    }
    let trends = study.trends();
    let rising = format!("as {} rises:", study.param_label);
    lines.push(Line::styled(
        clip(&rising, trend_w + nf * (col_w + 1)),
        th.heading(),
    ));
    let row = |label: &str, cell: &dyn Fn(&Trend) -> String| {
        let mut spans = vec![Span::raw(format!("{label:<trend_w$}"))];
        for t in &trends {
            spans.push(Span::raw(format!(" {:>col_w$}", cell(t))));
        }
        Line::from(spans)
    };
    lines.push(row(mag, &|t| t.peak_mag.word().to_string()));
    lines.push(row(freq, &|t| t.peak_f.word().to_string()));
    lines.push(row(share, &|t| {
        format!(
            "{}% / {}%",
            num(t.rises_share * 100.0, 2),
            num(t.falls_share * 100.0, 2)
        )
    }));
    if sentences {
        lines.push(Line::raw(""));
        for t in &trends {
            lines.push(Line::raw(sentence(&study.param_label, t)));
        }
    }
    let p = Paragraph::new(lines);
    if framed {
        p.block(block(&format!("main peaks and trends{scrolled}"), th))
            .render(area, buf);
    } else {
        p.render(area, buf);
    }
}
