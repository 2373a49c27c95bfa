//! The open-preset dialog (Ctrl-O): a list of presets above a path
//! field. Enter asks the app to open the path (`Act::Open`); the app asks
//! first when unsaved edits would be lost.

use super::field::{self, Field, Purpose};
use super::layout::{clear_for, popup, rows_of, title_fit};
use super::{Act, Popup, View};
use crate::tui::keys::{self, Action, Binding, Doc, b, code};
use crate::tui::widgets::block;
use biodyn::body;
use ratatui::buffer::Buffer;
use ratatui::crossterm::event::{KeyCode, KeyEvent};
use ratatui::layout::Rect;
use ratatui::text::Line;
use ratatui::widgets::{Paragraph, Widget, Wrap};
use std::path::{Path, PathBuf};

/// The open-preset dialog (a list plus a path field; the field's keys apply too).
pub static OPEN: &[Binding<Action>] = &[
    b(
        &[code(KeyCode::Up)],
        Action::Up,
        "previous file (fills the path field)",
        Some("↑↓ pick"),
    ),
    b(&[code(KeyCode::Down)], Action::Down, "next file", None),
    b(
        &[code(KeyCode::Enter)],
        Action::Commit,
        "open the path in the field",
        Some("Enter open"),
    ),
    b(
        &[code(KeyCode::Esc)],
        Action::Cancel,
        "close",
        Some("Esc close"),
    ),
];

#[derive(Debug, Clone, PartialEq)]
pub struct OpenDialog {
    /// (what the list shows, what `Preset::open` gets)
    pub entries: Vec<(String, String)>,
    pub sel: Option<usize>,
    pub field: Field,
}

impl OpenDialog {
    /// `presets/*.toml` and `*.toml` in the working folder, then the
    /// built-ins; the field starts at the current file.
    pub fn new(current: Option<&PathBuf>) -> OpenDialog {
        OpenDialog::in_folder(Path::new("."), current)
    }

    /// The same list for the folder `base`, its files named relative to it
    /// (so a test sees the files it made, not whatever the working folder
    /// holds).
    pub fn in_folder(base: &Path, current: Option<&PathBuf>) -> OpenDialog {
        let mut entries: Vec<(String, String)> = body::listed_presets(base)
            .into_iter()
            .map(|p| {
                let f = p.display().to_string();
                (f.clone(), f)
            })
            .collect();
        for (name, _) in body::SHIPPED {
            entries.push((format!("{name} (built-in)"), name.to_string()));
        }
        let text = current.map(|p| p.display().to_string()).unwrap_or_default();
        OpenDialog {
            entries,
            sel: None,
            field: Field::new(Purpose::OpenPath, "path or built-in name", text),
        }
    }

    /// Moves the selection (wrapping) and fills the field with it.
    pub fn step(&mut self, up: bool) {
        let n = self.entries.len();
        if n == 0 {
            return;
        }
        let i = match (self.sel, up) {
            (None, true) => n - 1,
            (None, false) => 0,
            (Some(i), true) => (i + n - 1) % n,
            (Some(i), false) => (i + 1) % n,
        };
        self.sel = Some(i);
        if let Some((_, arg)) = self.entries.get(i) {
            let arg = arg.clone();
            self.field.set_text(arg);
            self.field.selected = true;
        }
    }
}

impl Popup for OpenDialog {
    fn section() -> (&'static str, Vec<&'static Doc>) {
        ("Open preset (Ctrl-O)", keys::docs(OPEN))
    }

    fn keys(&self, _view: &View) -> Vec<&'static Doc> {
        [keys::docs(OPEN), field::docs()].concat()
    }

    fn on_key(&mut self, ev: &KeyEvent, view: &View) -> Vec<Act> {
        match keys::lookup(OPEN, ev) {
            Some(Action::Cancel) => vec![Act::Close],
            Some(Action::Up) => {
                self.step(true);
                Vec::new()
            }
            Some(Action::Down) => {
                self.step(false);
                Vec::new()
            }
            Some(Action::Commit) if self.field.text.trim().is_empty() => {
                self.field.error = Some(keys::arrows(
                    "give a path or pick a preset with ↑↓",
                    view.theme.ascii,
                ));
                Vec::new()
            }
            Some(Action::Commit) => vec![Act::Close, Act::Open(self.clone(), false)],
            _ => {
                field::edit(&mut self.field, ev);
                Vec::new()
            }
        }
    }

    /// The list of presets above the path field; the field and its refusal
    /// (wrapped, whole) always show, the list scrolls to keep the pick in view.
    fn render(&self, view: &View, area: Rect, buf: &mut Buffer) {
        let th = view.theme;
        let w = area.width.min(76);
        let inner_w = w.saturating_sub(2) as usize;
        let mut bottom = vec![
            Line::raw(""),
            Line::styled("path (type, Tab completes, or pick above):", th.dim()),
        ];
        bottom.extend(field::lines(&self.field, th));
        let bottom_rows = rows_of(&bottom, inner_w);
        let room = (area.height as usize).saturating_sub(2);
        let list_rows = self.entries.len().min(room.saturating_sub(bottom_rows));
        let h = (list_rows + bottom_rows + 2).min(area.height as usize) as u16;
        let r = popup(area, w, h, false);
        clear_for(r, area, buf);
        let skip = self.sel.map_or(0, |s| (s + 1).saturating_sub(list_rows));
        let mut lines: Vec<Line> = self
            .entries
            .iter()
            .enumerate()
            .skip(skip)
            .take(list_rows)
            .map(|(i, (label, _))| {
                let style = if self.sel == Some(i) {
                    th.selected()
                } else {
                    th.base()
                };
                Line::styled(format!(" {label}"), style)
            })
            .collect();
        lines.extend(bottom);
        Paragraph::new(lines)
            .wrap(Wrap { trim: false })
            .block(block(
                &title_fit("open preset — Enter open, Esc close", r.width),
                th,
            ))
            .render(r, buf);
    }

    fn scrolls(&self) -> bool {
        true
    }
}
