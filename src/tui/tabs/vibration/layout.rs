//! Where the Vibration tab draws what, shared by drawing and the mouse:
//! the settings panel (scrolled to keep the selected row in view), the
//! assessment table, the verdicts and the charts (traces or spectra).

use super::VibrationTab;
use crate::tui::widgets::SIDE_BY_SIDE;
use ratatui::layout::{Constraint, Layout, Rect};

/// Rows of the assessment table with its frame: the axes, the weighting
/// and k, seven metrics.
pub const TABLE_H: u16 = 11;

/// Rows the traces need under the table: two charts of 4 rows.
const MIN_CHART: u16 = 8;

/// The tab's panels as drawn in one area.
#[derive(Debug, Default, Clone, PartialEq, Eq)]
pub struct Areas {
    pub settings: Option<Rect>,
    pub table: Option<Rect>,
    /// Verdict panels, and whether each is the brief one.
    pub verdicts: Vec<(Rect, bool)>,
    /// Chart panels, and whether each shows the spectra (else the traces).
    pub charts: Vec<(Rect, bool)>,
}

impl Areas {
    /// The panel the traces are drawn in, if shown.
    pub fn traces(&self) -> Option<Rect> {
        self.charts
            .iter()
            .find(|(_, spectra)| !spectra)
            .map(|&(r, _)| r)
    }
}

/// The panels in `area`; `zoomed` is the app's `z` (one chart alone).
pub fn areas(t: &VibrationTab, area: Rect, zoomed: bool) -> Areas {
    let mut a = Areas::default();
    if zoomed {
        a.charts.push((area, t.panel == 1));
        return a;
    }
    let wide = area.width >= SIDE_BY_SIDE;
    // Narrow: 34 leaves the table its 44 columns inside a frame (x, y, z,
    // head) and a verdict "A(8) z 1.131: above action value" one line.
    let left_w = if wide { 46 } else { 34 };
    let [left, right] =
        Layout::horizontal([Constraint::Length(left_w), Constraint::Min(20)]).areas(area);
    // The rows, the run's state and, for a record, its columns.
    let columns = t.outcome().is_some_and(|o| o.columns.is_some());
    let rows = u16::try_from(t.rows().len() + usize::from(columns)).unwrap_or(u16::MAX);
    let settings_h = rows.saturating_add(3).min(left.height.saturating_sub(4));
    if wide {
        let [set, table, verdicts] = Layout::vertical([
            Constraint::Length(settings_h),
            Constraint::Length(TABLE_H),
            Constraint::Min(3),
        ])
        .areas(left);
        // A tri-axial record stacks four charts: give them more of it.
        let share = if tri_axial(t) { 70 } else { 55 };
        let [traces, spectra] =
            Layout::vertical([Constraint::Percentage(share), Constraint::Min(8)]).areas(right);
        a.settings = Some(set);
        a.table = Some(table);
        a.verdicts.push((verdicts, false));
        a.charts = vec![(traces, false), (spectra, true)];
        return a;
    }
    // Too short (60×16) for a chart of two traces over the table: one
    // panel at a time, `s` picks it (traces, spectra, table and notes).
    let short = right.height < TABLE_H + MIN_CHART;
    let notes = t.panel == 2 && t.outcome().is_some();
    let [set, verdicts] =
        Layout::vertical([Constraint::Length(settings_h), Constraint::Min(3)]).areas(left);
    a.settings = Some(set);
    // The notes in full on the right say all the brief verdicts say: the
    // left keeps the settings alone, no second copy cut short under them.
    if !notes || short {
        a.verdicts.push((verdicts, true));
    }
    if notes {
        if short {
            let [table, notes] =
                Layout::vertical([Constraint::Length(TABLE_H), Constraint::Min(0)]).areas(right);
            a.table = Some(table);
            a.verdicts.push((notes, false));
        } else {
            a.verdicts.push((right, false));
        }
        return a;
    }
    if short {
        a.charts.push((right, t.panel == 1));
        return a;
    }
    let [chart, table] =
        Layout::vertical([Constraint::Min(6), Constraint::Length(TABLE_H)]).areas(right);
    a.charts.push((chart, t.panel == 1));
    a.table = Some(table);
    a
}

/// The last run's record has x or y.
fn tri_axial(t: &VibrationTab) -> bool {
    t.outcome().is_some_and(|o| o.traces.tri_axial())
}

/// The first settings line shown in a panel `inner_h` rows high: where the
/// view was left (`settings_top`), moved the least that shows the selected
/// row; the status line after the rows shows when the last row is selected
/// and there is room.
pub fn settings_scroll(t: &VibrationTab, inner_h: usize) -> usize {
    let inner_h = inner_h.max(1);
    // The rows and the status line under them.
    let lines = t.rows().len() + 1;
    let sel = t.sel.min(lines.saturating_sub(2));
    let top = t.settings_top.min(lines.saturating_sub(inner_h));
    if sel < top {
        sel
    } else if sel >= top + inner_h {
        sel + 1 - inner_h
    } else {
        top
    }
}
