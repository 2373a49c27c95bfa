//! The app's dialogs over the tabs, one component per file as a tab is
//! (gitui's `src/popups/`): each owns its state, declares its keys, turns a
//! key into [`Act`]s that the app applies in one place
//! (`App::apply_acts`), and draws from a read-only [`View`] of the app.
//! A new dialog is one file plus one line in the registry below.
//!
//! The text field (`field.rs`) is a component of the same shape; it is not
//! an [`Overlay`] because the open dialog holds one and a tab opens one
//! (`Effect::OpenField`), so the app keeps it beside the overlay.

pub mod field;
mod layout;

use super::keys::Doc;
use super::theme::Theme;
use ratatui::buffer::Buffer;
use ratatui::crossterm::event::KeyEvent;
use ratatui::layout::Rect;

/// What a dialog sees of the app while it handles a key or draws: read
/// only, built by the app (`App::popup_view`).
#[derive(Debug, Clone)]
pub struct View {
    pub theme: Theme,
    /// The terminal's size (80x24 until known).
    pub size: (u16, u16),
    /// Unsaved edits of the body or the band.
    pub modified: bool,
    /// Why quitting needs a yes (`App::quit_reasons`).
    pub quit_reasons: Vec<&'static str>,
    /// A tab's own document (the Day tab's day) has unsaved edits: saving
    /// the model alone, then quitting, would lose them.
    pub other_unsaved: bool,
    /// The `?` page's lines (filled only while the help page is open).
    pub help: Vec<help::HelpLine>,
}

/// What a dialog asks the app to do; `App::apply_acts` carries it out.
/// A dialog stays open unless it says `Close` or `Show`.
#[derive(Debug, Clone, PartialEq)]
pub enum Act {
    /// The dialog closes.
    Close,
    /// Another dialog takes its place (a confirmation, or back).
    Show(Overlay),
    /// Stop background work and leave.
    Quit,
    /// Ask for a path, save the preset there, then quit.
    SaveThenQuit,
    /// Open the preset the dialog's field names; `true` once the user
    /// agreed to discard unsaved edits.
    Open(open::OpenDialog, bool),
    /// The open text field was committed / cancelled.
    CommitField,
    CancelField,
    /// Mouse capture on or off (`M`).
    ToggleMouse,
    /// An error on the status line.
    Fail(String),
}

/// A dialog: the contract of `component::Tab`, for what floats over it.
pub trait Popup {
    /// Its section of the `?` page and of `docs/keys.md`: the heading and
    /// every row it can answer to.
    fn section() -> (&'static str, Vec<&'static Doc>)
    where
        Self: Sized;

    /// The keys that apply now, most specific first (the hint bar).
    fn keys(&self, view: &View) -> Vec<&'static Doc>;

    /// Handles a key; the dialog changes its own state and says the rest.
    fn on_key(&mut self, ev: &KeyEvent, view: &View) -> Vec<Act>;

    /// Draws the dialog over `area` (the tabs' body).
    fn render(&self, view: &View, area: Rect, buf: &mut Buffer);

    /// A mouse wheel step scrolls it (as three ↑ or ↓ presses).
    fn scrolls(&self) -> bool {
        false
    }
}

/// `Variant(module::Type),` per dialog: declares `mod module;`, makes it
/// an `Overlay` and puts its keys on the `?` page (after the text field's,
/// in this order).
macro_rules! register {
    ($($variant:ident($module:ident :: $ty:ident)),+ $(,)?) => {
        $(pub mod $module;)+

        /// The dialog open over the tabs, if any.
        #[derive(Debug, Clone, PartialEq)]
        pub enum Overlay {
            None,
            $($variant($module::$ty)),+
        }

        impl Overlay {
            /// The open dialog as a component.
            pub fn popup(&self) -> Option<&dyn Popup> {
                match self {
                    Overlay::None => None,
                    $(Overlay::$variant(p) => Some(p)),+
                }
            }

            pub fn popup_mut(&mut self) -> Option<&mut dyn Popup> {
                match self {
                    Overlay::None => None,
                    $(Overlay::$variant(p) => Some(p)),+
                }
            }
        }

        /// Every dialog's section of the `?` page, the text field first.
        pub fn sections() -> Vec<(&'static str, Vec<&'static Doc>)> {
            vec![field::section(), $(<$module::$ty as Popup>::section()),+]
        }
    };
}

register! {
    Open(open::OpenDialog),
    Confirm(confirm::Confirm),
    Help(help::HelpView),
}
