//! The run panel under the settings: the live numbers of a run, the
//! finished network's, or (idle) what `t` will do and the selected
//! setting's help. Lines wrap, never cut: `areas` sizes the panel from
//! `rows_needed`, and the help is left out where it would not fit whole.

use super::history::epochs_text;
use super::run::Run;
use super::state::TrainingTab;
use crate::tui::shared::Shared;
use crate::tui::theme::Theme;
use crate::tui::widgets::block;
use crate::view::format::{NBSP, glue_units, num, wrap};
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Style;
use ratatui::text::Line;
use ratatui::widgets::{Paragraph, Widget};

#[derive(Debug, Clone, Copy)]
pub enum Tone {
    Plain,
    Dim,
    Key,
    Heading,
    Error,
}

impl Tone {
    fn style(self, th: Theme) -> Style {
        match self {
            Tone::Plain => th.base(),
            Tone::Dim => th.dim(),
            Tone::Key => th.key(),
            Tone::Heading => th.heading(),
            Tone::Error => th.error(),
        }
    }
}

/// The panel's title and lines: `core` always, `help` (the selected
/// setting's) only when it fits whole.
pub struct Panel {
    pub title: String,
    pub core: Vec<(String, Tone)>,
    pub help: Vec<(String, Tone)>,
}

pub fn secs(s: f64) -> String {
    if s < 60.0 {
        format!("{s:.1} s")
    } else if s < 3600.0 {
        format!("{}m{:02}s", (s / 60.0) as u64, (s % 60.0) as u64)
    } else {
        format!(
            "{}h{:02}m",
            (s / 3600.0) as u64,
            ((s % 3600.0) / 60.0) as u64
        )
    }
}

/// Rows `lines` take in `width` columns, as the panel's paragraph wraps
/// them (`Wrap { trim: true }`).
pub fn rows_needed(lines: &[(String, Tone)], width: usize) -> usize {
    let width = width.max(1);
    lines
        .iter()
        .map(|(text, _)| crate::view::format::wrapped_rows(&glue_units(text), width, true))
        .sum()
}

pub fn panel(t: &TrainingTab) -> Panel {
    let help: Vec<(String, Tone)> = match t.current().help() {
        Some(h) if !t.running() => vec![(h.to_string(), Tone::Dim)],
        _ => Vec::new(),
    };
    let Some(run) = &t.run else {
        return Panel {
            title: "run".into(),
            core: idle(t, !help.is_empty()),
            help,
        };
    };
    Panel {
        title: format!("run: {} {}", run.case, run.settings.trainer),
        core: of_run(run),
        help,
    }
}

/// Before the first run: why this model cannot train, or what `t` does.
fn idle(t: &TrainingTab, setting_selected: bool) -> Vec<(String, Tone)> {
    if let (None, Some(e), true) = (&t.settings.base, &t.base_err, t.this_model) {
        // The reason first: it is what the user has to act on.
        return vec![
            ("cannot train on this model:".into(), Tone::Error),
            (e.clone(), Tone::Plain),
        ];
    }
    let start = ("t starts training".to_string(), Tone::Key);
    if setting_selected {
        // The selected setting's help follows (it needs the room).
        return vec![start];
    }
    let paper = t.case.paper();
    let on = match &t.settings.base {
        Some(b) => format!(
            "Trains on a snapshot of tab 1's model ({} segments) at t.",
            b.n()
        ),
        None => "Trains on the paper's body; the model row picks tab 1's.".into(),
    };
    vec![
        (
            format!(
                "paper: {} epochs, MPRE {} %, RMS {}",
                paper.epochs, paper.mpre_pct, paper.rms
            ),
            Tone::Plain,
        ),
        start,
        (on, Tone::Dim),
    ]
}

