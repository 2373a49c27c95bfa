//! The `?` page: every key table the app has, the current tab's first,
//! scrolled, paged and searched (`/`). Its lines are built from the same
//! tables the keys are looked up in, so it cannot drift from them.

use super::layout::{clear_for, popup, title_fit};
use super::{Act, Popup, View};
use crate::tui::keys::{self, Action, Binding, Doc, b, code, k};
use crate::tui::widgets::block;
use crate::view::format::wrap;
use ratatui::buffer::Buffer;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget};

/// Widest the `?` page gets.
pub const HELP_W: u16 = 90;

/// This help page.
pub static HELP: &[Binding<Action>] = &[
    b(
        &[code(KeyCode::Up), k('k')],
        Action::Up,
        "scroll up",
        Some("↑↓ PgUp/PgDn scroll"),
    ),
    b(
        &[code(KeyCode::Down), k('j')],
        Action::Down,
        "scroll down",
        None,
    ),
    b(&[code(KeyCode::PageUp)], Action::PageUp, "one page up", None),
    b(
        &[code(KeyCode::PageDown), k(' ')],
        Action::PageDown,
        "one page down",
        None,
    ),
    b(&[code(KeyCode::Home), k('g')], Action::Home, "top", None),
    b(&[code(KeyCode::End), k('G')], Action::End, "bottom", None),
    b(
        &[k('/')],
        Action::Search,
        "search (type, Enter keeps it, Esc drops it)",
        Some("/ search"),
    ),
    b(
        &[k('n')],
        Action::NextMatch,
        "next match of the search",
        Some("n next"),
    ),
    b(
        &[code(KeyCode::Esc), k('?'), k('q')],
        Action::Cancel,
        "close help",
        Some("Esc close"),
    ),
    // The hint bar offers `M` on every screen, this one too.
    b(
        &[k('M')],
        Action::Mouse,
        "mouse on/off (the wheel scrolls this page)",
        None,
    ),
];

/// The `?` page: where it is scrolled to and what is searched for.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct HelpView {
    /// First line shown.
    pub scroll: usize,
    /// The search text (`/`); lines that hold it are marked.
    pub query: String,
    /// The search text is being typed.
    pub typing: bool,
}

impl HelpView {
    /// The first line at or after `from` (wrapping) whose text holds the
    /// query, ignoring case.
    pub fn find(&self, lines: &[String], from: usize) -> Option<usize> {
        let q = self.query.to_lowercase();
        if q.is_empty() {
            return None;
        }
        let n = lines.len();
        (0..n)
            .map(|i| (from + i) % n)
            .find(|&i| lines.get(i).is_some_and(|l| l.to_lowercase().contains(&q)))
    }
}

impl Popup for HelpView {
    fn section() -> (&'static str, Vec<&'static Doc>) {
        ("This help", keys::docs(HELP))
    }

