//! The frame around the tabs: the title line (tabs, file, modified mark),
//! the status line, the hint bar and the dialogs (text field, help, open,
//! confirmation). Drawn from a borrowed `&App`; nothing here changes state.

use super::app::App;
use super::dialog::{ConfirmKind, HelpView, OpenDialog, Overlay};
use super::field::Field;
use super::keys::{self, Doc, HelpLine};
use super::strings;
use super::terminal::{MIN_HEIGHT, MIN_WIDTH};
use super::theme::Theme;
use super::widgets::block;
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::Style;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Clear, Paragraph, Widget, Wrap};

/// Draws the whole app into the frame.
pub fn draw(frame: &mut ratatui::Frame, app: &App) {
    frame.render_widget(app, frame.area());
}

impl Widget for &App {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let th = self.shared.theme;
        if area.width < MIN_WIDTH || area.height < MIN_HEIGHT {
            let how = if self.quit_reasons().is_empty() {
                "q quits"
            } else {
                "Ctrl-C quits, losing unsaved edits"
            };
            let msg = format!(
                "{}: {}x{}, need {MIN_WIDTH}x{MIN_HEIGHT}; enlarge it ({how}). Keys wait till then.",
                strings::TOO_SMALL,
                area.width,
                area.height
            );
            Paragraph::new(msg)
                .style(th.error())
                .wrap(Wrap { trim: true })
                .render(area, buf);
            return;
        }
        let [top, body, status, hints] = Layout::vertical([
            Constraint::Length(1),
            Constraint::Min(1),
            Constraint::Length(1),
            Constraint::Length(1),
        ])
        .areas(area);
        self.render_title(top, buf);
        if self.zoom {
            self.tab().render_zoomed(&self.shared, body, buf);
        } else {
            self.tab().render(&self.shared, body, buf);
        }
        self.render_status(status, buf);
        self.render_hints(hints, buf);
        if let Some(f) = &self.field {
            render_field(f, body, buf, th);
        }
        match &self.overlay {
            Overlay::None => {}
            Overlay::Help(h) => render_help(&help_lines(self), h, body, buf, th),
            Overlay::Open(d) => render_open(d, body, buf, th),
            Overlay::Confirm(kind, _) => render_confirm(self, *kind, body, buf),
        }
        if th.ascii {
            crate::view::chart::asciify(area, buf);
        }
    }
}

impl App {
    /// The title bar's labels: the app name (if it fits), then one per
    /// tab. Full tab names when they leave room for the file name; else
    /// the app name goes, then names shrink to their first letters.
    fn title_labels(&self, width: u16) -> (Option<String>, Vec<String>) {
        let full: usize = self
            .tabs
            .iter()
            .enumerate()
            .map(|(i, t)| tab_name(i, t.title()).chars().count() + 2)
            .sum();
        let width = width as usize;
        // Decided with the "*modified" mark counted, so the bar does not
        // change shape on the first edit.
        let file_w = self.shared.file_label().chars().count() + 11;
        // Width of the bar with the other tabs' names cut to `n` letters.
        let cut = |n: usize| -> usize {
            self.tabs
                .iter()
                .enumerate()
                .map(|(i, t)| {
                    let len = t.title().chars().count();
                    let len = if i == self.current { len } else { len.min(n) };
                    tab_name(i, &"x".repeat(len)).chars().count() + 2
                })
                .sum()
        };
        let (show_app, short) = match full + file_w {
            w if w + 8 <= width => (true, None),
            w if w <= width => (false, None),
            _ if cut(3) + file_w <= width => (false, Some(3)),
            _ => (false, Some(1)),
        };
        let app = show_app.then(|| format!(" {} ", strings::APP));
        let tabs = self
            .tabs
            .iter()
            .enumerate()
            .map(|(i, t)| {
                let title: String = match short {
                    Some(n) if i != self.current => t.title().chars().take(n).collect(),
                    _ => t.title().to_string(),
                };
                format!(" {} ", tab_name(i, &title))
            })
            .collect();
        (app, tabs)
    }

