//! `biodyn fit`: fit a body model to measured APMS, DPMI or STHT (SPEC §8).

use super::args::{Format, ModelArgs, table_or_json};
use super::free::{self, ArgError};
use super::progress::Progress;
use crate::view::report::table::table;
use crate::view::report::{Report, render};
use anyhow::Result;
use biodyn::fit::{self, DataError, Fit, FitError, FreeParam, Intervals, Measured, Settings};
use biodyn::{Body, Preset};
use clap::Args;
use serde_json::{Map, Value, json};
use std::fmt::Write;
use std::path::PathBuf;

#[derive(Debug, Args)]
#[command(
    after_help = "Examples:\n  biodyn fit --data examples/synthetic-stht-apms-3pct-2deg.csv\n  biodyn fit --data subject3.csv --free k4,c4,body-mass --bound k4=2e4..5e5\n  biodyn fit --data apms.csv --preset paper-85kg --starts 32 --save fitted.toml --format json\n\nData: a CSV with f_hz and any of stht_mag, stht_phase_deg, dpmi_mag, dpmi_phase_deg,\napms_mag, apms_phase_deg (the header `biodyn response --format csv` prints), each\noptionally weighted by a <column>_sd column; empty cells are values not measured."
)]
pub struct FitArgs {
    /// Measured data, CSV (see below).
    #[arg(long, value_name = "FILE")]
    pub data: PathBuf,
    #[command(flatten)]
    pub model: ModelArgs,
    /// Parameters to fit, comma-separated: links (every k and c), masses,
    /// all, body-mass, m1.., k1.., c1.., a segment name (its mass) or a link
    /// name (its k and c).
    #[arg(long, value_name = "LIST", default_value = "links")]
    pub free: String,
    /// Box of a free parameter, repeatable: NAME=LO..HI (an end may be left
    /// empty). Default: 1/1000 to 1000 times the start value.
    #[arg(long = "bound", value_name = "NAME=LO..HI")]
    pub bound: Vec<String>,
    /// Levenberg–Marquardt runs: from the start model, then from seeded
    /// points within a factor of 3 of it. The best is kept.
    #[arg(long, value_name = "N", default_value_t = 8)]
    pub starts: usize,
    /// Seed of the start points: same seed, same result, bit for bit.
    #[arg(long, value_name = "N", default_value_t = 1, allow_negative_numbers = true, value_parser = super::args::whole)]
    pub seed: u64,
    /// How the 95 % intervals are found: profile (the cost minimised over
    /// the other parameters stays within F(0.95; 1, m − p)·s² of the best;
    /// honest where the cost is not quadratic or has other minima) or
    /// curvature (linearised at the best fit: quicker, often too narrow).
    #[arg(long, value_name = "METHOD", default_value = "profile", value_parser = interval_methods())]
    pub intervals: Intervals,
    /// Write the fitted model as a preset; its description records the data and the fit.
    #[arg(long, value_name = "FILE")]
    pub save: Option<PathBuf>,
    /// Replace a read-only --save file (its mode is kept).
    #[arg(long)]
    pub force: bool,
    /// Output format.
    #[arg(long, default_value = "table", value_parser = table_or_json())]
    pub format: Format,
}

pub fn run(a: &FitArgs) -> Result<String> {
    // The save is checked before the fit: not onto the data or the preset,
    // not a read-only file, a folder that takes it.
    let guard = biodyn::io::Guard::reading(
        std::iter::once(a.data.clone()).chain(a.model.input_file()),
        a.force,
    );
    if let Some(path) = &a.save {
        guard.check(path)?;
    }
    let preset = a.model.load()?;
    let data = Measured::load(&a.data)?;
    let words = |e| super::words::fit(e, &a.bound);
    let texts = a
        .bound
        .iter()
        .map(|b| free::parse_bound(b))
        .collect::<Result<Vec<_>, _>>()?;
    let selected = free::parse_free(&preset.body, &a.free)?;
    // The free list is checked before the bounds' names, as they are read.
    fit::free_params(&preset.body, &selected, &[]).map_err(words)?;
    let bounds = free::bounds(&preset.body, &texts)?;
    let free = fit::free_params(&preset.body, &selected, &bounds).map_err(words)?;
    let settings = Settings {
        starts: a.starts,
        seed: a.seed,
        intervals: a.intervals,
    };
    let result = fit_shown(&preset.body, &data, &free, settings).map_err(words)?;
    let report = render(
        &FitReport {
            preset: &preset,
            data: &data,
            result: &result,
        },
        a.format,
    )?;
    if let Some(path) = &a.save {
        let saved = fitted_preset(&preset, &data, &result, path);
        if let Err(e) = saved.save_guarded(path, &guard) {
            // The fit is not lost with the file: print it, then the error.
            super::emit(&report)?;
            return Err(anyhow::Error::new(e).context(format!(
                "the fit is printed above; {} was not written",
                path.display()
            )));
        }
        super::out::status!("saved the fitted model to {}", path.display());
    }
    Ok(report)
}

