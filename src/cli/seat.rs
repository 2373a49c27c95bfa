//! `biodyn seat`: a seat's figures in the frequency domain (SEAT %, the
//! pan's and the floor's a_w, the suspension's r.m.s. stroke) for a floor
//! PSD, for every input class, or the search of a box of one or two
//! parameters for the lowest SEAT that keeps a stroke limit.

use super::args::{BandArgs, Format, ModelArgs, quote};
use super::progress::{Progress, of};
use super::refused::Refused;
use super::seat_plot::{self, Chosen};
use crate::view::figure::response::file_name;
use crate::view::report::render;
use crate::view::report::seat::{SeatClasses, SeatOne};
use crate::view::report::seat_design::SeatDesign;
use anyhow::{Context, Result};
use biodyn::seat::{Design, FloorPsd, MAX_HZ, MIN_HZ, SeatError, SeatGrid, Vary, design_with};
use biodyn::time::{CLASSES, InputClass};
use clap::Args;
use std::path::PathBuf;

#[derive(Debug, Args)]
#[command(
    after_help = "Examples:\n  biodyn seat --preset paper-75kg-suspension-seat                 SEAT % per input class\n  biodyn seat --preset paper-75kg-suspension-seat --class EM6\n  biodyn seat --preset paper-75kg-suspension-seat --psd floor.csv --format json\n  biodyn seat --preset paper-75kg-suspension-seat --class EM6 \\\n      --vary suspension.c=200..4000 --stroke-rms-max 0.015"
)]
pub struct SeatArgs {
    #[command(flatten)]
    pub model: ModelArgs,
    /// The floor's acceleration PSD: a CSV with the header
    /// f_hz,psd_m2_s4_hz ((m/s²)²/Hz, frequencies rising).
    #[arg(long, value_name = "FILE", conflicts_with = "class")]
    pub psd: Option<PathBuf>,
    /// An input spectral class as the floor: EM1..EM9 (ISO 7096), IT1..IT4
    /// (EN 13490), AG1..AG3 (ISO 5007). With neither --psd nor --class:
    /// one row per class.
    #[arg(long, value_name = "NAME")]
    pub class: Option<String>,
    /// Search this parameter's box, NAME=LO..HI (repeatable, once or
    /// twice): a seat link's k or c, or a seat segment's mass, e.g.
    /// suspension.c=200..4000.
    #[arg(long, value_name = "NAME=LO..HI", allow_hyphen_values = true)]
    pub vary: Vec<String>,
    /// The search's limit on the suspension's r.m.s. stroke, m (with --vary).
    #[arg(long, value_name = "M", allow_negative_numbers = true)]
    pub stroke_rms_max: Option<f64>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
    /// Also write the seat's figure (SVG): its transmissibility, pan over
    /// floor and floor to head, and SEAT % per input class, the --class or
    /// --psd floor selected.
    #[arg(long, value_name = "FILE.svg")]
    pub plot: Option<PathBuf>,
    /// The transmissibility's band in --plot (--from, --to, --step; the
    /// preset's band by default).
    #[command(flatten)]
    pub band: BandArgs,
}

/// The example every hint about --vary gives.
const VARY_EXAMPLE: &str = "--vary suspension.c=200..4000 --stroke-rms-max 0.015";

pub fn run(a: &SeatArgs) -> Result<String> {
    let banded = a.band.from.is_some() || a.band.to.is_some() || a.band.step.is_some();
    if banded && (a.plot.is_none() || !a.vary.is_empty()) {
        return Err(Refused::error(
            "--from/--to/--step: the band is the seat figure's (--plot FILE.svg without --vary); SEAT % is integrated over the floor's PSD",
            "add --plot seat.svg for the transmissibility over that band, or leave the band out",
        ));
    }
    let figure_file = super::figure_file::check(
        a.plot.as_ref(),
        a.model.input_file().into_iter().chain(a.psd.clone()),
        None,
        "seat.svg",
    )?;
    let done = figures(a)?;
    if let Some(file) = figure_file {
        let band = a.band.band(done.preset.band)?;
        let svg = seat_plot::svg(
            &done.preset.body,
            &band,
            done.floor.as_ref(),
            done.searched.as_ref(),
        )?;
        file.write(&svg, &done.out)?;
    }
    Ok(done.out)
}

/// What the command worked out: its output, and for the figure the model,
/// the floor it was given and the search, when there was one.
struct Done {
    out: String,
    preset: biodyn::Preset,
    floor: Option<Chosen>,
    searched: Option<Design>,
}

