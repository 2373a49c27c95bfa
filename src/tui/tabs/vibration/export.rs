//! The Vibration tab's export (`x`): by the path's extension, the
//! simulation as `biodyn simulate --format csv` prints it (`compute.rs`
//! writes it), or the assessment the tab shows as `biodyn assess` prints
//! it, `--format json` for a `.json` path and the text (its table format)
//! for a `.txt` one: the same bytes as the command line for the same record,
//! settings and model (the report is `view::report::assess`, the command's
//! own), or for a `.svg` path the figure `biodyn assess --plot` draws (each
//! axis's weighted trace and its bands, then the head's). Run again from
//! the input on the export's thread, as the command runs it: a record with
//! other points' channels (backrest, feet) is judged with them, as `assess`
//! does.

use super::compute::{self, Input, Source};
use crate::view::figure::assess::Recorder;
use crate::view::report::assess;
use crate::view::report::input::{Source as Named, axes_words};
use biodyn::Body;
use biodyn::iso2631::{assess_points, assess_with};
use biodyn::time::{Generator, RecordError, TimeError};
use std::io::Write;
use std::path::Path;

/// What `x` writes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// `biodyn simulate --format csv`: every output, every sample.
    Simulation,
    /// `biodyn assess --format json`.
    AssessJson,
    /// `biodyn assess` (the table format: text).
    AssessText,
    /// `biodyn assess --plot FILE.svg`: the figure.
    AssessFigure,
}

impl Kind {
    /// By the path's extension: `.json` and `.txt` are the assessment,
    /// anything else (`.csv`) the simulation.
    pub fn of(path: &Path) -> Kind {
        let ext = path
            .extension()
            .map(|e| e.to_string_lossy().to_ascii_lowercase());
        match ext.as_deref() {
            Some("json") => Kind::AssessJson,
            Some("txt") => Kind::AssessText,
            Some("svg") => Kind::AssessFigure,
            _ => Kind::Simulation,
        }
    }

    /// The command whose output the file holds, for the status line.
    pub fn command(self) -> &'static str {
        match self {
            Kind::Simulation => "biodyn simulate --format csv",
            Kind::AssessJson => "biodyn assess --format json",
            Kind::AssessText => "biodyn assess",
            Kind::AssessFigure => "biodyn assess --plot",
        }
    }
}

/// What `biodyn assess` prints for this body (named `model`, the preset's
/// name) and input, in `kind`'s format.
pub fn assessment(body: &Body, model: &str, input: &Input, kind: Kind) -> Result<String, String> {
    compute::check(input)?;
    let (who, h) = (input.spine.as_ref(), input.exposure_h);
    // The figure's recorder re-simulates beside the assessment, as the
    // command's does.
    let figure = kind == Kind::AssessFigure;
    let mut recorder: Option<Recorder> = None;
    let (mut r, source) = match &input.source {
        Source::Signal(sig) => {
            let g =
                Generator::new(sig, input.fs_hz, input.duration_s).map_err(|e| e.to_string())?;
            let axes = compute::vertical();
            if figure {
                recorder = Some(Recorder::new(body, input.fs_hz, &axes)?);
            }
            let rows = Recorder::tee(&mut recorder, g.map(|a| Ok::<_, TimeError>([0.0, 0.0, a])));
            let r = assess_with(body, input.fs_hz, rows, &axes, h, who).map_err(|e| e.to_string())?;
            (r, Named::Signal(sig.to_string()))
        }
        Source::File {
            path,
            axes,
            unit,
            remove_mean,
        } => {
            let rec = compute::open_record(path, axes, *unit, *remove_mean, input.fs_hz)
                .map_err(|e| TimeError::from(e).to_string())?;
            let named = Named::Record {
                path: path.clone(),
                time: Some(rec.time_column().to_string()).filter(|t| !t.is_empty()),
                columns: Box::new(rec.columns().clone()),
            };
            let (fs, axes, points) = (rec.fs(), rec.axes(), rec.points());
            if !axes.has(biodyn::time::Axis::Z) {
                let why = RecordError::NoVertical {
                    path: path.clone(),
                    axes: axes_words(rec.columns()),
                };
                return Err(TimeError::from(why).to_string());
            }
            if figure {
                recorder = Some(Recorder::new(body, fs, &axes)?);
            }
            let r = if points.is_empty() {
                let rows = Recorder::tee(&mut recorder, rec.map(|r| r.map_err(TimeError::from)));
                assess_with(body, fs, rows, &axes, h, who)
            } else {
                let frames = Recorder::tee_frames(
                    &mut recorder,
                    rec.frames().map(|r| r.map_err(TimeError::from)),
                );
                assess_points(body, fs, frames, &axes, &points, h, who)
            }
            .map_err(|e| e.to_string())?;
            (r, named)
        }
    };
    if let Some(Err(e)) = &r.spine {
        return Err(e.to_string());
    }
    if who.is_none() {
        r.warnings.extend(assess::shock_note(&r));
    }
    let head = body
        .segments
        .get(body.head)
        .map_or("head", |s| s.name.as_str());
    Ok(match (kind, &recorder) {
        (Kind::AssessJson, _) => {
            crate::view::report::json::pretty(&assess::json(&r, model, &source))
                .map_err(|e| e.to_string())?
        }
        (Kind::AssessFigure, Some(rec)) => rec.figure(&r, head).svg(),
        _ => assess::text(&r, model, &source, head),
    })
}

/// Exports `kind` to `path` through the library's atomic save (a failed
/// export leaves the old file, or none); returns the simulation's rows or
/// the assessment's lines.
pub fn export(
    body: &Body,
    model: &str,
    input: &Input,
    kind: Kind,
    path: &Path,
) -> Result<u64, String> {
    if kind == Kind::Simulation {
        return compute::export(body, input, path);
    }
    let text = assessment(body, model, input, kind)?;
    biodyn::io::save_atomic_with(path, |f| f.write_all(text.as_bytes()))
        .map_err(|e| e.to_string())?;
    Ok(text.lines().count() as u64)
}
