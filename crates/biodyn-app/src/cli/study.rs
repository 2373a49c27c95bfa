//! `biodyn study`: one parameter varied, three functions overlaid.

use super::args::{BandArgs, Format, ModelArgs};
use super::out::{emit, fx, table};
use super::response::rows_json;
use anyhow::{Context, Result};
use biodyn::freq::response::Function;
use biodyn::freq::study::{self, Study, Trend};
use biodyn::{Band, Body, Preset};
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
    /// Comma-separated values, or ± percentages of the base value: 65,75,85 or -40%,0%,+40%
    #[arg(allow_hyphen_values = true)]
    pub values: String,
    #[command(flatten)]
    pub model: ModelArgs,
    #[command(flatten)]
    pub band: BandArgs,
    /// table: peak summary and trends; csv/json: the curves (json adds peaks and trends).
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
}

/// Parses the parameter and values and runs the study on the preset.
pub fn build(preset: &Preset, band: &Band, param: &str, values: &str) -> Result<Study> {
    let p = preset
        .body
        .param(param)
        .with_context(|| format!("study parameter '{param}'"))?;
    let steps = study::parse_steps(values)?;
    Ok(study::run(&preset.body, p, &steps, band)?)
}

pub fn run(a: &StudyArgs) -> Result<()> {
    let preset = a.model.load()?;
    let band = a.band.band(preset.band)?;
    let s = build(&preset, &band, &a.param, &a.values)?;
    emit(&match a.format {
        Format::Table => summary(&preset.body, &s),
        Format::Csv => csv(&s),
        Format::Json => json(&s)?,
    })
}

fn summary(body: &Body, s: &Study) -> String {
    let mut out = format!(
        "Study of {} ({}; base value {} {}) on {}–{} Hz, step {} Hz\n",
        s.param_label,
        describe(body, s),
        study::round_sig(s.base_value),
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
                        row.push(fx(p.mag, if p.function == Function::Stht { 4 } else { 2 }));
                    }
                    None => row.extend(["-".to_string(), "-".to_string()]),
                }
            }
            row
        })
        .collect();
    out += &table(
        &[
            "variant",
            "STHT f Hz",
            "STHT peak",
            "DPMI f Hz",
            "DPMI peak N·s/m",
            "APMS f Hz",
            "APMS peak kg",
        ],
        &rows,
    );
    let _ = writeln!(out, "\nAs {} increases:", s.param_label);
    for t in s.trends() {
        let _ = writeln!(out, "  {}", trend_line(&t));
    }
    out
}

/// One sentence per function: peak magnitude, peak frequency, share of band.
pub fn trend_line(t: &Trend) -> String {
    format!(
        "{}: peak magnitude {}, peak frequency {}; the magnitude rises at every step over {:.0} % of the band and falls over {:.0} %",
        t.function.name(),
        t.peak_mag.word(),
        t.peak_f.word(),
        100.0 * t.rises_share,
        100.0 * t.falls_share
    )
}

fn describe(body: &Body, s: &Study) -> String {
    match s.param {
        biodyn::Param::BodyMass => "segment masses = shares × body mass".into(),
        biodyn::Param::Mass(i) => format!("mass of {}", body.segments[i].name),
        biodyn::Param::Stiffness(i) => format!("stiffness of link {}", body.links[i].name),
        biodyn::Param::Damping(i) => format!("damping of link {}", body.links[i].name),
    }
}

fn csv(s: &Study) -> String {
    let mut out = String::from("variant,value,");
    out += super::response::CSV_HEADER;
    out.push('\n');
    for v in &s.variants {
        let label = v.label.replace('"', "'");
        for r in &v.curve {
            let _ = write!(out, "\"{label}\",{},{}", v.value, r.f_hz);
            for f in Function::ALL {
                let _ = write!(out, ",{},{}", r.mag(f), r.phase_deg(f));
            }
            out.push('\n');
        }
    }
    out
}

fn json(s: &Study) -> Result<String> {
    let variants: Vec<serde_json::Value> = s
        .variants
        .iter()
        .map(|v| {
            serde_json::json!({
                "label": v.label,
                "value": v.value,
                "peaks": v.peaks.iter().flatten().collect::<Vec<_>>(),
                "points": rows_json(&v.curve),
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
    Ok(serde_json::to_string_pretty(&doc)? + "\n")
}
