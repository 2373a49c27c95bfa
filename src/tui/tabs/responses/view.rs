//! Drawing the Responses tab: the readout at the cursor (wrapped to as many
//! rows as it needs), a legend line when measured data or a compared model
//! are shown, the compared peaks, and one chart per function with the
//! model's curve, the data's points, the compared model and the main peak.
//! `areas` and `chart` are shared with the mouse, so a click lands on what
//! was drawn. Reads state; changes nothing.

use super::ResponsesTab;
use crate::tui::shared::Shared;
use crate::tui::widgets::SIDE_BY_SIDE;
use crate::view::chart::{self, ChartOpts, Emphasis, Series};
use crate::view::format::{clip, num, unit};
use biodyn::Response;
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget, Wrap};

/// A chart needs this many rows for its frame, a plot and the x labels;
/// below it the tab shows only the current function's chart.
const CHART_MIN_ROWS: u16 = 6;

/// The response the readout shows: the exact one of `g` or a peak, or the
/// grid point under the cursor.
pub fn at_cursor<'a>(t: &'a ResponsesTab, s: &'a Shared) -> Option<&'a Response> {
    t.exact
        .as_ref()
        .or_else(|| s.derived.as_ref().and_then(|d| d.curve.get(t.cursor)))
}

/// "f 4.561 Hz", then "STHT 1.815 ∠-109.6°" for each function, packed into
/// lines no wider than `width` (a function's numbers are never split).
fn readout(t: &ResponsesTab, s: &Shared, width: u16) -> Vec<Line<'static>> {
    let th = s.theme;
    let Some(r) = at_cursor(t, s) else {
        return vec![Line::raw("no data")];
    };
    let mut chunks: Vec<Vec<Span<'static>>> = vec![vec![Span::styled(
        // An exact point (g, n) shows the frequency typed, not 4 digits.
        format!(
            "f {} Hz",
            num(r.f_hz, if t.exact.is_some() { 6 } else { 4 })
        ),
        th.heading(),
    )]];
    for f in biodyn::Function::ALL {
        chunks.push(vec![
            Span::styled(f.name(), th.key()),
            Span::raw(format!(
                " {}{}{} ∠{}°",
                num(r.mag(f), 4),
                if unit(f).is_empty() { "" } else { " " },
                unit(f),
                num(r.phase_deg(f), 4)
            )),
        ]);
    }
    if s.stale {
        chunks.push(vec![Span::styled("(updating…)", th.dim())]);
    }
    let w = usize::from(width.max(1));
    let mut lines: Vec<Vec<Span<'static>>> = Vec::new();
    let mut used = 0;
    for c in chunks {
        let len: usize = c.iter().map(|s| s.content.chars().count()).sum();
        match lines.last_mut() {
            Some(l) if used + 2 + len <= w => {
                l.push(Span::raw("  "));
                l.extend(c);
                used += 2 + len;
            }
            _ => {
                lines.push(c);
                used = len;
            }
        }
    }
    lines.into_iter().map(Line::from).collect()
}

/// "⣿ model  • data: file.csv: …  · ref: paper-75kg" above the charts: a
/// short chart hides its own legend, and NO_COLOR needs the glyphs named.
fn legend(t: &ResponsesTab, s: &Shared, width: u16) -> Option<Line<'static>> {
    if t.data.is_none() && t.compare.is_none() {
        return None;
    }
    let th = s.theme;
    let glyph = |i: usize| {
        Span::styled(
            chart::legend_glyph(i, th.ascii),
            chart::series_style(i, th.mono),
        )
    };
    let mut spans = vec![glyph(0), Span::raw(" model")];
    if let Some(c) = &t.compare {
        spans.push(Span::raw("  "));
        spans.push(Span::styled(
            chart::dim_glyph(th.ascii),
            chart::dim_style(th.mono),
        ));
        spans.push(Span::raw(format!(
            " ref: {} ({}; C clears)",
            c.name,
            super::compare::drawn_as(th.mono)
        )));
    }
    if let Some(d) = &t.data {
        let used: usize = spans.iter().map(|s| s.content.chars().count()).sum();
        let text = format!(" data: {}  (X clears, F fits)", d.describe());
        spans.push(Span::raw("  "));
        spans.push(glyph(1));
        spans.push(Span::raw(clip(
            &text,
            (width as usize).saturating_sub(used + 3),
        )));
    }
    Some(Line::from(spans))
}