/// The fit with its progress line: start i of n and the best cost so far,
/// then the profile walks (parameters done of those walked).
fn fit_shown(
    body: &Body,
    data: &Measured,
    free: &[FreeParam],
    s: Settings,
) -> Result<Fit, FitError> {
    let mut bar = Progress::bar("fit", s.starts as u64, format!("start 0/{}", s.starts));
    fit::fit_with(body, data, free, s, &mut |p| {
        bar.set_total((p.starts + p.profiles) as u64);
        bar.update((p.done + p.profiled) as u64, || match p.profiles {
            0 => format!(
                "start {}/{} best cost {:.4e}",
                p.done, p.starts, p.best_cost
            ),
            n => format!("profile {}/{n} best cost {:.4e}", p.profiled, p.best_cost),
        });
        true
    })
}

/// `profile` or `curvature`, named as the library names them.
fn interval_methods() -> impl clap::builder::TypedValueParser<Value = Intervals> {
    use clap::builder::TypedValueParser;
    let all = [Intervals::Profile, Intervals::Curvature];
    clap::builder::PossibleValuesParser::new(all.map(Intervals::key))
        .map(move |s| all.into_iter().find(|i| i.key() == s).unwrap_or_default())
}

/// The fit in the output layer's formats (table or JSON; not a grid).
struct FitReport<'a> {
    preset: &'a Preset,
    data: &'a Measured,
    result: &'a Fit,
}

impl Report for FitReport<'_> {
    fn table(&self) -> String {
        text(self.preset, self.data, self.result)
    }

    fn json(&self) -> Result<String, serde_json::Error> {
        crate::view::report::json::pretty(&json_report(self.preset, self.data, self.result))
    }
}

/// The start preset with the fitted body; the description says how it was
/// made. The data file's name and the preset's name (from the save path)
/// are written with control and invisible characters escaped (`\t`,
/// `\u{1}`): a preset refuses them, so a saved file with them in would not
/// load back.
fn fitted_preset(start: &Preset, data: &Measured, r: &Fit, path: &std::path::Path) -> Preset {
    let plain = |s: &str| biodyn::io::excerpt(s, usize::MAX);
    let names: Vec<&str> = r.params.iter().map(|p| p.name.as_str()).collect();
    let undetermined: Vec<&str> = r.undetermined().iter().map(|p| p.name.as_str()).collect();
    let mut description = format!(
        "{} fitted by biodyn fit to {} ({}; {} values at {} frequencies): free {}; {} starts, seed {}; cost {} (sum of squared log-magnitude and phase residuals), reached by {} starts",
        start.name,
        plain(&data.path),
        r.columns.join(", "),
        r.values,
        r.points,
        names.join(", "),
        r.settings.starts,
        r.settings.seed,
        r.cost,
        r.converged_starts,
    );
    if !undetermined.is_empty() {
        let _ = write!(
            description,
            "; not determined by the data: {}",
            undetermined.join(", ")
        );
    }
    Preset {
        name: path
            .file_stem()
            .map(|s| plain(&s.to_string_lossy()))
            .unwrap_or_else(|| "fitted".into()),
        description,
        source: start.source.clone(),
        body: r.body.clone(),
        band: start.band,
    }
}

fn json_report(preset: &Preset, data: &Measured, r: &Fit) -> Value {
    let params: Vec<Value> = r
        .params
        .iter()
        .map(|p| {
            json!({
                "name": p.name,
                "start": p.start,
                "value": p.value,
                "ci95_low": p.ci95_low,
                "ci95_high": p.ci95_high,
                "ci95_pieces": p.ci95_pieces.iter().map(|&(l, h)| json!([l, h])).collect::<Vec<_>>(),
                "determined": p.determined,
            })
        })
        .collect();
    let mut rms = Map::new();
    for c in &r.residual_rms {
        rms.insert(c.column.clone(), c.rms.into());
    }
    let peaks: Vec<Value> = r
        .peaks
        .iter()
        .map(|p| {
            json!({
                "function": p.function.key(),
                "data_f_hz": p.data_f_hz,
                "data_mag": p.data_mag,
                "data_at_edge": p.data_at_edge,
                "model_f_hz": p.model_f_hz,
                "model_mag": p.model_mag,
                "model_at_edge": p.model_at_edge,
            })
        })
        .collect();
    json!({
        "model": preset.name,
        "data": data.path,
        "columns": r.columns,
        "points": r.points,
        "values": r.values,
        "starts": r.settings.starts,
        "seed": r.settings.seed,
        "seconds": r.seconds,
        "cost": r.cost,
        "converged_starts": r.converged_starts,
        "intervals": r.settings.intervals.key(),
        "interval_threshold": r.q95,
        "parameters": params,
        "correlations": r.correlations,
        "residual_rms": rms,
        "peaks": peaks,
    })
}

