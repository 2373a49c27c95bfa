//! Keys and key tables. Every table is a list of [`Binding`]s; the app's
//! own (everywhere, text field, dialogs) live here, each tab declares its
//! own in its file. The `?` page, the hint bar and the lookup all read the
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
        "save the model as a preset (asks for a path)",
        Some("^S save"),
    ),
    b(
        &[ctrl('o')],
        A::Open,
        "open a preset: presets/*.toml, built-ins, a path",
        Some("^O open"),
    ),
    b(
        &[k('u')],
        A::Undo,
        "undo the last model edit",
        Some("u undo"),
    ),
    b(&[ctrl('r')], A::Redo, "redo", Some("^R redo")),
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

/// The open-preset dialog (a list plus a path field; the field's keys apply too).
pub static OPEN: &[Binding<Action>] = &[
    b(
        &[code(KC::Up)],
        A::Up,
        "previous file (fills the path field)",
        Some("↑↓ pick"),
    ),
    b(&[code(KC::Down)], A::Down, "next file", None),
    b(
        &[code(KC::Enter)],
        A::Commit,
        "open the path in the field",
        Some("Enter open"),
    ),
    b(&[code(KC::Esc)], A::Cancel, "close", Some("Esc close")),
];

/// The quit confirmation with unsaved edits (and, on the help page, every
/// confirmation's keys): `s` saves, then quits.
pub static CONFIRM: &[Binding<Action>] = &[
    b(&[k('y')], A::Yes, "yes", Some("y yes")),
    b(
        &[k('s')],
        A::SaveAndQuit,
        "quit prompt: save the model (asks for the path), then quit",
        Some("s save+quit"),
    ),
    b(
        &[k('n'), code(KC::Esc)],
        A::No,
        "no, go back",
        Some("n/Esc no"),
    ),
];

/// The other confirmations (quit with nothing unsaved, discard edits to
/// open a preset): yes or no, no `s`.
pub static CONFIRM_YES_NO: &[Binding<Action>] = &[
    b(&[k('y')], A::Yes, "yes", Some("y yes")),
    b(
        &[k('n'), code(KC::Esc)],
        A::No,
        "no, go back",
        Some("n/Esc no"),
    ),
];

/// This help page.
pub static HELP: &[Binding<Action>] = &[
    b(
        &[code(KC::Up), k('k')],
        A::Up,
        "scroll up",
        Some("↑↓ PgUp/PgDn scroll"),
    ),
    b(&[code(KC::Down), k('j')], A::Down, "scroll down", None),
    b(&[code(KC::PageUp)], A::PageUp, "one page up", None),
    b(
        &[code(KC::PageDown), k(' ')],
        A::PageDown,
        "one page down",
        None,
    ),
    b(&[code(KC::Home), k('g')], A::Home, "top", None),
    b(&[code(KC::End), k('G')], A::End, "bottom", None),
    b(
        &[k('/')],
        A::Search,
        "search (type, Enter keeps it, Esc drops it)",
        Some("/ search"),
    ),
    b(
        &[k('n')],
        A::NextMatch,
        "next match of the search",
        Some("n next"),
    ),
    b(
        &[code(KC::Esc), k('?'), k('q')],
        A::Cancel,
        "close help",
        Some("Esc close"),
    ),
    // The hint bar offers `M` on every screen, this one too.
    b(
        &[k('M')],
        A::Mouse,
        "mouse on/off (the wheel scrolls this page)",
        None,
    ),
];

/// The key that opens tab `i` (0-based): '1', '2', …; None past nine tabs.
pub fn tab_key(i: usize) -> Option<Key> {
    let d = u32::try_from(i + 1).ok().filter(|&d| d <= 9)?;
    char::from_digit(d, 10).map(k)
}

