//! The TUI's tests: renders through TestBackend (substring checks and
//! insta snapshots of every tab and dialog) and key sequences through the
//! real `update`.

mod ascii_keys;
mod background;
mod behaviour;
mod dialogs;
mod docs_keys;
mod docs_screens;
mod layout;
mod model_structure;
mod mouse_tables;
mod mouse_vibration;
mod paste;
mod path_fields;
mod saving;
mod shown_whole;
mod snapshots;
mod status_lines;
mod structure;
mod title_hints;
mod training;
mod training_bounds;
mod training_model;
mod training_runs;
mod training_screen;

use super::app::App;
use super::derived::Derived;
use super::event::Msg;
use super::tabs::responses::ResponsesTab;
use super::tabs::study::StudyTab;
use super::tabs::training::TrainingTab;
use super::theme::Theme;
use super::update::update;
use crate::view::chart::buffer_text;
use biodyn::Preset;
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

pub fn app() -> App {
    App::new(Preset::builtin_default(), None, Theme::default())
}

/// The app drawn at `w`×`h`, through the layout check (`layout.rs`): a
/// frame that breaks one of its rules fails the test that drew it, so
/// every snapshot taken through here (or `screen`) passes it.
pub fn frame(app: &App, w: u16, h: u16) -> ratatui::buffer::Buffer {
    let _ = crate::view::probe::take();
    let mut t = Terminal::new(TestBackend::new(w, h)).expect("test backend");
    t.draw(|f| super::draw(f, app)).expect("draw");
    let mut buf = t.backend().buffer().clone();
    let marks = crate::view::probe::take();
    let faults = layout::check(&mut buf, &marks);
    assert!(
        faults.is_empty(),
        "the layout check fails at {w}×{h}:\n{}\n{}",
        faults
            .iter()
            .map(|f| f.to_string())
            .collect::<Vec<_>>()
            .join("\n"),
        buffer_text(&buf).join("\n")
    );
    buf
}

/// The app drawn at `w`×`h` as text, through the layout check (`frame`).
pub fn screen(app: &App, w: u16, h: u16) -> String {
    buffer_text(&frame(app, w, h)).join("\n")
}

pub fn key(app: &mut App, code: KeyCode) {
    update(app, Msg::Key(KeyEvent::new(code, KeyModifiers::NONE)));
}

pub fn ctrl(app: &mut App, c: char) {
    update(
        app,
        Msg::Key(KeyEvent::new(KeyCode::Char(c), KeyModifiers::CONTROL)),
    );
}

pub fn typ(app: &mut App, s: &str) {
    for c in s.chars() {
        key(app, KeyCode::Char(c));
    }
}

pub fn derived(app: &App) -> &Derived {
    app.shared.derived.as_ref().expect("derived data")
}

pub fn responses(app: &App) -> &ResponsesTab {
    app.tab_state().expect("responses tab")
}

pub fn study(app: &App) -> &StudyTab {
    app.tab_state().expect("study tab")
}

pub fn training(app: &App) -> &TrainingTab {
    app.tab_state().expect("training tab")
}

/// The open field's error (empty when none is shown or no field is open).
pub fn field_error(app: &App) -> String {
    app.field
        .as_ref()
        .and_then(|f| f.error.clone())
        .unwrap_or_default()
}

/// A crossterm mouse event of `kind` at a 0-based cell, through `update`.
pub fn mouse(
    app: &mut App,
    kind: ratatui::crossterm::event::MouseEventKind,
    column: u16,
    row: u16,
) {
    update(
        app,
        Msg::Mouse(ratatui::crossterm::event::MouseEvent {
            kind,
            column,
            row,
            modifiers: KeyModifiers::NONE,
        }),
    );
}

/// Every file under `dir` (recursively) whose extension is `ext`.
pub fn files_under(dir: &std::path::Path, ext: &str) -> Vec<std::path::PathBuf> {
    fn walk(dir: &std::path::Path, ext: &str, out: &mut Vec<std::path::PathBuf>) {
        let Ok(rd) = std::fs::read_dir(dir) else {
            return;
        };
        for e in rd.flatten() {
            let p = e.path();
            if p.is_dir() {
                walk(&p, ext, out);
            } else if p.extension().is_some_and(|x| x == ext) {
                out.push(p);
            }
        }
    }
    let mut out = Vec::new();
    walk(dir, ext, &mut out);
    out
}

/// The README and every page under `docs/`, one after the other: a test
/// that checks what the docs say finds it whichever page it is on.
pub fn docs_text() -> String {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = vec![root.join("README.md")];
    let mut docs = files_under(&root.join("docs"), "md");
    docs.sort();
    files.extend(docs);
    files
        .iter()
        .filter_map(|p| std::fs::read_to_string(p).ok())
        .collect::<Vec<_>>()
        .join("\n")
}
