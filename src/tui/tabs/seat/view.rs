//! Drawing the Seat tab from a borrowed state: where the transmissibility
//! chart, the design map, the class bars and the stroke gauge go, and each
//! of them (the map's shading is `heat.rs`). Nothing here changes state.

use super::SeatTab;
use super::compute::SeatData;
use super::heat;
use crate::tui::keys;
use crate::tui::shared::Shared;
use crate::tui::theme::Theme;
use crate::tui::widgets::{SIDE_BY_SIDE, panel};
use crate::view::chart::{self, ChartOpts, Series};
use crate::view::format::{clip, num, wrap};
use biodyn::Function;
use biodyn::seat::{Design, SeatFigures};
use biodyn::time::CLASSES;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget};

/// What the tab says for a model without a seat.
pub const NO_SEAT: &str = "this model has no seat: SEAT, the seat's transmissibility and its travel need a seat between floor and body";

/// How to load one, after `NO_SEAT`.
pub const HOW_TO: &str = "Ctrl-O opens a preset with a seat: paper-75kg-suspension-seat (a suspension seat) or paper-75kg-rigid-seat (the same body on a rigid seat); from the shell, biodyn --preset paper-75kg-suspension-seat";

/// Where the four panels go.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Areas {
    pub chart: Rect,
    pub map: Rect,
    pub bars: Rect,
    pub stroke: Rect,
}

/// The chart and the map on top, the bars and the stroke below: the bars
/// get up to 16 rows (one per class), in columns when fewer fit.
pub fn areas(area: Rect) -> Areas {
    let wide = area.width >= SIDE_BY_SIDE;
    let bottom_h = (area.height / 2).clamp(6, CLASSES.len() as u16 + 2).min(area.height);
    let top_h = area.height - bottom_h;
    let chart_w = if wide { area.width / 2 } else { area.width * 9 / 25 };
    let stroke_w = if wide { 48 } else { 30 }.min(area.width / 2);
    let top = Rect { height: top_h, ..area };
    let bottom = Rect {
        y: area.y + top_h,
        height: bottom_h,
        ..area
    };
    Areas {
        chart: Rect { width: chart_w, ..top },
        map: Rect {
            x: top.x + chart_w,
            width: top.width - chart_w,
            ..top
        },
        bars: Rect {
            width: bottom.width - stroke_w,
            ..bottom
        },
        stroke: Rect {
            x: bottom.x + bottom.width - stroke_w,
            width: stroke_w,
            ..bottom
        },
    }
}

pub fn render(t: &SeatTab, s: &Shared, area: Rect, buf: &mut Buffer) {
    render_in(t, s, s.theme, area, buf);
}

/// `render` with the theme `th` (the `.txt` export's plain ASCII).
pub fn render_in(t: &SeatTab, s: &Shared, th: Theme, area: Rect, buf: &mut Buffer) {
    let Some(d) = &t.data else {
        no_seat(th, area, buf);
        return;
    };
    let a = areas(area);
    transmissibility(s, th, a.chart, buf);
    map(t, d, th, a.map, buf);
    bars(t, d, th, a.bars, buf);
    stroke(t, d, th, a.stroke, buf);
}

/// The design map alone (the app's `z`).
pub fn render_map(t: &SeatTab, s: &Shared, area: Rect, buf: &mut Buffer) {
    match &t.data {
        Some(d) => map(t, d, s.theme, area, buf),
        None => no_seat(s.theme, area, buf),
    }
}

fn no_seat(th: Theme, area: Rect, buf: &mut Buffer) {
    let inner = panel("seat", th, area, buf);
    let w = usize::from(inner.width.max(1));
    let mut lines: Vec<Line> = wrap(NO_SEAT, w, true)
        .into_iter()
        .map(|l| Line::styled(l, th.heading()))
        .collect();
    lines.push(Line::raw(""));
    lines.extend(
        wrap(&keys::arrows(HOW_TO, th.ascii), w, true)
            .into_iter()
            .map(Line::raw),
    );
    Paragraph::new(lines).render(inner, buf);
}