/// Which tab a key opens, among `n` tabs.
pub fn tab_of(ev: &KeyEvent, n: usize) -> Option<usize> {
    (0..n).find(|&i| tab_key(i).is_some_and(|key| key.matches(ev)))
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
    WORDS
        .iter()
        .fold(label.to_string(), |s, (arrow, word)| s.replace(arrow, word))
}

/// One line of the help page: a heading, or "keys  what".
#[derive(Debug, Clone, PartialEq)]
pub enum HelpLine {
    Heading(String),
    Row { keys: String, help: String },
}

impl HelpLine {
    /// The text a search looks in: the heading, or the keys and what.
    pub fn text(&self) -> String {
        match self {
            HelpLine::Heading(t) => t.clone(),
            HelpLine::Row { keys, help } => format!("{keys} {help}"),
        }
    }
}

/// One screen row of the help page: a heading, an entry's first row (its
/// keys and the start of what it does) or a continuation of the
/// description, indented under the description column.
#[derive(Debug, Clone, PartialEq)]
pub struct HelpRow {
    /// Index of the `HelpLine` this row belongs to.
    pub entry: usize,
    pub heading: bool,
    /// The keys, padded to the description column (first row only).
    pub keys: Option<String>,
    /// The heading, or this row's piece of the description (continuation
    /// rows start with the indent).
    pub text: String,
}

/// Keys column of the help page: two spaces, the keys, at least 14 wide.
const KEYS_W: usize = 14;

/// The help page laid out for `inner_w` columns: long descriptions wrap
/// onto continuation rows under the description column, so nothing is
/// cut at the border; scrolling, paging and search count these rows.
pub fn help_rows(help: &[HelpLine], inner_w: usize) -> Vec<HelpRow> {
    let mut out = Vec::new();
    for (entry, l) in help.iter().enumerate() {
        match l {
            HelpLine::Heading(t) => out.push(HelpRow {
                entry,
                heading: true,
                keys: None,
                text: t.clone(),
            }),
            HelpLine::Row { keys, help } => {
                let kw = keys.chars().count();
                let pad = if kw < KEYS_W { KEYS_W } else { kw + 1 };
                let col = 2 + pad;
                let room = inner_w.saturating_sub(col).max(12);
                for (i, piece) in wrap_words(help, room).into_iter().enumerate() {
                    out.push(if i == 0 {
                        HelpRow {
                            entry,
                            heading: false,
                            keys: Some(format!("  {keys:<pad$}")),
                            text: piece,
                        }
                    } else {
                        HelpRow {
                            entry,
                            heading: false,
                            keys: None,
                            text: format!("{:col$}{piece}", ""),
                        }
                    });
                }
            }
        }
    }
    out
}

/// `text` broken at spaces into rows of at most `w` characters (a word
/// longer than a row is broken inside); at least one row.
pub fn wrap_words(text: &str, w: usize) -> Vec<String> {
    let w = w.max(1);
    let mut rows: Vec<String> = Vec::new();
    let mut cur = String::new();
    for word in text.split(' ').filter(|s| !s.is_empty()) {
        let n = word.chars().count();
        let used = cur.chars().count();
        if used > 0 && used + 1 + n > w {
            rows.push(std::mem::take(&mut cur));
        }
        if !cur.is_empty() {
            cur.push(' ');
        }
        cur.push_str(word);
        while cur.chars().count() > w {
            let head: String = cur.chars().take(w).collect();
            let tail: String = cur.chars().skip(w).collect();
            rows.push(head);
            cur = tail;
        }
    }
    rows.push(cur);
    rows
}

/// Appends a section: its heading, then one row per binding.
pub fn help_section(out: &mut Vec<HelpLine>, heading: String, docs: &[&Doc]) {
    out.push(HelpLine::Heading(heading));
    for d in docs {
        let keys: Vec<String> = d.keys.iter().map(|k| k.label()).collect();
        out.push(HelpLine::Row {
            keys: keys.join(" / "),
            help: d.help.to_string(),
        });
    }
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
        assert_eq!(lookup(FIELD, &esc), Some(A::Cancel));
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
