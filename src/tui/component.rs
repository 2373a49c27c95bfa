//! The contract every tab keeps (gitui's components): it owns its state,
//! names itself, declares its keys, turns a key into effects and draws
//! from read-only shared state. The app holds the tabs as `Box<dyn Tab>`
//! in the order `tabs::all` registers them and knows nothing else of them.

use super::effect::Effect;
use super::event::Mailbox;
use super::keys::{Action, Doc};
use super::shared::Shared;
use ratatui::buffer::Buffer;
use ratatui::crossterm::event::KeyEvent;
use ratatui::layout::Rect;
use std::any::Any;

/// What a tab gets while it handles something: the shared state (read
/// only) and its mailbox to the main channel for background work.
pub struct Cx<'a> {
    pub shared: &'a Shared,
    pub mailbox: Mailbox,
}

/// What changed in the shared state.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Change {
    /// The body was edited (set, undo, redo).
    Edited,
    /// Another model was loaded (a fresh start for per-model state).
    Loaded,
    /// New curves and peaks arrived (`shared.derived`).
    Derived,
}

/// A tab's own file as the title bar shows it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FileTitle {
    /// "examples/day.toml", or "new day" before it has a file.
    pub label: String,
    /// It has a path (a new document's label is clipped at its end).
    pub has_path: bool,
    pub modified: bool,
}

/// A mouse event the app hands to the current tab, in screen cells.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Mouse {
    pub kind: MouseKind,
    pub column: u16,
    pub row: u16,
    /// The tab is drawn zoomed (`render_zoomed`), so its layout differs.
    pub zoomed: bool,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MouseKind {
    /// Left button pressed (acted on at the press, as keys are).
    Click,
    /// A second left press at the same cell within half a second.
    DoubleClick,
    WheelUp,
    WheelDown,
}

pub trait Tab: Any {
    /// The tab for a freshly loaded app (`tabs::all` calls it).
    fn new(shared: &Shared) -> Self
    where
        Self: Sized;

    /// The tab's name in the tab bar and the `?` page ("Model").
    fn title(&self) -> &'static str;

    /// The tab's key table, for the `?` page and the hint bar.
    fn keys(&self) -> Vec<&'static Doc>;

    /// Handles a key from the tab's own table; None if the key is not
    /// one of the tab's (the app's own keys are tried next).
    fn on_key(&mut self, ev: &KeyEvent, cx: &Cx) -> Option<Vec<Effect>>;

    /// One of the app's own keys (`keys::GLOBAL`) that the tab takes
    /// over for its own document: Ctrl-S / Ctrl-O / u / Ctrl-R on the Day
    /// tab save, open, undo and redo the day. None leaves it to the app.
    fn on_global(&mut self, _action: Action, _cx: &Cx) -> Option<Vec<Effect>> {
        None
    }

    /// The tab's own file, shown in the title bar while the tab is (in
    /// place of the model's preset): its label and whether it has unsaved
    /// edits. None shows the preset.
    fn file(&self) -> Option<FileTitle> {
        None
    }

    /// A `Purpose::Tab(tag)` field this tab opened was committed; Err
    /// keeps the field open with the reason.
    fn commit(&mut self, _tag: usize, _text: &str, _cx: &Cx) -> Result<Vec<Effect>, String> {
        Ok(Vec::new())
    }

    /// A click or wheel over the tab's `area` (as last drawn) while mouse
    /// capture is on (`M`). The default ignores it.
    fn on_mouse(&mut self, _m: Mouse, _area: Rect, _cx: &Cx) -> Vec<Effect> {
        Vec::new()
    }

    /// The shared state changed.
    fn on_change(&mut self, _change: Change, _cx: &Cx) {}

    /// A message the tab's own worker sent through its mailbox.
    fn on_msg(&mut self, _msg: Box<dyn Any + Send>, _cx: &Cx) -> Vec<Effect> {
        Vec::new()
    }

    fn render(&self, shared: &Shared, area: Rect, buf: &mut Buffer);

    /// The files the tab has read and shows (measured data, a record, a
    /// network): no save of the app may replace them.
    fn inputs(&self) -> Vec<std::path::PathBuf> {
        Vec::new()
    }

    /// Whether `z` can show one of the tab's charts full-screen now.
    fn has_chart(&self, _shared: &Shared) -> bool {
        false
    }

    /// Draws the tab's main chart alone over `area` (the app's `z`).
    fn render_zoomed(&self, shared: &Shared, area: Rect, buf: &mut Buffer) {
        self.render(shared, area, buf);
    }

    /// A short line shown on every tab's status line (a running training).
    fn summary(&self) -> Option<String> {
        None
    }

    /// Why quitting needs a confirmation ("a training is running").
    fn busy(&self) -> Option<&'static str> {
        None
    }

    /// Stops the tab's background work (on quit).
    fn shutdown(&mut self) {}
}
