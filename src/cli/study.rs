//! `biodyn study`: one parameter varied, three functions overlaid.

use super::args::{BandArgs, Format, ModelArgs};
use crate::view::report::table::{fx, table};
use crate::view::report::{self, Report, json, render};
use crate::view::trend;
use anyhow::{Context, Result};
use biodyn::freq::{self, Study};
use biodyn::{Band, Body, Function, Preset};
use clap::Args;
use std::fmt::Write;

#[derive(Debug, Args)]
#[command(
    after_help = "Examples:\n  biodyn study mass 65,75,85\n  biodyn study k4 -40%,0%,+40%\n  biodyn study c4 -40%,0%,+40% --format csv > c4.csv\n  biodyn study pelvis-seat.k 60000,90000,120000 --format json"
)]
pub struct StudyArgs {
    /// Parameter to vary: mass (body mass), m1..mN, k1..kN, c1..cN, a segment
    /// name, or LINK.k / LINK.c.
    pub param: String,
    /// Comma-separated values, or ± percentages of the base value: 65,75,85 or
    /// -40%,0%,+40%. Default: the paper's list (65,75,85 kg for mass, ±40 % else).
    #[arg(allow_hyphen_values = true)]
    pub values: Option<String>,
    #[command(flatten)]
    pub model: ModelArgs,
    #[command(flatten)]
    pub band: BandArgs,
    /// table: peak summary and trends; csv/json: the curves (json adds peaks and trends).
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
}

/// Parses the parameter and values (None: the paper's list) and runs the
/// study on the preset.
pub fn build(preset: &Preset, band: &Band, param: &str, values: Option<&str>) -> Result<Study> {
    let p = preset
        .body
        .param(param)
        .with_context(|| format!("study parameter '{}'", super::args::quote(param)))?;
    let steps = freq::parse_steps(values.unwrap_or(freq::paper_steps(p)))?;
    let mut progress = super::progress::counting("study", "frequencies");
    Ok(freq::run_study_with(
        &preset.body,
        p,
        &steps,
        band,
        &mut progress,
    )?)
}

pub fn run(a: &StudyArgs) -> Result<String> {
    let preset = a.model.load()?;
    let band = a.band.band(preset.band)?;
    let study = build(&preset, &band, &a.param, a.values.as_deref())?;
    render(
        &StudyReport {
            body: preset.body,
            study,
        },
        a.format,
    )
}

/// A study: the table is the peak summary and the trends; CSV and JSON
/// carry the curves (JSON adds peaks and trends).
struct StudyReport {
    body: Body,
    study: Study,
}

impl Report for StudyReport {
    fn table(&self) -> String {
        summary(&self.body, &self.study)
    }

    fn csv(&self) -> Option<String> {
        Some(report::study::curves_csv(&self.study))
    }

    fn json(&self) -> Result<String, serde_json::Error> {
        study_json(&self.study)
    }
}

fn summary(body: &Body, s: &Study) -> String {
    let mut out = format!(
        "Study of {} ({}; base value {} {}) on {}–{} Hz, step {} Hz\n",
        s.param_label,
        describe(body, s),
        freq::round_sig(s.base_value),
        s.param.unit(),
        s.band.from,
        s.band.to,
        s.band.step
    );
    let rows: Vec<Vec<String>> = s
        .variants
        .iter()
        .map(|v| {
            let mut row = vec![v.label.clone()];
            for p in &v.peaks {
                match p {
                    Some(p) => {
                        let edge = if p.at_edge { " (edge)" } else { "" };
                        row.push(format!("{}{edge}", fx(p.f_hz, 3)));
                        row.push(fx(p.mag, p.function.peak_decimals()));
                    }
                    None => row.extend(["-".to_string(), "-".to_string()]),
                }
            }
            row
        })
        .collect();
    let mut header = vec!["variant".to_string()];
    for f in Function::ALL {
        header.push(format!("{} f Hz", f.name()));
        header.push(match f.unit_label() {
            "" => format!("{} peak", f.name()),
            u => format!("{} peak {u}", f.name()),
        });
    }
    let h: Vec<&str> = header.iter().map(String::as_str).collect();
    out += &table(&h, &rows);
    out.push('\n');
    if let Some(why) = trend::nothing_to_compare(s) {
        let _ = writeln!(
            out,
            "{why}. Give two or more different values, e.g. 65,75,85 or -40%,0%,+40%."
        );
        return out;
    }
    for t in s.trends() {
        let _ = writeln!(out, "{}", trend::sentence(&s.param_label, &t));
    }
    out
}

fn describe(body: &Body, s: &Study) -> String {
    match s.param {
        biodyn::Param::BodyMass => "segment masses = shares × body mass".into(),
        biodyn::Param::Mass(i) => format!("mass of {}", body.segments[i].name),
        biodyn::Param::Stiffness(i) => format!("stiffness of link {}", body.links[i].name),
        biodyn::Param::Damping(i) => format!("damping of link {}", body.links[i].name),
    }
}

fn study_json(s: &Study) -> Result<String, serde_json::Error> {
    let variants: Vec<serde_json::Value> = s
        .variants
        .iter()
        .map(|v| {
            serde_json::json!({
                "label": v.label,
                "value": v.value,
                "peaks": v.peaks.iter().flatten().collect::<Vec<_>>(),
                "points": json::curve_rows(&v.curve),
            })
        })
        .collect();
    let doc = serde_json::json!({
        "param": s.param_label,
        "unit": s.param.unit(),
        "base_value": s.base_value,
        "band": s.band,
        "variants": variants,
        "trends": s.trends(),
    });
    json::pretty(&doc)
}
