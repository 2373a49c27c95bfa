//! A one-line text field: pre-filled, edited in place, committed or
//! cancelled by its owner. It keeps the last refusal so the user sees why.
//! A component like the dialogs: its state, its key table (`FIELD`), its
//! key handler and its drawing.
//!
//! The pre-filled text starts selected (the convention of every GUI text
//! box): the first character typed replaces it, Backspace clears it, and
//! an arrow, Home or End keeps it and edits in place. Ctrl-A/E/U/W/K and
//! Alt-Backspace do what they do in a shell.

use super::Act;
use super::layout::{clear_for, popup, rows_of, title_fit};
use crate::tui::keys::{self, Action, Binding, Doc, alt, b, code, ctrl};
use crate::tui::theme::Theme;
use crate::tui::widgets::block;
use ratatui::buffer::Buffer;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget, Wrap};

/// What a committed field is for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Purpose {
    /// A model parameter: the app parses and sets it (undoable).
    Param(biodyn::Param),
    /// Where to save the preset.
    SavePath,
    /// Where to save the preset before quitting (the quit prompt's `s`).
    SaveAndQuit,
    /// The open dialog's path.
    OpenPath,
    /// Where to write the export the current tab offered (`e`).
    Export,
    /// The band (from, to, step) the app keeps with the preset.
    Band,
    /// Something the tab that opened the field handles; the tag is the
    /// tab's own (a settings row, "save network", …).
    Tab(usize),
}

#[derive(Debug, Clone, PartialEq)]
pub struct Field {
    pub purpose: Purpose,
    pub label: String,
    pub text: String,
    /// The pre-filled text: committing it unchanged changes nothing.
    pub initial: String,
    /// Cursor position in chars.
    pub cursor: usize,
    /// The whole text is selected: typing replaces it.
    pub selected: bool,
    /// A file path: Tab completes it and `~` is the home folder.
    pub path: bool,
    /// Why the last commit was refused.
    pub error: Option<String>,
}

impl Field {
    pub fn new(purpose: Purpose, label: impl Into<String>, text: impl Into<String>) -> Field {
        let text = text.into();
        Field {
            purpose,
            label: label.into(),
            cursor: text.chars().count(),
            selected: !text.is_empty(),
            path: matches!(
                purpose,
                Purpose::SavePath | Purpose::SaveAndQuit | Purpose::OpenPath
            ),
            initial: text.clone(),
            text,
            error: None,
        }
    }

    /// Marks the field as a file path (Tab completes, `~` expands).
    pub fn for_path(mut self) -> Field {
        self.path = true;
        self
    }

    /// Tab: completes the path as far as it is unambiguous; the error line
    /// says how many files still match, or that none does.
    pub fn complete(&mut self) {
        if !self.path {
            return;
        }
        match crate::tui::paths::complete(&self.text) {
            Some((t, 1)) => self.set_text(t),
            Some((t, n)) => {
                self.set_text(t);
                self.error = Some(format!("{n} files match; type more, then Tab"));
            }
            None => self.error = Some("no file starts so".into()),
        }
    }

    fn len(&self) -> usize {
        self.text.chars().count()
    }

    fn byte(&self, char_idx: usize) -> usize {
        self.text
            .char_indices()
            .nth(char_idx)
            .map_or(self.text.len(), |(i, _)| i)
    }

    /// Drops the chars in `from..to` and puts the cursor at `from`.
    fn cut(&mut self, from: usize, to: usize) {
        let (a, b) = (self.byte(from), self.byte(to));
        if a < b {
            self.text.replace_range(a..b, "");
            self.error = None;
        }
        self.cursor = from;
        self.selected = false;
    }

    /// A typed character: replaces a selection, else goes in at the cursor.
    pub fn insert(&mut self, c: char) {
        if self.selected {
            self.text.clear();
            self.cursor = 0;
            self.selected = false;
        }
        let at = self.byte(self.cursor);
        self.text.insert(at, c);
        self.cursor += 1;
        self.error = None;
    }

    /// Typed text (a paste arrives as characters, tabs included).
    pub fn insert_str(&mut self, s: &str) {
        s.chars().for_each(|c| self.insert(c));
    }

    pub fn backspace(&mut self) {
        if self.selected {
            self.cut(0, self.len());
        } else if self.cursor > 0 {
            self.cut(self.cursor - 1, self.cursor);
        }
    }

    pub fn delete(&mut self) {
        if self.selected {
            self.cut(0, self.len());
        } else if self.cursor < self.len() {
            self.cut(self.cursor, self.cursor + 1);
        }
    }

    pub fn left(&mut self) {
        self.selected = false;
        self.cursor = self.cursor.saturating_sub(1);
    }

    pub fn right(&mut self) {
        self.selected = false;
        self.cursor = (self.cursor + 1).min(self.len());
    }

    pub fn home(&mut self) {
        self.selected = false;
        self.cursor = 0;
    }

