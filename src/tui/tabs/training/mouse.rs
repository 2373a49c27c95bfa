//! The mouse on the Training tab: a click selects a settings row, a
//! double click edits it (as Enter does), the wheel moves the selection.

use super::view::areas;
use super::{Action, TrainingTab};
use crate::tui::component::{Cx, Mouse, MouseKind};
use crate::tui::effect::Effect;
use ratatui::layout::{Position, Rect};

impl TrainingTab {
    pub(super) fn mouse(&mut self, m: Mouse, area: Rect, cx: &Cx) -> Vec<Effect> {
        match m.kind {
            MouseKind::WheelUp => return self.act(Action::Up, cx),
            MouseKind::WheelDown => return self.act(Action::Down, cx),
            MouseKind::Click | MouseKind::DoubleClick => {}
        }
        // Zoomed, the tab shows only its charts: no rows to click.
        if m.zoomed {
            return Vec::new();
        }
        let Some(i) = self.row_at(area, m.column, m.row) else {
            return Vec::new();
        };
        let picked = i != self.row;
        self.row = i;
        if m.kind == MouseKind::DoubleClick {
            return self.act(Action::Edit, cx);
        }
        if picked {
            vec![Effect::Status(self.describe(self.current(), cx.shared.theme.ascii))]
        } else {
            Vec::new()
        }
    }

    /// The settings row drawn at (`column`, `row`), inside the list's frame.
    pub fn row_at(&self, area: Rect, column: u16, row: u16) -> Option<usize> {
        let a = areas(self, area);
        let s = a.settings;
        let inner = Rect::new(
            s.x.saturating_add(1),
            s.y.saturating_add(1),
            s.width.saturating_sub(2),
            s.height.saturating_sub(2),
        );
        if !inner.contains(Position::new(column, row)) {
            return None;
        }
        let i = usize::from(row - inner.y) + a.scroll;
        (i < self.rows().len()).then_some(i)
    }
}
