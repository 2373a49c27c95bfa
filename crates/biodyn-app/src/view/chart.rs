//! Response charts, shared by the TUI tabs and `biodyn plot` so that both
//! look alike.
//!
//! ratatui's Chart has no log axis, no autoscale, and spreads its axis
//! labels evenly whatever they say; so the axes are drawn here. Data are
//! transformed (log10 on request), bounds are padded to round numbers so
//! the axes do not jump (a magnitude axis starts at 0), and each tick is a
//! round number drawn in the cell its value maps to, by the same rule as
//! the data points (see `axis`). The curves themselves go through ratatui's
//! Canvas, one series at a time, and are laid together so that none hides
//! another entirely: where curves share a cell, the cells alternate between
//! them. Each series has its own marker as well as its own colour, so
//! meaning never rides on colour alone; `ascii` gives every series, the
//! cursor and the peaks their own plain ASCII glyph.

use super::axis::{self, Mapping, Plan, Scale, Tick};
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Color, Style};
use ratatui::symbols::Marker;
use ratatui::widgets::canvas::{Canvas, Line as CanvasLine, Points};
use ratatui::widgets::{Block, Borders, Widget};

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
const PEAK: (char, char) = ('◆', '^');
const CURSOR: (char, char) = ('│', '|');

fn marker(i: usize, ascii: bool) -> Marker {
    if ascii {
        ASCII_MARKERS[i % ASCII_MARKERS.len()]
    } else {
        MARKERS[i % MARKERS.len()]
    }
}

/// Dots per cell (across, down) of a marker's grid in ratatui's Canvas.
fn dots(m: Marker) -> (u16, u16) {
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
    /// Points to mark (peaks), drawn on top and named "peak" in the legend.
    pub marks: Vec<(f64, f64)>,
    /// Fixed y range in data units; None autoscales with padding (from 0
    /// when every value is ≥ 0: a magnitude axis never goes negative).
    pub y_range: Option<(f64, f64)>,
}

/// Least spacing of x ticks in columns, and of y ticks in rows.
const X_SPACING: i32 = 10;
const Y_SPACING: i32 = 3;

/// Where the parts of a chart go, and how values map to cells.
#[derive(Debug, Clone, PartialEq)]
pub struct Layout {
    /// The plot: data cells only, axes and labels outside it.
    pub plot: Rect,
    pub x: Mapping,
    pub y: Mapping,
    pub x_plan: Plan,
    pub y_plan: Plan,
}

impl Layout {
    /// The column of an x value (in data units), None outside the plot.
    pub fn column(&self, x: f64, log: bool) -> Option<u16> {
        let v = if log { x.log10() } else { x };
        self.x.cell(v).map(|c| self.plot.x + c)
    }

    /// The row of a y value (in data units), None outside the plot.
    pub fn row(&self, y: f64, log: bool) -> Option<u16> {
        let v = if log { y.log10() } else { y };
        self.y.cell(v).map(|c| self.plot.y + c)
    }
}

/// The data of each series in axis units (log10 where asked), without the
/// points a log axis or a NaN cannot show.
fn transformed(series: &[Series], opts: &ChartOpts) -> Vec<Vec<(f64, f64)>> {
    let t = |v: f64, log: bool| if log { v.log10() } else { v };
    series
        .iter()
        .map(|s| {
            s.points
                .iter()
                .filter(|(x, y)| {
                    x.is_finite()
                        && y.is_finite()
                        && (!opts.log_x || *x > 0.0)
                        && (!opts.log_y || *y > 0.0)
                })
                .map(|&(x, y)| (t(x, opts.log_x), t(y, opts.log_y)))
                .collect()
        })
        .collect()
}

/// The frame of the chart: a full border when tall enough, else only the
/// top rule with the title (two more rows of plot where they matter most).
fn frame(area: Rect, opts: &ChartOpts) -> Block<'static> {
    let block = if area.height < 10 {
        Block::new().borders(Borders::TOP)
    } else {
        Block::bordered()
    };
    let block = block.title(opts.title.clone());
    if opts.ascii {
        block.border_set(ratatui::symbols::border::PLAIN)
    } else {
        block
    }
}

