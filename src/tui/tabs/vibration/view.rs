//! Drawing the Vibration tab from a borrowed state: the settings, the
//! traces (per-column min/max, so no peak disappears), the one-third-octave
//! spectra as paired bars, the assessment table and the verdicts. Nothing
//! here changes state.

use super::VibrationTab;
use super::compute::Outcome;
use super::layout::{areas, settings_scroll};
use super::glyphs::{fix, fix_lines};
use crate::tui::keys;
use super::settings::Row;
use crate::tui::shared::Shared;
use crate::tui::theme::Theme;
use crate::tui::widgets::block;
use crate::view::format::{clip, num};
use biodyn::iso2631::{A8_ACTION, A8_LIMIT, VDV_ACTION, VDV_LIMIT, Channel, Verdict};
use ratatui::buffer::Buffer;
use ratatui::layout::{Position, Rect};
use ratatui::style::Style;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget, Wrap};


pub fn render(t: &VibrationTab, s: &Shared, area: Rect, buf: &mut Buffer) {
    draw(t, s, area, buf, false);
}

/// The chart alone (the app's `z`): the traces, or the spectra when `s`
/// shows them.
pub fn render_zoomed(t: &VibrationTab, s: &Shared, area: Rect, buf: &mut Buffer) {
    draw(t, s, area, buf, true);
}

fn draw(t: &VibrationTab, s: &Shared, area: Rect, buf: &mut Buffer, zoomed: bool) {
    let a = areas(t, area, zoomed);
    let o = t.outcome();
    if let Some(r) = a.settings {
        settings(t, s, r, buf);
    }
    if let Some(r) = a.table {
        assessment(o, s.theme, r, buf);
    }
    for (r, brief) in a.verdicts {
        verdict_lines(o, s.theme, r, buf, brief);
    }
    for (r, spectra) in a.charts {
        charts(t, s, r, buf, spectra);
    }
}

/// What a click in the settings panel is on: a row, or the kind row's
/// ◀ or ▶.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SettingsHit {
    Row(usize),
    PrevKind,
    NextKind,
}

/// The settings lines: one per row (label, value), then the run's state.
fn settings_lines(t: &VibrationTab, s: &Shared, area: Rect) -> Vec<Line<'static>> {
    let th = s.theme;
    let st = &t.settings;
    let rows = t.rows();
    let label_w = rows
        .iter()
        .map(|&r| st.row_text(r).0.chars().count())
        .max()
        .unwrap_or(8);
    let inner_w = usize::from(area.width.saturating_sub(2));
    let value_w = inner_w.saturating_sub(label_w + 1);
    let mut lines: Vec<Line> = rows
        .iter()
        .enumerate()
        .map(|(i, &r)| {
            let (label, unit, value) = st.row_text(r);
            let value = match r {
                Row::Kind => format!("◀ {value} ▶"),
                _ if unit.is_empty() => value,
                _ => format!("{value} {unit}"),
            };
            let style = if i == t.sel { th.selected() } else { th.base() };
            Line::from(vec![
                Span::styled(format!("{label:<label_w$} "), th.dim()),
                Span::styled(clip(&value, value_w), style),
            ])
        })
        .collect();
    let state = if t.running {
        let how_far = match t.progress {
            Some((done, Some(total))) if total > 0 => {
                format!(" {} %", (done * 100 / total).min(99))
            }
            Some((done, None)) => format!(" {} samples", done),
            _ => String::new(),
        };
        Span::styled(format!("computing in the background…{how_far}"), th.dim())
    } else {
        match &t.result {
            Some(Ok(o)) => Span::styled(
                format!(
                    "{} samples at {} Hz",
                    o.traces.seat.len,
                    num(o.traces.fs, 6)
                ),
                th.dim(),
            ),
            Some(Err(_)) => Span::styled("error: see the chart panel", th.error()),
            None => Span::raw(""),
        }
    };
    lines.push(Line::from(state));
    fix_lines(th, lines)
}

/// The settings panel's frame, `width` wide. Its title names the keys the
/// hint bar leaves out: ←→ step the kind (in ASCII spelt out, as `<` `>`
/// scroll the traces); where that is too long the panel's name goes.
fn settings_block(th: Theme, width: u16) -> ratatui::widgets::Block<'static> {
    let room = usize::from(width).saturating_sub(4);
    let title = ["signal (←→ kind, Enter edit)", "←→ kind, Enter edit"]
        .map(|t| keys::arrows(t, th.ascii))
        .into_iter()
        .find(|t| t.chars().count() <= room)
        .unwrap_or_else(|| keys::arrows("signal (←→ kind, Enter edit)", th.ascii));
    block(&title, th)
}

fn settings(t: &VibrationTab, s: &Shared, area: Rect, buf: &mut Buffer) {
    let th = s.theme;
    let top = settings_scroll(t, usize::from(settings_block(th, area.width).inner(area).height));
    Paragraph::new(settings_lines(t, s, area))
        .scroll((u16::try_from(top).unwrap_or(u16::MAX), 0))
        .block(settings_block(th, area.width))
        .render(area, buf);
}

/// The first settings line shown in `area` (as `settings` draws it).
pub fn settings_top(t: &VibrationTab, s: &Shared, area: Rect) -> usize {
    settings_scroll(t, usize::from(settings_block(s.theme, area.width).inner(area).height))
}

