//! Tab Responses: STHT, DPMI and APMS over the band (magnitude or phase,
//! linear or log axes), a frequency cursor that reads the exact values of
//! all three, and the main peaks marked.

use crate::tui::component::{Change, Cx, Tab};
use crate::tui::effect::Effect;
use crate::tui::keys::{self, Binding, Doc, b, code, k};
use crate::tui::shared::Shared;
use crate::tui::widgets::SIDE_BY_SIDE;
use crate::view::chart::{self, ChartOpts};
use crate::view::format::{num, unit};
use ratatui::buffer::Buffer;
use ratatui::crossterm::event::{KeyCode as KC, KeyEvent};
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget, Wrap};

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Action {
    Left,
    Right,
    PageUp,
    PageDown,
    Home,
    End,
    NextPeak,
    TogglePhase,
    ToggleLog,
}

static KEYS: &[Binding<Action>] = &[
    b(
        &[code(KC::Left), k('h')],
        Action::Left,
        "frequency cursor down one step",
        Some("←→ cursor"),
    ),
    b(
        &[code(KC::Right), k('l')],
        Action::Right,
        "frequency cursor up one step",
        None,
    ),
    b(
        &[code(KC::PageDown), k('L')],
        Action::PageDown,
        "cursor up 1 Hz",
        None,
    ),
    b(
        &[code(KC::PageUp), k('H')],
        Action::PageUp,
        "cursor down 1 Hz",
        None,
    ),
    b(
        &[code(KC::Home)],
        Action::Home,
        "cursor to the band start",
        None,
    ),
    b(&[code(KC::End)], Action::End, "cursor to the band end", None),
    b(
        &[k('n')],
        Action::NextPeak,
        "cursor to the next peak (any function)",
        Some("n peak"),
    ),
    b(
        &[k('p')],
        Action::TogglePhase,
        "magnitude / phase",
        Some("p mag/phase"),
    ),
    b(
        &[k('a')],
        Action::ToggleLog,
        "linear / log axes",
        Some("a lin/log"),
    ),
];

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ResponsesTab {
    pub phase: bool,
    pub log: bool,
    /// Index into the band's grid.
    pub cursor: usize,
    /// Put the cursor on the STHT peak once the curves are there (a new model).
    to_peak: bool,
}

impl Default for ResponsesTab {
    fn default() -> Self {
        ResponsesTab {
            phase: false,
            log: false,
            cursor: 0,
            to_peak: true,
        }
    }
}

impl ResponsesTab {
    fn act(&mut self, a: Action, s: &Shared) {
        let last = s.curve_len().saturating_sub(1);
        let per_hz = (1.0 / s.band().step).round().max(1.0) as usize;
        match a {
            Action::Left => self.cursor = self.cursor.saturating_sub(1),
            Action::Right => self.cursor = (self.cursor + 1).min(last),
            Action::PageUp => self.cursor = self.cursor.saturating_sub(per_hz),
            Action::PageDown => self.cursor = (self.cursor + per_hz).min(last),
            Action::Home => self.cursor = 0,
            Action::End => self.cursor = last,
            Action::TogglePhase => self.phase = !self.phase,
            Action::ToggleLog => self.log = !self.log,
            Action::NextPeak => {
                let Some(d) = &s.derived else { return };
                let here = d.curve.get(self.cursor).map_or(0.0, |r| r.f_hz);
                let mut fs: Vec<f64> = d
                    .functions
                    .iter()
                    .flat_map(|c| c.peaks.iter().map(|p| p.f_hz))
                    .collect();
                fs.sort_by(f64::total_cmp);
                let step = s.band().step;
                let next = fs
                    .iter()
                    .find(|&&f| f > here + step / 2.0)
                    .or(fs.first())
                    .copied();
                if let Some(f) = next {
                    self.cursor = s.index_of(f);
                }
            }
        }
    }
}

impl Tab for ResponsesTab {
    fn new(_shared: &Shared) -> Self {
        ResponsesTab::default()
    }