/// The seat's transmissibility |pan/floor| and floor-to-head over the band.
fn transmissibility(s: &Shared, th: Theme, area: Rect, buf: &mut Buffer) {
    let Some(d) = &s.derived else {
        let inner = panel("seat transmissibility", th, area, buf);
        let w = usize::from(inner.width.max(1));
        let lines: Vec<Line> = wrap(&s.computing(), w, true).into_iter().map(Line::raw).collect();
        Paragraph::new(lines).render(inner, buf);
        return;
    };
    let series: Vec<Series> = [Function::SeatTr, Function::FloorHead]
        .iter()
        .map(|&f| Series {
            name: f.name().to_string(),
            points: d.curve.iter().map(|r| (r.f_hz, r.mag(f))).collect(),
        })
        .collect();
    let opts = ChartOpts {
        title: " seat transmissibility |pan/floor|, floor to head ".into(),
        x_title: "f (Hz)".into(),
        y_title: "|T|".into(),
        ascii: th.ascii,
        mono: th.mono,
        ..Default::default()
    };
    chart::render(area, buf, &series, &opts);
}

/// "EM6" per class with its SEAT as a bar: the selected one reversed.
fn bars(t: &SeatTab, d: &SeatData, th: Theme, area: Rect, buf: &mut Buffer) {
    let title = if area.width >= 70 {
        "SEAT % per input class (←→ selects; 100 % = the floor's a_w)"
    } else {
        "SEAT % per input class (←→)"
    };
    let title = keys::arrows(title, th.ascii);
    let inner = panel(&title, th, area, buf);
    let rows = usize::from(inner.height);
    if rows == 0 || inner.width < 12 {
        return;
    }
    let cols = CLASSES.len().div_ceil(rows);
    let col_w = usize::from(inner.width) / cols;
    let bar_w = col_w.saturating_sub(3 + 1 + 6 + 1);
    let max = d
        .classes
        .iter()
        .filter_map(|r| r.as_ref().ok())
        .map(|f| f.seat_pct)
        .fold(100.0, f64::max)
        * 1.05;
    let hundred = ((100.0 / max) * bar_w as f64).round() as usize;
    let full = if th.ascii { '#' } else { '█' };
    let mut lines: Vec<Vec<Span>> = vec![Vec::new(); rows];
    for (i, c) in CLASSES.iter().enumerate() {
        let (row, col) = (i % rows, i / rows);
        if col >= cols {
            break;
        }
        let selected = i == t.class;
        let label = Span::styled(
            format!("{:<3}", c.name),
            if selected { th.selected() } else { th.base() },
        );
        let mut spans = vec![label, Span::raw(" ")];
        match &d.classes[i] {
            Ok(f) => {
                let n = ((f.seat_pct / max) * bar_w as f64).round() as usize;
                let n = n.min(bar_w);
                let style = if selected { th.heading() } else { th.ok() };
                spans.push(Span::styled(full.to_string().repeat(n), style));
                let rest: String = (n..bar_w)
                    .map(|j| if j == hundred { if th.ascii { '|' } else { '│' } } else { ' ' })
                    .collect();
                spans.push(Span::styled(rest, th.dim()));
                spans.push(Span::raw(format!(" {:>5} ", num(f.seat_pct, 3))));
            }
            Err(_) => spans.push(Span::styled(format!("{:<w$}", " error", w = bar_w + 7), th.error())),
        }
        lines[row].extend(spans);
    }
    let lines: Vec<Line> = lines.into_iter().map(Line::from).collect();
    Paragraph::new(lines).render(inner, buf);
}

/// The selected class: its SEAT and a_w, and the r.m.s. travel as ±3σ
/// against ±stroke/2 (the travel end-stop to end-stop), with the limit.
fn stroke(t: &SeatTab, d: &SeatData, th: Theme, area: Rect, buf: &mut Buffer) {
    let c = &CLASSES[t.class];
    let inner = panel(&format!("{} stroke", c.name), th, area, buf);
    let w = usize::from(inner.width);
    if w < 10 {
        return;
    }
    let mut lines = vec![Line::styled(clip(&format!("{} {}", c.name, c.standard), w), th.heading())];
    match &d.classes[t.class] {
        Ok(f) => lines.extend(stroke_lines(f, d.limit_m, t.limit_m.is_none(), th, w)),
        Err(e) => lines.extend(wrap(e, w, true).into_iter().map(|l| Line::styled(l, th.error()))),
    }
    Paragraph::new(lines).render(inner, buf);
}

