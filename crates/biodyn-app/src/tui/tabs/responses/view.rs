//! Drawing the Responses tab: the readout at the cursor, a legend line when
//! measured data are loaded, and one chart per function with the model's
//! curve, the data's points and the main peak. Reads state; changes nothing.

use super::ResponsesTab;
use crate::tui::shared::Shared;
use crate::tui::widgets::SIDE_BY_SIDE;
use crate::view::chart::{self, ChartOpts, Series};
use crate::view::format::{clip, num, unit};
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget, Wrap};

/// "STHT 1.52 ∠-12.3°" for each function at the cursor.
fn readout(t: &ResponsesTab, s: &Shared) -> Line<'static> {
    let th = s.theme;
    let Some(r) = s.derived.as_ref().and_then(|d| d.curve.get(t.cursor)) else {
        return Line::raw("no data");
    };
    let mut spans = vec![Span::styled(
        format!("f {} Hz", num(r.f_hz, 4)),
        th.heading(),
    )];
    for f in biodyn::Function::ALL {
        spans.push(Span::raw("  "));
        spans.push(Span::styled(f.name(), th.key()));
        spans.push(Span::raw(format!(
            " {}{}{} ∠{}°",
            num(r.mag(f), 4),
            if unit(f).is_empty() { "" } else { " " },
            unit(f),
            num(r.phase_deg(f), 3)
        )));
    }
    if s.stale {
        spans.push(Span::styled("  (updating…)", th.dim()));
    }
    Line::from(spans)
}

/// "⣿ model  • data: file.csv: 196 frequencies, …" above the charts: a
/// short chart hides its own legend, and NO_COLOR needs the glyphs named.
fn legend(t: &ResponsesTab, s: &Shared, width: u16) -> Option<Line<'static>> {
    let d = t.data.as_ref()?;
    let th = s.theme;
    let text = format!(
        " data: {}  (X clears, F fits)",
        d.describe()
    );
    Some(Line::from(vec![
        Span::styled(chart::legend_glyph(0, th.ascii), chart::series_style(0, th.mono)),
        Span::raw(" model  "),
        Span::styled(
            chart::legend_glyph(1, th.ascii),
            chart::series_style(1, th.mono),
        ),
        Span::raw(clip(&text, (width as usize).saturating_sub(10))),
    ]))
}

/// Per function (in `derived.functions` order), the model's curve and the
/// data's points for the mode shown; empty where the data have no such
/// column. Built when the curves, the data or the mode change, not per frame.
pub fn overlaid(t: &ResponsesTab, s: &Shared) -> Vec<Vec<Series>> {
    let (Some(o), Some(d)) = (&t.data, &s.derived) else {
        return Vec::new();
    };
    d.functions
        .iter()
        .map(|c| {
            let model = if t.phase { &c.phase } else { &c.mag };
            let Some(data) = o.series(c.function, t.phase, model) else {
                return Vec::new();
            };
            vec![model.clone(), data]
        })
        .collect()
}

pub fn render(t: &ResponsesTab, s: &Shared, area: Rect, buf: &mut Buffer) {
    let legend = legend(t, s, area.width);
    let rows = if legend.is_some() { 2 } else { 1 };
    let [top, charts] =
        Layout::vertical([Constraint::Length(rows), Constraint::Min(3)]).areas(area);
    let Some(d) = &s.derived else {
        Paragraph::new(s.computing())
            .style(s.theme.dim())
            .wrap(Wrap { trim: true })
            .render(area, buf);
        return;
    };
    let [read, key] = Layout::vertical([Constraint::Length(1), Constraint::Length(rows - 1)]).areas(top);
    Paragraph::new(readout(t, s))
        .wrap(Wrap { trim: true })
        .render(read, buf);
    if let Some(l) = legend {
        l.render(key, buf);
    }
    let n = u32::try_from(d.functions.len().max(1)).unwrap_or(1);
    let ratios = vec![Constraint::Ratio(1, n); d.functions.len()];
    let areas = if area.width >= SIDE_BY_SIDE {
        Layout::horizontal(ratios).split(charts)
    } else {
        Layout::vertical(ratios).split(charts)
    };
    let f_cursor = d.curve.get(t.cursor).map(|r| r.f_hz);
    for (i, (c, &cell)) in d.functions.iter().zip(areas.iter()).enumerate() {
        let f = c.function;
        let series = if t.phase { &c.phase } else { &c.mag };
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
        let long = format!("{} ({}){peak}", f.name(), f.long_name());
        let title = if tall && long.chars().count() + 2 <= cell.width as usize {
            long
        } else if tall {
            format!("{}{peak}", f.name())
        } else {
            format!("{} {what} vs f Hz{peak}", f.name())
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
            cursor_x: f_cursor,
            marks,
            y_range: None,
        };
        match t.overlaid.get(i).filter(|v| !v.is_empty()) {
            Some(both) => chart::render(cell, buf, both, &opts),
            None => chart::render(cell, buf, std::slice::from_ref(series), &opts),
        }
    }
}
