//! Response charts drawn with ratatui's `Chart`, shared by the TUI tabs and
//! `biodyn plot` so that both look alike.
//!
//! ratatui's Chart has no log axis and no autoscale: the data are transformed
//! here (log10 on request), bounds are padded to round numbers so the axes do
//! not jump, and the tick labels are written in the original units. Each
//! series has its own marker as well as its own colour, so meaning never rides
//! on colour alone; `ascii` swaps every glyph for plain ASCII after rendering,
//! for fonts without braille or box drawing.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Color, Style};
use ratatui::symbols::Marker;
use ratatui::text::Span;
use ratatui::widgets::{Axis, Block, Chart, Dataset, GraphType, LegendPosition, Widget};

/// Colours of the series, in order; markers differ too (see `MARKERS`).
const COLORS: [Color; 6] = [
    Color::Cyan,
    Color::Yellow,
    Color::Magenta,
    Color::Green,
    Color::Red,
    Color::Blue,
];
/// Markers cycle with the series so that NO_COLOR still tells them apart.
/// Quadrant, not Bar, third: a Bar line fills whole cells and hides the others.
const MARKERS: [Marker; 4] = [
    Marker::Braille,
    Marker::Dot,
    Marker::Quadrant,
    Marker::Block,
];
/// In ASCII mode braille cannot be transliterated per series, so it is skipped.
const ASCII_MARKERS: [Marker; 3] = [Marker::Dot, Marker::Block, Marker::Bar];

/// The glyph series `i` is drawn with, for legends drawn outside the chart
/// (a short chart hides its own).
pub fn legend_glyph(i: usize, ascii: bool) -> &'static str {
    let m = if ascii {
        ASCII_MARKERS[i % ASCII_MARKERS.len()]
    } else {
        MARKERS[i % MARKERS.len()]
    };
    match (m, ascii) {
        (Marker::Dot, true) => "*",
        (Marker::Block, true) => "#",
        (Marker::Bar, true) => "o",
        (Marker::Braille, _) => "⣿",
        (Marker::Dot, _) => "•",
        (Marker::Quadrant, _) => "▚",
        (Marker::Block, _) => "█",
        (Marker::Bar, _) => "▄",
        _ => "*",
    }
}

/// The colour of series `i` (none when `mono`).
pub fn series_style(i: usize, mono: bool) -> Style {
    if mono {
        Style::default()
    } else {
        Style::default().fg(COLORS[i % COLORS.len()])
    }
}

/// One named curve.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    pub name: String,
    pub points: Vec<(f64, f64)>,
}

/// Everything about a chart except its data.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ChartOpts {
    pub title: String,
    pub x_title: String,
    pub y_title: String,
    pub log_x: bool,
    pub log_y: bool,
    /// Plain ASCII glyphs only.
    pub ascii: bool,
    /// No colours at all (NO_COLOR, or plain text output).
    pub mono: bool,
    /// A vertical line at this x (the frequency cursor).
    pub cursor_x: Option<f64>,
    /// Points to mark (peaks), drawn as a separate series named "peak".
    pub marks: Vec<(f64, f64)>,
    /// Fixed y range in data units; None autoscales with padding.
    pub y_range: Option<(f64, f64)>,
}