/// The command's output: the figures for one floor, every class, or the
/// design search.
fn figures(a: &SeatArgs) -> Result<Done> {
    let preset = a.model.load()?;
    let body = &preset.body;
    if !body.has_seat() {
        return Err(SeatError::NoSeat.into());
    }
    match (a.vary.is_empty(), a.stroke_rms_max) {
        (true, Some(m)) => {
            return Err(Refused::error(
                format!(
                    "--stroke-rms-max {}: the limit is the design search's, and nothing is varied",
                    biodyn::io::num(m)
                ),
                format!(
                    "search a box with it: {VARY_EXAMPLE}; leave it out for the seat's figures"
                ),
            ));
        }
        (false, None) => {
            return Err(Refused::error(
                "--vary: the search needs a limit on the suspension's r.m.s. stroke (--stroke-rms-max M)",
                format!(
                    "e.g. {VARY_EXAMPLE} (m r.m.s.; the preset's stroke_m is end-stop to end-stop)"
                ),
            ));
        }
        _ => {}
    }
    let floor = match (&a.psd, &a.class) {
        (Some(path), _) => Chosen {
            psd: FloorPsd::load(path)?,
            name: file_name(&path.to_string_lossy()),
            file: true,
        },
        (None, Some(name)) => {
            let c = class(name)?;
            Chosen {
                psd: FloorPsd::Class(c),
                name: c.name.to_string(),
                file: false,
            }
        }
        (None, None) if a.vary.is_empty() => {
            return Ok(Done {
                out: every_class(&preset.name, body, a.format)?,
                preset,
                floor: None,
                searched: None,
            });
        }
        (None, None) => {
            return Err(Refused::error(
                "--vary: the search is for one floor: give --class NAME or --psd FILE",
                format!("e.g. --class EM6 {VARY_EXAMPLE}"),
            ));
        }
    };
    let psd = &floor.psd;
    let input = match &a.psd {
        Some(path) => path.display().to_string(),
        None => psd.name(),
    };
    let grid = SeatGrid::new(psd)?;
    if let Some(words) = clipped(psd, &grid) {
        super::out::note!("note: {input}: {words}");
    }
    if let Some(limit) = a.stroke_rms_max {
        let vary = a
            .vary
            .iter()
            .map(|text| {
                let (name, lo, hi) = parse_vary(text)?;
                Vary::new(body, name, lo, hi).with_context(|| format!("--vary {}", quote(text)))
            })
            .collect::<Result<Vec<_>>>()?;
        let design = {
            let mut line = None;
            let mut progress = |done: usize, map: usize| {
                let bar = line.get_or_insert_with(|| {
                    Progress::bar("seat", map as u64, of(0, map, "map points"))
                });
                bar.update(done as u64, || match done.checked_sub(map) {
                    None | Some(0) => of(done, map, "map points"),
                    Some(more) => format!("map done, refining: {more} evaluations"),
                });
            };
            design_with(body, &grid, &vary, limit, &mut progress)?
        };
        let report = SeatDesign {
            model: preset.name.clone(),
            input,
            design,
        };
        return Ok(Done {
            out: render(&report, a.format)?,
            preset,
            floor: Some(floor),
            searched: Some(report.design),
        });
    }
    let about = match psd {
        FloorPsd::Class(c) => format!("{}, {}–{} Hz", c.standard, c.band_hz.0, c.band_hz.1),
        FloorPsd::Table { rows, .. } if grid.range() != psd.range() => format!(
            "{} rows, {}–{} Hz, integrated over {}–{} Hz",
            rows.len(),
            biodyn::io::num(psd.range().0),
            biodyn::io::num(psd.range().1),
            biodyn::io::num(grid.range().0),
            biodyn::io::num(grid.range().1)
        ),
        FloorPsd::Table { rows, .. } => format!(
            "{} rows, {}–{} Hz",
            rows.len(),
            biodyn::io::num(psd.range().0),
            biodyn::io::num(psd.range().1)
        ),
    };
    let figures = grid.figures(body)?;
    let out = render(
        &SeatOne {
            model: preset.name.clone(),
            input,
            about,
            integrated_hz: grid.range(),
            figures,
        },
        a.format,
    )?;
    Ok(Done {
        out,
        preset,
        floor: Some(floor),
        searched: None,
    })
}