    pub fn end(&mut self) {
        self.selected = false;
        self.cursor = self.len();
    }

    /// Ctrl-U: everything before the cursor.
    pub fn kill_to_start(&mut self) {
        let to = if self.selected {
            self.len()
        } else {
            self.cursor
        };
        self.cut(0, to);
    }

    /// Ctrl-K: everything from the cursor on.
    pub fn kill_to_end(&mut self) {
        let from = if self.selected { 0 } else { self.cursor };
        self.cut(from, self.len());
    }

    /// Ctrl-W: the word before the cursor (up to whitespace), as bash does.
    pub fn kill_word(&mut self) {
        self.kill_back_while(|c| c.is_whitespace());
    }

    /// Alt-Backspace: back to the previous punctuation or space, so
    /// `presets/my-body.toml` loses `toml`, then `body`, as in readline.
    pub fn kill_word_part(&mut self) {
        self.kill_back_while(|c| !c.is_alphanumeric());
    }

    fn kill_back_while(&mut self, sep: impl Fn(char) -> bool) {
        if self.selected {
            return self.cut(0, self.len());
        }
        let chars: Vec<char> = self.text.chars().collect();
        let mut i = self.cursor.min(chars.len());
        while i > 0 && chars.get(i - 1).is_some_and(|&c| sep(c)) {
            i -= 1;
        }
        while i > 0 && chars.get(i - 1).is_some_and(|&c| !sep(c)) {
            i -= 1;
        }
        self.cut(i, self.cursor);
    }

    /// Replaces the text (a pick from a list, a completion): the cursor at
    /// the end, nothing selected.
    pub fn set_text(&mut self, t: impl Into<String>) {
        self.text = t.into();
        self.end();
        self.error = None;
    }
}

use Action as A;
use KeyCode as KC;

/// A text field is open (cell edit, path prompt, study values).
pub static FIELD: &[Binding<Action>] = &[
    b(
        &[code(KC::Enter)],
        A::Commit,
        "commit (an invalid value is refused, with why)",
        Some("Enter commit"),
    ),
    b(
        &[code(KC::Esc)],
        A::Cancel,
        "cancel, leave the value unchanged",
        Some("Esc cancel"),
    ),
    b(
        &[code(KC::Left)],
        A::Left,
        "move the text cursor (keeps the pre-filled value; typing first replaces it)",
        None,
    ),
    b(&[code(KC::Right)], A::Right, "move the text cursor", None),
    b(
        &[code(KC::Home), ctrl('a')],
        A::Home,
        "start of field",
        None,
    ),
    b(&[code(KC::End), ctrl('e')], A::End, "end of field", None),
    b(
        &[code(KC::Backspace)],
        A::DeleteBack,
        "delete before the cursor (other keys type)",
        None,
    ),
    b(
        &[code(KC::Delete)],
        A::DeleteFwd,
        "delete at the cursor",
        None,
    ),
    b(
        &[ctrl('u')],
        A::KillToStart,
        "delete everything before the cursor",
        None,
    ),
    b(
        &[ctrl('k')],
        A::KillToEnd,
        "delete from the cursor to the end",
        None,
    ),
    b(
        &[ctrl('w')],
        A::KillWord,
        "delete the word before the cursor",
        None,
    ),
    b(
        &[alt(KC::Backspace)],
        A::KillWordPart,
        "delete back to the previous / . - or space",
        None,
    ),
    b(
        &[code(KC::Tab)],
        A::Complete,
        "complete a file path (~ is home); in a value list, a separator",
        None,
    ),
];

/// The field's section of the `?` page.
pub fn section() -> (&'static str, Vec<&'static Doc>) {
    ("Text field", docs())
}

/// The field's keys, for the hint bar.
pub fn docs() -> Vec<&'static Doc> {
    keys::docs(FIELD)
}

/// A key in the app's open field: Enter and Esc go to the app (which
/// knows what the field is for), the rest edits.
pub fn on_key(f: &mut Field, ev: &KeyEvent) -> Vec<Act> {
    match keys::lookup(FIELD, ev) {
        Some(Action::Commit) => vec![Act::CommitField],
        Some(Action::Cancel) => vec![Act::CancelField],
        _ => {
            edit(f, ev);
            Vec::new()
        }
    }
}

/// Longest paste a field takes, characters: a path or a list of values is
/// far shorter; a longer one is a wrong clipboard, refused whole.
pub const MAX_PASTE: usize = 4096;

/// Pasted text into the field at the cursor: a trailing newline dropped,
/// other line breaks and tabs made spaces (a pasted column or row of
/// values becomes a list), other control characters dropped. A paste over
/// [`MAX_PASTE`] is refused whole, the reason shown under the field.
pub fn paste(f: &mut Field, text: &str) {
    let text = text
        .strip_suffix("\r\n")
        .or_else(|| text.strip_suffix('\n'))
        .unwrap_or(text);
    let n = text.chars().count();
    if n > MAX_PASTE {
        f.error = Some(format!(
            "paste of {n} characters refused: a field takes at most {MAX_PASTE}"
        ));
        return;
    }
    let clean: String = text
        .replace("\r\n", " ")
        .chars()
        .filter_map(|c| match c {
            '\n' | '\r' | '\t' => Some(' '),
            c if c.is_control() => None,
            c => Some(c),
        })
        .collect();
    f.insert_str(&clean);
}

