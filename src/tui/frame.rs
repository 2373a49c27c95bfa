//! The frame around the tabs: the title line (tabs, file, modified mark),
//! the status line and the hint bar; the open field and dialog draw
//! themselves over it (`popups/`). Drawn from a borrowed `&App`; nothing
//! here changes state.

use super::app::App;
use super::keys::{self, Doc, tab_name};
use super::popups::field;
use super::popups::help::HelpLine;
use super::strings;
use super::terminal::{MIN_HEIGHT, MIN_WIDTH};
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget, Wrap};

/// Draws the whole app into the frame.
pub fn draw(frame: &mut ratatui::Frame, app: &App) {
    frame.render_widget(app, frame.area());
}

impl Widget for &App {
    fn render(self, area: Rect, buf: &mut Buffer) {
        self.render_glyphs(area, buf);
        if self.shared.theme.ascii {
            crate::view::chart::asciify(area, buf);
        }
    }
}

impl App {
    /// The whole frame before ASCII mode maps its glyphs (`asciify`): a
    /// test reads it to check that no text names an arrow key by its glyph
    /// there (it would turn into `<` `>` `^` `v`, keys of their own).
    pub(crate) fn render_glyphs(&self, area: Rect, buf: &mut Buffer) {
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
        let [top, body, status, hints] = self.areas(area);
        self.render_title(top, buf);
        if self.zoom {
            self.tab().render_zoomed(&self.shared, body, buf);
        } else {
            self.tab().render(&self.shared, body, buf);
        }
        self.render_status(status, area.height, buf);
        self.render_hints(hints, buf);
        if let Some(f) = &self.field {
            field::render(f, body, buf, th);
        }
        if let Some(p) = self.overlay.popup() {
            p.render(&self.popup_view(), body, buf);
        }
    }
}

impl App {
    /// The frame's rows: title, body, status (one line, more while a
    /// message needs them: [`App::status_rows`]), hint bar.
    fn areas(&self, area: Rect) -> [Rect; 4] {
        let status = self.status_rows(area.width, area.height).len().max(1);
        Layout::vertical([
            Constraint::Length(1),
            Constraint::Min(1),
            Constraint::Length(u16::try_from(status).unwrap_or(1)),
            Constraint::Length(1),
        ])
        .areas(area)
    }

    /// The tab's area in a `width`×`height` terminal (mouse hit tests draw
    /// from the same layout as the frame).
    pub fn body_area(&self, width: u16, height: u16) -> Rect {
        self.areas(Rect::new(0, 0, width, height))[1]
    }

    /// The status area's rows at `width`: the message word-wrapped (never
    /// cut: the status area grows, to at most a quarter of the screen and
    /// at least 2 lines), then the running jobs' summaries, on the
    /// message's last row where they fit, else on a row of their own.
    /// Each row: its part of the message, then its summaries (`  │ …`).
    pub fn status_rows(&self, width: u16, height: u16) -> Vec<(String, String)> {
        let w = usize::from(width.saturating_sub(1)).max(1);
        let cap = usize::from(height / 4).max(2);
        let mut rows: Vec<(String, String)> = Vec::new();
        if !self.status.text.is_empty() {
            let prefix = if self.status.error { "error: " } else { "" };
            let text = format!("{prefix}{}", self.status.text);
            let wrapped = crate::view::format::wrap(&text, w, true);
            rows.extend(
                wrapped
                    .into_iter()
                    .map(|r| (format!(" {r}"), String::new())),
            );
        }
        for t in self.tabs.iter().filter_map(|t| t.summary()) {
            let fits = rows.last().is_some_and(|(m, sum)| {
                m.chars().count() + sum.chars().count() + 4 + t.chars().count()
                    <= usize::from(width)
            });
            match rows.last_mut() {
                Some((_, sum)) if fits => sum.push_str(&format!("  │ {t}")),
                _ => rows.push((String::new(), format!(" {t}"))),
            }
        }
        // Over a quarter of the screen: the summaries' own rows go first
        // (they come back with the message's end), then the message's last
        // row shown ends in "…".
        while rows.len() > cap && rows.last().is_some_and(|(m, _)| m.is_empty()) {
            rows.pop();
        }
        if rows.len() > cap {
            rows.truncate(cap);
            if let Some((m, sum)) = rows.last_mut() {
                sum.clear();
                let keep = usize::from(width).saturating_sub(1);
                let cut = crate::view::format::clip(m, keep);
                *m = format!("{}…", cut.trim_end_matches('…'));
            }
        }
        rows
    }