/// Draws the chart into `buf` over `area`.
pub fn render(area: Rect, buf: &mut Buffer, series: &[Series], opts: &ChartOpts) {
    if area.width < 10 || area.height < 5 {
        return;
    }
    let tx = |x: f64| if opts.log_x { x.max(1e-300).log10() } else { x };
    let ty = |y: f64| if opts.log_y { y.max(1e-300).log10() } else { y };
    let data: Vec<Vec<(f64, f64)>> = series
        .iter()
        .map(|s| {
            s.points
                .iter()
                .filter(|(x, y)| x.is_finite() && y.is_finite() && (!opts.log_y || *y > 0.0))
                .map(|&(x, y)| (tx(x), ty(y)))
                .collect()
        })
        .collect();
    let (mut x0, mut x1, mut y0, mut y1) = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    for &(x, y) in data.iter().flatten() {
        x0 = x0.min(x);
        x1 = x1.max(x);
        y0 = y0.min(y);
        y1 = y1.max(y);
    }
    if let Some((a, b)) = opts.y_range {
        y0 = ty(a);
        y1 = ty(b);
    }
    if !x0.is_finite() {
        (x0, x1, y0, y1) = (0.0, 1.0, 0.0, 1.0);
    }
    if x1 <= x0 {
        x1 = x0 + 1.0;
    }
    // Labels need room: about one per 12 columns and one per 3 rows.
    let max_x = ((area.width as usize).saturating_sub(8) / 12).clamp(2, 11);
    let max_y = ((area.height as usize).saturating_sub(4) / 3).clamp(2, 6);
    let (x0, x1, nx) = if opts.log_x {
        (x0, x1, max_x.min(5))
    } else {
        nice_axis(x0, x1, 0.0, max_x)
    };
    let (y0, y1, ny) = if opts.y_range.is_some() {
        (y0, y1.max(y0 + f64::EPSILON), max_y.min(3))
    } else if opts.log_y {
        let (a, b) = (
            y0 - 0.05 * (y1 - y0).max(0.1),
            y1 + 0.05 * (y1 - y0).max(0.1),
        );
        (a, b, max_y.min(4))
    } else {
        nice_axis(y0, y1, 0.05, max_y)
    };

    let marks: Vec<(f64, f64)> = opts.marks.iter().map(|&(x, y)| (tx(x), ty(y))).collect();
    let cursor: Vec<(f64, f64)> = opts
        .cursor_x
        .map(|c| vec![(tx(c), y0), (tx(c), y1)])
        .unwrap_or_default();

    let markers: &[Marker] = if opts.ascii { &ASCII_MARKERS } else { &MARKERS };
    let style = |i: usize| {
        if opts.mono {
            Style::default()
        } else {
            Style::default().fg(COLORS[i % COLORS.len()])
        }
    };
    let mut datasets: Vec<Dataset> = series
        .iter()
        .zip(&data)
        .enumerate()
        .map(|(i, (s, d))| {
            Dataset::default()
                .name(s.name.clone())
                .marker(markers[i % markers.len()])
                .graph_type(GraphType::Line)
                .style(style(i))
                .data(d)
        })
        .collect();
    if !cursor.is_empty() {
        datasets.push(
            Dataset::default()
                .marker(Marker::Dot)
                .graph_type(GraphType::Line)
                .style(if opts.mono {
                    Style::default()
                } else {
                    Style::default().fg(Color::DarkGray)
                })
                .data(&cursor),
        );
    }
    if !marks.is_empty() {
        datasets.push(
            Dataset::default()
                .name("peak")
                .marker(if opts.ascii {
                    Marker::Quadrant
                } else {
                    Marker::Block
                })
                .graph_type(GraphType::Scatter)
                .style(if opts.mono {
                    Style::default()
                } else {
                    Style::default().fg(Color::White)
                })
                .data(&marks),
        );
    }

    let x_labels = tick_labels(x0, x1, opts.log_x, nx);
    let y_labels = tick_labels(y0, y1, opts.log_y, ny);
    // A short chart keeps only the top rule (with the title): two more rows
    // and columns of plot where they matter most (three stacked at 80x24).
    let mut block = if area.height < 10 {
        Block::new()
            .borders(ratatui::widgets::Borders::TOP)
            .title(opts.title.clone())
    } else {
        Block::bordered().title(opts.title.clone())
    };
    if opts.ascii {
        block = block.border_set(ratatui::symbols::border::PLAIN);
    }
    let chart = Chart::new(datasets)
        .block(block)
        .x_axis(
            Axis::default()
                .title(opts.x_title.clone())
                .bounds([x0, x1])
                .labels(x_labels),
        )
        .y_axis(
            Axis::default()
                .title(opts.y_title.clone())
                .bounds([y0, y1])
                .labels(y_labels),
        )
        .legend_position(if series.len() > 1 || !opts.marks.is_empty() {
            Some(LegendPosition::TopRight)
        } else {
            None
        })
        .hidden_legend_constraints((
            ratatui::layout::Constraint::Percentage(60),
            ratatui::layout::Constraint::Percentage(60),
        ));
    chart.render(area, buf);
    if opts.ascii {
        asciify(area, buf);
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
                '•' => "*",
                '█' => "#",
                '▄' | '▀' => "o",
                '─' | '━' | '═' | '—' | '–' => "-",
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
                '×' => "x",
                'µ' => "u",
                _ => "?",
            };
            cell.set_symbol(rep);
        }
    }
}

/// Round axis bounds and a label count whose spacing is 1, 2 or 5 × 10^k:
/// [lo, hi] padded by `pad` of its span, at most `max_labels` labels.
pub fn nice_axis(lo: f64, hi: f64, pad: f64, max_labels: usize) -> (f64, f64, usize) {
    let (lo, hi) = if hi > lo {
        (lo, hi)
    } else {
        let d = if lo == 0.0 { 1.0 } else { lo.abs() * 0.1 };
        (lo - d, hi + d)
    };
    let p = pad * (hi - lo);
    let (lo, hi) = (lo - p, hi + p);
    // Three labels at least: a range across zero needs lo, 0 and hi, and
    // with two the search below could never succeed.
    let wanted = max_labels;
    let max_labels = max_labels.max(3);
    let mut step = nice_step((hi - lo) / (max_labels - 1) as f64);
    // Each round at least doubles the step, so 64 rounds cover any f64 span.
    for _ in 0..64 {
        if !(step.is_finite() && step > 0.0) {
            break;
        }
        let a = (lo / step).floor() * step;
        let b = (hi / step).ceil() * step;
        let n = ((b - a) / step).round();
        if n.is_finite() && n + 1.0 <= max_labels as f64 {
            // On a short axis only the (round) ends get a label.
            let n = if wanted < 3 { 2 } else { n as usize + 1 };
            return (a, b, n.max(2));
        }
        step = nice_step(step * 1.5);
    }
    (lo, hi, 2)
}

