//! The frame around the tabs: the title line (tabs, file, modified mark),
//! the status line, the hint bar and the dialogs (text field, help, open,
//! confirmation). Drawn from a borrowed `&App`; nothing here changes state.

use super::app::{App, ConfirmKind, OpenDialog, Overlay, Tab};
use super::field::Field;
use super::keys;
use super::strings;
use super::terminal::{MIN_HEIGHT, MIN_WIDTH};
use super::theme::Theme;
use super::{model, responses, study, training};
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::Style;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Clear, Paragraph, Widget, Wrap};

impl Widget for &App {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let th = self.theme;
        if area.width < MIN_WIDTH || area.height < MIN_HEIGHT {
            let msg = format!(
                "{}: {}x{}, need {MIN_WIDTH}x{MIN_HEIGHT} (q quits)",
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
        match self.tab {
            Tab::Model => model::render(self, body, buf),
            Tab::Responses => responses::render(self, body, buf),
            Tab::Study => study::render(self, body, buf),
            Tab::Training => training::render(self, body, buf),
        }
        self.render_status(status, buf);
        self.render_hints(hints, buf);
        if let Some(f) = &self.field {
            render_field(f, body, buf, th);
        }
        match &self.overlay {
            Overlay::None => {}
            Overlay::Help { scroll } => render_help(*scroll, body, buf, th),
            Overlay::Open(d) => render_open(d, body, buf, th),
            Overlay::Confirm(kind, _) => render_confirm(self, *kind, body, buf),
        }
        if th.ascii {
            crate::view::chart::asciify(area, buf);
        }
    }
}

impl App {
    fn render_title(&self, area: Rect, buf: &mut Buffer) {
        let th = self.theme;
        let mut spans = vec![Span::styled(format!(" {} ", strings::APP), th.title())];
        for (i, t) in strings::TABS.iter().enumerate() {
            let style = if i == self.tab.index() {
                th.active_tab()
            } else {
                th.base()
            };
            spans.push(Span::styled(format!(" {t} "), style));
        }
        let tabs_w: usize = spans.iter().map(|s| s.width()).sum();
        let mut file = self.file_label();
        if self.modified() {
            file.push_str(" *modified");
        }
        let room = (area.width as usize).saturating_sub(tabs_w + 2);
        let file = clip_left(&file, room);
        let pad = (area.width as usize).saturating_sub(tabs_w + file.chars().count() + 1);
        spans.push(Span::raw(" ".repeat(pad)));
        spans.push(Span::styled(file, th.heading()));
        Line::from(spans).render(area, buf);
    }

    fn render_status(&self, area: Rect, buf: &mut Buffer) {
        let th = self.theme;
        let (prefix, style) = if self.status.error {
            ("error: ", th.error())
        } else {
            ("", th.ok())
        };
        let mut spans = vec![Span::styled(
            format!(" {prefix}{}", self.status.text),
            style,
        )];
        if let Some(t) = self.training.summary() {
            spans.push(Span::styled(format!("  │ {t}"), th.dim()));
        }
        Line::from(spans).render(area, buf);
    }

    fn render_hints(&self, area: Rect, buf: &mut Buffer) {
        let th = self.theme;
        let mut spans = Vec::new();
        let mut used = 1usize;
        for h in keys::hints(&self.contexts()) {
            let (k, what) = h.split_once(' ').unwrap_or((h, ""));
            let w = k.chars().count() + what.chars().count() + 3;
            if used + w > area.width as usize {
                break;
            }
            used += w;
            spans.push(Span::raw(" "));
            spans.push(Span::styled(k, th.key()));
            spans.push(Span::styled(format!(" {what} "), th.dim()));
        }
        Line::from(spans).render(area, buf);
    }
}

/// Keeps the end of a long path: the file name matters most.
fn clip_left(s: &str, room: usize) -> String {
    let n = s.chars().count();
    if n <= room {
        s.to_string()
    } else if room < 2 {
        String::new()
    } else {
        let tail: String = s.chars().skip(n - (room - 1)).collect();
        format!("…{tail}")
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

fn block(title: &str, th: Theme) -> Block<'static> {
    Block::bordered()
        .border_set(th.border_set())
        .title(Span::styled(format!(" {title} "), th.heading()))
}

/// The field with a visible cursor cell (reverse video) and the last refusal.
fn field_lines(f: &Field, th: Theme) -> Vec<Line<'static>> {
    let chars: Vec<char> = f.text.chars().collect();
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
    Clear.render(r, buf);
    Paragraph::new(lines)
        .wrap(Wrap { trim: false })
        .block(block(
            &format!("{} — Enter commit, Esc cancel", f.label),
            th,
        ))
        .render(r, buf);
}

fn render_help(scroll: u16, area: Rect, buf: &mut Buffer, th: Theme) {
    let r = popup(area, area.width.min(90), area.height, false);
    Clear.render(r, buf);
    let mut lines = Vec::new();
    for (heading, keys, what) in keys::help_lines() {
        match heading {
            Some(h) => lines.push(Line::styled(h.to_string(), th.heading())),
            None => lines.push(Line::from(vec![
                Span::styled(format!("  {keys:<14}"), th.key()),
                Span::raw(what),
            ])),
        }
    }
    let max = (lines.len() as u16).saturating_sub(r.height.saturating_sub(2));
    Paragraph::new(lines)
        .scroll((scroll.min(max), 0))
        .block(block("keys — ↑↓ scroll, Esc close", th))
        .render(r, buf);
}

fn render_open(d: &OpenDialog, area: Rect, buf: &mut Buffer, th: Theme) {
    let h = (d.entries.len() as u16 + 6).min(area.height);
    let r = popup(area, area.width.min(76), h, false);
    Clear.render(r, buf);
    let mut lines: Vec<Line> = d
        .entries
        .iter()
        .enumerate()
        .map(|(i, (label, _))| {
            let style = if d.sel == Some(i) {
                th.selected()
            } else {
                th.base()
            };
            Line::styled(format!(" {label}"), style)
        })
        .collect();
    lines.push(Line::raw(""));
    lines.push(Line::styled("path (type, or pick above):", th.dim()));
    lines.extend(field_lines(&d.field, th));
    Paragraph::new(lines)
        .wrap(Wrap { trim: false })
        .block(block("open preset — Enter open, Esc close", th))
        .render(r, buf);
}

fn render_confirm(app: &App, kind: ConfirmKind, area: Rect, buf: &mut Buffer) {
    let th = app.theme;
    let mut why = Vec::new();
    if app.modified() {
        why.push("the model has unsaved edits");
    }
    if kind == ConfirmKind::Quit && app.training.running() {
        why.push("a training is running");
    }
    let question = match kind {
        ConfirmKind::Quit => "Quit anyway?",
        ConfirmKind::Discard => "Discard them and open the other preset?",
    };
    let why = why.join(" and ");
    let mut chars = why.chars();
    let why: String = chars
        .next()
        .map(|c| c.to_uppercase().chain(chars).collect())
        .unwrap_or_default();
    let lines = vec![
        Line::raw(format!(" {why}.")),
        Line::styled(format!(" {question}  y yes / n no"), th.heading()),
    ];
    let r = popup(area, area.width.min(64), 4, false);
    Clear.render(r, buf);
    Paragraph::new(lines)
        .style(Style::default())
        .block(block("confirm", th))
        .render(r, buf);
}
