//! Where the Model tab draws what: the tables, and beside them (when
//! there is room) the modes, the main peaks and the STHT curve; the mouse
//! asks `split` where the tables are.

use super::{ModelTab, confirm, panels, table};
use crate::tui::shared::Shared;
use crate::view::chart::{self, ChartOpts};
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};

/// Below this width the tables take the whole tab (modes and peaks are on
/// the Responses tab and at larger sizes).
const TABLES_ALONE: u16 = 74;

pub fn render(t: &ModelTab, s: &Shared, area: Rect, buf: &mut Buffer) {
    render_body(t, s, area, buf);
    confirm::render_question(t, s, area, buf);
}

/// Where the tab draws: the tables, and beside them the side panels when
/// there is room (drawing and the mouse both ask here).
pub fn split(area: Rect) -> (Rect, Option<Rect>) {
    if area.width < TABLES_ALONE {
        return (area, None);
    }
    let right_w = if area.width >= 120 {
        area.width - 72
    } else {
        34
    };
    let [left, right] =
        Layout::horizontal([Constraint::Min(40), Constraint::Length(right_w)]).areas(area);
    (left, Some(right))
}

fn render_body(t: &ModelTab, s: &Shared, area: Rect, buf: &mut Buffer) {
    let th = s.theme;
    let wide = area.width >= 120;
    let (left, right) = split(area);
    table::render_tables(t, s, left, buf);
    let Some(right) = right else {
        return;
    };
    // Each panel as tall as its lines wrapped to its width (an error's
    // reason and advice whole); the modes take at most two thirds.
    let modes_h = panels::rows(&panels::modes_lines(s, th, wide), right.width)
        .min(right.height.saturating_mul(2) / 3);
    let peaks_h = panels::rows(&panels::peaks_lines(s, th), right.width)
        .min(right.height.saturating_sub(modes_h));
    let [modes, peaks, rest] = Layout::vertical([
        Constraint::Length(modes_h),
        Constraint::Length(peaks_h),
        Constraint::Min(0),
    ])
    .areas(right);
    panels::modes(s, modes, buf, th, wide);
    panels::peaks(s, peaks, buf, th);
    // On a tall screen, the STHT curve shows every edit at once.
    if rest.height >= 12 {
        stht_chart(s, rest, buf);
    }
}

/// The STHT magnitude with its main peak marked (also the `z` zoom).
pub fn stht_chart(s: &Shared, area: Rect, buf: &mut Buffer) {
    let th = s.theme;
    if let Some(c) = s.derived.as_ref().and_then(|d| d.functions.first()) {
        let f = c.function;
        let marks = c
            .main
            .filter(|p| !p.at_edge)
            .map(|p| vec![(p.f_hz, p.mag)])
            .unwrap_or_default();
        let opts = ChartOpts {
            title: format!("{} ({})", f.name(), f.long_name()),
            x_title: "f Hz".into(),
            y_title: format!("|{}|", f.name()),
            ascii: th.ascii,
            mono: th.mono,
            marks,
            ..Default::default()
        };
        chart::render(area, buf, std::slice::from_ref(&c.mag), &opts);
    }
}
