//! Tab Model: the body mass, the segment and link tables (editable), and
//! beside them the modes and peaks of the current model.

mod panels;

use crate::tui::component::{Change, Cx, Tab};
use crate::tui::effect::Effect;
use crate::tui::field::{Field, Purpose};
use crate::tui::keys::{self, Binding, Doc, b, code, k};
use crate::tui::shared::Shared;
use crate::tui::widgets::{block, cell};
use crate::view::chart::{self, ChartOpts};
use crate::view::format::{clip, for_edit, num};
use biodyn::{Body, End, Param};
use ratatui::buffer::Buffer;
use ratatui::crossterm::event::{KeyCode as KC, KeyEvent};
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget};

/// The `+`/`-` factor: `+` multiplies by it, `-` divides, so they undo
/// each other exactly (×0.95 after ×1.05 would not).
pub const NUDGE: f64 = 1.05;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Action {
    Up,
    Down,
    Left,
    Right,
    Edit,
    NudgeUp,
    NudgeDown,
}

static KEYS: &[Binding<Action>] = &[
    b(
        &[code(KC::Up), k('k')],
        Action::Up,
        "previous row",
        Some("↑↓←→ move"),
    ),
    b(&[code(KC::Down), k('j')], Action::Down, "next row", None),
    b(
        &[code(KC::Left), k('h')],
        Action::Left,
        "previous column (k / c of a link)",
        None,
    ),
    b(
        &[code(KC::Right), k('l')],
        Action::Right,
        "next column",
        None,
    ),
    b(
        &[code(KC::Enter), k('e')],
        Action::Edit,
        "edit the selected value",
        Some("Enter edit"),
    ),
    b(
        &[k('+'), k('=')],
        Action::NudgeUp,
        "raise the selected value by 5 % (×1.05)",
        Some("+/- 5%"),
    ),
    b(
        &[k('-')],
        Action::NudgeDown,
        "lower it (÷1.05, so + then - gives it back)",
        None,
    ),
];

/// The selected cell: row 0 is the body mass, then one row per segment,
/// then one per link (column 0 = k, 1 = c).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ModelTab {
    pub row: usize,
    pub col: usize,
}

impl ModelTab {
    fn rows(body: &Body) -> usize {
        1 + body.segments.len() + body.links.len()
    }

    fn clamp(&mut self, body: &Body) {
        self.row = self.row.min(Self::rows(body) - 1);
        if self.link(body).is_none() {
            self.col = 0;
        }
    }

    fn link(&self, body: &Body) -> Option<usize> {
        self.row
            .checked_sub(1 + body.segments.len())
            .filter(|&i| i < body.links.len())
    }

    /// The parameter under the cursor.
    pub fn param(&self, body: &Body) -> Param {
        let n = body.segments.len();
        match self.row {
            0 => Param::BodyMass,
            r if r <= n => Param::Mass(r - 1),
            r if self.col == 0 => Param::Stiffness(r - 1 - n),
            r => Param::Damping(r - 1 - n),
        }
    }

    fn act(&mut self, a: Action, s: &Shared) -> Vec<Effect> {
        let rows = Self::rows(&s.body);
        match a {
            Action::Up => self.row = (self.row + rows - 1) % rows,
            Action::Down => self.row = (self.row + 1) % rows,
            Action::Left | Action::Right if self.link(&s.body).is_some() => {
                self.col = 1 - self.col
            }
            Action::Left | Action::Right => {}
            Action::Edit | Action::NudgeUp | Action::NudgeDown
                if self.param(&s.body) == Param::BodyMass && !has_shares(&s.body) =>
            {
                return vec![Effect::Error(format!(
                    "this model gives segment masses, not shares: its body mass is their sum ({} kg); edit m1…m{} instead",
                    num(s.body.seated_mass(), 4),
                    s.body.segments.len()
                ))];
            }
            Action::Edit => {
                let p = self.param(&s.body);
                return vec![Effect::OpenField(Field::new(
                    Purpose::Param(p),
                    s.describe(p),
                    for_edit(s.body.get(p)),
                ))];
            }
            Action::NudgeUp | Action::NudgeDown => {
                let p = self.param(&s.body);
                let v = s.body.get(p);
                if v == 0.0 {
                    return vec![Effect::Error(format!(
                        "{} is 0: a percentage step cannot move it; press Enter to type a value",
                        s.body.label(p)
                    ))];
                }
                let next = if a == Action::NudgeUp {
                    v * NUDGE
                } else {
                    v / NUDGE
                };
                return vec![Effect::SetParam(p, next)];
            }
        }
        Vec::new()
    }
}

