//! Where the Study tab draws what, shared by drawing and the mouse
//! (mouse.rs): the header row, the charts and the legend.

use super::{StudyTab, table};
use biodyn::Function;
use crate::tui::widgets::SIDE_BY_SIDE;
use biodyn::freq::Study;
use ratatui::layout::{Constraint, Layout, Rect};

/// Where the tab draws what: the header row, the charts (with the index
/// of their function) and the peak table; shared by drawing and clicks.
pub struct Areas {
    pub header: Rect,
    /// The current chart's values at the cursor in one line, when zoomed
    /// or too narrow for the legend's cursor column (else no rows).
    pub readout: Rect,
    pub charts: Vec<(usize, Rect)>,
    pub table: Rect,
    pub sentences: bool,
    pub framed: bool,
}

pub fn layout(t: &StudyTab, study: &Study, area: Rect, zoom: bool) -> Areas {
    let shown: Vec<usize> = if area.width >= SIDE_BY_SIDE {
        (0..Function::ALL.len()).collect()
    } else {
        vec![t.func]
    };
    let sentences = area.height >= 34;
    let compare = table::comparable(study);
    // A short tab drops the table's frame (table.rs) to keep the trends.
    let frame = if area.height >= 20 { 2 } else { 0 };
    // The values at the cursor: beside the variants' names in the legend
    // when they fit there, else a line of their own above the chart.
    let line = t.cursor.f_hz.is_some_and(|f_hz| {
        let r = table::Readout {
            f_hz,
            functions: shown
                .iter()
                .filter_map(|&i| Function::ALL.get(i).copied())
                .collect(),
            at: &t.cursor.at,
        };
        zoom || !table::cursor_fits(study, area.width, frame > 0, &r)
    });
    // Without anything to compare, the heading and why (wrapped).
    let message = table::nothing_to_compare(study, area.width, frame > 0).len();
    let message = u16::try_from(message).unwrap_or(u16::MAX);
    let fixed = if compare { 5 } else { 1 + message } + frame + if sentences && compare { 4 } else { 0 };
    let want = u16::try_from(study.variants.len())
        .unwrap_or(u16::MAX)
        .saturating_add(fixed);
    // The chart keeps at least half the tab (and its frame); the table
    // scrolls its variant rows when they do not all fit.
    let chart_min = if area.height >= 20 {
        (area.height.saturating_sub(1) / 2).max(8)
    } else {
        6
    };
    let table_h = if zoom {
        0
    } else {
        let h = want
            .min(area.height.saturating_sub(1 + chart_min))
            .max(fixed.min(area.height / 3));
        // The readout line comes out of the chart's rows while the chart
        // keeps its 6, else out of the table's.
        let chart_rows = area.height.saturating_sub(1 + h);
        if line && chart_rows < 7 {
            h.saturating_sub(7 - chart_rows)
        } else {
            h
        }
    };
    let [header, readout, charts, table] = Layout::vertical([
        Constraint::Length(1),
        Constraint::Length(u16::from(line)),
        Constraint::Min(6),
        Constraint::Length(table_h),
    ])
    .areas(area);
    let n = u32::try_from(shown.len()).unwrap_or(1);
    let cells = Layout::horizontal(vec![Constraint::Ratio(1, n); shown.len()]).split(charts);
    Areas {
        header,
        readout,
        charts: shown.into_iter().zip(cells.iter().copied()).collect(),
        table,
        sentences,
        framed: frame > 0,
    }
}