/// Lays a chart out in `area`: bounds, ticks and the plot rectangle. None
/// when the area is too small for a plot.
pub fn layout(area: Rect, series: &[Series], opts: &ChartOpts) -> Option<Layout> {
    if area.width < 10 || area.height < 5 {
        return None;
    }
    let inner = frame(area, opts).inner(area);
    if inner.height < 4 || inner.width < 8 {
        return None;
    }
    let data = transformed(series, opts);
    let (kx, ky) = dots(marker(0, opts.ascii));
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
    if !x0.is_finite() {
        (x0, x1, y0, y1) = if opts.log_y {
            (0.0, 1.0, 0.0, 1.0)
        } else {
            (0.0, 1.0, 0.0, 1.0)
        };
    }

    // y first: its labels' width decides where the plot starts.
    let plot_h = inner.height - 2;
    let y_scale = match opts.y_range {
        Some((a, b)) if a.is_finite() && b.is_finite() && (!opts.log_y || a > 0.0) => {
            let t = |v: f64| if opts.log_y { v.log10() } else { v };
            (y0, y1) = (t(a), t(b));
            Scale::Fixed { log: opts.log_y }
        }
        _ if opts.log_y => Scale::Log,
        _ => Scale::Linear {
            pad: 0.05,
            floor_zero: true,
        },
    };
    let y_map = |lo: f64, hi: f64| Mapping {
        lo,
        hi,
        cells: plot_h,
        sub: ky,
        flip: true,
    };
    let y_fits = |lo: f64, hi: f64, ticks: &[Tick]| {
        let m = y_map(lo, hi);
        let rows: Option<Vec<i32>> = ticks.iter().map(|t| m.cell(t.at).map(i32::from)).collect();
        let Some(rows) = rows else { return false };
        let gap = if ticks.len() <= 2 { 1 } else { Y_SPACING };
        rows.windows(2).all(|w| (w[0] - w[1]).abs() >= gap)
            && ticks
                .iter()
                .all(|t| t.label.chars().count() < inner.width as usize / 3)
    };
    let y_plan = axis::plan(y0, y1, y_scale, &y_fits);
    let yw = y_plan
        .ticks
        .iter()
        .map(|t| t.label.chars().count() as u16)
        .max()
        .unwrap_or(0);

    // x: labels centred on their column may reach left under the y labels;
    // on the right the plot gives up what the last label needs.
    let px0 = inner.x + yw + 1;
    let x_scale = if opts.log_x {
        Scale::Log
    } else {
        Scale::Linear {
            pad: 0.0,
            floor_zero: false,
        }
    };
    let x_for = |margin: u16, strict: bool| -> Option<(Plan, u16)> {
        let w = inner.right().checked_sub(px0 + margin)?;
        if w < 2 {
            return None;
        }
        let fits =
            |lo: f64, hi: f64, ticks: &[Tick]| x_fits(lo, hi, ticks, w, kx, px0, inner, strict);
        Some((axis::plan(x0, x1, x_scale, &fits), w))
    };
    let (first, w) = x_for(0, false)?;
    let over = overflow(&first, w, kx, px0, inner);
    let (x_plan, plot_w) = if over == 0 {
        (first, w)
    } else {
        x_for(over, true)?
    };
    let plot = Rect::new(px0, inner.y, plot_w, plot_h);
    Some(Layout {
        plot,
        x: Mapping {
            lo: x_plan.lo,
            hi: x_plan.hi,
            cells: plot_w,
            sub: kx,
            flip: false,
        },
        y: y_map(y_plan.lo, y_plan.hi),
        x_plan,
        y_plan,
    })
}

/// Columns (first, last) of an x label centred on column `col`.
fn label_span(col: i32, label: &str) -> (i32, i32) {
    let n = label.chars().count() as i32;
    let start = col - n / 2;
    (start, start + n - 1)
}

/// Do the x labels fit: inside the frame, apart, no closer than
/// `X_SPACING` columns when there are more than two?
#[allow(clippy::too_many_arguments)]
fn x_fits(
    lo: f64,
    hi: f64,
    ticks: &[Tick],
    w: u16,
    kx: u16,
    px0: u16,
    inner: Rect,
    strict: bool,
) -> bool {
    let m = Mapping {
        lo,
        hi,
        cells: w,
        sub: kx,
        flip: false,
    };
    let mut prev: Option<(i32, i32)> = None;
    for t in ticks {
        let Some(c) = m.cell(t.at) else {
            return false;
        };
        let col = i32::from(px0) + i32::from(c);
        let (a, b) = label_span(col, &t.label);
        if a < i32::from(inner.x) || (strict && b >= i32::from(inner.right())) {
            return false;
        }
        if let Some((pc, pb)) = prev {
            let spacing = if ticks.len() > 2 { X_SPACING } else { 0 };
            if a <= pb + 1 || col - pc < spacing {
                return false;
            }
        }
        prev = Some((col, b));
    }
    true
}