/// Cursor moves and deletions from the field table; other characters type.
pub fn edit(f: &mut Field, ev: &KeyEvent) {
    match keys::lookup(FIELD, ev) {
        Some(Action::Left) => f.left(),
        Some(Action::Right) => f.right(),
        Some(Action::Home) => f.home(),
        Some(Action::End) => f.end(),
        Some(Action::DeleteBack) => f.backspace(),
        Some(Action::DeleteFwd) => f.delete(),
        Some(Action::KillToStart) => f.kill_to_start(),
        Some(Action::KillToEnd) => f.kill_to_end(),
        Some(Action::KillWord) => f.kill_word(),
        Some(Action::KillWordPart) => f.kill_word_part(),
        Some(Action::Complete) if f.path => f.complete(),
        // A tab in another field is pasted text: a separator (a space,
        // which a terminal can draw).
        Some(Action::Complete) => f.insert(' '),
        Some(_) => {}
        None => {
            if let KeyCode::Char(c) = ev.code
                && !ev
                    .modifiers
                    .intersects(KeyModifiers::CONTROL | KeyModifiers::ALT)
            {
                f.insert(c);
            }
        }
    }
}

/// The field with a visible cursor cell (reverse video) and the last refusal.
pub fn lines(f: &Field, th: Theme) -> Vec<Line<'static>> {
    let chars: Vec<char> = f.text.chars().collect();
    if f.selected {
        // The pre-filled value, selected: typing replaces it. In ASCII the
        // arrow would read as `<`, a key of its own: it is spelt out.
        let hint = keys::arrows(" (type to replace, ← to edit)", th.ascii);
        let mut lines = vec![Line::from(vec![
            Span::styled(f.text.clone(), th.selected()),
            Span::styled(hint, th.dim()),
        ])];
        if let Some(e) = &f.error {
            lines.push(Line::styled(format!("refused: {e}"), th.error()));
        }
        return lines;
    }
    let before: String = chars[..f.cursor.min(chars.len())].iter().collect();
    let at: String = chars
        .get(f.cursor)
        .map_or(" ".to_string(), |c| c.to_string());
    let after: String = chars.iter().skip(f.cursor + 1).collect();
    let mut lines = vec![Line::from(vec![
        Span::styled(before, th.field()),
        Span::styled(at, th.selected()),
        Span::styled(after, th.field()),
    ])];
    if let Some(e) = &f.error {
        lines.push(Line::styled(format!("refused: {e}"), th.error()));
    }
    lines
}

/// The field at the bottom of `area`, its label and keys in the frame.
pub fn render(f: &Field, area: Rect, buf: &mut Buffer, th: Theme) {
    let w = area.width.min(76);
    let lines = lines(f, th);
    let inner_w = w.saturating_sub(2).max(1) as usize;
    let rows = rows_of(&lines, inner_w);
    let r = popup(area, w, rows as u16 + 2, true);
    clear_for(r, area, buf);
    let frame = block(
        &title_fit(&format!("{} — Enter commit, Esc cancel", f.label), r.width),
        th,
    );
    let inner = frame.inner(r);
    frame.render(r, buf);
    // A text taller than the screen (a long paste): the refusal stays in
    // view at the bottom and the text scrolls to the cursor's row.
    let (text, refusal) = lines.split_at(lines.len().min(1));
    let below = u16::try_from(rows_of(refusal, inner_w)).unwrap_or(u16::MAX);
    let text_h = inner.height.saturating_sub(below);
    // Up to the cursor's cell (a space past the end, as `lines` draws it).
    let mut before: String = f.text.chars().take(f.cursor).collect();
    before.push(f.text.chars().nth(f.cursor).unwrap_or(' '));
    let at_row = crate::view::format::wrapped_rows(&before, inner_w, false).saturating_sub(1);
    let top = u16::try_from(at_row)
        .unwrap_or(u16::MAX)
        .saturating_sub(text_h.saturating_sub(1));
    let top = if f.selected { 0 } else { top };
    Paragraph::new(text.to_vec())
        .wrap(Wrap { trim: false })
        .scroll((top, 0))
        .render(
            Rect {
                height: text_h,
                ..inner
            },
            buf,
        );
    Paragraph::new(refusal.to_vec())
        .wrap(Wrap { trim: false })
        .render(
            Rect {
                y: inner.y + text_h,
                height: below.min(inner.height),
                ..inner
            },
            buf,
        );
}

#[cfg(test)]
#[path = "field_tests.rs"]
mod tests;
