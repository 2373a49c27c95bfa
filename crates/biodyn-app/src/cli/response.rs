//! `biodyn response`: STHT, DPMI and APMS over a band.

use super::args::{BandArgs, Format, ModelArgs};
use super::out::{emit, fx, table};
use anyhow::Result;
use biodyn::Solver;
use biodyn::freq::response::{Function, Response};
use clap::Args;
use std::fmt::Write;

/// The exact CSV header, shared with the reference tables.
pub const CSV_HEADER: &str =
    "f_hz,stht_mag,stht_phase_deg,dpmi_mag,dpmi_phase_deg,apms_mag,apms_phase_deg";

#[derive(Debug, Args)]
#[command(
    after_help = "Examples:\n  biodyn response\n  biodyn response --format csv --step 0.01 > br.csv\n  biodyn response --body-mass 85 --set k4=54000 --from 1 --to 10 --format json"
)]
pub struct ResponseArgs {
    #[command(flatten)]
    pub model: ModelArgs,
    #[command(flatten)]
    pub band: BandArgs,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
}

pub fn run(a: &ResponseArgs) -> Result<()> {
    let preset = a.model.load()?;
    let band = a.band.band(preset.band)?;
    let curve = Solver::new(&preset.body).sweep(&band);
    emit(&match a.format {
        Format::Csv => csv(&curve),
        Format::Json => json(&curve)?,
        Format::Table => text(&curve),
    })
}

pub fn csv(curve: &[Response]) -> String {
    let mut s = String::with_capacity(curve.len() * 120);
    s.push_str(CSV_HEADER);
    s.push('\n');
    for r in curve {
        let _ = write!(s, "{}", r.f_hz);
        for f in Function::ALL {
            let _ = write!(s, ",{},{}", r.mag(f), r.phase_deg(f));
        }
        s.push('\n');
    }
    s
}

/// One JSON object per frequency, keyed like the CSV columns.
pub fn rows_json(curve: &[Response]) -> Vec<serde_json::Value> {
    curve
        .iter()
        .map(|r| {
            let mut m = serde_json::Map::new();
            m.insert("f_hz".into(), r.f_hz.into());
            for f in Function::ALL {
                m.insert(format!("{}_mag", f.key()), r.mag(f).into());
                m.insert(format!("{}_phase_deg", f.key()), r.phase_deg(f).into());
            }
            serde_json::Value::Object(m)
        })
        .collect()
}

fn json(curve: &[Response]) -> Result<String> {
    Ok(serde_json::to_string_pretty(&rows_json(curve))? + "\n")
}

fn text(curve: &[Response]) -> String {
    let rows: Vec<Vec<String>> = curve
        .iter()
        .map(|r| {
            vec![
                fx(r.f_hz, 3),
                fx(r.mag(Function::Stht), 4),
                fx(r.phase_deg(Function::Stht), 1),
                fx(r.mag(Function::Dpmi), 1),
                fx(r.phase_deg(Function::Dpmi), 1),
                fx(r.mag(Function::Apms), 2),
                fx(r.phase_deg(Function::Apms), 1),
            ]
        })
        .collect();
    table(
        &[
            "f Hz",
            "|STHT|",
            "STHT deg",
            "|DPMI| N·s/m",
            "DPMI deg",
            "|APMS| kg",
            "APMS deg",
        ],
        &rows,
    )
}