/// Per function (in `derived.functions` order), the model's curve, the
/// data's points (where the data have that column) and the compared
/// model's curve (always last: `chart` dims it), for the mode shown. Built when the curves, the data, the
/// compared model or the mode change, not per frame; empty when there is
/// nothing to lay over.
pub fn overlaid(t: &ResponsesTab, s: &Shared) -> Vec<Vec<Series>> {
    let Some(d) = &s.derived else {
        return Vec::new();
    };
    if t.data.is_none() && t.compare.is_none() {
        return Vec::new();
    }
    d.functions
        .iter()
        .map(|c| {
            let model = if t.phase { &c.phase } else { &c.mag };
            let mut v = vec![model.clone()];
            if let Some(o) = &t.data {
                match o.series(c.function, t.phase, model) {
                    Some(data) => v.push(data),
                    // No such column: the compared model alone over it.
                    None if t.compare.is_some() => {}
                    None => return Vec::new(),
                }
            }
            if let Some(r) = &t.compare {
                let f = c.function;
                v.push(Series {
                    name: format!("ref {}", r.name),
                    points: r
                        .curve
                        .iter()
                        .map(|x| (x.f_hz, if t.phase { x.phase_deg(f) } else { x.mag(f) }))
                        .collect(),
                });
            }
            v
        })
        .collect()
}

/// Where the tab draws: the rows above the charts, and each chart shown
/// with its function's index. `zoom` (the app's `z`) and a tab too short
/// for every chart show only the current function's.
pub struct Areas {
    pub top: Rect,
    pub charts: Vec<(usize, Rect)>,
}

fn top_lines(t: &ResponsesTab, s: &Shared, width: u16) -> Vec<Line<'static>> {
    let mut lines = readout(t, s, width);
    // The copied line whole when the status line cannot show it all,
    // broken only after commas: a terminal selection across the lines then
    // holds every number whole, with line breaks only between values.
    let w = usize::from(width.max(1));
    if let Some(c) = t.copied.as_ref().filter(|c| c.chars().count() + 1 > w) {
        lines.extend(
            break_after_commas(c, w)
                .into_iter()
                .map(|p| Line::styled(p, s.theme.ok())),
        );
    }
    if let (Some(c), Some(d)) = (&t.compare, &s.derived) {
        // Side by side every chart shows: each function's peaks; else the
        // current function's (f, a click and n change it).
        let shown: Vec<usize> = if width >= SIDE_BY_SIDE {
            (0..d.functions.len()).collect()
        } else {
            vec![t.func]
        };
        for i in shown {
            let Some(x) = d.functions.get(i) else {
                continue;
            };
            let model = x.main.filter(|p| !p.at_edge);
            lines.push(Line::raw(c.peak_line_in(x.function, model, usize::from(width))));
        }
    }
    lines.extend(legend(t, s, width));
    lines
}

pub fn areas(t: &ResponsesTab, s: &Shared, area: Rect, zoom: bool) -> Areas {
    let rows = u16::try_from(top_lines(t, s, area.width).len()).unwrap_or(1);
    let [top, charts] =
        Layout::vertical([Constraint::Length(rows), Constraint::Min(0)]).areas(area);
    let n = s.derived.as_ref().map_or(0, |d| d.functions.len());
    let func = t.func.min(n.saturating_sub(1));
    let side = area.width >= SIDE_BY_SIDE;
    let fits_all = side || charts.height >= CHART_MIN_ROWS * u16::try_from(n).unwrap_or(3);
    let charts = if n == 0 {
        Vec::new()
    } else if zoom || !fits_all {
        vec![(func, charts)]
    } else {
        let ratios = vec![Constraint::Ratio(1, u32::try_from(n).unwrap_or(3)); n];
        let split = if side {
            Layout::horizontal(ratios).split(charts)
        } else {
            Layout::vertical(ratios).split(charts)
        };
        split.iter().copied().enumerate().collect()
    };
    Areas { top, charts }
}

