//! The held-out errors under the prediction: one row per held-out curve
//! (value, max and mean error, interpolation or extrapolation, ◀ on the
//! one charted). Narrow panels drop the mean, then shorten the words; a
//! number is never cut.

use super::state::TrainingTab;
use crate::tui::shared::Shared;
use crate::tui::widgets::block;
use crate::view::chart;
use crate::view::format::num;
use biodyn::ann::HoldoutResult;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Paragraph, Widget};

pub fn render(t: &TrainingTab, s: &Shared, area: Rect, buf: &mut Buffer, loss_hidden: bool) {
    let th = s.theme;
    let (Some(holdouts), Some(out)) = (
        t.shown_holdouts(),
        t.run.as_ref().and_then(|r| r.outcome.as_ref()),
    ) else {
        return;
    };
    let inner = usize::from(area.width.saturating_sub(2));
    let unit = out.net.case.param_unit();
    let shown = t.holdout_value();
    let rows = holdout_rows(holdouts, unit, shown, inner);
    // The chart above may be too short for its own legend: name the series here.
    let mut lines = vec![Line::from(vec![
        Span::styled(
            chart::legend_glyph(0, th.ascii),
            chart::series_style(0, th.mono),
        ),
        Span::raw(" analytic  "),
        Span::styled(
            chart::legend_glyph(1, th.ascii),
            chart::series_style(1, th.mono),
        ),
        Span::raw(" network"),
    ])];
    lines.extend(rows.into_iter().map(Line::raw));
    let full = holdout_layout(holdouts, unit, inner).0 == 0;
    let titles: &[&str] = match (full, loss_hidden) {
        (true, true) => &[
            "held-out errors (◀ charted) — z: loss curve too",
            "held-out errors (◀ charted)",
        ],
        (true, false) => &["held-out errors (◀ charted)"],
        (false, _) => &[
            "held-out max errors (◀ charted)",
            "held-out max error (◀ chart)",
            "max error (◀ charted)",
            "max error",
        ],
    };
    let title = titles
        .iter()
        .find(|t| t.chars().count() <= inner)
        .or(titles.last())
        .copied()
        .unwrap_or_default();
    Paragraph::new(lines)
        .block(block(title, th))
        .render(area, buf);
}

type Layout4 = fn(&HoldoutResult, &str, usize) -> String;

/// The row layouts, most words first: value, unit, interp/extrap, max and
/// mean error; the narrower ones drop the mean, then shorten the words.
const HOLDOUT_LAYOUTS: [Layout4; 4] = [
    |h, unit, vw| {
        format!(
            "{:>vw$} {unit} {} max {:>5}% mean {:>5}%",
            num(h.value, 4),
            ix(h),
            num(h.max_err_pct, 3),
            num(h.mean_err_pct, 3)
        )
    },
    |h, unit, vw| {
        format!(
            "{:>vw$} {unit} {} max {:>5} %",
            num(h.value, 4),
            ix(h),
            num(h.max_err_pct, 3)
        )
    },
    |h, unit, vw| {
        let ex = if h.extrapolation { " extrap" } else { "" };
        format!("{:>vw$} {unit} {:>5} %{ex}", num(h.value, 4), num(h.max_err_pct, 3))
    },
    |h, unit, vw| {
        let ex = if h.extrapolation { " ext" } else { "" };
        format!("{:>vw$} {unit} {:>5} %{ex}", num(h.value, 4), num(h.max_err_pct, 3))
    },
];

fn ix(h: &HoldoutResult) -> &'static str {
    if h.extrapolation { "extrap" } else { "interp" }
}

/// The first layout whose every row (with its " ◀") fits `inner`
/// columns, the narrowest otherwise; and the value column's width.
fn holdout_layout(hs: &[HoldoutResult], unit: &str, inner: usize) -> (usize, usize) {
    let vw = hs
        .iter()
        .map(|h| num(h.value, 4).chars().count())
        .max()
        .unwrap_or(1);
    // The full layout keeps a 7-wide value column, as before.
    let width = |i: usize| if i == 0 { vw.max(7) } else { vw };
    let last = HOLDOUT_LAYOUTS.len() - 1;
    let pick = (0..last)
        .find(|&i| {
            hs.iter()
                .all(|h| HOLDOUT_LAYOUTS[i](h, unit, width(i)).chars().count() + 2 <= inner)
        })
        .unwrap_or(last);
    (pick, width(pick))
}

fn holdout_rows(hs: &[HoldoutResult], unit: &str, shown: f64, inner: usize) -> Vec<String> {
    let (pick, vw) = holdout_layout(hs, unit, inner);
    hs.iter()
        .map(|h| {
            let mark = if h.value == shown { " ◀" } else { "" };
            format!("{}{mark}", HOLDOUT_LAYOUTS[pick](h, unit, vw))
        })
        .collect()
}
