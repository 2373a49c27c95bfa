//! Drawing the Vibration tab from a borrowed state: the settings, and
//! where the traces, the spectra, the assessment table and the verdicts go
//! (each drawn by its own file). Nothing here changes state.

use super::VibrationTab;
use super::glyphs::{fix, fix_lines};
use super::layout::{areas, settings_scroll};
use super::settings::Row;
use super::table;
use crate::tui::keys;
use crate::tui::shared::Shared;
use crate::tui::theme::Theme;
use crate::tui::widgets::{block, glued, unglue};
use crate::view::format::{clip, num};
use ratatui::buffer::Buffer;
use ratatui::layout::{Position, Rect};
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
        table::assessment(o, s.theme, r, buf);
    }
    for (r, brief) in a.verdicts {
        table::verdict_lines(o, s.theme, r, buf, brief);
    }
    for (r, spectra) in a.charts {
        charts(t, s, r, buf, spectra);
    }
}

/// What a click in the settings panel is on: a row, or the ◀ or ▶ of a
/// row that steps (the kind, the unit).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SettingsHit {
    Row(usize),
    Prev(usize),
    Next(usize),
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
                Row::Kind | Row::Unit | Row::Mean => format!("◀ {value} ▶"),
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
        // The panel is 30 columns inside at 80×24: the long form would be
        // cut before its number, so the first form that fits is shown.
        let said = [
            format!("computing in the background…{how_far}"),
            format!("computing…{how_far}"),
            how_far.trim_start().to_string(),
        ]
        .into_iter()
        .find(|t| t.chars().count() <= inner_w)
        .unwrap_or_default();
        Span::styled(said, th.dim())
    } else {
        match &t.result {
            Some(Ok(o)) => Span::styled(
                format!(
                    "{} samples at {} Hz",
                    o.traces.samples(),
                    num(o.traces.fs, 6)
                ),
                th.dim(),
            ),
            Some(Err(_)) => Span::styled("error: see the chart panel", th.error()),
            None => Span::raw(""),
        }
    };
    lines.push(Line::from(state));
    // A record: which column is which axis, in what unit.
    if let Some(cols) = t.outcome().and_then(|o| o.columns.as_ref()) {
        lines.push(Line::styled(cols.clone(), th.dim()));
    }
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
    // A stepping row's arrows: the first and last glyph of its value.
    if matches!(t.rows().get(i), Some(Row::Kind | Row::Unit | Row::Mean))
        && let [label, value] = line.spans.as_slice()
    {
        let from = label.width();
        let text: Vec<char> = value.content.chars().collect();
        if text.first() == Some(&'◀') && x == from {
            return Some(SettingsHit::Prev(i));
        }
        if text.last() == Some(&'▶') && x + 1 == from + text.len() {
            return Some(SettingsHit::Next(i));
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
            Paragraph::new(glued(vec![
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
            ]))
            .wrap(Wrap { trim: false })
            .block(block("vibration", th))
            .render(area, buf);
            unglue(area, buf);
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
