//! The confirmations: quit with something to lose (unsaved edits, a
//! running training) and discarding edits to open another preset. The
//! question is rebuilt every frame from the app's view, so a training that
//! ends while it is open leaves nothing to lose.

use super::open::OpenDialog;
use super::layout::{clear_for, popup};
use super::{Act, Overlay, Popup, View};
use crate::tui::keys::{self, Action, Binding, Doc, b, code, k};
use crate::tui::widgets::block;
use ratatui::buffer::Buffer;
use ratatui::crossterm::event::{KeyCode, KeyEvent};
use ratatui::layout::Rect;
use ratatui::style::Style;
use ratatui::text::Line;
use ratatui::widgets::{Paragraph, Widget};

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ConfirmKind {
    Quit,
    /// Open the preset named in the open dialog's field (kept beside the
    /// confirmation), discarding unsaved edits.
    Discard,
}

/// A question waiting for y or n.
#[derive(Debug, Clone, PartialEq)]
pub struct Confirm {
    pub kind: ConfirmKind,
    /// The open dialog a discard question came from: `n` goes back to it.
    pub back: Option<OpenDialog>,
}

impl Confirm {
    pub fn new(kind: ConfirmKind, back: Option<OpenDialog>) -> Confirm {
        Confirm { kind, back }
    }

    /// The keys it answers to, for its hint and its handling alike: `s`
    /// (save the model, then quit) only when quitting with unsaved model
    /// edits and no other unsaved document, which `s` would lose.
    pub fn table(&self, view: &View) -> &'static [Binding<Action>] {
        match self.kind {
            ConfirmKind::Quit if view.modified && !view.other_unsaved => CONFIRM,
            _ => CONFIRM_YES_NO,
        }
    }
}

/// The quit confirmation with unsaved edits (and, on the help page, every
/// confirmation's keys): `s` saves, then quits.
pub static CONFIRM: &[Binding<Action>] = &[
    b(&[k('y')], Action::Yes, "yes", Some("y yes")),
    b(
        &[k('s')],
        Action::SaveAndQuit,
        "quit prompt: save the model (asks for the path), then quit",
        Some("s save+quit"),
    ),
    b(
        &[k('n'), code(KeyCode::Esc)],
        Action::No,
        "no, go back",
        Some("n/Esc no"),
    ),
];

/// The other confirmations (quit with nothing unsaved, discard edits to
/// open a preset): yes or no, no `s`.
pub static CONFIRM_YES_NO: &[Binding<Action>] = &[
    b(&[k('y')], Action::Yes, "yes", Some("y yes")),
    b(
        &[k('n'), code(KeyCode::Esc)],
        Action::No,
        "no, go back",
        Some("n/Esc no"),
    ),
];

impl Popup for Confirm {
    fn section() -> (&'static str, Vec<&'static Doc>) {
        ("Confirmation", keys::docs(CONFIRM))
    }

    fn keys(&self, view: &View) -> Vec<&'static Doc> {
        keys::docs(self.table(view))
    }

    fn on_key(&mut self, ev: &KeyEvent, view: &View) -> Vec<Act> {
        match (keys::lookup(self.table(view), ev), self.kind) {
            (Some(Action::Yes), ConfirmKind::Quit) => vec![Act::Quit],
            (Some(Action::SaveAndQuit), ConfirmKind::Quit) if view.modified => {
                vec![Act::Close, Act::SaveThenQuit]
            }
            (Some(Action::Yes), ConfirmKind::Discard) => match self.back.take() {
                Some(d) => vec![Act::Close, Act::Open(d, true)],
                None => vec![Act::Close],
            },
            (Some(Action::No), _) => match self.back.take() {
                Some(d) => vec![Act::Show(Overlay::Open(d))],
                None => vec![Act::Close],
            },
            _ => Vec::new(),
        }
    }

    fn render(&self, view: &View, area: Rect, buf: &mut Buffer) {
        let th = view.theme;
        let why = match self.kind {
            ConfirmKind::Quit => view.quit_reasons.clone(),
            ConfirmKind::Discard => vec!["the model has unsaved edits"],
        };
        let question = match self.kind {
            ConfirmKind::Quit if view.modified => "Quit anyway? y yes / s save, then quit / n no",
            ConfirmKind::Quit if why.is_empty() => "Quit now?  y yes / n no",
            ConfirmKind::Quit => "Quit anyway?  y yes / n no",
            ConfirmKind::Discard => "Discard them and open the other preset?  y yes / n no",
        };
        let why = if why.is_empty() {
            "nothing is running or unsaved any more".to_string()
        } else {
            why.join(" and ")
        };
        let mut chars = why.chars();
        let why: String = chars
            .next()
            .map(|c| c.to_uppercase().chain(chars).collect())
            .unwrap_or_default();
        let lines = vec![
            Line::raw(format!(" {why}.")),
            Line::styled(format!(" {question}"), th.heading()),
        ];
        let r = popup(area, area.width.min(64), 4, false);
        clear_for(r, area, buf);
        Paragraph::new(lines)
            .style(Style::default())
            .block(block("confirm", th))
            .render(r, buf);
    }
}