/// What is under `at` in the settings panel drawn in `area`.
pub fn settings_hit(t: &VibrationTab, s: &Shared, area: Rect, at: Position) -> Option<SettingsHit> {
    let inner = settings_block(s.theme, area.width).inner(area);
    if !inner.contains(at) {
        return None;
    }
    let i = usize::from(at.y - inner.y) + settings_top(t, s, area);
    if i >= t.rows().len() {
        return None;
    }
    let lines = settings_lines(t, s, area);
    let line = lines.get(i)?;
    let x = usize::from(at.x - inner.x);
    // The kind row's arrows: the first and last glyph of its value.
    if i == 0
        && let [label, value] = line.spans.as_slice()
    {
        let from = label.width();
        let text: Vec<char> = value.content.chars().collect();
        if text.first() == Some(&'◀') && x == from {
            return Some(SettingsHit::PrevKind);
        }
        if text.last() == Some(&'▶') && x + 1 == from + text.len() {
            return Some(SettingsHit::NextKind);
        }
    }
    // Anywhere else on the row's line selects it, as in any list.
    Some(SettingsHit::Row(i))
}

/// The traces or the spectra; an error of the run, in full, in their place.
pub(super) fn charts(t: &VibrationTab, s: &Shared, area: Rect, buf: &mut Buffer, spectra: bool) {
    let th = s.theme;
    let o = match &t.result {
        Some(Ok(o)) => o,
        Some(Err(e)) => {
            Paragraph::new(vec![
                Line::styled("The run cannot go ahead:", th.error()),
                Line::raw(fix(th, e)),
                Line::raw(""),
                Line::styled(
                    keys::arrows(
                        "↑↓ pick a setting and Enter edits it; ←→ picks another signal kind.",
                        th.ascii,
                    ),
                    th.dim(),
                ),
            ])
            .wrap(Wrap { trim: false })
            .block(block("vibration", th))
            .render(area, buf);
            return;
        }
        None => {
            Paragraph::new(Line::styled("computing…", th.dim()))
                .block(block("vibration", th))
                .render(area, buf);
            return;
        }
    };
    if spectra {
        super::spectra::render(o, th, t.running, area, buf);
    } else {
        super::traces::render(t, o, th, area, buf);
    }
}

fn assessment(o: Option<&Outcome>, th: Theme, area: Rect, buf: &mut Buffer) {
    let Some(o) = o else {
        Paragraph::new("")
            .block(block("ISO 2631-1", th))
            .render(area, buf);
        return;
    };
    let r = &o.assessment;
    let (se, he) = (&r.seat, &r.head);
    let row = |name: &str, f: &dyn Fn(&Channel) -> f64, d: usize| {
        let name = fix(th, name);
        Line::raw(format!(
            "{name:<15}{:>9}{:>9}",
            format!("{:.d$}", f(se)),
            format!("{:.d$}", f(he))
        ))
    };
    let exp = format!("VDV {} h", num(r.exposure_h, 4));
    let lines = vec![
        Line::styled(
            format!("{:<15}{:>9}{:>9}", "", "seat", "head"),
            th.heading(),
        ),
        row("a_w m/s²", &|c| c.metrics.aw, 3),
        row("peak m/s²", &|c| c.metrics.peak, 3),
        row("crest factor", &|c| c.metrics.crest, 2),
        row("MTVV m/s²", &|c| c.metrics.mtvv, 3),
        row("VDV m/s^1.75", &|c| c.metrics.vdv, 2),
        row("A(8) m/s²", &|c| c.exposure.a8, 3),
        row(&exp, &|c| c.exposure.vdv, 2),
    ];
    let title = format!(
        "ISO 2631-1, {}, {} h/day",
        r.weighting.name(),
        num(r.exposure_h, 4)
    );
    Paragraph::new(lines)
        .block(block(&title, th))
        .render(area, buf);
}

/// A verdict's style: the words carry the meaning, colour only adds to it.
fn verdict_style(v: Verdict, th: Theme) -> Style {
    match v {
        Verdict::BelowAction => th.ok(),
        Verdict::AboveAction => th.heading(),
        Verdict::AboveLimit => th.error(),
    }
}

/// The verdicts, comfort words and warnings; `brief` (a narrow left
/// column) keeps the verdicts and counts the warnings, `s` shows them all.
fn verdict_lines(o: Option<&Outcome>, th: Theme, area: Rect, buf: &mut Buffer, brief: bool) {
    let Some(o) = o else {
        Paragraph::new("")
            .block(block("EU 2002/44/EC (seat)", th))
            .render(area, buf);
        return;
    };
    let r = &o.assessment;
    let mut lines = vec![
        Line::from(vec![
            Span::raw(format!("A(8) {:.3}: ", r.seat.exposure.a8)),
            Span::styled(r.eu.a8.words(), verdict_style(r.eu.a8, th)),
        ]),
        Line::from(vec![
            Span::raw(format!("VDV {:.2}: ", r.seat.exposure.vdv)),
            Span::styled(r.eu.vdv.words(), verdict_style(r.eu.vdv, th)),
        ]),
    ];
    let n = r.warnings.len();
    if brief && n > 0 {
        let line = format!("! {n} warning{}: s shows", if n == 1 { "" } else { "s" });
        lines.push(Line::styled(line, th.heading()));
    } else if !brief {
        lines.extend(
            r.warnings
                .iter()
                .map(|w| Line::styled(format!("! {w}"), th.heading())),
        );
    }
    lines.push(Line::raw(format!(
        "comfort seat: {}",
        r.comfort_seat.join(" / ")
    )));
    lines.push(Line::raw(format!(
        "comfort head: {}",
        r.comfort_head.join(" / ")
    )));
    if !brief {
        lines.push(Line::styled(
            format!("EU action/limit: A(8) {A8_ACTION}/{A8_LIMIT} m/s², VDV {VDV_ACTION}/{VDV_LIMIT} m/s^1.75"),
            th.dim(),
        ));
    }
    Paragraph::new(fix_lines(th, lines))
        .wrap(Wrap { trim: true })
        .block(block("EU 2002/44/EC (seat), comfort", th))
        .render(area, buf);
}
