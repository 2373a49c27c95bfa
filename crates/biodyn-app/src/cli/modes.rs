//! `biodyn modes` and `biodyn peaks`.

use super::args::{BandArgs, ModelArgs, TableOrJson};
use super::out::{emit, fx, table};
use anyhow::Result;
use biodyn::Solver;
use biodyn::freq::modes::{self, ModeKind};
use biodyn::freq::peaks;
use biodyn::freq::response::Function;
use clap::Args;

#[derive(Debug, Args)]
#[command(
    after_help = "Examples:\n  biodyn modes\n  biodyn modes --preset boileau-rakheja-1998 --format json"
)]
pub struct ModesArgs {
    #[command(flatten)]
    pub model: ModelArgs,
    #[arg(long, value_enum, default_value_t = TableOrJson::Table)]
    pub format: TableOrJson,
}

pub fn run_modes(a: &ModesArgs) -> Result<()> {
    let preset = a.model.load()?;
    let m = modes::analyse(&preset.body)?;
    if a.format == TableOrJson::Json {
        return emit(&(serde_json::to_string_pretty(&m)? + "\n"));
    }
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
    emit(&s)
}

#[derive(Debug, Args)]
#[command(after_help = "Examples:\n  biodyn peaks\n  biodyn peaks --body-mass 65 --format json")]
pub struct PeaksArgs {
    #[command(flatten)]
    pub model: ModelArgs,
    #[command(flatten)]
    pub band: BandArgs,
    #[arg(long, value_enum, default_value_t = TableOrJson::Table)]
    pub format: TableOrJson,
}

pub fn run_peaks(a: &PeaksArgs) -> Result<()> {
    let preset = a.model.load()?;
    let band = a.band.band(preset.band)?;
    let solver = Solver::new(&preset.body);
    let curve = solver.sweep(&band);
    let all: Vec<peaks::Peak> = Function::ALL
        .iter()
        .flat_map(|&f| peaks::find_in(&solver, &curve, f))
        .collect();
    if a.format == TableOrJson::Json {
        return emit(&(serde_json::to_string_pretty(&all)? + "\n"));
    }
    let rows: Vec<Vec<String>> = all
        .iter()
        .map(|p| {
            vec![
                p.function.name().to_string(),
                fx(p.f_hz, 4),
                format!("{:.6}", p.mag),
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
    emit(&s)
}
