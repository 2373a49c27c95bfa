//! `biodyn plot`: the TUI's response chart, rendered into a buffer and
//! printed as text — quick exploration over SSH, or in a pipe.

use super::args::{BandArgs, FunctionArg, ModelArgs};
use super::refused::Refused;
use crate::view::chart::Series;
use crate::view::report::plot::{self, PlotText};
use anyhow::{Result, bail};
use biodyn::{Response, Solver, freq};
use clap::Args;
use std::io::IsTerminal;

/// Chart sizes `biodyn plot` draws.
const WIDTHS: std::ops::RangeInclusive<u64> = 20..=1000;
const HEIGHTS: std::ops::RangeInclusive<u64> = 8..=500;

#[derive(Debug, Args)]
#[command(
    after_help = "Examples:\n  biodyn plot stht\n  biodyn plot apms --study mass=65,75,85\n  biodyn plot dpmi --study k4=-40%,0%,+40% --log-x --ascii --width 100 --height 30"
)]
pub struct PlotArgs {
    /// Which response function to draw (seat_tr and floor_head: on a model
    /// with a seat).
    #[arg(value_enum)]
    pub function: FunctionArg,
    /// Overlay a study: PARAM=VALUES, e.g. mass=65,75,85 or k4=-40%,0%,+40%
    #[arg(long, value_name = "PARAM=VALUES", allow_hyphen_values = true)]
    pub study: Option<String>,
    /// Plot the phase (degrees) instead of the magnitude.
    #[arg(long, conflicts_with = "log_y")]
    pub phase: bool,
    /// Logarithmic frequency axis.
    #[arg(long)]
    pub log_x: bool,
    /// Logarithmic magnitude axis (not with --phase: a phase can be negative).
    #[arg(long)]
    pub log_y: bool,
    /// Plain ASCII characters (for fonts without braille or box drawing).
    #[arg(long)]
    pub ascii: bool,
    /// Width in columns, 20..1000 (default: the terminal's, or 100 in a pipe).
    #[arg(long)]
    pub width: Option<u64>,
    /// Height in rows, 8..500 (default: the terminal's minus 2, or 30 in a pipe).
    #[arg(long)]
    pub height: Option<u64>,
    #[command(flatten)]
    pub model: ModelArgs,
    #[command(flatten)]
    pub band: BandArgs,
}

pub fn run(a: &PlotArgs) -> Result<String> {
    let preset = a.model.load()?;
    let band = a.band.band(preset.band)?;
    let function = a.function.0;
    if function.needs_seat() && !preset.body.has_seat() {
        return Err(Refused::error(
            format!(
                "{}, the {}, is a seat's function: the model '{}' has no seat",
                function.key(),
                function.long_name(),
                super::args::quote(&preset.name)
            ),
            format!(
                "draw it on a model with a [seat] table, e.g. `biodyn plot {} --preset paper-75kg-suspension-seat`",
                function.key()
            ),
        ));
    }
    let (tw, th) = if std::io::stdout().is_terminal() {
        crossterm::terminal::size()
            .map(|(w, h)| (u64::from(w), u64::from(h.saturating_sub(2))))
            .unwrap_or((100, 30))
    } else {
        (100, 30)
    };
    let (w, h) = (a.width.unwrap_or(tw), a.height.unwrap_or(th));
    let (Some(w16), Some(h16)) = (
        u16::try_from(w).ok().filter(|_| WIDTHS.contains(&w)),
        u16::try_from(h).ok().filter(|_| HEIGHTS.contains(&h)),
    ) else {
        bail!("plot size {w}x{h}: --width must be 20..1000 and --height 8..500");
    };

    let value = |r: &Response| {
        if a.phase {
            r.phase_deg(function)
        } else {
            r.mag(function)
        }
    };
    let mut series = Vec::new();
    let mut marks = Vec::new();
    match &a.study {
        Some(spec) => {
            // PARAM alone takes the paper's list, as `biodyn study PARAM`.
            let (param, values) = match spec.split_once('=') {
                Some((p, v)) => (p, Some(v)),
                None => (spec.as_str(), None),
            };
            let s = super::study::build(&preset, &band, param.trim(), values)?;
            (series, marks) = crate::view::report::study::chart_series(&s, function, a.phase);
        }
        None => {
            band.check_work(preset.body.n())?;
            let solver = Solver::try_new(&preset.body)?;
            let curve = solver.sweep(&band);
            series.push(Series {
                name: preset.name.clone(),
                points: curve.iter().map(|r| (r.f_hz, value(r))).collect(),
            });
            if !a.phase {
                marks.extend(
                    freq::find_peaks_in(&solver, &curve, function)
                        .iter()
                        .map(|p| (p.f_hz, p.mag)),
                );
            }
        }
    }
    let o = PlotText {
        function,
        log_x: a.log_x,
        log_y: a.log_y,
        ascii: a.ascii,
        width: w16,
        height: h16,
    };
    let text = plot::chart_text(&series, marks, a.phase, &o);
    Ok(text)
}