fn nice_step(raw: f64) -> f64 {
    let e = raw.log10().floor();
    let base = 10f64.powf(e);
    let m = raw / base;
    let n = if m <= 1.0 {
        1.0
    } else if m <= 2.0 {
        2.0
    } else if m <= 5.0 {
        5.0
    } else {
        10.0
    };
    n * base
}

/// `n` evenly spaced labels over [lo, hi] (in transformed units), printed in
/// data units: 10^v on a log axis.
fn tick_labels(lo: f64, hi: f64, log: bool, n: usize) -> Vec<Span<'static>> {
    (0..n)
        .map(|i| {
            let v = lo + (hi - lo) * i as f64 / (n - 1) as f64;
            let v = if log { 10f64.powf(v) } else { v };
            Span::raw(short(v))
        })
        .collect()
}

/// Compact number for a tick label: 3 significant digits, k for thousands.
pub fn short(v: f64) -> String {
    let a = v.abs();
    // Tiny values (an RMS error on a log axis) keep their digits: 3.7e-4.
    if a > 0.0 && a < 0.01 {
        return format!("{v:.1e}");
    }
    let s = if a >= 10_000.0 {
        format!("{:.0}k", v / 1000.0)
    } else if a >= 100.0 {
        format!("{v:.0}")
    } else if a >= 10.0 {
        format!("{v:.1}")
    } else if a >= 1.0 || a == 0.0 {
        format!("{v:.2}")
    } else {
        format!("{v:.3}")
    };
    if s.contains('.') && !s.ends_with('k') {
        let t = s.trim_end_matches('0').trim_end_matches('.');
        if t.is_empty() || t == "-" {
            "0".into()
        } else {
            t.to_string()
        }
    } else {
        s
    }
}

/// The buffer as text lines, trailing blanks trimmed: for `biodyn plot` and
/// for snapshot tests.
pub fn buffer_text(buf: &Buffer) -> Vec<String> {
    let area = buf.area;
    (area.top()..area.bottom())
        .map(|y| {
            let mut line = String::new();
            for x in area.left()..area.right() {
                if let Some(c) = buf.cell((x, y)) {
                    line.push_str(c.symbol());
                }
            }
            line.trim_end().to_string()
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample() -> Vec<Series> {
        vec![
            Series {
                name: "65 kg".into(),
                points: (0..50)
                    .map(|i| (i as f64 * 0.4 + 0.5, (i as f64 * 0.3).sin() + 2.0))
                    .collect(),
            },
            Series {
                name: "85 kg".into(),
                points: (0..50)
                    .map(|i| (i as f64 * 0.4 + 0.5, (i as f64 * 0.2).cos() + 2.0))
                    .collect(),
            },
        ]
    }

    #[test]
    fn nice_range_contains_data_and_is_round() {
        let (a, b, n) = nice_axis(0.93, 1.78, 0.05, 5);
        assert!(a <= 0.93 && b >= 1.78 && n <= 5);
        assert!((a * 10.0 - (a * 10.0).round()).abs() < 1e-9);
        let (a, b, _) = nice_axis(5.0, 5.0, 0.05, 5);
        assert!(a < 5.0 && b > 5.0);
        // A short phase axis across zero once looped until overflow.
        let (a, b, n) = nice_axis(-170.0, 30.0, 0.05, 2);
        assert!(a <= -170.0 && b >= 30.0 && (2..=3).contains(&n));
        // 0.5..20 Hz gets round labels 0, 5, 10, 15, 20.
        assert_eq!(nice_axis(0.5, 20.0, 0.0, 5), (0.0, 20.0, 5));
    }

    #[test]
    fn ascii_mode_leaves_only_ascii_and_distinct_markers() {
        let area = Rect::new(0, 0, 70, 20);
        let mut buf = Buffer::empty(area);
        let opts = ChartOpts {
            title: "STHT".into(),
            x_title: "f (Hz)".into(),
            y_title: "|STHT|".into(),
            ascii: true,
            mono: true,
            ..Default::default()
        };
        render(area, &mut buf, &sample(), &opts);
        let text = buffer_text(&buf).join("\n");
        assert!(text.is_ascii(), "{text}");
        assert!(text.contains('*') && text.contains('#'), "{text}");
        assert!(text.contains("65 kg") && text.contains("85 kg"));
    }

    #[test]
    fn log_axis_labels_are_in_data_units() {
        let area = Rect::new(0, 0, 60, 16);
        let mut buf = Buffer::empty(area);
        let s = vec![Series {
            name: "x".into(),
            points: vec![(1.0, 10.0), (10.0, 1000.0)],
        }];
        let opts = ChartOpts {
            log_y: true,
            log_x: true,
            ..Default::default()
        };
        render(area, &mut buf, &s, &opts);
        let text = buffer_text(&buf).join("\n");
        assert!(text.contains("10"), "{text}");
    }

    #[test]
    fn short_labels() {
        assert_eq!(short(54000.0), "54k");
        assert_eq!(short(2.5), "2.5");
        assert_eq!(short(0.0), "0");
        assert_eq!(short(150.0), "150");
        assert_eq!(short(0.00037), "3.7e-4");
    }
}