    /// The tab whose name is drawn at `column` of the title bar (a click).
    pub fn tab_at(&self, width: u16, column: u16) -> Option<usize> {
        let (app, tabs) = self.title_labels(width);
        let mut x = app.map_or(0, |a| a.chars().count());
        let col = usize::from(column);
        for (i, t) in tabs.iter().enumerate() {
            let w = t.chars().count();
            if (x..x + w).contains(&col) {
                return Some(i);
            }
            x += w;
        }
        None
    }

    fn render_title(&self, area: Rect, buf: &mut Buffer) {
        let th = self.shared.theme;
        let (app, tabs) = self.title_labels(area.width);
        let mut spans = Vec::new();
        if let Some(a) = app {
            spans.push(Span::styled(a, th.title()));
        }
        for (i, t) in tabs.into_iter().enumerate() {
            let style = if i == self.current {
                th.active_tab()
            } else {
                th.base()
            };
            spans.push(Span::styled(t, style));
        }
        let tabs_w: usize = spans.iter().map(|s| s.width()).sum();
        let room = (area.width as usize).saturating_sub(tabs_w + 2);
        let file = self.file_title(room);
        let pad = (area.width as usize).saturating_sub(tabs_w + file.chars().count() + 1);
        spans.push(Span::raw(" ".repeat(pad)));
        spans.push(Span::styled(file, th.heading()));
        Line::from(spans).render(area, buf);
    }

    /// The preset's name (or path) and its state within `room` columns:
    /// "(built-in)" goes first, then "*modified" shrinks to "*", then the
    /// name is clipped (a path keeps its end, the file name).
    fn file_title(&self, room: usize) -> String {
        let s = &self.shared;
        let (name, builtin) = match &s.path {
            Some(p) => (p.display().to_string(), false),
            None => (s.preset.name.clone(), true),
        };
        let marks: &[&str] = if self.modified() {
            &[" *modified", " *"]
        } else {
            &[""]
        };
        let mut tries = Vec::new();
        for m in marks {
            if builtin {
                tries.push(format!("{name} (built-in){m}"));
            }
            tries.push(format!("{name}{m}"));
        }
        if let Some(t) = tries.into_iter().find(|t| t.chars().count() <= room) {
            return t;
        }
        let m = marks.last().copied().unwrap_or("");
        let keep = room.saturating_sub(m.chars().count());
        let name = if builtin {
            crate::view::format::clip(&name, keep)
        } else {
            crate::view::format::clip_start(&name, keep)
        };
        format!("{name}{m}")
    }

    fn render_status(&self, area: Rect, buf: &mut Buffer) {
        let th = self.shared.theme;
        let (prefix, style) = if self.status.error {
            ("error: ", th.error())
        } else {
            ("", th.ok())
        };
        let mut spans = Vec::new();
        if !self.status.text.is_empty() {
            spans.push(Span::styled(
                format!(" {prefix}{}", self.status.text),
                style,
            ));
        }
        for t in self.tabs.iter().filter_map(|t| t.summary()) {
            // A separator only after other text: alone, the summary starts the line.
            let sep = if spans.is_empty() { " " } else { "  │ " };
            spans.push(Span::styled(format!("{sep}{t}"), th.dim()));
        }
        Line::from(spans).render(area, buf);
    }

    fn render_hints(&self, area: Rect, buf: &mut Buffer) {
        let th = self.shared.theme;
        let mut spans = Vec::new();
        // Help and the mouse's state always show, at the right end (`?`,
        // `M`): on a narrow screen they are what a new user needs most.
        let mouse = if self.mouse { "mouse on" } else { "mouse off" };
        let mouse_w = mouse.chars().count() + 4 + "? help ".len() + 1;
        let mut used = 1usize + mouse_w;
        for h in keys::hints(self.active_keys()) {
            let (k, what) = h.split_once(' ').unwrap_or((h, ""));
            if k == "?" {
                continue;
            }
            // ASCII turns each arrow into < > ^ v, which are keys too.
            let k = if th.ascii {
                keys::ascii_arrows(k)
            } else {
                k.to_string()
            };
            let w = k.chars().count() + what.chars().count() + 3;
            if used + w > area.width as usize {
                break;
            }
            used += w;
            spans.push(Span::raw(" "));
            spans.push(Span::styled(k, th.key()));
            spans.push(Span::styled(format!(" {what} "), th.dim()));
        }
        let pad = (area.width as usize + 1).saturating_sub(used);
        spans.push(Span::raw(" ".repeat(pad)));
        spans.push(Span::styled("?", th.key()));
        spans.push(Span::styled(" help ", th.dim()));
        spans.push(Span::raw(" "));
        spans.push(Span::styled("M", th.key()));
        spans.push(Span::styled(format!(" {mouse} "), th.dim()));
        Line::from(spans).render(area, buf);
    }
}

