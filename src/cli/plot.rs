//! `biodyn plot`: the TUI's response chart, rendered into a buffer and
//! printed as text — quick exploration over SSH, or in a pipe — or the same
//! figure as SVG for a paper (`--format svg`, `--output fig.svg`).

use super::args::{BandArgs, FunctionArg, ModelArgs};
use super::refused::Refused;
use crate::view::chart::{Emphasis, Series};
use crate::view::figure::{self, response::ResponseFigure};
use crate::view::report::plot::{self, PlotText};
use anyhow::{Context, Result, bail};
use biodyn::fit::{Channel, Measured, Quantity};
use biodyn::{Body, Solver, freq};
use clap::{Args, ValueEnum};
use std::io::IsTerminal;
use std::path::{Path, PathBuf};

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
    /// Width: text, columns 20..1000 (default: the terminal's, or 100 in a
    /// pipe); svg, pixels 200..4000 (default 800).
    #[arg(long)]
    pub width: Option<u64>,
    /// Height: text, rows 8..500 (default: the terminal's minus 2, or 30 in
    /// a pipe); svg, pixels 150..4000 (default 500).
    #[arg(long)]
    pub height: Option<u64>,
    /// Measured data over the model: a CSV as `biodyn fit --data` reads
    /// (f_hz, then e.g. apms_mag, apms_mag_sd for error bars).
    #[arg(long, value_name = "FILE")]
    pub data: Option<PathBuf>,
    /// A second model drawn beneath (grey, dotted): a preset name or file.
    #[arg(long, value_name = "PRESET")]
    pub compare: Option<String>,
    /// text (the chart as characters) or svg (a figure for a paper).
    /// Default: from --output's extension, else text.
    #[arg(long, value_enum)]
    pub format: Option<PlotFormat>,
    /// Write the figure to FILE (.svg or .txt) instead of standard output.
    #[arg(long, value_name = "FILE")]
    pub output: Option<PathBuf>,
    #[command(flatten)]
    pub model: ModelArgs,
    #[command(flatten)]
    pub band: BandArgs,
}

/// What `plot` writes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum PlotFormat {
    Text,
    Svg,
}

impl PlotFormat {
    fn of(path: &Path) -> Option<PlotFormat> {
        match path.extension()?.to_str()?.to_ascii_lowercase().as_str() {
            "svg" => Some(PlotFormat::Svg),
            "txt" => Some(PlotFormat::Text),
            _ => None,
        }
    }
}

/// The format asked for: --format, else --output's extension, else text.
fn format_of(a: &PlotArgs) -> Result<PlotFormat> {
    let from_path = match &a.output {
        Some(p) => Some(PlotFormat::of(p).ok_or_else(|| {
            Refused::error(
                format!(
                    "--output {}: the figure's format comes from the extension, and this one is neither .svg nor .txt",
                    p.display()
                ),
                "name the file fig.svg (a figure) or fig.txt (the chart as text); PNG is not written: `rsvg-convert fig.svg -o fig.png` makes one",
            )
        })?),
        None => None,
    };
    match (a.format, from_path) {
        (Some(f), Some(g)) if f != g => bail!(
            "--format {} disagrees with --output's extension ({}): give one of them",
            if f == PlotFormat::Svg { "svg" } else { "text" },
            a.output
                .as_deref()
                .map(Path::display)
                .map_or(String::new(), |d| d.to_string())
        ),
        (Some(f), _) | (None, Some(f)) => Ok(f),
        (None, None) => Ok(PlotFormat::Text),
    }
}

/// Writes the plot: to --output (checked before the work, saved atomically)
/// or returned for standard output.
pub fn run(a: &PlotArgs) -> Result<String> {
    let format = format_of(a)?;
    let guard = biodyn::io::Guard::reading(
        a.model
            .input_file()
            .into_iter()
            .chain(a.data.clone())
            .chain(
                a.compare
                    .as_ref()
                    .map(PathBuf::from)
                    .filter(|p| p.is_file()),
            ),
        false,
    );
    if let Some(path) = &a.output {
        guard.check(path)?;
    }
    let text = figure_text(a, format)?;
    match &a.output {
        Some(path) => {
            biodyn::io::save_guarded(path, &guard, text.as_bytes())
                .with_context(|| format!("the figure was not written to {}", path.display()))?;
            Ok(String::new())
        }
        None => Ok(text),
    }
}

