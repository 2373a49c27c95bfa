//! Keys and key tables. Every table is a list of [`Binding`]s; the app's
//! own (everywhere) lives here, each dialog (`popups/`) and each tab
//! declares its own in its file. The `?` page, the hint bar and the lookup all read the
//! same tables, so none of them can drift from what the keys really do.

use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

/// A key with the modifiers that matter (Ctrl). Shift is ignored for
/// characters, because terminals disagree on whether `+` or `?` carry it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Key {
    pub code: KeyCode,
    pub ctrl: bool,
    pub alt: bool,
}

pub const fn k(c: char) -> Key {
    Key {
        code: KeyCode::Char(c),
        ctrl: false,
        alt: false,
    }
}
pub const fn ctrl(c: char) -> Key {
    Key {
        code: KeyCode::Char(c),
        ctrl: true,
        alt: false,
    }
}
pub const fn code(code: KeyCode) -> Key {
    Key {
        code,
        ctrl: false,
        alt: false,
    }
}
/// A key with Alt (Meta) held, e.g. Alt-Backspace.
pub const fn alt(code: KeyCode) -> Key {
    Key {
        code,
        ctrl: false,
        alt: true,
    }
}

/// What a binding says about itself: the keys, the help line, the hint.
#[derive(Debug, Clone, Copy)]
pub struct Doc {
    pub keys: &'static [Key],
    /// What it does, for the help screen.
    pub help: &'static str,
    /// Short form for the hint bar (several bindings may share one entry,
    /// e.g. "↑↓←→ move"); None keeps it out of the bar.
    pub hint: Option<&'static str>,
}

/// One row of a table: keys → an action of the table's own type.
#[derive(Debug, Clone, Copy)]
pub struct Binding<A> {
    pub action: A,
    pub doc: Doc,
}

/// A table row: `b(&[keys], action, help, hint)`.
pub const fn b<A>(
    keys: &'static [Key],
    action: A,
    help: &'static str,
    hint: Option<&'static str>,
) -> Binding<A> {
    Binding {
        action,
        doc: Doc { keys, help, hint },
    }
}

/// The action bound to `ev` in `table`.
pub fn lookup<A: Copy>(table: &[Binding<A>], ev: &KeyEvent) -> Option<A> {
    table
        .iter()
        .find(|b| b.doc.keys.iter().any(|k| k.matches(ev)))
        .map(|b| b.action)
}

/// The docs of a table, for the help page and the hint bar.
pub fn docs<A>(table: &'static [Binding<A>]) -> Vec<&'static Doc> {
    table.iter().map(|b| &b.doc).collect()
}

impl Key {
    /// The key as the help screen writes it.
    pub fn label(self) -> String {
        let base = match self.code {
            KeyCode::Char(' ') => "space".to_string(),
            KeyCode::Char(c) => c.to_string(),
            KeyCode::Enter => "Enter".into(),
            KeyCode::Esc => "Esc".into(),
            KeyCode::Tab => "Tab".into(),
            KeyCode::BackTab => "Shift-Tab".into(),
            KeyCode::Up => "↑".into(),
            KeyCode::Down => "↓".into(),
            KeyCode::Left => "←".into(),
            KeyCode::Right => "→".into(),
            KeyCode::PageUp => "PgUp".into(),
            KeyCode::PageDown => "PgDn".into(),
            KeyCode::Home => "Home".into(),
            KeyCode::End => "End".into(),
            KeyCode::Backspace => "Backspace".into(),
            KeyCode::Delete => "Delete".into(),
            other => format!("{other:?}"),
        };
        if self.ctrl {
            format!("Ctrl-{}", base.to_uppercase())
        } else if self.alt {
            format!("Alt-{base}")
        } else {
            base
        }
    }

    pub fn matches(self, ev: &KeyEvent) -> bool {
        let ev_ctrl = ev.modifiers.contains(KeyModifiers::CONTROL);
        let ev_alt = ev.modifiers.contains(KeyModifiers::ALT);
        if ev_ctrl != self.ctrl || ev_alt != self.alt {
            return false;
        }
        match (self.code, ev.code) {
            // Ctrl-letters arrive lower- or upper-case depending on the terminal.
            (KeyCode::Char(a), KeyCode::Char(b)) if self.ctrl => a.eq_ignore_ascii_case(&b),
            (a, b) => a == b,
        }
    }
}

/// The app's own actions: everywhere, and in the text field and dialogs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Action {
    Quit,
    ForceQuit,
    Help,
    NextTab,
    PrevTab,
    Save,
    Open,
    Undo,
    Redo,
    Up,
    Down,
    Left,
    Right,
    Home,
    End,
    Commit,
    Cancel,
    DeleteBack,
    DeleteFwd,
    KillToStart,
    KillToEnd,
    KillWord,
    KillWordPart,
    Complete,
    Yes,
    No,
    SaveAndQuit,
    PageUp,
    PageDown,
    Search,
    NextMatch,
    Zoom,
    Band,
    Mouse,
}

use Action as A;
use KeyCode as KC;

