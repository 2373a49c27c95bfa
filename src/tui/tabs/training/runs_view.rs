//! The runs table: the last runs side by side (case, trainer, seed,
//! epochs, time, RMS, MPRE, held-out max / mean error). Columns that do
//! not fit the width are left out, least useful first; numbers are never cut.

use super::history::{RunRecord, epochs_text};
use super::state::TrainingTab;
use crate::tui::shared::Shared;
use crate::tui::widgets::block;
use crate::view::format::num;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::Line;
use ratatui::widgets::{Paragraph, Widget};

type Cell = fn(usize, &RunRecord) -> String;

/// (heading, width, cell, priority: lower stays longer).
const COLUMNS: [(&str, usize, Cell, u8); 11] = [
    ("#", 1, |i, _| (i + 1).to_string(), 0),
    ("case", 9, |_, r| r.case.key().to_string(), 0),
    ("tr", 8, |_, r| r.trainer.key().to_string(), 1),
    ("body", 6, |_, r| r.body.clone(), 4),
    ("seed", 6, |_, r| r.seed.to_string(), 5),
    ("epochs", 8, |_, r| epochs_text(&r.member_epochs), 2),
    ("time s", 6, |_, r| num(r.seconds, 3), 4),
    ("RMS", 7, |_, r| opt(r.rms), 0),
    ("MPRE%", 6, |_, r| opt(r.mpre_pct), 1),
    ("ho max%", 7, |_, r| opt(r.holdout_max_pct), 0),
    ("mean%", 6, |_, r| opt(r.holdout_mean_pct), 3),
];

fn opt(v: Option<f64>) -> String {
    v.map_or("-".into(), |v| num(v, 3))
}

/// The columns that fit `width`, in table order.
fn fitting(width: usize) -> Vec<usize> {
    let mut order: Vec<usize> = (0..COLUMNS.len()).collect();
    order.sort_by_key(|&i| COLUMNS[i].3);
    let mut used = 0;
    let mut keep = Vec::new();
    for i in order {
        let w = COLUMNS[i].1 + 1;
        if used + w <= width {
            used += w;
            keep.push(i);
        }
    }
    keep.sort_unstable();
    keep
}

pub fn render(t: &TrainingTab, s: &Shared, area: Rect, buf: &mut Buffer) {
    let th = s.theme;
    let cols = fitting(usize::from(area.width.saturating_sub(2)));
    let row = |cells: Vec<String>| -> String {
        cols.iter()
            .zip(cells)
            .map(|(&i, c)| {
                let w = COLUMNS[i].1;
                if (1..=3).contains(&i) {
                    format!("{c:<w$}")
                } else {
                    format!("{c:>w$}")
                }
            })
            .collect::<Vec<_>>()
            .join(" ")
    };
    let mut lines = vec![Line::styled(
        row(cols.iter().map(|&i| COLUMNS[i].0.to_string()).collect()),
        th.heading(),
    )];
    let runs = &t.history.runs;
    // The newest runs when not all fit.
    let room = usize::from(area.height.saturating_sub(3));
    let skip = runs.len().saturating_sub(room);
    for (i, r) in runs.iter().enumerate().skip(skip) {
        lines.push(Line::raw(row(cols.iter().map(|&c| (COLUMNS[c].2)(i, r)).collect())));
    }
    let title = format!("last {} runs (newest last)", runs.len());
    Paragraph::new(lines).block(block(&title, th)).render(area, buf);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn narrow_tables_keep_the_key_columns() {
        let names = |w| -> Vec<&str> { fitting(w).iter().map(|&i| COLUMNS[i].0).collect() };
        assert_eq!(names(44), ["#", "case", "tr", "RMS", "MPRE%", "ho max%"]);
        assert_eq!(names(200).len(), COLUMNS.len());
    }
}