fn stroke_lines(f: &SeatFigures, limit_m: f64, default: bool, th: Theme, w: usize) -> Vec<Line<'static>> {
    let mm = |m: f64| num(m * 1e3, 3);
    let half = f.stroke_available_m / 2.0;
    let three = 3.0 * f.stroke_rms_m;
    let share = if half > 0.0 { three / half } else { f64::INFINITY };
    let gauge_w = w.saturating_sub(2).max(4);
    let n = ((share.min(1.0)) * gauge_w as f64).round() as usize;
    let mark = ((3.0 * limit_m / half).min(1.0) * gauge_w as f64).round() as usize;
    let (full, empty, tick) = if th.ascii { ('#', '.', '|') } else { ('█', '░', '│') };
    let style = if share > 1.0 {
        th.error()
    } else if f.stroke_rms_m > limit_m {
        th.heading()
    } else {
        th.ok()
    };
    let gauge: String = (0..gauge_w)
        .map(|i| if i == mark.min(gauge_w - 1) && i >= n { tick } else if i < n { full } else { empty })
        .collect();
    let verdict = if share > 1.0 {
        if th.ascii { "3 sd past the end-stops" } else { "3σ past the end-stops" }
    } else if f.stroke_rms_m > limit_m {
        "over the limit"
    } else {
        "within the limit"
    };
    let limit_line = if default {
        format!("limit {} mm = stroke/6", mm(limit_m))
    } else {
        format!("limit {} mm r.m.s. (typed)", mm(limit_m))
    };
    let pm = if th.ascii { "+/-" } else { "±" };
    let sigma = if th.ascii { " sd" } else { "σ" };
    let mut out = vec![
        Line::raw(clip(&format!("SEAT {} %", num(f.seat_pct, 4)), w)),
        Line::raw(clip(
            &format!("a_w pan {} floor {} m/s²", num(f.pan_aw_m_s2, 3), num(f.floor_aw_m_s2, 3)),
            w,
        )),
        Line::raw(clip(
            &format!(
                "r.m.s. stroke {} of {} mm",
                mm(f.stroke_rms_m),
                mm(f.stroke_available_m)
            ),
            w,
        )),
        Line::raw(clip(
            &format!("3{sigma} {pm}{} of {pm}{} mm", mm(three), mm(half)),
            w,
        )),
        Line::from(vec![
            Span::raw("["),
            Span::styled(gauge, style),
            Span::raw("]"),
        ]),
        Line::styled(clip(verdict, w), style),
        Line::styled(clip(&limit_line, w), th.dim()),
    ];
    if default {
        let why = format!("(3{sigma} fits {pm}stroke/2; s edits)");
        out.push(Line::styled(clip(&why, w), th.dim()));
    } else {
        out.push(Line::styled(clip("(s edits; empty: stroke/6)", w), th.dim()));
    }
    out
}

/// The design map's panel: k labels, the heat map, c labels, the legend,
/// and the numbers beside it (best and now).
fn map(t: &SeatTab, d: &SeatData, th: Theme, area: Rect, buf: &mut Buffer) {
    let c = &CLASSES[t.class];
    let title = format!("design map {}: SEAT % over suspension k, c", c.name);
    let inner = panel(&title, th, area, buf);
    let design = match &d.design {
        Ok(design) => design,
        Err(e) => {
            let w = usize::from(inner.width.max(1));
            let lines: Vec<Line> = wrap(e, w, true)
                .into_iter()
                .map(|l| Line::styled(l, th.error()))
                .collect();
            Paragraph::new(lines).render(inner, buf);
            return;
        }
    };
    let now = d.classes.get(t.class).and_then(|r| r.as_ref().ok());
    let numbers = numbers(design, d, now, th, inner.height);
    let num_w = numbers
        .iter()
        .map(|l| l.width())
        .max()
        .unwrap_or(0)
        .min(usize::from(inner.width) / 2) as u16;
    let label_w: u16 = 6;
    let heat_w = inner.width.saturating_sub(num_w + 1 + label_w);
    if heat_w < 6 || inner.height < 4 {
        Paragraph::new(numbers).render(inner, buf);
        return;
    }
    // Rows: the heat, then the c labels, then the legend.
    let heat_h = inner.height - 2;
    let heat = Rect::new(inner.x + label_w, inner.y, heat_w, heat_h);
    let ks = &design.map.axes[0];
    let cs = &design.map.axes[1];
    let (kl, kh) = (ks.first().copied().unwrap_or(0.0), ks.last().copied().unwrap_or(0.0));
    let (cl, ch) = (cs.first().copied().unwrap_or(0.0), cs.last().copied().unwrap_or(0.0));
    let label = |v: f64| format!("{:>5}", clip(&num(v, 3), 5));
    buf.set_string(inner.x, inner.y, label(kh), th.dim());
    buf.set_string(inner.x, inner.y + heat_h / 2, "k N/m", th.dim());
    buf.set_string(inner.x, inner.y + heat_h - 1, label(kl), th.dim());
    let best = (design.best.values[0], design.best.values[1]);
    heat::draw(&design.map, d.limit_m, best, (d.now[0], d.now[1]), th, heat, buf);
    let c_row = inner.y + heat_h;
    let hi = num(ch, 3);
    buf.set_string(heat.x, c_row, num(cl, 3), th.dim());
    let mid = "c N·s/m";
    let mid_x = heat.x + heat_w.saturating_sub(mid.chars().count() as u16) / 2;
    buf.set_string(mid_x, c_row, mid, th.dim());
    buf.set_string(heat.x + heat_w.saturating_sub(hi.chars().count() as u16), c_row, &hi, th.dim());
    let (lo, hi) = heat::range(&design.map);
    let g = |x: (char, char)| heat::glyph(x, th.ascii);
    let shades: String = heat::SHADES.iter().map(|&s| g(s)).collect();
    let legend = format!(
        "{shades} SEAT {}–{} %  {} limit  {} best  {} now",
        num(lo, 3),
        num(hi, 3),
        g(heat::CONTOUR),
        g(heat::BEST),
        g(heat::NOW)
    );
    let legend_w = usize::from(inner.width);
    buf.set_string(inner.x, c_row + 1, clip(&legend, legend_w), th.dim());
    let nums = Rect::new(inner.x + inner.width - num_w, inner.y, num_w, heat_h);
    Paragraph::new(numbers).render(nums, buf);
}

