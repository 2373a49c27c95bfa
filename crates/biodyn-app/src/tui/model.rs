//! Tab 1, Model: the body mass, the segment and link tables (editable), and
//! beside them the modes and peaks of the current model.

use super::app::{App, NUDGE};
use super::field::{Field, Purpose};
use super::keys::Action;
use super::theme::Theme;
use crate::view::format::{clip, for_edit, num, unit};
use biodyn::freq::modes::ModeKind;
use biodyn::{Body, End, Function, Param};
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::Style;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Paragraph, Widget};

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

    pub fn clamp(&mut self, body: &Body) {
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
}

/// What the user reads for a parameter: "k4 pelvis-seat (N/m)".
pub fn describe(body: &Body, p: Param) -> String {
    let what = match p {
        Param::BodyMass => String::new(),
        Param::Mass(i) => format!(" {}", body.segments[i].name),
        Param::Stiffness(i) | Param::Damping(i) => format!(" {}", body.links[i].name),
    };
    format!("{}{what} ({})", body.label(p), p.unit())
}

pub fn on_action(app: &mut App, a: Action) {
    let rows = ModelTab::rows(&app.body);
    let t = &mut app.model;
    match a {
        Action::Up => t.row = (t.row + rows - 1) % rows,
        Action::Down => t.row = (t.row + 1) % rows,
        Action::Left | Action::Right if t.link(&app.body).is_some() => t.col = 1 - t.col,
        Action::Edit => {
            let p = t.param(&app.body);
            let label = describe(&app.body, p);
            app.field = Some(Field::new(
                Purpose::Param(p),
                label,
                for_edit(app.body.get(p)),
            ));
        }
        Action::NudgeUp | Action::NudgeDown => {
            let p = t.param(&app.body);
            let v = app.body.get(p);
            if v == 0.0 {
                app.status.text = format!(
                    "{} is 0: a percentage step cannot move it; press Enter to type a value",
                    app.body.label(p)
                );
                app.status.error = true;
                return;
            }
            let f = if a == Action::NudgeUp {
                1.0 + NUDGE
            } else {
                1.0 - NUDGE
            };
            match app.set_param(p, v * f) {
                Ok(()) => {
                    app.status.text = format!(
                        "{} = {} {}",
                        app.body.label(p),
                        num(app.body.get(p), 6),
                        p.unit()
                    );
                    app.status.error = false;
                }
                Err(e) => {
                    app.status.text = e;
                    app.status.error = true;
                }
            }
        }
        _ => {}
    }
}

pub fn render(app: &App, area: Rect, buf: &mut Buffer) {
    let th = app.theme;
    let wide = area.width >= 120;
    let right_w = if wide { area.width - 72 } else { 34 };
    let [left, right] =
        Layout::horizontal([Constraint::Min(40), Constraint::Length(right_w)]).areas(area);
    render_tables(app, left, buf);
    let n_modes = app.derived.modes.as_ref().map_or(1, |m| m.damped.len());
    let n_peaks: usize = app.derived.peaks.iter().map(|p| p.len().max(1) + 1).sum();
    let [modes, peaks, rest] = Layout::vertical([
        Constraint::Length(n_modes as u16 + 3),
        Constraint::Length((n_peaks as u16 + 3).min(9)),
        Constraint::Min(0),
    ])
    .areas(right);
    render_modes(app, modes, buf, th, wide);
    render_peaks(app, peaks, buf, th);
    // On a tall screen, the STHT curve shows every edit at once.
    if rest.height >= 12 {
        let f = Function::Stht;
        let marks = app.derived.main[0]
            .filter(|p| !p.at_edge)
            .map(|p| vec![(p.f_hz, p.mag)])
            .unwrap_or_default();
        let opts = crate::view::chart::ChartOpts {
            title: format!("{} ({})", f.name(), f.long_name()),
            x_title: "f Hz".into(),
            y_title: "|STHT|".into(),
            ascii: th.ascii,
            mono: th.mono,
            marks,
            ..Default::default()
        };
        crate::view::chart::render(rest, buf, std::slice::from_ref(&app.derived.mag[0]), &opts);
    }
}

fn cell(text: String, w: usize, selected: bool, th: Theme) -> Span<'static> {
    let s = format!("{text:>w$}");
    if selected {
        Span::styled(s, th.selected())
    } else {
        Span::raw(s)
    }
}

fn block(title: String, th: Theme) -> Block<'static> {
    Block::bordered()
        .border_set(th.border_set())
        .title(Span::styled(format!(" {title} "), th.heading()))
}