/// An interval end: "unbounded" where the data do not bound it.
fn end(v: Option<f64>) -> String {
    v.map_or_else(|| "unbounded".into(), sig)
}

/// Four significant figures for eyes; plain below a million.
fn sig(v: f64) -> String {
    if !v.is_finite() {
        return "unbounded".into();
    }
    if v == 0.0 {
        return "0".into();
    }
    let mag = v.abs().log10().floor() as i32;
    if (-2..6).contains(&mag) {
        let decimals = (3 - mag).max(0) as usize;
        format!("{v:.decimals$}")
    } else {
        format!("{v:.3e}")
    }
}

fn text(preset: &Preset, data: &Measured, r: &Fit) -> String {
    let mut s = String::new();
    let (lo, hi) = (
        data.f_hz.first().copied().unwrap_or(0.0),
        data.f_hz.last().copied().unwrap_or(0.0),
    );
    let _ = writeln!(s, "fit of {} to {}", preset.name, data.path);
    let _ = writeln!(
        s,
        "data: {} frequencies, {lo}–{hi} Hz; {} values in {}",
        r.points,
        r.values,
        r.columns.join(", ")
    );
    let _ = writeln!(
        s,
        "{} free parameters, {} starts (seed {}): {} reached the best cost {} in {:.3} s",
        r.params.len(),
        r.settings.starts,
        r.settings.seed,
        r.converged_starts,
        sig(r.cost),
        r.seconds
    );
    let dof = r.values - r.params.len();
    let _ = match r.settings.intervals {
        Intervals::Profile => writeln!(
            s,
            "95 % intervals by profile likelihood: where the cost, minimised over the other parameters, stays within F(0.95; 1, {dof}) = {:.3} times s² of the best\n",
            r.q95
        ),
        Intervals::Curvature => writeln!(
            s,
            "95 % intervals from the curvature at the best fit: ln p ± t(0.975; {dof}) σ, t = {:.3}; too narrow where the cost is not quadratic\n",
            r.q95.sqrt()
        ),
    };
    let rows: Vec<Vec<String>> = r
        .params
        .iter()
        .map(|p| {
            let mut note = String::new();
            if p.at_bound {
                note += " at bound";
            }
            if p.other_minimum {
                note += " *";
            }
            vec![
                p.name.clone(),
                p.unit.to_string(),
                sig(p.start),
                sig(p.value),
                end(p.ci95_low),
                end(p.ci95_high),
                format!("{}{note}", if p.determined { "yes" } else { "NO" }),
            ]
        })
        .collect();
    s += &table(
        &[
            "parameter",
            "unit",
            "start",
            "fitted",
            "95% low",
            "95% high",
            "determined",
        ],
        &rows,
    );

    s += "\ncorrelations\n";
    let names: Vec<&str> = r.params.iter().map(|p| p.name.as_str()).collect();
    let mut header = vec![""];
    header.extend(names.iter().copied());
    let rows: Vec<Vec<String>> = r
        .correlations
        .iter()
        .zip(&names)
        .map(|(row, n)| {
            let mut cells = vec![n.to_string()];
            cells.extend(row.iter().map(|c| {
                if c.is_finite() {
                    format!("{c:.2}")
                } else {
                    "-".into()
                }
            }));
            cells
        })
        .collect();
    s += &table(&header, &rows);

    s += "\nresidual r.m.s. per column\n";
    let rows: Vec<Vec<String>> = r
        .residual_rms
        .iter()
        .map(|c| {
            let v = if c.column.ends_with("_deg") {
                format!("{:.2}°", c.rms)
            } else {
                format!("{:.2} %", 100.0 * c.rms)
            };
            vec![c.column.clone(), v]
        })
        .collect();
    s += &table(&["column", "r.m.s."], &rows);

    if !r.peaks.is_empty() {
        s += "\nmain peaks, data and fitted model\n";
        let edge = |e: bool| if e { " (edge)" } else { "" };
        let rows: Vec<Vec<String>> = r
            .peaks
            .iter()
            .map(|p| {
                vec![
                    p.function.name().to_string(),
                    format!("{:.2}{}", p.data_f_hz, edge(p.data_at_edge)),
                    sig(p.data_mag),
                    format!("{:.2}{}", p.model_f_hz, edge(p.model_at_edge)),
                    sig(p.model_mag),
                ]
            })
            .collect();
        s += &table(
            &["function", "data Hz", "data |H|", "model Hz", "model |H|"],
            &rows,
        );
    }

    s.push('\n');
    let undetermined = r.undetermined();
    if undetermined.is_empty() {
        s += "Every free parameter is determined: its 95 % interval lies within a factor of 2 of its value.\n";
    } else {
        let names: Vec<&str> = undetermined.iter().map(|p| p.name.as_str()).collect();
        let _ = writeln!(
            s,
            "Not determined by these data: {}. Their 95 % intervals reach past a factor of 2 of the fitted value, so read those values as unknown; leave them out of --free, or add data that show them (phases, STHT for the head-neck link).",
            names.join(", ")
        );
    }
    if r.params.iter().any(|p| p.other_minimum) {
        s += "* The interval takes in another start's minimum that the data do not reject (its cost is inside the joint 95 % region): the data cannot choose between them.\n";
        for p in r.params.iter().filter(|p| p.ci95_pieces.len() > 1) {
            let pieces: Vec<String> = p
                .ci95_pieces
                .iter()
                .map(|&(l, h)| format!("{} to {}", end(l), end(h)))
                .collect();
            let _ = writeln!(
                s,
                "  {}: the 95 % set has gaps: {} {}",
                p.name,
                pieces.join(" or "),
                p.unit
            );
        }
    }
    if r.params
        .iter()
        .any(|p| p.ci95_low.is_none() || p.ci95_high.is_none())
    {
        let _ = writeln!(
            s,
            "unbounded: the interval reaches the parameter's box (--bound, or 1/1000 to 1000 × its start within the model's limits): the data do not bound it on that side."
        );
    }
    if r.converged_starts == 1 && r.settings.starts > 1 {
        s += "Only one start reached the best cost: the fit has other minima; more --starts may find a better one.\n";
    }
    s
}