/// What a chart is drawn from: the series, how each stands out (the
/// compared model dimmed) and the options.
pub struct ChartSpec {
    pub series: Vec<Series>,
    pub emphasis: Vec<Emphasis>,
    pub opts: ChartOpts,
}

/// The series and options of function `i`'s chart in `cell`; `alone` when
/// it is the only chart shown (its title then says `f` shows the next).
pub fn chart(t: &ResponsesTab, s: &Shared, i: usize, cell: Rect, alone: bool) -> Option<ChartSpec> {
    let d = s.derived.as_ref()?;
    let c = d.functions.get(i)?;
    let f = c.function;
    let series = match t.overlaid.get(i) {
        Some(v) if !v.is_empty() => v.clone(),
        _ => vec![if t.phase {
            c.phase.clone()
        } else {
            c.mag.clone()
        }],
    };
    // The compared model is the last of the overlaid series.
    let mut emphasis = vec![Emphasis::Normal; series.len()];
    if t.compare.is_some()
        && series.len() > 1
        && let Some(e) = emphasis.last_mut()
    {
        *e = Emphasis::Dim;
    }
    let u = unit(f);
    let what = if t.phase {
        "phase °".to_string()
    } else if u.is_empty() {
        "magnitude".to_string()
    } else {
        format!("magnitude, {u}")
    };
    let tall = cell.height >= 12;
    // The marked peak in numbers, so it can be read, not just seen.
    let peak = match c.main {
        Some(p) if !p.at_edge && !t.phase => format!(
            " · peak {} Hz, {}{}{}",
            num(p.f_hz, 4),
            num(p.mag, 4),
            if u.is_empty() { "" } else { " " },
            u
        ),
        _ => String::new(),
    };
    let next = if alone && d.functions.len() > 1 {
        " · f next"
    } else {
        ""
    };
    let long = format!("{} ({}){peak}{next}", f.name(), f.long_name());
    let title = if tall && long.chars().count() + 2 <= cell.width as usize {
        long
    } else if tall {
        format!("{}{peak}{next}", f.name())
    } else {
        format!("{} {what} vs f Hz{peak}{next}", f.name())
    };
    let marks = match c.main {
        Some(p) if !t.phase && !p.at_edge => vec![(p.f_hz, p.mag)],
        _ => Vec::new(),
    };
    let opts = ChartOpts {
        title,
        x_title: if tall { "f Hz".into() } else { String::new() },
        y_title: if tall { what } else { String::new() },
        log_x: t.log,
        log_y: t.log && !t.phase,
        ascii: s.theme.ascii,
        mono: s.theme.mono,
        cursor_x: at_cursor(t, s).map(|r| r.f_hz),
        marks,
        y_range: None,
    };
    Some(ChartSpec {
        series,
        emphasis,
        opts,
    })
}

pub fn render(t: &ResponsesTab, s: &Shared, area: Rect, buf: &mut Buffer, zoom: bool) {
    if s.derived.is_none() {
        Paragraph::new(s.computing())
            .style(s.theme.dim())
            .wrap(Wrap { trim: true })
            .render(area, buf);
        return;
    }
    let a = areas(t, s, area, zoom);
    Paragraph::new(top_lines(t, s, area.width)).render(a.top, buf);
    let alone = a.charts.len() == 1;
    for &(i, cell) in &a.charts {
        if let Some(c) = chart(t, s, i, cell, alone) {
            chart::render_with(cell, buf, &c.series, &c.emphasis, &c.opts);
        }
    }
}

/// `line` in lines of at most `w` characters, each break right after a
/// comma (a value longer than `w` alone is cut, the only way it can fit).
pub fn break_after_commas(line: &str, w: usize) -> Vec<String> {
    let w = w.max(1);
    let mut out: Vec<String> = Vec::new();
    let mut cur = String::new();
    for piece in line.split_inclusive(',') {
        if !cur.is_empty() && cur.chars().count() + piece.chars().count() > w {
            out.push(std::mem::take(&mut cur));
        }
        cur.push_str(piece);
        while cur.chars().count() > w {
            let head: String = cur.chars().take(w).collect();
            cur = cur.chars().skip(w).collect();
            out.push(head);
        }
    }
    if !cur.is_empty() {
        out.push(cur);
    }
    out
}
