//! Where the Study tab draws what, shared by drawing and the mouse: a
//! click lands on the header's arrows or values, a chart, or the legend.

use super::cursor::round4;
use super::{Action, StudyTab, table, view};
use crate::tui::component::{Cx, Mouse, MouseKind};
use crate::tui::effect::Effect;
use crate::tui::widgets::SIDE_BY_SIDE;
use crate::view::chart;
use crate::view::format::num;
use biodyn::Function;
use biodyn::freq::study::Study;
use ratatui::layout::{Constraint, Layout, Rect};

impl StudyTab {
    /// A click on the header's ◀ or ▶ picks the parameter, on the values
    /// edits them; a click in a chart makes its function the current one
    /// (f, export) and puts the cursor on the frequency under it (to 4
    /// significant digits, computed there); the wheel scrolls the legend.
    pub(super) fn mouse(&mut self, m: Mouse, area: Rect, cx: &Cx) -> Vec<Effect> {
        match m.kind {
            MouseKind::WheelUp => return self.act(Action::LegendUp, cx),
            MouseKind::WheelDown => return self.act(Action::LegendDown, cx),
            MouseKind::Click | MouseKind::DoubleClick => {}
        }
        let at = ratatui::layout::Position::new(m.column, m.row);
        if m.row == area.y {
            let s = cx.shared;
            let x = m.column.saturating_sub(area.x) as usize;
            // "vary ◀ {describe} ▶  base {b}  values {v}"
            let left = 5;
            let right = left + 2 + s.describe(self.param()).chars().count() + 1;
            let values = right + 2 + format!("  base {}  ", num(s.body.get(self.param()), 5)).chars().count() - 1;
            return if x == left {
                self.act(Action::Left, cx)
            } else if x == right {
                self.act(Action::Right, cx)
            } else if x >= values {
                self.act(Action::Edit, cx)
            } else {
                Vec::new()
            };
        }
        let Some(Ok(study)) = &self.result else {
            return Vec::new();
        };
        let l = layout(self, study, area, m.zoomed);
        let Some(&(fi, cell)) = l.charts.iter().find(|(_, r)| r.contains(at)) else {
            return Vec::new();
        };
        let b = *cx.shared.band();
        let f = view::chart(self, cx.shared, study, fi, l.charts.len() == 1)
            .and_then(|(series, opts)| {
                chart::layout(cell, series, &opts)?.x_at(m.column, opts.log_x)
            })
            .map(|f| round4(f).clamp(b.from, b.to));
        if let Some(f) = f {
            self.cursor.set(f);
        }
        if fi != self.func {
            self.func = fi;
            let name = Function::ALL.get(fi).map_or("", |f| f.name());
            return vec![Effect::Status(format!("{name}: the chart x exports"))];
        }
        self.cursor.said()
    }
}

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