    /// The title bar's labels: the app name (if it fits), then one per
    /// tab. Full tab names whenever they fit beside the file part at its
    /// shortest unclipped form (the name and " *": `paper-75kg *`, a path's
    /// file name); only then do the other tabs' names shrink, to three
    /// letters, else to one. The app name shows only when everything fits.
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
        let file_w = match self.tab().file() {
            Some(f) => f.label.chars().count(),
            None => self.shared.file_label().chars().count(),
        } + 11;
        let least_file_w = self.least_file_title() + 1;
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
        // Each length of the other tabs' names first two spaces apart, then
        // one (seven full names fit 80 columns so), before cutting them more.
        let n = self.tabs.len();
        let fits = |w: usize| w + least_file_w <= width;
        let (show_app, short, pad) = match full + file_w {
            w if w + 8 <= width => (true, None, " "),
            w if w <= width => (false, None, " "),
            _ if fits(full) => (false, None, " "),
            _ if fits(full - n) => (false, None, ""),
            _ if fits(cut(3)) => (false, Some(3), " "),
            _ if fits(cut(3) - n) => (false, Some(3), ""),
            _ if fits(cut(1)) => (false, Some(1), " "),
            _ => (false, Some(1), ""),
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
                format!(" {}{pad}", tab_name(i, &title))
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
        let own = self.tab().file();
        let (name, builtin) = match (&own, &s.path) {
            // A tab's own new document ("new day") says so itself.
            (Some(f), _) => (f.label.clone(), false),
            (None, Some(p)) => (p.display().to_string(), false),
            (None, None) => (s.preset.name.clone(), true),
        };
        let modified = own.as_ref().map_or(self.modified(), |f| f.modified);
        let clip_end = builtin || own.as_ref().is_some_and(|f| !f.has_path);
        let marks: &[&str] = if modified {
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
        let name = if clip_end {
            crate::view::format::clip(&name, keep)
        } else {
            crate::view::format::clip_start(&name, keep)
        };
        format!("{name}{m}")
    }

    /// Columns of the file part at its shortest before the name is
    /// clipped: the name (a path's file name after "…") and " *".
    fn least_file_title(&self) -> usize {
        let own = self.tab().file();
        let name = match (&own, &self.shared.path) {
            (Some(f), _) => f.label.clone(),
            (None, Some(p)) => p.display().to_string(),
            (None, None) => self.shared.preset.name.clone(),
        };
        let has_path = own
            .as_ref()
            .map_or(self.shared.path.is_some(), |f| f.has_path);
        let n = name.chars().count();
        let shortest = if has_path {
            // clip_start keeps the end: "…" and the file name.
            let base = std::path::Path::new(&name)
                .file_name()
                .map_or(n, |b| b.to_string_lossy().chars().count());
            n.min(base + 1)
        } else {
            n
        };
        shortest + 2
    }

    fn render_status(&self, area: Rect, height: u16, buf: &mut Buffer) {
        let th = self.shared.theme;
        let style = if self.status.error {
            th.error()
        } else {
            th.ok()
        };
        let lines: Vec<Line> = self
            .status_rows(area.width, height)
            .into_iter()
            .map(|(message, sum)| {
                Line::from(vec![
                    Span::styled(message, style),
                    Span::styled(sum, th.dim()),
                ])
            })
            .collect();
        Paragraph::new(lines).render(area, buf);
    }

    fn render_hints(&self, area: Rect, buf: &mut Buffer) {
        let th = self.shared.theme;
        let mut spans = Vec::new();
        // Help and the mouse's state always show, at the right end (`?`,
        // `M`): on a narrow screen they are what a new user needs most.
        let mouse = if self.mouse { "mouse on" } else { "mouse off" };
        let mouse_w = mouse.chars().count() + 4 + "? help ".len() + 1;
        // ASCII turns each arrow into < > ^ v, which are keys too.
        let entries: Vec<(String, &str)> = keys::hints(self.active_keys())
            .into_iter()
            .map(|h| h.split_once(' ').unwrap_or((h, "")))
            .filter(|(k, _)| *k != "?")
            .map(|(k, what)| (keys::arrows(k, th.ascii), what))
            .collect();
        let width = |(k, what): &(String, &str)| k.chars().count() + what.chars().count() + 3;
        // The quit key always shows where it is a key: room is kept for it,
        // and the hints after the first that does not fit are dropped
        // (the tables list the most important first).
        let quit = keys::quit_hint()
            .and_then(|q| q.split_once(' '))
            .map(|(k, _)| k);
        let is_quit = |(k, _): &(String, &str)| Some(k.as_str()) == quit;
        let mut room = (area.width as usize).saturating_sub(1 + mouse_w);
        room = room.saturating_sub(entries.iter().filter(|e| is_quit(e)).map(width).sum());
        let mut full = false;
        let mut used = 1usize + mouse_w;
        for e in &entries {
            let w = width(e);
            if !is_quit(e) {
                if full || w > room {
                    full = true;
                    continue;
                }
                room -= w;
            }
            used += w;
            spans.push(Span::raw(" "));
            spans.push(Span::styled(e.0.clone(), th.key()));
            spans.push(Span::styled(format!(" {} ", e.1), th.dim()));
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

impl App {
    /// The key docs that apply now, most specific first (the hint bar).
    pub fn active_keys(&self) -> Vec<&'static Doc> {
        match self.overlay.popup() {
            Some(p) => p.keys(&self.popup_view()),
            None if self.field.is_some() => field::docs(),
            None => [self.tab().keys(), keys::docs(keys::GLOBAL)].concat(),
        }
    }
}

/// The `?` page's lines for the tab shown (`App::help_lines`).
pub fn help_lines(app: &App) -> Vec<HelpLine> {
    app.help_lines()
}