/// What a PSD file's rows outside [`MIN_HZ`]–[`MAX_HZ`] become, in words;
/// None when every row is inside.
fn clipped(psd: &FloorPsd, grid: &SeatGrid) -> Option<String> {
    let ((lo, hi), (from, to)) = (psd.range(), grid.range());
    let below = (lo < from).then(|| {
        format!(
            "the rows below {MIN_HZ} Hz (from {} Hz) are left out: |W_k| is under 0.032 there",
            biodyn::io::num(lo)
        )
    });
    let above = (hi > to).then(|| {
        format!(
            "the rows above {MAX_HZ} Hz (to {} Hz) are left out: |W_k| is under 1.3e-4 there",
            biodyn::io::num(hi)
        )
    });
    match (below, above) {
        (None, None) => None,
        (b, a) => Some(b.into_iter().chain(a).collect::<Vec<_>>().join("; ")),
    }
}

/// The figures under every input class.
fn every_class(model: &str, body: &biodyn::Body, format: Format) -> Result<String> {
    let rows = CLASSES
        .iter()
        .map(|c| Ok((c, SeatGrid::new(&FloorPsd::Class(c))?.figures(body)?)))
        .collect::<Result<Vec<_>, SeatError>>()?;
    render(
        &SeatClasses {
            model: model.to_string(),
            rows,
        },
        format,
    )
}

/// The class named on the command line.
fn class(name: &str) -> Result<&'static InputClass> {
    InputClass::parse(name).ok_or_else(|| {
        Refused::error(
            format!(
                "--class {}: not an input spectral class; the classes are {}",
                quote(name),
                InputClass::names()
            ),
            "e.g. --class EM6 (any case); leave --class out for the table of every class",
        )
    })
}

/// `NAME=LO..HI` split and its ends parsed as numbers (the library checks
/// the name and the range).
pub fn parse_vary(text: &str) -> Result<(&str, f64, f64)> {
    let bad = |why: String| {
        Refused::error(
            format!("--vary {}: {why}", quote(text)),
            format!("write NAME=LO..HI with 0 < LO < HI, e.g. {VARY_EXAMPLE}"),
        )
    };
    let Some((name, range)) = text.split_once('=') else {
        return Err(bad("expected NAME=LO..HI".into()));
    };
    let name = name.trim();
    if name.is_empty() {
        return Err(bad("the parameter name is empty".into()));
    }
    let Some((lo, hi)) = range.split_once("..") else {
        return Err(bad(format!(
            "the range '{}' is not LO..HI",
            quote(range.trim())
        )));
    };
    let number = |s: &str| {
        let s = s.trim();
        s.parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .ok_or_else(|| bad(format!("'{}' is not a finite number", quote(s))))
    };
    Ok((name, number(lo)?, number(hi)?))
}

/// What to try next after a seat error.
pub fn hint(cause: &(dyn std::error::Error + 'static)) -> Option<String> {
    let e = cause.downcast_ref::<SeatError>()?;
    Some(match e {
        SeatError::NoSeat => "`biodyn seat --preset paper-75kg-suspension-seat`; `biodyn preset show paper-75kg-suspension-seat` prints a [seat] table to copy".into(),
        SeatError::Read { .. }
        | SeatError::Empty { .. }
        | SeatError::Header { .. }
        | SeatError::Field { .. }
        | SeatError::Unsorted { .. }
        | SeatError::TooFew { .. }
        | SeatError::Silent { .. } => "a PSD file is a regular CSV file: the header f_hz,psd_m2_s4_hz, then rows of frequency (Hz, rising strictly) and density ((m/s²)²/Hz, ≥ 0); `#` starts a comment".into(),
        SeatError::NoWeightedInput { .. } | SeatError::OutsideRange { .. } => "give the floor's PSD where W_k weighs (0.4 to 100 Hz), or use --class NAME".into(),
        SeatError::Unresolved { .. } => "a damping ratio under about 1e-4 makes a resonance too sharp for the integration; give the seat's and the body's links some damping (`biodyn modes` lists the damping ratios)".into(),
        SeatError::BadVary { .. } | SeatError::Model { .. } => "vary a seat link's k or c or a seat segment's mass, e.g. --vary suspension.k=4000..20000 --vary suspension.c=200..4000; `biodyn preset show` names the links".into(),
        SeatError::BadRange { .. } => format!("write NAME=LO..HI with 0 < LO < HI, e.g. {VARY_EXAMPLE}"),
        SeatError::VariedTwice(_) | SeatError::TooManyVaried { .. } | SeatError::NothingVaried => "give --vary once or twice, each parameter once: e.g. --vary suspension.k=4000..20000 --vary suspension.c=200..4000".into(),
        SeatError::BadLimit(_) => "e.g. --stroke-rms-max 0.015 (m r.m.s., finite and > 0; the preset's stroke_m is end-stop to end-stop)".into(),
        SeatError::Infeasible { .. } => "a stiffer or more damped suspension travels less: raise the box's HI, or allow more with --stroke-rms-max".into(),
    })
}