/// A rectangle of `w`×`h` centred horizontally in `area`, at `y_frac` of its height.
fn popup(area: Rect, w: u16, h: u16, bottom: bool) -> Rect {
    let w = w.min(area.width);
    let h = h.min(area.height);
    let x = area.x + (area.width - w) / 2;
    let y = if bottom {
        area.bottom() - h
    } else {
        area.y + (area.height - h) / 2
    };
    Rect::new(x, y, w, h)
}

/// Clears the rows a popup covers across the whole of `area`, so no
/// piece of a panel behind it (a corner, a letter) shows beside it.
fn clear_for(r: Rect, area: Rect, buf: &mut Buffer) {
    Clear.render(Rect::new(area.x, r.y, area.width, r.height), buf);
}

/// Rows `lines` take when wrapped to `inner_w` columns.
fn wrapped_rows(lines: &[Line], inner_w: usize) -> usize {
    let inner_w = inner_w.max(1);
    lines
        .iter()
        .map(|l| l.width().max(1).div_ceil(inner_w))
        .sum()
}

/// The field with a visible cursor cell (reverse video) and the last refusal.
fn field_lines(f: &Field, th: Theme) -> Vec<Line<'static>> {
    let chars: Vec<char> = f.text.chars().collect();
    if f.selected {
        // The pre-filled value, selected: typing replaces it.
        let mut lines = vec![Line::from(vec![
            Span::styled(f.text.clone(), th.selected()),
            Span::styled(" (type to replace, ← to edit)", th.dim()),
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

fn render_field(f: &Field, area: Rect, buf: &mut Buffer, th: Theme) {
    let w = area.width.min(76);
    let lines = field_lines(f, th);
    let inner_w = w.saturating_sub(2).max(1) as usize;
    let rows: usize = lines
        .iter()
        .map(|l| l.width().max(1).div_ceil(inner_w))
        .sum();
    let r = popup(area, w, rows as u16 + 2, true);
    clear_for(r, area, buf);
    Paragraph::new(lines)
        .wrap(Wrap { trim: false })
        .block(block(
            &title_fit(&format!("{} — Enter commit, Esc cancel", f.label), r.width),
            th,
        ))
        .render(r, buf);
}

fn render_help(help: &[HelpLine], h: &HelpView, area: Rect, buf: &mut Buffer, th: Theme) {
    let r = popup(area, area.width.min(HELP_W), area.height, false);
    clear_for(r, area, buf);
    let q = h.query.to_lowercase();
    let hits: Vec<bool> = help
        .iter()
        .map(|l| !q.is_empty() && l.text().to_lowercase().contains(&q))
        .collect();
    let found = hits.iter().any(|&b| b);
    let rows = keys::help_rows(help, usize::from(r.width.saturating_sub(2)));
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
    let title = if th.ascii {
        keys::ascii_arrows(&title)
    } else {
        title
    };
    Paragraph::new(lines)
        .scroll((u16::try_from(top).unwrap_or(u16::MAX), 0))
        .block(block(&title_fit(&title, r.width), th))
        .render(r, buf);
}

/// Widest the `?` page gets.
pub const HELP_W: u16 = 90;

/// A popup title cut to its frame (`w` columns) at the last ` — ` part
/// that fits (the key list the hint bar also shows), else clipped.
fn title_fit(title: &str, w: u16) -> String {
    // The block draws the title as " title " from the corner on.
    let room = usize::from(w).saturating_sub(4);
    let mut t = title.to_string();
    while t.chars().count() > room {
        match t.rfind(" — ") {
            Some(i) => t.truncate(i),
            None => return crate::view::format::clip(&t, room),
        }
    }
    t
}

/// The list of presets above the path field; the field and its refusal
/// (wrapped, whole) always show, the list scrolls to keep the pick in view.
fn render_open(d: &OpenDialog, area: Rect, buf: &mut Buffer, th: Theme) {
    let w = area.width.min(76);
    let inner_w = w.saturating_sub(2) as usize;
    let mut bottom = vec![
        Line::raw(""),
        Line::styled("path (type, Tab completes, or pick above):", th.dim()),
    ];
    bottom.extend(field_lines(&d.field, th));
    let bottom_rows = wrapped_rows(&bottom, inner_w);
    let room = (area.height as usize).saturating_sub(2);
    let list_rows = d.entries.len().min(room.saturating_sub(bottom_rows));
    let h = (list_rows + bottom_rows + 2).min(area.height as usize) as u16;
    let r = popup(area, w, h, false);
    clear_for(r, area, buf);
    let skip = d.sel.map_or(0, |s| (s + 1).saturating_sub(list_rows));
    let mut lines: Vec<Line> = d
        .entries
        .iter()
        .enumerate()
        .skip(skip)
        .take(list_rows)
        .map(|(i, (label, _))| {
            let style = if d.sel == Some(i) {
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

fn render_confirm(app: &App, kind: ConfirmKind, area: Rect, buf: &mut Buffer) {
    let th = app.shared.theme;
    let why = match kind {
        ConfirmKind::Quit => app.quit_reasons(),
        ConfirmKind::Discard => vec!["the model has unsaved edits"],
    };
    // Rebuilt every frame: a training run that ends while the question
    // is open leaves nothing to lose.
    let question = match kind {
        ConfirmKind::Quit if app.modified() => "Quit anyway? y yes / s save, then quit / n no",
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

/// "1 Model": the digit that opens the tab, then its title.
pub fn tab_name(i: usize, title: &str) -> String {
    match keys::tab_key(i) {
        Some(k) => format!("{} {title}", k.label()),
        None => title.to_string(),
    }
}

impl App {
    /// The key docs that apply now, most specific first (the hint bar).
    pub fn active_keys(&self) -> Vec<&'static Doc> {
        match &self.overlay {
            Overlay::Confirm(kind, _) => keys::docs(self.confirm_keys(*kind)),
            Overlay::Help(_) => keys::docs(keys::HELP),
            Overlay::Open(_) => [keys::docs(keys::OPEN), keys::docs(keys::FIELD)].concat(),
            Overlay::None if self.field.is_some() => keys::docs(keys::FIELD),
            Overlay::None => [self.tab().keys(), keys::docs(keys::GLOBAL)].concat(),
        }
    }
}

/// The `?` page: the current tab's keys first (the page opens there),
/// then everywhere (with one digit per tab), the other tabs' keys under
/// their names, then the field and the dialogs.
pub fn help_lines(app: &App) -> Vec<HelpLine> {
    let mut out = Vec::new();
    let cur = app.current.min(app.tabs.len().saturating_sub(1));
    if let Some(t) = app.tabs.get(cur) {
        keys::help_section(&mut out, tab_name(cur, t.title()), &t.keys());
    }
    keys::help_section(&mut out, "Everywhere".into(), &keys::docs(keys::GLOBAL));
    for (i, t) in app.tabs.iter().enumerate() {
        if let Some(k) = keys::tab_key(i) {
            out.push(HelpLine::Row {
                keys: k.label(),
                help: format!("{} tab", t.title()),
            });
        }
    }
    for (i, t) in app.tabs.iter().enumerate().filter(|(i, _)| *i != cur) {
        keys::help_section(&mut out, tab_name(i, t.title()), &t.keys());
    }
    keys::help_section(&mut out, "Text field".into(), &keys::docs(keys::FIELD));
    keys::help_section(
        &mut out,
        "Open preset (Ctrl-O)".into(),
        &keys::docs(keys::OPEN),
    );
    keys::help_section(&mut out, "Confirmation".into(), &keys::docs(keys::CONFIRM));
    keys::help_section(&mut out, "This help".into(), &keys::docs(keys::HELP));
    if app.shared.theme.ascii {
        for l in &mut out {
            if let HelpLine::Row { keys, .. } = l {
                *keys = keys::ascii_arrows(keys);
            }
        }
    }
    out
}