/// Columns the x labels of `plan` reach past the frame on the right.
fn overflow(plan: &Plan, w: u16, kx: u16, px0: u16, inner: Rect) -> u16 {
    let m = Mapping {
        lo: plan.lo,
        hi: plan.hi,
        cells: w,
        sub: kx,
        flip: false,
    };
    plan.ticks
        .iter()
        .filter_map(|t| {
            let col = i32::from(px0) + i32::from(m.cell(t.at)?);
            let (_, b) = label_span(col, &t.label);
            Some((b - i32::from(inner.right()) + 1).max(0) as u16)
        })
        .max()
        .unwrap_or(0)
}

/// Draws the chart into `buf` over `area`.
pub fn render(area: Rect, buf: &mut Buffer, series: &[Series], opts: &ChartOpts) {
    if area.width < 10 || area.height < 5 {
        return;
    }
    frame(area, opts).render(area, buf);
    let Some(lay) = layout(area, series, opts) else {
        if opts.ascii {
            asciify(area, buf);
        }
        return;
    };
    draw_axes(&lay, buf, opts);
    draw_data(&lay, buf, series, opts);
    draw_titles(&lay, buf, opts);
    draw_legend(&lay, buf, series, opts);
    if opts.ascii {
        asciify(area, buf);
    }
}

/// Writes `text` at (x, y), at most `w` cells, in `style` over a reset cell.
fn put(buf: &mut Buffer, x: u16, y: u16, text: &str, w: u16, style: Style) {
    for (i, ch) in text.chars().take(w as usize).enumerate() {
        if let Some(cell) = buf.cell_mut((x + i as u16, y)) {
            cell.set_char(ch).set_fg(Color::Reset).set_style(style);
        }
    }
}

/// The axis lines with a tick mark at each label, and the labels.
fn draw_axes(lay: &Layout, buf: &mut Buffer, opts: &ChartOpts) {
    let p = lay.plot;
    let (ax, ay) = (p.x - 1, p.bottom());
    let plain = Style::default();
    let tick_rows: Vec<u16> = lay
        .y_plan
        .ticks
        .iter()
        .filter_map(|t| lay.y.cell(t.at))
        .collect();
    for r in 0..p.height {
        let g = if tick_rows.contains(&r) { "┤" } else { "│" };
        put(buf, ax, p.y + r, g, 1, plain);
    }
    let tick_cols: Vec<u16> = lay
        .x_plan
        .ticks
        .iter()
        .filter_map(|t| lay.x.cell(t.at))
        .collect();
    put(buf, ax, ay, "└", 1, plain);
    for c in 0..p.width {
        let g = if tick_cols.contains(&c) { "┬" } else { "─" };
        put(buf, p.x + c, ay, g, 1, plain);
    }
    for t in &lay.y_plan.ticks {
        if let Some(r) = lay.y.cell(t.at) {
            let n = t.label.chars().count() as u16;
            put(buf, ax.saturating_sub(n), p.y + r, &t.label, n, plain);
        }
    }
    for t in &lay.x_plan.ticks {
        if let Some(c) = lay.x.cell(t.at) {
            let (a, _) = label_span(i32::from(p.x + c), &t.label);
            let n = t.label.chars().count() as u16;
            put(buf, a.max(0) as u16, ay + 1, &t.label, n, plain);
        }
    }
    let _ = opts;
}

