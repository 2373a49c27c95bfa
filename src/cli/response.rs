//! `biodyn response`: STHT, DPMI and APMS over a band; on a model with a
//! seat, the seat's transmissibility and floor to head after them.

use super::args::{BandArgs, Format, ModelArgs};
use crate::view::report::{Report, csv, json, render, table};
use anyhow::Result;
use biodyn::{Function, Response, Solver};
use clap::Args;

#[derive(Debug, Args)]
#[command(
    after_help = "Examples:\n  biodyn response\n  biodyn response --format csv --step 0.01 > br.csv\n  biodyn response --body-mass 85 --set k4=54000 --from 1 --to 10 --format json"
)]
pub struct ResponseArgs {
    #[command(flatten)]
    pub model: ModelArgs,
    #[command(flatten)]
    pub band: BandArgs,
    /// At these frequencies only (Hz, comma-separated) instead of a band:
    /// --at 4.6 or --at 3.75,4.56,5.13.
    #[arg(
        long,
        value_name = "HZ,…",
        value_delimiter = ',',
        allow_negative_numbers = true,
        conflicts_with_all = ["from", "to", "step"]
    )]
    pub at: Vec<f64>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
}

/// A response curve in every format, with the functions the model has
/// (`Function::of(has_seat)`).
pub struct Curve {
    pub curve: Vec<Response>,
    pub functions: &'static [Function],
}

impl Report for Curve {
    fn table(&self) -> String {
        table::curve_of(&self.curve, self.functions)
    }

    fn csv(&self) -> Option<String> {
        Some(csv::curve_of(&self.curve, self.functions))
    }

    fn json(&self) -> Result<String, serde_json::Error> {
        json::pretty(&json::curve_rows_of(&self.curve, self.functions))
    }
}

pub fn run(a: &ResponseArgs) -> Result<String> {
    let preset = a.model.load()?;
    if !a.at.is_empty() {
        let freqs =
            a.at.iter()
                .map(|&f| biodyn::check_freq("at", f))
                .collect::<Result<Vec<_>, _>>()?;
        let solver = Solver::try_new(&preset.body)?;
        let curve = Curve {
            curve: solver.sweep_freqs(&freqs),
            functions: Function::of(solver.has_seat()),
        };
        return render(&curve, a.format);
    }
    let band = a.band.band(preset.band)?;
    band.check_work(preset.body.n())?;
    let solver = Solver::try_new(&preset.body)?;
    let mut progress = super::progress::counting("response", "frequencies");
    let curve = Curve {
        curve: solver.sweep_with(&band, &mut progress),
        functions: Function::of(solver.has_seat()),
    };
    drop(progress); // the line is cleared before the result is printed
    render(&curve, a.format)
}
