//! The mouse on the Vibration tab. In the settings panel a click selects a
//! row as ↑↓ would, a double click edits it as Enter does (on the signal
//! and unit rows: steps to the next, as →), a click on ◀ or ▶ steps the
//! kind or the unit as ←→ do, and the wheel moves the selection a row. Over the seat and head
//! traces the wheel zooms in and out as `+`/`-` do, but about the time
//! under the pointer, and a click centres the window on the clicked time
//! (the way to reach a spike in a long record; `0` shows it all again).
//! The spectra, the assessment and the verdicts have nothing to select.
//! Where things are comes from `layout::areas`, as drawn.

use super::VibrationTab;
use super::bindings::Action;
use super::layout;
use super::settings::Row;
use super::traces;
use super::view::{self, SettingsHit};
use crate::tui::component::{Cx, Mouse, MouseKind};
use crate::tui::effect::Effect;
use crate::view::format::num;
use ratatui::layout::{Position, Rect};

impl VibrationTab {
    pub(super) fn mouse(&mut self, m: Mouse, area: Rect, cx: &Cx) -> Vec<Effect> {
        let a = layout::areas(self, area, m.zoomed);
        let at = Position::new(m.column, m.row);
        if let Some(set) = a.settings.filter(|r| r.contains(at)) {
            return self.settings_mouse(m.kind, set, at, cx);
        }
        if let Some(tr) = a.traces().filter(|r| r.contains(at)) {
            return self.traces_mouse(m.kind, tr, at);
        }
        Vec::new()
    }

    fn settings_mouse(&mut self, kind: MouseKind, set: Rect, at: Position, cx: &Cx) -> Vec<Effect> {
        let s = cx.shared;
        // Hold the view where it is drawn: the first click of a double
        // click must not scroll another row under the pointer.
        self.settings_top = view::settings_top(self, s, set);
        let last = self.rows().len().saturating_sub(1);
        let effects = match kind {
            MouseKind::WheelUp => {
                self.sel = self.sel.min(last).saturating_sub(1);
                Vec::new()
            }
            MouseKind::WheelDown => {
                self.sel = (self.sel + 1).min(last);
                Vec::new()
            }
            MouseKind::Click | MouseKind::DoubleClick => match view::settings_hit(self, s, set, at)
            {
                None => Vec::new(),
                Some(SettingsHit::Prev(i)) => {
                    self.sel = i;
                    self.act(Action::PrevKind, cx)
                }
                Some(SettingsHit::Next(i)) => {
                    self.sel = i;
                    self.act(Action::NextKind, cx)
                }
                Some(SettingsHit::Row(i)) => {
                    self.sel = i;
                    match (kind, self.rows().get(i)) {
                        (MouseKind::DoubleClick, Some(Row::Kind | Row::Unit | Row::Mean)) => {
                            self.act(Action::NextKind, cx)
                        }
                        (MouseKind::DoubleClick, _) => self.act(Action::Edit, cx),
                        _ => Vec::new(),
                    }
                }
            },
        };
        self.settings_top = view::settings_top(self, s, set);
        effects
    }

    fn traces_mouse(&mut self, kind: MouseKind, area: Rect, at: Position) -> Vec<Effect> {
        let Some((time, frac, t0)) = self
            .outcome()
            .and_then(|o| traces::time_at(self, o, area, at).map(|(t, f)| (t, f, o.traces.t0)))
        else {
            return Vec::new();
        };
        match kind {
            MouseKind::WheelUp => self.zoom_about(1, time, frac),
            MouseKind::WheelDown => self.zoom_about(-1, time, frac),
            MouseKind::Click | MouseKind::DoubleClick if self.zoom == 0 => {
                return vec![Effect::Status(
                    "the whole record shows: the wheel (or +) zooms in about the pointer".into(),
                )];
            }
            MouseKind::Click | MouseKind::DoubleClick => {
                self.centre_on(time);
                return vec![Effect::Status(format!(
                    "centred on {} s (wheel: zoom about the pointer; 0: whole record)",
                    num(t0 + time, 5)
                ))];
            }
        }
        Vec::new()
    }
}
