//! The mouse on the Model tab: a click selects the table cell under it as
//! the arrow keys would, a double click edits it as Enter would (on a
//! segment's or link's name: renames it, as `r`), the wheel moves the
//! selection a row. Where things are comes from `table::hit`, the layout
//! the tables are drawn with; the side panels and the zoomed chart have
//! nothing to select.

use super::table::{self, Target};
use super::{Action, ModelTab};
use crate::tui::component::{Cx, Mouse, MouseKind};
use crate::tui::effect::Effect;
use ratatui::layout::{Position, Rect};

impl ModelTab {
    pub(super) fn mouse(&mut self, m: Mouse, area: Rect, cx: &Cx) -> Vec<Effect> {
        let s = cx.shared;
        if m.zoomed {
            return Vec::new();
        }
        if self.pending.is_some() {
            // Nothing acts behind the question.
            return vec![Effect::Status(
                "answer the delete question first: y, x, or n/Esc".into(),
            )];
        }
        let (tables, _) = super::view::split(area);
        let at = Position::new(m.column, m.row);
        if !tables.contains(at) {
            return Vec::new();
        }
        // Hold the view where it is drawn, so a click (or the first of a
        // double click) never scrolls another row under the pointer.
        self.top = table::scroll_in(self, s, tables);
        let effects = match m.kind {
            MouseKind::WheelUp | MouseKind::WheelDown => {
                let last = Self::rows(&s.body) - 1;
                self.row = if m.kind == MouseKind::WheelUp {
                    self.row.saturating_sub(1)
                } else {
                    (self.row + 1).min(last)
                };
                self.fit_col(&s.body);
                Vec::new()
            }
            MouseKind::Click | MouseKind::DoubleClick => {
                let double = m.kind == MouseKind::DoubleClick;
                match table::hit(self, s, tables, at) {
                    None => return Vec::new(),
                    Some(Target::Cell { row, col }) => {
                        self.row = row;
                        self.col = col;
                        self.fit_col(&s.body);
                        if double {
                            self.act(Action::Edit, s)
                        } else {
                            Vec::new()
                        }
                    }
                    Some(Target::Name(row)) => {
                        self.row = row;
                        self.fit_col(&s.body);
                        if double {
                            self.act(Action::Rename, s)
                        } else {
                            Vec::new()
                        }
                    }
                }
            }
        };
        self.top = table::scroll_in(self, s, tables);
        effects
    }
}