/// What to try next for an error of `biodyn fit`, if it is one.
pub fn hint(cause: &(dyn std::error::Error + 'static)) -> Option<String> {
    if let Some(d) = cause.downcast_ref::<DataError>() {
        return Some(match d {
            DataError::Read(_) => "give the path of a regular CSV file (at most 16 MiB)".into(),
            _ => format!(
                "data: a header with f_hz and any of {} (optional <column>_sd); frequencies > 0 and increasing; empty cells are values not measured",
                biodyn::fit::KNOWN
            ),
        });
    }
    if let Some(a) = cause.downcast_ref::<ArgError>() {
        return Some(match a {
            ArgError::Free(_) => FREE_HINT.into(),
            ArgError::Bound(_) => BOUND_HINT.into(),
        });
    }
    let f = cause.downcast_ref::<FitError>()?;
    Some(match f {
        FitError::Data(d) => return hint(d),
        FitError::EmptyFree
        | FitError::NotInModel { .. }
        | FitError::NoSuchLink { .. }
        | FitError::MassTwice { .. }
        | FitError::NoBodyMass
        | FitError::NoShare { .. }
        | FitError::OffShare { .. } => FREE_HINT.into(),
        FitError::ZeroStart { .. } => {
            "give it a positive start with --set NAME=VALUE, or leave it out of --free".into()
        }
        FitError::BadBound { .. }
        | FitError::BoundNotFree { .. }
        | FitError::BoundTwice { .. }
        | FitError::AboveLimit { .. }
        | FitError::BelowLimit { .. }
        | FitError::EmptyBox { .. } => BOUND_HINT.into(),
        FitError::TooFewValues { .. } => {
            "free fewer parameters (e.g. --free k4,c4) or give more frequencies or columns".into()
        }
        FitError::BadStarts { .. } => "e.g. --starts 8".into(),
        _ => "`biodyn fit --help` describes the data file and the options".into(),
    })
}

const FREE_HINT: &str = "--free takes a comma-separated list: links, masses, all, body-mass, m1.., k1.., c1.., segment or link names";
const BOUND_HINT: &str =
    "e.g. --bound k4=1e4..1e6 (0 < LO < HI, either end may be empty), for a parameter in --free";