impl Tab for ModelTab {
    fn new(_shared: &Shared) -> Self {
        ModelTab::default()
    }

    fn title(&self) -> &'static str {
        "Model"
    }

    fn keys(&self) -> Vec<&'static Doc> {
        keys::docs(KEYS)
    }

    fn on_key(&mut self, ev: &KeyEvent, cx: &Cx) -> Option<Vec<Effect>> {
        keys::lookup(KEYS, ev).map(|a| self.act(a, cx.shared))
    }

    fn on_change(&mut self, _change: Change, cx: &Cx) {
        self.clamp(&cx.shared.body);
    }

    fn render(&self, s: &Shared, area: Rect, buf: &mut Buffer) {
        render(self, s, area, buf);
    }

    fn has_chart(&self, s: &Shared) -> bool {
        s.derived.is_some()
    }

    fn render_zoomed(&self, s: &Shared, area: Rect, buf: &mut Buffer) {
        stht_chart(s, area, buf);
    }
}

/// Every segment has a share of the body mass (so the body mass is editable).
fn has_shares(b: &Body) -> bool {
    b.segments.iter().all(|s| s.share.is_some())
}

/// Below this width the tables take the whole tab (modes and peaks are on
/// the Responses tab and at larger sizes).
const TABLES_ALONE: u16 = 74;

fn render(t: &ModelTab, s: &Shared, area: Rect, buf: &mut Buffer) {
    let th = s.theme;
    let wide = area.width >= 120;
    if area.width < TABLES_ALONE {
        render_tables(t, s, area, buf);
        return;
    }
    let right_w = if wide { area.width - 72 } else { 34 };
    let [left, right] =
        Layout::horizontal([Constraint::Min(40), Constraint::Length(right_w)]).areas(area);
    render_tables(t, s, left, buf);
    let n_modes = match &s.modes {
        Some(Ok(m)) => m.damped.len(),
        _ => 1,
    };
    let n_peaks: usize = s.derived.as_ref().map_or(1, |d| {
        d.functions.iter().map(|c| c.peaks.len().max(1) + 1).sum()
    });
    let [modes, peaks, rest] = Layout::vertical([
        Constraint::Length((n_modes as u16).saturating_add(3)),
        Constraint::Length((n_peaks as u16).saturating_add(3).min(9)),
        Constraint::Min(0),
    ])
    .areas(right);
    panels::modes(s, modes, buf, th, wide);
    panels::peaks(s, peaks, buf, th);
    // On a tall screen, the STHT curve shows every edit at once.
    if rest.height >= 12 {
        stht_chart(s, rest, buf);
    }
}

/// The STHT magnitude with its main peak marked (also the `z` zoom).
fn stht_chart(s: &Shared, area: Rect, buf: &mut Buffer) {
    let th = s.theme;
    if let Some(c) = s.derived.as_ref().and_then(|d| d.functions.first()) {
        let f = c.function;
        let marks = c
            .main
            .filter(|p| !p.at_edge)
            .map(|p| vec![(p.f_hz, p.mag)])
            .unwrap_or_default();
        let opts = ChartOpts {
            title: format!("{} ({})", f.name(), f.long_name()),
            x_title: "f Hz".into(),
            y_title: format!("|{}|", f.name()),
            ascii: th.ascii,
            mono: th.mono,
            marks,
            ..Default::default()
        };
        chart::render(area, buf, std::slice::from_ref(&c.mag), &opts);
    }
}