/// Keys that work on every tab (after the tab's own). The digits that pick
/// a tab are not here: there is one per registered tab (`tab_key`).
pub static GLOBAL: &[Binding<Action>] = &[
    b(
        &[ctrl('c')],
        A::ForceQuit,
        "quit at once, even with unsaved edits",
        None,
    ),
    b(
        &[k('q')],
        A::Quit,
        "quit (asks first: unsaved edits, running training)",
        Some("q quit"),
    ),
    b(&[k('?')], A::Help, "all key bindings", Some("? help")),
    b(&[code(KC::Tab)], A::NextTab, "next tab", None),
    b(&[code(KC::BackTab)], A::PrevTab, "previous tab", None),
    b(
        &[ctrl('s')],
        A::Save,
        "save the model as a preset (on the Day tab: the day file); asks for a path",
        Some("^S save"),
    ),
    b(
        &[ctrl('o')],
        A::Open,
        "open a preset: presets/*.toml, built-ins, a path (on the Day tab: a day file)",
        Some("^O open"),
    ),
    b(
        &[k('u')],
        A::Undo,
        "undo the last model edit (on the Day tab: the last edit of the day)",
        Some("u undo"),
    ),
    b(
        &[ctrl('r')],
        A::Redo,
        "redo (on the Day tab: of the day)",
        Some("^R redo"),
    ),
    b(
        &[k('z')],
        A::Zoom,
        "zoom: the tab's chart full-screen (z or Esc: back)",
        Some("z zoom"),
    ),
    b(
        &[k('b')],
        A::Band,
        "edit the band: from, to, step in Hz (undoable; saved with the preset)",
        Some("b band"),
    ),
    // Its state is always on the right of the hint bar (frame.rs).
    b(
        &[k('M')],
        A::Mouse,
        "mouse on/off: click tabs, values, charts (off: select text to copy)",
        None,
    ),
];

/// The quit key's hint-bar entry ("q quit"): the hint bar always keeps it.
pub fn quit_hint() -> Option<&'static str> {
    GLOBAL
        .iter()
        .find(|b| b.action == A::Quit)
        .and_then(|b| b.doc.hint)
}

/// The key that opens tab `i` (0-based): '1', '2', …; None past nine tabs.
pub fn tab_key(i: usize) -> Option<Key> {
    let d = u32::try_from(i + 1).ok().filter(|&d| d <= 9)?;
    char::from_digit(d, 10).map(k)
}

/// Which tab a key opens, among `n` tabs.
pub fn tab_of(ev: &KeyEvent, n: usize) -> Option<usize> {
    (0..n).find(|&i| tab_key(i).is_some_and(|key| key.matches(ev)))
}

/// "1 Model": the digit that opens the tab, then its title.
pub fn tab_name(i: usize, title: &str) -> String {
    match tab_key(i) {
        Some(k) => format!("{} {title}", k.label()),
        None => title.to_string(),
    }
}

/// Hint-bar entries of `docs` (most specific first), without repeats.
pub fn hints<'a>(docs: impl IntoIterator<Item = &'a Doc>) -> Vec<&'static str> {
    let mut out: Vec<&'static str> = Vec::new();
    for d in docs {
        if let Some(h) = d.hint
            && !out.contains(&h)
        {
            out.push(h);
        }
    }
    out
}

/// A text that names arrow keys (a hint, a prompt, a panel title) as the
/// theme shows it: in ASCII with the arrows spelled out ([`ascii_arrows`]),
/// else as written. Not for arrows that are not keys (`◀ value ▶`, `→` in
/// "k4 54000 → 90000"): those stay glyphs.
pub fn arrows(text: &str, ascii: bool) -> String {
    if ascii {
        ascii_arrows(text)
    } else {
        text.to_string()
    }
}

/// A key label with its arrows spelled out, for ASCII terminals: there
/// the arrows would become `<` `>` `^` `v`, which are keys of their own.
pub fn ascii_arrows(label: &str) -> String {
    const WORDS: [(&str, &str); 8] = [
        ("←→", "Left/Right"),
        ("↑↓", "Up/Down"),
        ("←", "Left"),
        ("→", "Right"),
        ("↑", "Up"),
        ("↓", "Down"),
        ("◀", "Left"),
        ("▶", "Right"),
    ];
    let mut out = String::new();
    let mut rest = label;
    // Arrows side by side ("↑↓←→") become words with a `/` between them.
    let mut after_word = false;
    while let Some(c) = rest.chars().next() {
        if let Some((arrow, word)) = WORDS.iter().find(|(a, _)| rest.starts_with(a)) {
            if after_word {
                out.push('/');
            }
            out.push_str(word);
            rest = &rest[arrow.len()..];
            after_word = true;
        } else {
            out.push(c);
            rest = &rest[c.len_utf8()..];
            after_word = false;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ctrl_is_told_apart_and_shift_ignored() {
        let s = KeyEvent::new(KeyCode::Char('s'), KeyModifiers::CONTROL);
        assert_eq!(lookup(GLOBAL, &s), Some(A::Save));
        let s = KeyEvent::new(KeyCode::Char('s'), KeyModifiers::NONE);
        assert_eq!(lookup(GLOBAL, &s), None);
        let q = KeyEvent::new(KeyCode::Char('?'), KeyModifiers::SHIFT);
        assert_eq!(lookup(GLOBAL, &q), Some(A::Help));
        let esc = KeyEvent::new(KeyCode::Esc, KeyModifiers::NONE);
        let field = crate::tui::popups::field::FIELD;
        assert_eq!(lookup(field, &esc), Some(A::Cancel));
    }

    #[test]
    fn tab_keys_are_the_digits() {
        assert_eq!(tab_key(0), Some(k('1')));
        assert_eq!(tab_key(8), Some(k('9')));
        assert_eq!(tab_key(9), None);
        let three = KeyEvent::new(KeyCode::Char('3'), KeyModifiers::NONE);
        assert_eq!(tab_of(&three, 5), Some(2));
        assert_eq!(tab_of(&three, 2), None);
    }
}
