//! The mouse on the Study tab: the header's arrows and values, a click
//! in a chart (the frequency cursor and the function), the wheel (legend).

use super::cursor::round4;
use super::layout::layout;
use super::{Action, StudyTab, view};
use crate::tui::component::{Cx, Mouse, MouseKind};
use crate::tui::effect::Effect;
use crate::view::chart;
use crate::view::format::num;
use biodyn::Function;
use ratatui::layout::Rect;

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
