//! Tab 2, Responses: STHT, DPMI and APMS over the band (magnitude or
//! phase, linear or log axes), a frequency cursor that reads the exact
//! values of all three, and the main peaks marked.

use super::app::App;
use super::keys::Action;
use crate::view::chart::{self, ChartOpts};
use crate::view::format::{num, unit};
use biodyn::Function;
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget, Wrap};

/// Width from which the three charts sit side by side.
pub const SIDE_BY_SIDE: u16 = 140;

#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ResponsesTab {
    pub phase: bool,
    pub log: bool,
    /// Index into the band's grid.
    pub cursor: usize,
}

pub fn on_action(app: &mut App, a: Action) {
    let last = app.derived.curve.len().saturating_sub(1);
    let per_hz = (1.0 / app.preset.band.step).round().max(1.0) as usize;
    let t = &mut app.responses;
    match a {
        Action::Left => t.cursor = t.cursor.saturating_sub(1),
        Action::Right => t.cursor = (t.cursor + 1).min(last),
        Action::PageUp => t.cursor = t.cursor.saturating_sub(per_hz),
        Action::PageDown => t.cursor = (t.cursor + per_hz).min(last),
        Action::Home => t.cursor = 0,
        Action::End => t.cursor = last,
        Action::TogglePhase => t.phase = !t.phase,
        Action::ToggleLog => t.log = !t.log,
        Action::NextPeak => {
            let here = app.derived.curve.get(t.cursor).map_or(0.0, |r| r.f_hz);
            let mut fs: Vec<f64> = app.derived.peaks.iter().flatten().map(|p| p.f_hz).collect();
            fs.sort_by(f64::total_cmp);
            let step = app.preset.band.step;
            let next = fs
                .iter()
                .find(|&&f| f > here + step / 2.0)
                .or(fs.first())
                .copied();
            if let Some(f) = next {
                let b = &app.preset.band;
                t.cursor = (((f - b.from) / b.step).round().max(0.0) as usize).min(last);
            }
        }
        _ => {}
    }
}

/// "STHT 1.52 ∠-12.3°" for each function at the cursor.
fn readout(app: &App) -> Line<'static> {
    let th = app.theme;
    let Some(r) = app.derived.curve.get(app.responses.cursor) else {
        return Line::raw("no data");
    };
    let mut spans = vec![Span::styled(
        format!("f {} Hz", num(r.f_hz, 4)),
        th.heading(),
    )];
    for f in Function::ALL {
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
    Line::from(spans)
}

pub fn render(app: &App, area: Rect, buf: &mut Buffer) {
    let t = app.responses;
    let [top, charts] = Layout::vertical([Constraint::Length(1), Constraint::Min(3)]).areas(area);
    Paragraph::new(readout(app))
        .wrap(Wrap { trim: true })
        .render(top, buf);
    let side = area.width >= SIDE_BY_SIDE;
    let areas = if side {
        Layout::horizontal([Constraint::Ratio(1, 3); 3]).split(charts)
    } else {
        Layout::vertical([Constraint::Ratio(1, 3); 3]).split(charts)
    };
    let f_cursor = app.derived.curve.get(t.cursor).map(|r| r.f_hz);
    for (fi, f) in Function::ALL.iter().enumerate() {
        let series = if t.phase {
            &app.derived.phase[fi]
        } else {
            &app.derived.mag[fi]
        };
        let u = unit(*f);
        let what = if t.phase {
            "phase °".to_string()
        } else if u.is_empty() {
            "magnitude".to_string()
        } else {
            format!("magnitude, {u}")
        };
        let tall = areas[fi].height >= 12;
        // The marked peak in numbers, so it can be read, not just seen.
        let peak = match app.derived.main[fi] {
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
        let title = if tall && long.chars().count() + 2 <= areas[fi].width as usize {
            long
        } else if tall {
            format!("{}{peak}", f.name())
        } else {
            format!("{} {what} vs f Hz{peak}", f.name())
        };
        let marks = match app.derived.main[fi] {
            Some(p) if !t.phase && !p.at_edge => vec![(p.f_hz, p.mag)],
            _ => Vec::new(),
        };
        let opts = ChartOpts {
            title,
            x_title: if tall { "f Hz".into() } else { String::new() },
            y_title: if tall { what } else { String::new() },
            log_x: t.log,
            log_y: t.log && !t.phase,
            ascii: app.theme.ascii,
            mono: app.theme.mono,
            cursor_x: f_cursor,
            marks,
            y_range: None,
        };
        chart::render(areas[fi], buf, std::slice::from_ref(series), &opts);
    }
}
