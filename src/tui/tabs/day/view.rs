//! Drawing the Day tab from its state: the operations table above, the
//! per-axis sheet and the day's totals with the verdict in the middle,
//! the points bars below. Nothing here changes state.

use super::DayTab;
use super::bars::{self, verdict_style};
use super::edit::Col;
use super::records::State;
use super::sheet::Row;
use crate::tui::theme::Theme;
use crate::tui::widgets::panel;
use crate::view::format::{clip, num};
use biodyn::exposure::{Day, DayVdv, Source};
use biodyn::iso2631::{A8_ACTION, A8_LIMIT, VDV_ACTION, VDV_LIMIT, Verdict};
use biodyn::time::Axis;
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::Modifier;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget};

pub fn render(t: &DayTab, th: Theme, area: Rect, buf: &mut Buffer) {
    let n = t.ops.len().max(1) as u16;
    let h = area.height;
    let ops_h = (n + 3).min(h * 2 / 5).max(4);
    // The bars: one per operation, the day's and the scale; the sheet
    // (three axes per operation) keeps the day panel's eight rows and
    // takes the rest.
    let bars_h = (n + 4).max(5).min(h.saturating_sub(ops_h + 8)).max(5);
    let [top, mid, bottom] = Layout::vertical([
        Constraint::Length(ops_h),
        Constraint::Min(8),
        Constraint::Length(bars_h),
    ])
    .areas(area);
    let day_w = if area.width >= 140 { 46 } else { 31 };
    let [left, right] =
        Layout::horizontal([Constraint::Min(20), Constraint::Length(day_w)]).areas(mid);
    operations(t, th, top, buf);
    axes_sheet(t, th, left, buf);
    day_panel(t, th, right, buf);
    bars::render(&t.sheet, &t.ops, th, bottom, buf);
}

/// The first of `n` rows shown in `room` so that `sel` is in view.
fn scroll(sel: usize, n: usize, room: usize) -> usize {
    if room == 0 || n <= room {
        0
    } else {
        sel.saturating_sub(room - 1).min(n - room)
    }
}

/// Hours in a narrow column: 2 decimals, fewer as they grow; "never";
/// "<0.01" rather than a 0.00 that reads as no time.
fn hours(h: Option<f64>) -> String {
    match h {
        None => "never".into(),
        Some(h) if h < 0.005 => "<0.01".into(),
        Some(h) if h < 100.0 => format!("{h:.2}"),
        Some(h) if h < 1e5 => format!("{h:.0}"),
        Some(_) => ">1e5".into(),
    }
}