fn figure_text(a: &PlotArgs, format: PlotFormat) -> Result<String> {
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
    let svg = format == PlotFormat::Svg;
    let (tw, th) = if svg {
        (u64::from(figure::PANEL_PX.0), u64::from(figure::PANEL_PX.1))
    } else if std::io::stdout().is_terminal() {
        // A terminal with no size (a bare pseudo-terminal) says 0x0.
        crossterm::terminal::size()
            .ok()
            .filter(|&(w, h)| w > 0 && h > 2)
            .map_or((100, 30), |(w, h)| (u64::from(w), u64::from(h - 2)))
    } else {
        (100, 30)
    };
    let (w, h) = (a.width.unwrap_or(tw), a.height.unwrap_or(th));
    let px =
        |v: u64, r: &std::ops::RangeInclusive<u32>| u32::try_from(v).ok().filter(|v| r.contains(v));
    let (wp, hp) = (px(w, &figure::WIDTH_PX), px(h, &figure::HEIGHT_PX));
    if svg && (wp.is_none() || hp.is_none()) {
        bail!(
            "figure size {w}x{h} px: --width must be 200..4000 and --height 150..4000 with --format svg"
        );
    }
    let (Some(w16), Some(h16)) = (
        u16::try_from(w).ok().filter(|_| svg || WIDTHS.contains(&w)),
        u16::try_from(h)
            .ok()
            .filter(|_| svg || HEIGHTS.contains(&h)),
    ) else {
        bail!("plot size {w}x{h}: --width must be 20..1000 and --height 8..500");
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
            series.push(plot::curve_series(&preset.name, &curve, function, a.phase));
            if !a.phase {
                marks.extend(
                    freq::find_peaks_in(&solver, &curve, function)
                        .iter()
                        .map(|p| (p.f_hz, p.mag)),
                );
            }
        }
    }
    let model: &[(f64, f64)] = series.first().map_or(&[], |s| &s.points);
    let data = match &a.data {
        Some(path) => {
            let m = Measured::load(path)?;
            let pts =
                figure::response::measured(&m, function, a.phase, model).ok_or_else(|| {
                    Refused::error(
                        format!(
                            "{} has no {} column",
                            path.display(),
                            Channel::new(function, quantity(a.phase)).key()
                        ),
                        format!(
                            "its columns: {}; plot one of those, or add the column",
                            m.column_names().join(", ")
                        ),
                    )
                })?;
            Some((figure::response::data_name(&m.path), pts))
        }
        None => None,
    };
    let reference = match &a.compare {
        Some(name) => Some(compared(name, &band, function, a.phase)?),
        None => None,
    };
    if svg {
        let f = ResponseFigure {
            function,
            phase: a.phase,
            log_x: a.log_x,
            log_y: a.log_y,
            series: &series,
            marks: &marks,
            data: data.as_ref().map(|(n, p)| (n.as_str(), p.as_slice())),
            reference: reference.as_ref(),
            size: (
                wp.unwrap_or(figure::PANEL_PX.0),
                hp.unwrap_or(figure::PANEL_PX.1),
            ),
        };
        return Ok(figure::response::figure(&f).svg());
    }
    let mut emphasis = vec![Emphasis::Normal; series.len()];
    if let Some((name, pts)) = data {
        series.push(Series {
            name,
            points: pts.iter().map(|p| (p.0, p.1)).collect(),
        });
        emphasis.push(Emphasis::Normal);
    }
    if let Some(r) = reference {
        series.push(r);
        emphasis.push(Emphasis::Dim);
    }
    let o = PlotText {
        function,
        log_x: a.log_x,
        log_y: a.log_y,
        ascii: a.ascii,
        width: w16,
        height: h16,
    };
    Ok(plot::chart_text_with(
        &series, &emphasis, marks, a.phase, &o,
    ))
}

fn quantity(phase: bool) -> Quantity {
    if phase {
        Quantity::Phase
    } else {
        Quantity::Mag
    }
}

/// The compared model's curve over the same band.
fn compared(
    name: &str,
    band: &biodyn::Band,
    function: biodyn::Function,
    phase: bool,
) -> Result<Series> {
    let m = super::args::ModelArgs {
        preset: Some(name.to_string()),
        body_mass: None,
        set: Vec::new(),
    };
    let preset = m.load().context("--compare")?;
    if function.needs_seat() && !preset.body.has_seat() {
        bail!(
            "--compare {name}: {} is a seat's function and '{}' has no seat; compare with a seated model",
            function.key(),
            preset.name
        );
    }
    band.check_work(preset.body.n())?;
    let body: &Body = &preset.body;
    let curve = Solver::try_new(body)?.sweep(band);
    Ok(plot::curve_series(&preset.name, &curve, function, phase))
}