fn render_tables(app: &App, area: Rect, buf: &mut Buffer) {
    let th = app.theme;
    let b = &app.body;
    let sel = app.model;
    let wide = area.width >= 70;
    let name_w = b
        .segments
        .iter()
        .map(|s| s.name.chars().count())
        .chain(b.links.iter().map(|l| l.name.chars().count()))
        .max()
        .unwrap_or(4)
        .clamp(4, if wide { 24 } else { 18 });
    let body_mass = b.get(Param::BodyMass);
    let seated = b.seated_mass();
    let shares = b.segments.iter().all(|s| s.share.is_some());
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
                (false, _) => "  = seated: no shares, edit the masses".to_string(),
            },
            th.dim(),
        ),
    ])];
    lines.push(Line::raw(""));
    lines.push(Line::styled(
        format!("   {:<name_w$} {:>10} {:>7}", "segment", "mass kg", "share"),
        th.heading(),
    ));
    for (i, s) in b.segments.iter().enumerate() {
        let share = s.mass / body_mass * 100.0;
        let head = if i == b.head { "*" } else { " " };
        lines.push(Line::from(vec![
            Span::raw(format!("m{:<2}{:<name_w$}", i + 1, clip(&s.name, name_w))),
            Span::raw(" "),
            cell(num(s.mass, 5), 10, sel.row == i + 1, th),
            Span::raw(format!(" {:>6}%{head}", num(share, 3))),
        ]));
    }
    lines.push(Line::raw(""));
    lines.push(Line::styled(
        format!(
            "   {:<name_w$} {:>10} {:>9}{}",
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
            Span::raw(format!("{:<3}{:<name_w$}", i + 1, clip(&l.name, name_w))),
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
        app.preset.name,
        if app.modified() { " (modified)" } else { "" }
    );
    // Keep the selected row in view on a short terminal.
    let sel_line = match sel.row {
        0 => 0,
        r if r <= n => 2 + r,
        r => 4 + r,
    };
    let inner = area.height.saturating_sub(2) as usize;
    let scroll = (sel_line + 1).saturating_sub(inner) as u16;
    Paragraph::new(lines)
        .scroll((scroll, 0))
        .block(block(title, th))
        .render(area, buf);
}

fn render_modes(app: &App, area: Rect, buf: &mut Buffer, th: Theme, shapes: bool) {
    // Shape magnitudes per segment (largest 1), when there is room for them.
    let shape = |v: &[f64]| -> String {
        if !shapes {
            return String::new();
        }
        let cells: Vec<String> = v.iter().map(|x| format!("{:>6}", num(*x, 2))).collect();
        format!("  {}", cells.join(""))
    };
    let mut lines = Vec::new();
    match &app.derived.modes {
        Err(e) => lines.push(Line::styled(e.clone(), th.error())),
        Ok(m) => {
            let heads: Vec<String> = (1..=app.body.segments.len())
                .map(|i| format!("{:>6}", format!("|x{i}|")))
                .collect();
            lines.push(Line::styled(
                format!(
                    "{:<2} {:>7} {:>7} {:>6}{}",
                    "#",
                    "fn Hz",
                    "fd Hz",
                    "ζ",
                    if shapes {
                        format!("  {}", heads.join(""))
                    } else {
                        String::new()
                    }
                ),
                th.heading(),
            ));
            for (i, mode) in m.damped.iter().enumerate() {
                let text = match mode.kind {
                    ModeKind::Oscillatory {
                        damped_hz,
                        natural_hz,
                        damping_ratio,
                    } => format!(
                        "{:<2} {:>7} {:>7} {:>6}{}",
                        i + 1,
                        num(natural_hz, 4),
                        num(damped_hz, 4),
                        num(damping_ratio, 3),
                        shape(&mode.shape_mag)
                    ),
                    ModeKind::Overdamped { rate_per_s, .. } => format!(
                        "{:<2} {:<22}{}",
                        i + 1,
                        format!("overdamped, {}/s", num(rate_per_s, 4)),
                        shape(&mode.shape_mag)
                    ),
                };
                lines.push(Line::raw(text));
            }
        }
    }
    Paragraph::new(lines)
        .block(block("modes (seat fixed)".into(), th))
        .render(area, buf);
}

fn render_peaks(app: &App, area: Rect, buf: &mut Buffer, th: Theme) {
    let mut lines = vec![Line::styled(
        format!("{:<5} {:>8} {:>9}", "", "f Hz", "magnitude"),
        th.heading(),
    )];
    for (fi, f) in Function::ALL.iter().enumerate() {
        match app.derived.main[fi] {
            Some(p) => {
                let edge = if p.at_edge { " (band edge)" } else { "" };
                lines.push(Line::from(vec![
                    Span::styled(format!("{:<5}", f.name()), th.key()),
                    Span::raw(format!(
                        " {:>8} {:>9} {}{edge}",
                        num(p.f_hz, 4),
                        num(p.mag, 4),
                        unit(*f)
                    )),
                ]));
            }
            None => lines.push(Line::raw(format!("{:<5} no peak", f.name()))),
        }
        let others = app.derived.peaks[fi].len().saturating_sub(1);
        if others > 0 {
            let list: Vec<String> = app.derived.peaks[fi]
                .iter()
                .filter(|p| Some(**p) != app.derived.main[fi])
                .map(|p| format!("{} Hz", num(p.f_hz, 3)))
                .collect();
            lines.push(Line::styled(
                format!("      also {}", list.join(", ")),
                th.dim(),
            ));
        }
    }
    Paragraph::new(lines)
        .style(Style::default())
        .block(block("main peaks".into(), th))
        .render(area, buf);
}
