//! `biodyn assess`: ISO 2631-1 exposure of the seat record and what the
//! model says reaches the head; EU 2002/44/EC verdicts and comfort words.

use super::args::{Format, ModelArgs, table_or_json};
use super::input::{InputArgs, Samples};
use super::progress::Counted;
use super::report::ReportArgs;
use crate::view::figure::assess::Recorder;
use crate::view::report::{Report, assess, axes_only, html, json, meta, render};
use anyhow::Result;
use biodyn::iso2631::spine::Person;
use biodyn::iso2631::{assess_axes_only, assess_points, assess_with};
use biodyn::time::Axis;
use clap::Args;
use serde_json::Value;

#[derive(Debug, Args)]
#[command(
    after_help = "Examples:\n  biodyn assess --signal sine:freq=5,amp=1\n  biodyn assess --signal random:rms=0.8,band=1-20,seed=1+shock:peak=15,width=0.1,at=30 --duration 60\n  biodyn assess --input seat.csv --exposure 6 --format json\n  biodyn assess --input ride.csv --exposure 4 --spine age=25,years=10,days=240,sex=male\n  biodyn assess --input seat.csv --exposure 6 --report assessment.html"
)]
pub struct AssessArgs {
    #[command(flatten)]
    pub model: ModelArgs,
    #[command(flatten)]
    pub input: InputArgs,
    /// Hours a day of this vibration, for A(8) and the VDV over the exposure:
    /// 6.5, 6:30, 6h30, 6h or 45min (over 0, at most 24 h).
    #[arg(
        long,
        value_name = "HOURS",
        default_value = "8",
        allow_negative_numbers = true,
        value_parser = parse_exposure
    )]
    pub exposure: f64,
    /// ISO 2631-5:2018 spinal dose and injury risk of the seat's z for this person:
    /// age when the exposure starts, years of it, days a year, sex (Annex C's constants).
    #[arg(long, value_name = "age=A,years=N,days=D,sex=male|female", value_parser = parse_spine)]
    pub spine: Option<Person>,
    #[arg(long, default_value = "table", value_parser = table_or_json())]
    pub format: Format,
    /// Also write a figure (SVG): each axis's weighted trace and its
    /// one-third-octave bands, then the head's (the model's).
    #[arg(long, value_name = "FILE.svg")]
    pub plot: Option<std::path::PathBuf>,
    #[command(flatten)]
    pub report: ReportArgs,
}

pub fn run(a: &AssessArgs) -> Result<String> {
    let inputs = a
        .report
        .inputs(a.input.input.iter().cloned().chain(a.model.input_file()));
    let page = a.report.check(&inputs)?;
    let figure = super::figure_file::check(
        a.plot.as_ref(),
        &inputs,
        a.report.report.as_ref(),
        "assess.svg",
    )?;
    let meta = a.report.meta()?;
    let preset = a.model.load()?;
    let input = a.input.open()?;
    if !input.axes.has(Axis::Z) {
        return axes_only(a, input, page, figure.is_some(), &meta);
    }
    let source = input.source.clone();
    let (body, fs, axes, who) = (&preset.body, input.fs, &input.axes, a.spine.as_ref());
    // The figure is drawn for --plot and for the report's page.
    let mut recorder = match a.plot.is_some() || a.report.report.is_some() {
        true => Some(Recorder::new(body, fs, axes).map_err(anyhow::Error::msg)?),
        false => None,
    };
    // The samples counted on the progress line, which is gone when they are.
    let mut r = match input.rows {
        Samples::Seat(rows) => {
            let rows = Recorder::tee(&mut recorder, Counted::new(rows, "assess", input.total));
            assess_with(body, fs, rows, axes, a.exposure, who)?
        }
        Samples::Frames(f) => {
            let f = Recorder::tee_frames(&mut recorder, Counted::new(f, "assess", input.total));
            assess_points(body, fs, f, axes, &input.points, a.exposure, who)?
        }
    };
    if let Some(Err(e)) = &r.spine {
        return Err(e.clone().into());
    }
    if a.spine.is_none() {
        r.warnings.extend(assess::shock_note(&r));
    }
    let head_name = preset
        .body
        .segments
        .get(preset.body.head)
        .map_or("head", |s| s.name.as_str());
    let mut json = assess::json(&r, &preset.name, &source);
    if let (Some(m), Some(o)) = (meta::json(&meta), json.as_object_mut()) {
        o.insert("meta".into(), m);
    }
    let report = AssessReport {
        json,
        table: meta::text(&meta) + &assess::text(&r, &preset.name, &source, head_name),
    };
    let out = render(&report, a.format)?;
    let mut written = Vec::new();
    if let (Some(file), Some(rec)) = (figure, &recorder) {
        // The assessment is not lost with the figure: printed, then the error.
        written.push(file.write(&rec.figure(&r, head_name).svg(), &out)?);
    }
    if let Some(page) = page {
        // Without the model, the figure has no head either.
        let head = (!a.report.no_model).then_some(head_name);
        let figures: Vec<String> = recorder
            .iter()
            .map(|rec| rec.figure_of(&r, head).inline_svg())
            .collect();
        page.write_after(
            &html::assess::page_of(&report.json, head, &figures),
            &out,
            &written,
        )?;
    }
    Ok(out)
}