fn of_run(run: &Run) -> Vec<(String, Tone)> {
    let state = if run.paused() {
        "paused".to_string()
    } else if run.running() {
        "running".to_string()
    } else if let Some(e) = &run.failed {
        format!("failed: {e}")
    } else if let Some(f) = &run.finished {
        format!("ended: {}", f.stop)
    } else {
        "ended".into()
    };
    let bad = run.failed.is_some() || run.finished.as_ref().is_some_and(|f| f.stop.is_diverged());
    let state_tone = if bad { Tone::Error } else { Tone::Heading };
    let mut lines = Vec::new();
    // Numbers first: on a short panel the state line goes before RMS and MPRE do.
    match (&run.finished, &run.last) {
        (Some(f), _) => {
            lines.push((
                format!(
                    "RMS {}  MPRE {}",
                    f.rms.map_or("-".into(), |v| num(v, 3)),
                    f.mpre_pct.map_or("-".into(), |v| format!("{} %", num(v, 3)))
                ),
                Tone::Plain,
            ));
            lines.push((
                format!(
                    "right {} of outputs",
                    f.share_right
                        .map_or("-".into(), |v| format!("{} %", num(v * 100.0, 3)))
                ),
                Tone::Plain,
            ));
            // Per member, as the runs table counts them.
            let epochs = match &run.outcome {
                Some(o) => epochs_text(&o.member_epochs),
                None => f.epochs.to_string(),
            };
            lines.push((
                format!("epochs {epochs} in {}", secs(run.working_s(f.train_seconds))),
                Tone::Plain,
            ));
            // The live numbers were one member's last epoch; these are the
            // finished network's, measured once more on the training data.
            let members = run.outcome.as_ref().map_or(1, |o| o.net.members.len());
            let of = if members > 1 {
                let how = match run.settings.combine {
                    biodyn::ann::Combine::Mean => "mean",
                    biodyn::ann::Combine::Median => "median",
                };
                format!("of the final net ({how} of {members})")
            } else {
                "of the final net (re-measured)".to_string()
            };
            lines.push((of, Tone::Dim));
            lines.push((state, state_tone));
            lines.push((TrainingTab::trained_on(&run.settings), Tone::Dim));
        }
        (None, Some(p)) => {
            lines.push((format!("{state} {}", short_on(run)), state_tone));
            let member = if p.members > 1 {
                format!(" (net {}/{})", p.member + 1, p.members)
            } else {
                String::new()
            };
            lines.push((format!("epoch {}/{}{member}", p.epoch, p.max_epochs), Tone::Plain));
            lines.push((
                format!("RMS {}  MPRE {} %", num(p.rms, 3), num(p.mpre_pct, 3)),
                Tone::Plain,
            ));
            lines.push((
                format!(
                    "right {} %  {} ep/s",
                    num(p.share_right * 100.0, 3),
                    num(p.epochs_per_s, 3)
                ),
                Tone::Plain,
            ));
            let left = (p.max_epochs.saturating_sub(p.epoch)
                + (p.members.saturating_sub(p.member + 1)) as u64 * p.max_epochs)
                as f64;
            let working = run.working_s(p.elapsed_s);
            // ETA only after a second of warm-up, when the rate means something.
            let eta = if working >= 1.0 && p.epochs_per_s > 0.0 {
                format!("ETA ≤ {}", secs(left / p.epochs_per_s))
            } else {
                "ETA …".into()
            };
            lines.push((format!("elapsed {}  {eta}", secs(working)), Tone::Plain));
        }
        (None, None) => {
            lines.push((format!("{state} {}", short_on(run)), state_tone));
            lines.push(("preparing data…".into(), Tone::Plain));
        }
    }
    lines
}

/// "(paper's body)" or "(this model, 5 seg)": what a live run trains on.
fn short_on(run: &Run) -> String {
    match &run.settings.base {
        None => "(paper's body)".into(),
        Some(b) => format!("(this model, {} seg)", b.n()),
    }
}

/// Rows the panel wants: its lines and, when they fit in `max`, the help.
pub fn height(t: &TrainingTab, inner_w: usize, max: u16) -> u16 {
    let p = panel(t);
    let core = rows_needed(&p.core, inner_w) + 2;
    let all = core + rows_needed(&p.help, inner_w);
    let want = if all <= usize::from(max) { all } else { core };
    u16::try_from(want).unwrap_or(u16::MAX)
}

pub fn render(t: &TrainingTab, s: &Shared, area: Rect, buf: &mut Buffer) {
    let th = s.theme;
    let p = panel(t);
    let inner_w = usize::from(area.width.saturating_sub(2));
    let mut lines = p.core;
    if rows_needed(&lines, inner_w) + rows_needed(&p.help, inner_w) + 2
        <= usize::from(area.height)
    {
        lines.extend(p.help);
    }
    // Wrapped here, as the paragraph would, so a number keeps its unit
    // (`glue_units`) and the rows then show a plain space between them.
    let lines: Vec<Line> = lines
        .into_iter()
        .flat_map(|(text, tone)| {
            let style = tone.style(th);
            wrap(&glue_units(&text), inner_w.max(1), true)
                .into_iter()
                .map(move |row| Line::styled(row.replace(NBSP, " "), style))
        })
        .collect();
    Paragraph::new(lines)
        .block(block(&p.title, th))
        .render(area, buf);
}