fn render_tables(t: &ModelTab, s: &Shared, area: Rect, buf: &mut Buffer) {
    let th = s.theme;
    let b = &s.body;
    let sel = *t;
    let wide = area.width >= 70;
    let name_w = b
        .segments
        .iter()
        .map(|s| s.name.chars().count())
        .chain(b.links.iter().map(|l| l.name.chars().count()))
        .max()
        .unwrap_or(4)
        .clamp(4, if wide { 24 } else { 18 });
    // Row labels as wide as the largest index needs: "m1 ", "m400 ".
    let digits = |n: usize| n.max(1).to_string().len();
    let seg_w = digits(b.segments.len()) + 1;
    let link_w = digits(b.links.len()) + 2;
    let body_mass = b.get(Param::BodyMass);
    let seated = b.seated_mass();
    let shares = has_shares(b);
    let mut lines = vec![Line::from(vec![
        Span::styled("body mass ", th.heading()),
        cell(num(body_mass, 5), 8, sel.row == 0, th),
        Span::raw(" kg"),
        Span::styled(
            match (shares, wide) {
                (true, true) => {
                    format!("  seated {} kg; an edit rescales by share", num(seated, 4))
                }
                (true, false) => format!("  seated {} kg", num(seated, 4)),
                (false, _) => format!("  = m1+…+m{} (no shares)", b.segments.len()),
            },
            th.dim(),
        ),
    ])];
    lines.push(Line::raw(""));
    lines.push(Line::styled(
        format!(
            "{:w$}{:<name_w$} {:>10} {:>7}",
            "",
            "segment",
            "mass kg",
            if shares { "share" } else { "" },
            w = seg_w + 1
        ),
        th.heading(),
    ));
    for (i, seg) in b.segments.iter().enumerate() {
        let share = seg.mass / body_mass * 100.0;
        let head = if i == b.head { "*" } else { " " };
        lines.push(Line::from(vec![
            Span::raw(format!(
                "m{:<seg_w$}{:<name_w$}",
                i + 1,
                clip(&seg.name, name_w)
            )),
            Span::raw(" "),
            cell(num(seg.mass, 5), 10, sel.row == i + 1, th),
            Span::raw(if shares {
                format!(" {:>6}%{head}", num(share, 3))
            } else {
                format!(" {:>7}{head}", "")
            }),
        ]));
    }
    lines.push(Line::raw(""));
    lines.push(Line::styled(
        format!(
            "{:link_w$}{:<name_w$} {:>10} {:>9}{}",
            "",
            "link",
            "k N/m",
            "c N·s/m",
            if wide { "  joins" } else { "" }
        ),
        th.heading(),
    ));
    let n = b.segments.len();
    for (i, l) in b.links.iter().enumerate() {
        let row = 1 + n + i;
        let lower = match l.lower {
            End::Seat => "seat".to_string(),
            End::Segment(j) => b.segments.get(j).map_or("?".into(), |s| s.name.clone()),
        };
        let mut spans = vec![
            Span::raw(format!(
                "{:<link_w$}{:<name_w$}",
                i + 1,
                clip(&l.name, name_w)
            )),
            Span::raw(" "),
            cell(num(l.k, 6), 10, sel.row == row && sel.col == 0, th),
            Span::raw(" "),
            cell(num(l.c, 6), 9, sel.row == row && sel.col == 1, th),
        ];
        if wide {
            let upper = b.segments.get(l.upper).map_or("?", |s| s.name.as_str());
            spans.push(Span::styled(format!("  {upper}–{lower}"), th.dim()));
        }
        lines.push(Line::from(spans));
    }
    lines.push(Line::raw(""));
    lines.push(Line::styled(
        "* head (STHT). Masses: kg; k: N/m; c: N·s/m.",
        th.dim(),
    ));
    let title = format!(
        "model: {}{}",
        s.preset.name,
        if s.modified() { " (modified)" } else { "" }
    );
    // Keep the selected row in view on a short terminal.
    let sel_line = match sel.row {
        0 => 0,
        r if r <= n => 2 + r,
        r => 4 + r,
    };
    let inner = area.height.saturating_sub(2) as usize;
    let scroll = (sel_line + 1).saturating_sub(inner);
    Paragraph::new(lines)
        .scroll((u16::try_from(scroll).unwrap_or(u16::MAX), 0))
        .block(block(&title, th))
        .render(area, buf);
}