/// The curves, the cursor beneath them and the peaks above them.
fn draw_data(lay: &Layout, buf: &mut Buffer, series: &[Series], opts: &ChartOpts) {
    let p = lay.plot;
    let data = transformed(series, opts);
    let scratch_area = Rect::new(0, 0, p.width, p.height);
    // Each series alone on a scratch canvas, in the reference cells.
    let layers: Vec<Buffer> = data
        .iter()
        .enumerate()
        .map(|(i, d)| {
            let m = marker(i, opts.ascii);
            let (kx, ky) = dots(m);
            let pts: Vec<(f64, f64)> = d
                .iter()
                .map(|&(x, y)| {
                    let tx = lay.x.renorm(lay.x.norm(x), kx);
                    let ty = lay.y.renorm(lay.y.norm(y), ky);
                    (tx, 1.0 - ty)
                })
                .collect();
            let color = series_style(i, opts.mono).fg.unwrap_or(Color::Reset);
            let mut b = Buffer::empty(scratch_area);
            Canvas::default()
                .marker(m)
                .x_bounds([0.0, 1.0])
                .y_bounds([0.0, 1.0])
                .paint(|ctx| {
                    ctx.draw(&Points {
                        coords: &pts,
                        color,
                    });
                    for w in pts.windows(2) {
                        ctx.draw(&CanvasLine::new(w[0].0, w[0].1, w[1].0, w[1].1, color));
                    }
                })
                .render(scratch_area, &mut b);
            b
        })
        .collect();
    let cursor_col = opts.cursor_x.and_then(|c| lay.column(c, opts.log_x));
    let cursor_style = if opts.mono {
        Style::default()
    } else {
        Style::default().fg(Color::DarkGray)
    };
    let cursor = if opts.ascii { CURSOR.1 } else { CURSOR.0 };
    let mut here: Vec<usize> = Vec::with_capacity(layers.len());
    for r in 0..p.height {
        for c in 0..p.width {
            here.clear();
            here.extend((0..layers.len()).filter(|&i| {
                layers[i]
                    .cell((c, r))
                    .is_some_and(|cell| cell.symbol() != " ")
            }));
            let Some(out) = buf.cell_mut((p.x + c, p.y + r)) else {
                continue;
            };
            // Curves sharing a cell take turns by column: both stay visible.
            if let Some(&i) = here.get(usize::from(c) % here.len().max(1)) {
                if let Some(src) = layers[i].cell((c, r)) {
                    out.set_symbol(src.symbol()).set_fg(src.fg);
                    if src.bg != Color::Reset {
                        out.set_bg(src.bg);
                    }
                }
            } else if cursor_col == Some(p.x + c) {
                out.set_char(cursor).set_style(cursor_style);
            }
        }
    }
    let peak = if opts.ascii { PEAK.1 } else { PEAK.0 };
    let peak_style = if opts.mono {
        Style::default()
    } else {
        Style::default().fg(Color::White)
    };
    for &(x, y) in &opts.marks {
        if let (Some(c), Some(r)) = (lay.column(x, opts.log_x), lay.row(y, opts.log_y)) {
            put(buf, c, r, &peak.to_string(), 1, peak_style);
        }
    }
}

/// The y title at the top left of the plot, the x title at its bottom
/// right, each only where it fits.
fn draw_titles(lay: &Layout, buf: &mut Buffer, opts: &ChartOpts) {
    let p = lay.plot;
    let yw = opts.y_title.chars().count() as u16;
    if !opts.y_title.is_empty() && yw + 1 < p.width && p.height > 2 {
        put(buf, p.x, p.y, &opts.y_title, yw, Style::default());
    }
    let xw = opts.x_title.chars().count() as u16;
    if !opts.x_title.is_empty() && xw < p.width && p.height > 2 {
        put(
            buf,
            p.right() - xw,
            p.bottom() - 1,
            &opts.x_title,
            xw,
            Style::default(),
        );
    }
}

/// A boxed legend at the top right of the plot: each series' glyph and
/// name, and the peak glyph; left out when it would cover over 60 % of
/// the plot's width or height.
fn draw_legend(lay: &Layout, buf: &mut Buffer, series: &[Series], opts: &ChartOpts) {
    if series.len() < 2 && opts.marks.is_empty() {
        return;
    }
    let mut rows: Vec<(String, Style, String)> = series
        .iter()
        .enumerate()
        .filter(|(_, s)| !s.name.is_empty())
        .map(|(i, s)| {
            (
                legend_glyph(i, opts.ascii).to_string(),
                series_style(i, opts.mono),
                s.name.clone(),
            )
        })
        .collect();
    if !opts.marks.is_empty() {
        let style = if opts.mono {
            Style::default()
        } else {
            Style::default().fg(Color::White)
        };
        rows.push((peak_glyph(opts.ascii).into(), style, "peak".into()));
    }
    let p = lay.plot;
    let inner_w = rows
        .iter()
        .map(|(_, _, n)| n.chars().count() + 2)
        .max()
        .unwrap_or(0) as u16;
    let (w, h) = (inner_w + 2, rows.len() as u16 + 2);
    if rows.is_empty()
        || u32::from(w) * 10 > u32::from(p.width) * 6
        || u32::from(h) * 10 > u32::from(p.height) * 6
    {
        return;
    }
    let x = p.right() - w;
    // Below the y title when they would meet.
    let title_end = p.x + opts.y_title.chars().count() as u16;
    let y = if !opts.y_title.is_empty() && x <= title_end && h < p.height {
        p.y + 1
    } else {
        p.y
    };
    let area = Rect::new(x, y, w, h);
    for yy in area.top()..area.bottom() {
        for xx in area.left()..area.right() {
            if let Some(cell) = buf.cell_mut((xx, yy)) {
                cell.set_char(' ').set_fg(Color::Reset);
            }
        }
    }
    Block::bordered().render(area, buf);
    for (k, (g, style, name)) in rows.iter().enumerate() {
        let yy = y + 1 + k as u16;
        put(buf, x + 1, yy, g, 1, *style);
        put(buf, x + 3, yy, name, inner_w - 2, Style::default());
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
#[path = "chart_tests.rs"]
mod axes_tests;

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
