//! `biodyn modes` and `biodyn peaks`.

use super::args::{BandArgs, Format, ModelArgs, table_or_json};
use crate::view::report::table::{fx, table};
use crate::view::report::{Report, json, render};
use anyhow::Result;
use biodyn::freq::{self, ModeKind, Modes, Peak};
use biodyn::{Band, Function, Preset, Solver};
use clap::Args;

#[derive(Debug, Args)]
#[command(
    after_help = "Examples:\n  biodyn modes\n  biodyn modes --preset boileau-rakheja-1998 --format json"
)]
pub struct ModesArgs {
    #[command(flatten)]
    pub model: ModelArgs,
    #[arg(long, default_value = "table", value_parser = table_or_json())]
    pub format: Format,
}

pub fn run_modes(a: &ModesArgs) -> Result<String> {
    let preset = a.model.load()?;
    let modes = freq::analyse_modes(&preset.body)?;
    render(&ModesReport { preset, modes }, a.format)
}

/// The modes of one model.
struct ModesReport {
    preset: Preset,
    modes: Modes,
}

impl Report for ModesReport {
    fn json(&self) -> Result<String, serde_json::Error> {
        json::pretty(&self.modes)
    }

    fn table(&self) -> String {
        let (preset, m) = (&self.preset, &self.modes);
        modes_table(preset, m)
    }
}

fn modes_table(preset: &Preset, m: &Modes) -> String {
    let names: Vec<&str> = preset
        .body
        .segments
        .iter()
        .map(|s| s.name.as_str())
        .collect();
    let shape = |v: &[f64]| {
        v.iter()
            .map(|x| format!("{x:+.3}"))
            .collect::<Vec<_>>()
            .join(" ")
    };
    let rows: Vec<Vec<String>> = m
        .damped
        .iter()
        .enumerate()
        .map(|(i, md)| match md.kind {
            ModeKind::Oscillatory {
                damped_hz,
                natural_hz,
                damping_ratio,
            } => vec![
                (i + 1).to_string(),
                "oscillatory".into(),
                fx(natural_hz, 3),
                fx(damped_hz, 3),
                fx(damping_ratio, 4),
                "-".into(),
                shape(&md.shape_mag),
            ],
            ModeKind::Overdamped {
                rate_per_s,
                natural_hz,
            } => vec![
                (i + 1).to_string(),
                "overdamped".into(),
                fx(natural_hz, 3),
                "-".into(),
                ">= 1".into(),
                fx(rate_per_s, 2),
                shape(&md.shape_mag),
            ],
        })
        .collect();
    let mut s = format!(
        "Damped modes of {} (seat held still; eigenvalues of the state matrix)\n",
        preset.name
    );
    s += &table(
        &[
            "#",
            "kind",
            "natural Hz",
            "damped Hz",
            "damping ratio",
            "decay 1/s",
            &format!("|shape| {}", names.join(", ")),
        ],
        &rows,
    );
    s += "\nUndamped natural frequencies (M^-1 K)\n";
    let rows: Vec<Vec<String>> = m
        .undamped
        .iter()
        .enumerate()
        .map(|(i, u)| {
            let sh: Vec<String> = u.shape.iter().map(|x| format!("{x:+.3}")).collect();
            vec![(i + 1).to_string(), fx(u.natural_hz, 3), sh.join(" ")]
        })
        .collect();
    s += &table(
        &["#", "natural Hz", &format!("shape {}", names.join(", "))],
        &rows,
    );
    s
}

#[derive(Debug, Args)]
#[command(after_help = "Examples:\n  biodyn peaks\n  biodyn peaks --body-mass 65 --format json")]
pub struct PeaksArgs {
    #[command(flatten)]
    pub model: ModelArgs,
    #[command(flatten)]
    pub band: BandArgs,
    #[arg(long, default_value = "table", value_parser = table_or_json())]
    pub format: Format,
}

pub fn run_peaks(a: &PeaksArgs) -> Result<String> {
    let preset = a.model.load()?;
    let band = a.band.band(preset.band)?;
    band.check_work(preset.body.n())?;
    let solver = Solver::try_new(&preset.body)?;
    let curve = solver.sweep(&band);
    let all: Vec<Peak> = Function::ALL
        .iter()
        .flat_map(|&f| freq::find_peaks_in(&solver, &curve, f))
        .collect();
    render(&PeaksReport { preset, band, all }, a.format)
}

/// The resonance peaks of one model on a band.
struct PeaksReport {
    preset: Preset,
    band: Band,
    all: Vec<Peak>,
}

impl Report for PeaksReport {
    fn json(&self) -> Result<String, serde_json::Error> {
        json::pretty(&self.all)
    }

    fn table(&self) -> String {
        let (preset, band, all) = (&self.preset, &self.band, &self.all);
        let rows: Vec<Vec<String>> = all
            .iter()
            .map(|p| {
                vec![
                    p.function.name().to_string(),
                    fx(p.f_hz, 4),
                    if p.unbounded {
                        "unbounded (undamped)".to_string()
                    } else {
                        format!("{:.6}", p.mag)
                    },
                    p.function.unit().to_string(),
                ]
            })
            .collect();
        let mut s = format!(
            "Resonance peaks of {} on {}–{} Hz (refined to 1e-6 Hz)\n",
            preset.name, band.from, band.to
        );
        if rows.is_empty() {
            s += "no interior peak in this band\n";
        } else {
            s += &table(&["function", "f Hz", "magnitude", "unit"], &rows);
        }
        s
    }
}