/// The numbers beside the map: the best point and the model's own.
fn numbers(
    design: &Design,
    d: &SeatData,
    now: Option<&SeatFigures>,
    th: Theme,
    height: u16,
) -> Vec<Line<'static>> {
    let g = |x: (char, char)| heat::glyph(x, th.ascii);
    let b = &design.best;
    let mm = |m: f64| num(m * 1e3, 3);
    let (k, c) = (b.values[0], b.values[1]);
    let seat_now = now.map_or("–".into(), |f| num(f.seat_pct, 3));
    let stroke_now = now.map_or("–".into(), |f| mm(f.stroke_rms_m));
    let edge = design.vary.iter().zip(&b.values).any(|(v, &x)| {
        (x / v.lo - 1.0).abs() < 1e-6 || (x / v.hi - 1.0).abs() < 1e-6
    });
    let long = height >= 14;
    let mut out = Vec::new();
    let h = |s: String| Line::styled(s, th.heading());
    if long {
        out.push(h(format!("{} best", g(heat::BEST))));
        out.push(Line::raw(format!(" k {} N/m", num(k, 4))));
        out.push(Line::raw(format!(" c {} N·s/m", num(c, 4))));
        out.push(Line::raw(format!(" SEAT {} %", num(b.figures.seat_pct, 3))));
        out.push(Line::raw(format!(" stroke {} mm", mm(b.figures.stroke_rms_m))));
        if edge {
            out.push(Line::styled(" on the box's edge".to_string(), th.dim()));
        }
        out.push(h(format!("{} now", g(heat::NOW))));
        out.push(Line::raw(format!(" k {} N/m", num(d.now[0], 4))));
        out.push(Line::raw(format!(" c {} N·s/m", num(d.now[1], 4))));
        out.push(Line::raw(format!(" SEAT {seat_now} %")));
        out.push(Line::raw(format!(" stroke {stroke_now} mm")));
        out.push(Line::styled(format!("limit {} mm", mm(d.limit_m)), th.dim()));
        out.push(Line::styled(" r.m.s. (s edits)".to_string(), th.dim()));
        out.push(Line::styled("box ×1/4…×4 (c)".to_string(), th.dim()));
    } else {
        out.push(h(format!(
            "{} best {} %{}",
            g(heat::BEST),
            num(b.figures.seat_pct, 3),
            if edge { " edge" } else { "" }
        )));
        out.push(Line::raw(format!(" k {} c {}", num(k, 3), num(c, 3))));
        out.push(Line::raw(format!(" stroke {} mm", mm(b.figures.stroke_rms_m))));
        out.push(h(format!("{} now {seat_now} %", g(heat::NOW))));
        out.push(Line::raw(format!(" k {} c {}", num(d.now[0], 3), num(d.now[1], 3))));
        out.push(Line::raw(format!(" stroke {stroke_now} mm")));
    }
    out
}