fn operations(t: &DayTab, th: Theme, area: Rect, buf: &mut Buffer) {
    let inner = panel(
        "operations: a_w m/s² before k, or a record (Enter edits)",
        th,
        area,
        buf,
    );
    let w = inner.width as usize;
    let name_w = t
        .ops
        .iter()
        .map(|o| o.name.chars().count())
        .max()
        .unwrap_or(0)
        .clamp(9, if w >= 140 { 30 } else { 16 });
    let rec_w = w.saturating_sub(name_w + 7 + 3 * 7 + 2);
    let mut lines = vec![Line::styled(
        format!(
            " {:<name_w$} {:>6} {:>6} {:>6} {:>6}  {}",
            "operation", "hours", "a_w x", "a_w y", "a_w z", "record (axes, unit)"
        ),
        th.dim(),
    )];
    if t.ops.is_empty() {
        lines.push(Line::raw(" no operations: a adds one, Ctrl-O opens a day file"));
    }
    let room = (inner.height as usize).saturating_sub(1);
    let first = scroll(t.row, t.ops.len(), room);
    for (i, o) in t.ops.iter().enumerate().skip(first).take(room) {
        let sel = |c: Col| i == t.row && t.col == c;
        let style = |c: Col, dim: bool| {
            if sel(c) {
                th.selected()
            } else if dim {
                th.dim()
            } else {
                th.base()
            }
        };
        let mark = if i == t.row { "›" } else { " " }; // `>` in ASCII
        let mut spans = vec![
            Span::raw(mark),
            Span::styled(
                format!("{:<name_w$}", clip(&o.name, name_w)),
                style(Col::Name, false).add_modifier(if i == t.row {
                    Modifier::BOLD
                } else {
                    Modifier::empty()
                }),
            ),
            Span::raw(" "),
            Span::styled(format!("{:>6}", num(o.hours, 4)), style(Col::Hours, false)),
        ];
        let (cells, dim, record): ([String; 3], bool, String) = match &o.source {
            Source::Measured { aw, .. } => (
                Axis::ALL.map(|a| aw.get(a).map_or("-".into(), |v| num(*v, 3))),
                false,
                String::new(),
            ),
            Source::Record(r) => {
                let cells = match t.records.get(r) {
                    Some(State::Done(Ok(m))) => {
                        Axis::ALL.map(|a| m.axes.get(a).map_or("-".into(), |x| num(x.aw, 3)))
                    }
                    Some(State::Done(Err(_))) => ["err".into(), "err".into(), "err".into()],
                    _ => ["…".into(), "…".into(), "…".into()],
                };
                (cells, true, super::edit::record_text(r))
            }
        };
        for (a, c) in Axis::ALL.iter().zip(cells) {
            spans.push(Span::raw(" "));
            spans.push(Span::styled(format!("{c:>6}"), style(Col::Aw(*a), dim)));
        }
        spans.push(Span::raw("  "));
        let rec = if record.is_empty() && sel(Col::Record) {
            "-".to_string()
        } else {
            clip(&record, rec_w)
        };
        spans.push(Span::styled(rec, style(Col::Record, false)));
        lines.push(Line::from(spans));
    }
    Paragraph::new(lines).render(inner, buf);
}