/// A record without z: the Directive on the axes it has, no body (it is
/// driven vertically), said in every output; the figure and the spine need z.
fn axes_only(
    a: &AssessArgs,
    input: super::input::Input,
    page: Option<super::report::Pending>,
    plot: bool,
    meta: &biodyn::exposure::Meta,
) -> Result<String> {
    if a.spine.is_some() {
        anyhow::bail!(
            "--spine judges the seat's z (ISO 2631-5), and this record has none: {}",
            axes_only::NO_BODY
        );
    }
    if plot {
        anyhow::bail!(
            "--plot draws the seat's z and the head, and this record has no z: leave --plot out ({})",
            axes_only::NO_BODY
        );
    }
    if !input.points.is_empty() {
        input.require_vertical()?;
    }
    let Samples::Seat(rows) = input.rows else {
        anyhow::bail!("{}", axes_only::NO_BODY);
    };
    let rows = Counted::new(rows, "assess", input.total);
    let r = assess_axes_only(input.fs, rows, &input.axes, a.exposure)?;
    let mut json = axes_only::json(&r, &input.source);
    if let (Some(m), Some(o)) = (meta::json(meta), json.as_object_mut()) {
        o.insert("meta".into(), m);
    }
    let report = AssessReport {
        json,
        table: meta::text(meta) + &axes_only::text(&r, &input.source),
    };
    let out = render(&report, a.format)?;
    if let Some(page) = page {
        page.write(&html::assess::page_of(&report.json, None, &[]), &out)?;
    }
    Ok(out)
}

/// `--exposure` as people write hours (`6:30`, `6h30`, `45min`), in
/// the command line's words.
fn parse_exposure(s: &str) -> Result<f64, String> {
    use biodyn::exposure::{HOURS_FORMS, HoursError, hours_text, parse_hours};
    parse_hours(s).map_err(|e| match e {
        HoursError::Form(_) => format!("not hours; write {HOURS_FORMS}, e.g. --exposure 6:30"),
        HoursError::Minutes { example, .. } => {
            format!("minutes past the hour are 0 to 59; write e.g. --exposure {example}")
        }
        HoursError::Range { hours, .. } => format!(
            "{}: the exposure must be over 0 and at most 24 h a day, e.g. --exposure 8",
            hours_text(hours)
        ),
    })
}

fn parse_spine(s: &str) -> Result<Person, String> {
    Person::parse(s).map_err(|e| e.to_string())
}

/// The assessment in the output layer's formats (table or JSON).
struct AssessReport {
    json: Value,
    table: String,
}

impl Report for AssessReport {
    fn table(&self) -> String {
        self.table.clone()
    }

    fn json(&self) -> Result<String, serde_json::Error> {
        json::pretty(&self.json)
    }
}