    fn keys(&self, _view: &View) -> Vec<&'static Doc> {
        keys::docs(HELP)
    }

    /// Scrolling, paging and `/` search. Its length and page come from the
    /// lines and the terminal's height.
    fn on_key(&mut self, ev: &KeyEvent, view: &View) -> Vec<Act> {
        let h = self;
        // The rows as `render` lays them out (long entries wrap): a
        // search finds an entry's first row.
        let (cols, rows) = view.size;
        let help = &view.help;
        let inner_w = usize::from(cols.min(HELP_W).saturating_sub(2));
        let lines: Vec<String> = help_rows(help, inner_w)
            .iter()
            .map(|r| match (&r.keys, r.heading) {
                (Some(_), _) | (_, true) => help.get(r.entry).map(|l| l.text()).unwrap_or_default(),
                _ => String::new(),
            })
            .collect();
        // The page's inner height: the body less the popup's frame.
        let inner_h = usize::from(rows.saturating_sub(5)).max(1);
        let page = inner_h.saturating_sub(1).max(1);
        let last = lines.len().saturating_sub(inner_h);
        if h.typing {
            match ev.code {
                KeyCode::Esc => {
                    h.typing = false;
                    h.query.clear();
                }
                KeyCode::Enter => h.typing = false,
                KeyCode::Backspace => {
                    h.query.pop();
                }
                KeyCode::Char(c)
                    if !ev
                        .modifiers
                        .intersects(KeyModifiers::CONTROL | KeyModifiers::ALT) =>
                {
                    h.query.push(c);
                    if let Some(i) = h.find(&lines, h.scroll) {
                        h.scroll = i;
                    }
                }
                _ => {}
            }
            return Vec::new();
        }
        let mut acts = Vec::new();
        match keys::lookup(HELP, ev) {
            Some(Action::Up) => h.scroll = h.scroll.saturating_sub(1),
            Some(Action::Down) => h.scroll += 1,
            Some(Action::PageUp) => h.scroll = h.scroll.saturating_sub(page),
            Some(Action::PageDown) => h.scroll += page,
            Some(Action::Home) => h.scroll = 0,
            Some(Action::End) => h.scroll = last,
            Some(Action::Search) => {
                h.typing = true;
                h.query.clear();
            }
            Some(Action::NextMatch) => match h.find(&lines, h.scroll + 1) {
                Some(i) => h.scroll = i,
                None if h.query.is_empty() => acts.push(Act::Fail("/ starts a search".into())),
                None => acts.push(Act::Fail(format!(
                    "'{}' not found in the key help",
                    h.query
                ))),
            },
            Some(Action::Mouse) => acts.push(Act::ToggleMouse),
            Some(Action::Cancel) if !h.query.is_empty() => h.query.clear(),
            Some(Action::Cancel) => return vec![Act::Close],
            _ => {}
        }
        h.scroll = h.scroll.min(last);
        acts
    }

    fn render(&self, view: &View, area: Rect, buf: &mut Buffer) {
        let (h, th, help) = (self, view.theme, &view.help);
        let r = popup(area, area.width.min(HELP_W), area.height, false);
        clear_for(r, area, buf);
        let q = h.query.to_lowercase();
        let hits: Vec<bool> = help
            .iter()
            .map(|l| !q.is_empty() && l.text().to_lowercase().contains(&q))
            .collect();
        let found = hits.iter().any(|&b| b);
        let rows = help_rows(help, usize::from(r.width.saturating_sub(2)));
        let lines: Vec<Line> = rows
            .iter()
            .map(|row| {
                let line = match (&row.keys, row.heading) {
                    (_, true) => Line::styled(row.text.clone(), th.heading()),
                    (Some(k), _) => Line::from(vec![
                        Span::styled(k.clone(), th.key()),
                        Span::raw(row.text.clone()),
                    ]),
                    (None, _) => Line::raw(row.text.clone()),
                };
                if hits.get(row.entry).copied().unwrap_or(false) {
                    line.patch_style(th.selected())
                } else {
                    line
                }
            })
            .collect();
        let total = lines.len();
        let max = total.saturating_sub(r.height.saturating_sub(2) as usize);
        let top = h.scroll.min(max);
        let title = if h.typing && !q.is_empty() && !found {
            format!("keys — search: {}_ not found (Esc drop)", h.query)
        } else if h.typing {
            format!("keys — search: {}_ (Enter keep, Esc drop)", h.query)
        } else if !q.is_empty() && !found {
            format!("keys — '{}' not found: / again, Esc clear", h.query)
        } else if !h.query.is_empty() {
            format!("keys — '{}': n next, Esc clear", h.query)
        } else {
            format!(
                "keys {}–{} of {total} — ↑↓ PgUp/PgDn Home/End, / search, Esc close",
                top + 1,
                (top + r.height.saturating_sub(2) as usize).min(total)
            )
        };
        let title = keys::arrows(&title, th.ascii);
        Paragraph::new(lines)
            .scroll((u16::try_from(top).unwrap_or(u16::MAX), 0))
            .block(block(&title_fit(&title, r.width), th))
            .render(r, buf);
    }

    fn scrolls(&self) -> bool {
        true
    }
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

/// The `?` page: the current tab's keys first (the page opens there),
/// then everywhere (with one digit per tab), the other tabs' keys under
/// their names, then the field and the dialogs (`popups::sections`).
/// `tabs`: each tab's title and keys, in tab-bar order.
pub fn lines(tabs: &[(&str, Vec<&'static Doc>)], current: usize, ascii: bool) -> Vec<HelpLine> {
    let mut out = Vec::new();
    let cur = current.min(tabs.len().saturating_sub(1));
    if let Some((title, docs)) = tabs.get(cur) {
        section(&mut out, keys::tab_name(cur, title), docs);
    }
    section(&mut out, "Everywhere".into(), &keys::docs(keys::GLOBAL));
    for (i, (title, _)) in tabs.iter().enumerate() {
        if let Some(k) = keys::tab_key(i) {
            out.push(HelpLine::Row {
                keys: k.label(),
                help: format!("{title} tab"),
            });
        }
    }
    for (i, (title, docs)) in tabs.iter().enumerate().filter(|(i, _)| *i != cur) {
        section(&mut out, keys::tab_name(i, title), docs);
    }
    for (heading, docs) in super::sections() {
        section(&mut out, heading.into(), &docs);
    }
    if ascii {
        for l in &mut out {
            if let HelpLine::Row { keys, .. } = l {
                *keys = keys::ascii_arrows(keys);
            }
        }
    }
    out
}

/// Appends a section: its heading, then one row per binding.
pub fn section(out: &mut Vec<HelpLine>, heading: String, docs: &[&Doc]) {
    out.push(HelpLine::Heading(heading));
    for d in docs {
        let keys: Vec<String> = d.keys.iter().map(|k| k.label()).collect();
        out.push(HelpLine::Row {
            keys: keys.join(" / "),
            help: d.help.to_string(),
        });
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
                for (i, piece) in wrap(help, room, true).into_iter().enumerate() {
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