/// Per operation and axis, as `biodyn day`'s sheet: k·a_w, partial A(8),
/// points, hours to the action and limit values (and VDV when wide, and
/// the hours to the VDV values when wider; "-" without a VDV).
fn axes_sheet(t: &DayTab, th: Theme, area: Rect, buf: &mut Buffer) {
    let inner = panel(
        "per operation and axis (k 1.4 on x, y; 1.0 on z)",
        th,
        area,
        buf,
    );
    let w = inner.width as usize;
    let vdv = w >= 70;
    let vdv_h = w >= 90;
    let fixed = 3 + 7 * 3 + 8 * 2 + if vdv { 9 } else { 0 } + if vdv_h { 20 } else { 0 };
    let name_w = w.saturating_sub(fixed).clamp(4, 24);
    let mut head = format!(
        "{:<name_w$} {:>2} {:>6} {:>6} {:>6} {:>7} {:>7}",
        clip("operation", name_w), "ax", "k·a_w", "A(8)", "points", "EAV h", "ELV h"
    );
    if vdv {
        head.push_str(&format!(" {:>8}", "VDV"));
    }
    if vdv_h {
        head.push_str(&format!(" {:>9} {:>9}", "VDV EAV h", "VDV ELV h"));
    }
    // (operation, line)
    let mut rows: Vec<(usize, Line)> = Vec::new();
    for (i, (row, o)) in t.sheet.rows.iter().zip(&t.ops).enumerate() {
        let name = clip(&o.name, name_w);
        let name_style = if i == t.row {
            th.base().add_modifier(Modifier::BOLD)
        } else {
            th.base()
        };
        match row {
            Row::Done(op) if op.axes.is_empty() => rows.push((
                i,
                Line::from(vec![
                    Span::styled(format!("{name:<name_w$} "), name_style),
                    Span::styled("no a_w yet: Enter on a_w x, y or z", th.dim()),
                ]),
            )),
            Row::Done(op) => {
                for (k, (a, e)) in op.axes.iter().enumerate() {
                    let shown = if k == 0 { name.as_str() } else { "" };
                    let mut s = format!(
                        " {:>2} {:>6.3} {:>6.3} {:>6.1} {:>7} {:>7}",
                        a.name(),
                        e.kaw,
                        e.a8,
                        e.points,
                        hours(e.hours_to_eav),
                        hours(e.hours_to_elv)
                    );
                    if vdv {
                        s.push_str(&format!(
                            " {:>8}",
                            e.vdv_exposure.map_or("-".into(), |v| format!("{v:.2}"))
                        ));
                    }
                    if vdv_h {
                        let [to_eav, to_elv] = match e.hours_to_vdv {
                            Some(h) => [hours(h.to_eav), hours(h.to_elv)],
                            None => ["-".into(), "-".into()],
                        };
                        s.push_str(&format!(" {to_eav:>9} {to_elv:>9}"));
                    }
                    rows.push((
                        i,
                        Line::from(vec![
                            Span::styled(format!("{shown:<name_w$}"), name_style),
                            Span::raw(s),
                        ]),
                    ));
                }
                // What the record's reading assumed or changed, under its
                // rows, as `biodyn day` lists them under the table.
                for n in super::sheet::notes_of(o, &t.records) {
                    for l in indented(&format!("note: {n}"), name_w + 1, w) {
                        rows.push((i, Line::styled(l, th.dim())));
                    }
                }
            }
            Row::Measuring => rows.push((
                i,
                Line::from(vec![
                    Span::styled(format!("{name:<name_w$} "), name_style),
                    Span::styled("reading the record…", th.dim()),
                ]),
            )),
            Row::Failed(why) => {
                for (k, l) in indented(why, name_w + 1, w).into_iter().enumerate() {
                    let shown = if k == 0 { name.as_str() } else { "" };
                    let l = l.get(name_w + 1..).unwrap_or_default().to_string();
                    rows.push((
                        i,
                        Line::from(vec![
                            Span::styled(format!("{shown:<name_w$} "), name_style),
                            Span::styled(l, th.error()),
                        ]),
                    ));
                }
            }
        }
    }
    let room = (inner.height as usize).saturating_sub(1);
    // Keep the selected operation's rows in view: its last row, then its first.
    let last = rows.iter().rposition(|(i, _)| *i == t.row).unwrap_or(0);
    let first_of = rows.iter().position(|(i, _)| *i == t.row).unwrap_or(0);
    let mut top = scroll(last, rows.len(), room);
    if first_of < top {
        top = first_of;
    }
    let mut lines = vec![Line::styled(head, th.dim())];
    lines.extend(rows.into_iter().skip(top).take(room).map(|(_, l)| l));
    Paragraph::new(lines).render(inner, buf);
}

/// `text` wrapped into the `width - indent` columns right of `indent`
/// spaces (a reason or a note under an operation's name), a row each.
fn indented(text: &str, indent: usize, width: usize) -> Vec<String> {
    let room = width.saturating_sub(indent).max(8);
    crate::view::format::wrap(text, room, true)
        .into_iter()
        .map(|l| format!("{:indent$}{l}", ""))
        .collect()
}