    fn title(&self) -> &'static str {
        "Responses"
    }

    fn keys(&self) -> Vec<&'static Doc> {
        keys::docs(KEYS)
    }

    fn on_key(&mut self, ev: &KeyEvent, cx: &Cx) -> Option<Vec<Effect>> {
        let a = keys::lookup(KEYS, ev)?;
        self.act(a, cx.shared);
        Some(Vec::new())
    }

    fn on_change(&mut self, change: Change, cx: &Cx) {
        let s = cx.shared;
        if change == Change::Loaded {
            self.to_peak = true;
        }
        if let Some(d) = &s.derived
            && self.to_peak
        {
            self.cursor = s.index_of(d.first_main().map_or(5.0, |p| p.f_hz));
            self.to_peak = false;
        }
        self.cursor = self.cursor.min(s.curve_len().saturating_sub(1));
    }

    fn render(&self, s: &Shared, area: Rect, buf: &mut Buffer) {
        render(self, s, area, buf);
    }
}

/// "STHT 1.52 ∠-12.3°" for each function at the cursor.
fn readout(t: &ResponsesTab, s: &Shared) -> Line<'static> {
    let th = s.theme;
    let Some(r) = s.derived.as_ref().and_then(|d| d.curve.get(t.cursor)) else {
        return Line::raw("no data");
    };
    let mut spans = vec![Span::styled(
        format!("f {} Hz", num(r.f_hz, 4)),
        th.heading(),
    )];
    for f in biodyn::Function::ALL {
        spans.push(Span::raw("  "));
        spans.push(Span::styled(f.name(), th.key()));
        spans.push(Span::raw(format!(
            " {}{}{} ∠{}°",
            num(r.mag(f), 4),
            if unit(f).is_empty() { "" } else { " " },
            unit(f),
            num(r.phase_deg(f), 3)
        )));
    }
    if s.stale {
        spans.push(Span::styled("  (updating…)", th.dim()));
    }
    Line::from(spans)
}

fn render(t: &ResponsesTab, s: &Shared, area: Rect, buf: &mut Buffer) {
    let [top, charts] = Layout::vertical([Constraint::Length(1), Constraint::Min(3)]).areas(area);
    let Some(d) = &s.derived else {
        Paragraph::new(s.computing())
            .style(s.theme.dim())
            .wrap(Wrap { trim: true })
            .render(area, buf);
        return;
    };
    Paragraph::new(readout(t, s))
        .wrap(Wrap { trim: true })
        .render(top, buf);
    let n = u32::try_from(d.functions.len().max(1)).unwrap_or(1);
    let ratios = vec![Constraint::Ratio(1, n); d.functions.len()];
    let areas = if area.width >= SIDE_BY_SIDE {
        Layout::horizontal(ratios).split(charts)
    } else {
        Layout::vertical(ratios).split(charts)
    };
    let f_cursor = d.curve.get(t.cursor).map(|r| r.f_hz);
    for (c, &cell) in d.functions.iter().zip(areas.iter()) {
        let f = c.function;
        let series = if t.phase { &c.phase } else { &c.mag };
        let u = unit(f);
        let what = if t.phase {
            "phase °".to_string()
        } else if u.is_empty() {
            "magnitude".to_string()
        } else {
            format!("magnitude, {u}")
        };
        let tall = cell.height >= 12;
        // The marked peak in numbers, so it can be read, not just seen.
        let peak = match c.main {
            Some(p) if !p.at_edge && !t.phase => format!(
                " · peak {} Hz, {}{}{}",
                num(p.f_hz, 4),
                num(p.mag, 4),
                if u.is_empty() { "" } else { " " },
                u
            ),
            _ => String::new(),
        };
        let long = format!("{} ({}){peak}", f.name(), f.long_name());
        let title = if tall && long.chars().count() + 2 <= cell.width as usize {
            long
        } else if tall {
            format!("{}{peak}", f.name())
        } else {
            format!("{} {what} vs f Hz{peak}", f.name())
        };
        let marks = match c.main {
            Some(p) if !t.phase && !p.at_edge => vec![(p.f_hz, p.mag)],
            _ => Vec::new(),
        };
        let opts = ChartOpts {
            title,
            x_title: if tall { "f Hz".into() } else { String::new() },
            y_title: if tall { what } else { String::new() },
            log_x: t.log,
            log_y: t.log && !t.phase,
            ascii: s.theme.ascii,
            mono: s.theme.mono,
            cursor_x: f_cursor,
            marks,
            y_range: None,
        };
        chart::render(cell, buf, std::slice::from_ref(series), &opts);
    }
}