/// The day per axis and its exposure: the highest axis of A(8) and of
/// the VDV, marked, with the EU verdicts in words (and colour, where there
/// is colour). A VDV missing from an operation leaves the known part, a
/// lower bound (≥): judged as such, the verdict open only below the limit.
fn day_panel(t: &DayTab, th: Theme, area: Rect, buf: &mut Buffer) {
    let inner = panel("the day (EU 2002/44/EC)", th, area, buf);
    let wide = inner.width >= 40;
    let head = if wide {
        format!(
            "{:<4} {:>9} {:>7}  {:>12}",
            "axis", "A(8) m/s²", "points", "VDV m/s^1.75"
        )
    } else {
        format!("{:<4} {:>6} {:>6}  {:>7}", "axis", "A(8)", "pts", "VDV")
    };
    let mut lines = vec![Line::styled(head, th.dim())];
    let k = t.sheet.left_out.len();
    let left_out = Line::styled(
        format!("not judged: {k} operation{} left out", if k == 1 { "" } else { "s" }),
        th.heading(),
    );
    let Some(d) = &t.sheet.day else {
        lines.push(Line::raw("no operation has an a_w yet"));
        if k > 0 && !t.ops.is_empty() {
            lines.push(left_out);
        }
        Paragraph::new(lines).render(inner, buf);
        return;
    };
    let vdv_axis = d.vdv_verdict.value().map(|v| v.0);
    for (a, x) in d.axes.iter() {
        let m1 = if a == d.a8_axis { "◀" } else { " " };
        let m2 = if Some(a) == vdv_axis { "◀" } else { "" };
        let v = match (x.vdv, x.vdv_known) {
            (Some(v), _) => format!("{v:.2}"),
            (None, Some(v)) => format!("≥{v:.2}"),
            (None, None) => "-".into(),
        };
        lines.push(Line::raw(if wide {
            format!("{:<4} {:>9.3} {:>7.1}{m1} {v:>12}{m2}", a.name(), x.a8, x.points)
        } else {
            format!("{:<4} {:>6.3} {:>6.1}{m1} {v:>7}{m2}", a.name(), x.a8, x.points)
        }));
    }
    if t.sheet.complete() {
        let mut a8 = vec![Span::styled(
            format!("A(8) {}: {}", d.a8_axis, d.eu_a8.words()),
            verdict_style(d.eu_a8, th),
        )];
        if wide {
            a8.push(Span::styled(format!(" ({A8_ACTION}/{A8_LIMIT})"), th.dim()));
        }
        lines.push(Line::from(a8));
        lines.extend(vdv_lines(d, wide, th));
    } else {
        lines.push(left_out);
    }
    let total: f64 = t.ops.iter().map(|o| o.hours).sum();
    lines.push(Line::styled(
        format!("{} h of the day's 24 h", num(total, 4)),
        th.dim(),
    ));
    Paragraph::new(lines).render(inner, buf);
}

/// The day's VDV verdict (a line that fits 29 columns; more when wide),
/// then, for a lower bound, how many operations lack a VDV.
fn vdv_lines(d: &Day, wide: bool, th: Theme) -> Vec<Line<'static>> {
    let values = if wide {
        format!(" ({VDV_ACTION}/{VDV_LIMIT})")
    } else {
        String::new()
    };
    let mut out = Vec::new();
    match d.vdv_verdict {
        DayVdv::Known { axis, verdict, .. }
        | DayVdv::AtLeast {
            axis,
            at_least: verdict @ Verdict::AboveLimit,
            ..
        } => out.push(Line::from(vec![
            Span::styled(format!("VDV {axis}: {}", verdict.words()), verdict_style(verdict, th)),
            Span::styled(values, th.dim()),
        ])),
        DayVdv::AtLeast {
            axis,
            at_least: Verdict::AboveAction,
            ..
        } => out.push(Line::styled(
            if wide {
                format!("VDV {axis}: at least above action, limit open")
            } else {
                format!("VDV {axis}: at least above action")
            },
            verdict_style(Verdict::AboveAction, th),
        )),
        DayVdv::AtLeast { axis, vdv, .. } => out.push(Line::styled(
            if wide {
                format!("VDV not judged: at least {vdv:.2} on {axis}")
            } else {
                format!("VDV not judged (≥{vdv:.2} {axis})")
            },
            th.heading(),
        )),
        DayVdv::Unknown => out.push(Line::styled("VDV not judged: none measured", th.heading())),
    }
    if let DayVdv::AtLeast { .. } = d.vdv_verdict {
        let n = d
            .operations
            .iter()
            .enumerate()
            .filter(|(i, _)| d.axes.iter().any(|(_, x)| x.lacking_vdv.contains(i)))
            .count();
        out.push(Line::styled(
            format!("≥: {n} operation{} without a VDV", if n == 1 { "" } else { "s" }),
            th.dim(),
        ));
    }
    out
}
