//! `biodyn predict`: a trained network's curve beside the analytic one.

use anyhow::{Context, bail};
use biodyn::ann::case::{Group, K4_BODY_MASS};
use biodyn::ann::metrics::{curve_error, pct_error};
use biodyn::ann::netfile;
use biodyn::{Band, Body, Param, Solver};
use serde::Serialize;
use std::io::Write;
use std::path::PathBuf;

#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum PredictFormat {
    Table,
    Csv,
    Json,
}

#[derive(clap::Args, Debug, Clone)]
pub struct PredictArgs {
    /// A network file written by `biodyn train --save`.
    #[arg(long)]
    pub net: PathBuf,
    /// Body mass in kg (mass networks; default 75).
    #[arg(long)]
    pub body_mass: Option<f64>,
    /// Set a body parameter, e.g. k4=72000 (repeatable).
    #[arg(long = "set", value_name = "NAME=VALUE")]
    pub set: Vec<String>,
    #[arg(long, default_value_t = 0.5)]
    pub from: f64,
    #[arg(long, default_value_t = 20.0)]
    pub to: f64,
    #[arg(long, default_value_t = 0.1)]
    pub step: f64,
    #[arg(long, value_enum, default_value_t = PredictFormat::Table)]
    pub format: PredictFormat,
}

#[derive(Serialize)]
struct Point {
    f_hz: f64,
    predicted: f64,
    analytic: f64,
    err_pct: f64,
}

#[derive(Serialize)]
struct JsonOut<'a> {
    case: &'static str,
    function: &'static str,
    unit: &'static str,
    inputs: serde_json::Map<String, serde_json::Value>,
    max_err_pct: f64,
    mean_err_pct: f64,
    extrapolation: bool,
    points: &'a [Point],
}

pub fn run(a: &PredictArgs) -> anyhow::Result<()> {
    let net = netfile::load(&a.net)?;
    let case = net.case;
    let band = Band::new(a.from, a.to, a.step).context("--from/--to/--step")?;
    let mut body = Body::paper(match case.group() {
        Group::Mass => a.body_mass.unwrap_or(75.0),
        Group::K4 => a.body_mass.unwrap_or(K4_BODY_MASS),
    })
    .context("--body-mass")?;
    if case.group() == Group::K4 && a.body_mass.is_some_and(|m| m != K4_BODY_MASS) {
        eprintln!(
            "warning: {case} was trained at {K4_BODY_MASS} kg and does not see body mass; \
             the analytic curve uses the new mass, the network cannot"
        );
    }
    for s in &a.set {
        let Some((name, value)) = s.split_once('=') else {
            bail!("--set '{s}': write NAME=VALUE, e.g. k4=72000");
        };
        let value: f64 = value
            .trim()
            .parse()
            .with_context(|| format!("--set '{s}': '{}' is not a number", value.trim()))?;
        let p = body.param(name).with_context(|| format!("--set '{s}'"))?;
        body.set(p, value).with_context(|| format!("--set '{s}'"))?;
        let seen = match case.group() {
            Group::Mass => matches!(p, Param::Mass(0..=3) | Param::BodyMass),
            Group::K4 => p == Param::Stiffness(3),
        };
        if !seen {
            eprintln!(
                "warning: {case} does not see {}: only the analytic curve changes",
                body.label(p)
            );
        }
    }
    let value = match case.group() {
        Group::Mass => body.get(Param::BodyMass),
        Group::K4 => body.get(Param::Stiffness(3)),
    };
    let (lo, hi) = net
        .settings
        .train_values
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &v| {
            (l.min(v), h.max(v))
        });
    let extrapolation = value < lo || value > hi;
    if extrapolation {
        eprintln!(
            "note: {} = {value} {} lies outside the trained range {lo}–{hi}: this is extrapolation",
            case.param_name(),
            case.param_unit()
        );
    }
    let freqs = band.freqs();
    let predicted = net.predict_body(&body, &freqs)?;
    let solver = Solver::new(&body);
    let points: Vec<Point> = freqs
        .iter()
        .zip(&predicted)
        .map(|(&f, &p)| {
            let an = solver.at(f).mag(case.function());
            Point {
                f_hz: f,
                predicted: p,
                analytic: an,
                err_pct: pct_error(p, an),
            }
        })
        .collect();
    let an: Vec<f64> = points.iter().map(|p| p.analytic).collect();
    let (max, mean) = curve_error(&predicted, &an);
    let inputs_at = case.inputs_of(&body, 0.0)?;
    let names = case.input_names();
    let inputs: Vec<(&'static str, f64)> = names[..names.len() - 1]
        .iter()
        .copied()
        .zip(inputs_at)
        .collect();
    let mut w = std::io::stdout().lock();
    let func = case.function();
    match a.format {
        PredictFormat::Csv => {
            writeln!(w, "f_hz,predicted,analytic,err_pct")?;
            for p in &points {
                writeln!(w, "{},{},{},{}", p.f_hz, p.predicted, p.analytic, p.err_pct)?;
            }
            eprintln!("{case}: max error {max:.3} %, mean {mean:.3} %");
        }
        PredictFormat::Json => {
            serde_json::to_writer_pretty(
                &mut w,
                &JsonOut {
                    case: case.key(),
                    function: func.name(),
                    unit: func.unit(),
                    inputs: inputs
                        .iter()
                        .map(|(n, v)| ((*n).to_string(), serde_json::Value::from(*v)))
                        .collect(),
                    max_err_pct: max,
                    mean_err_pct: mean,
                    extrapolation,
                    points: &points,
                },
            )?;
            writeln!(w)?;
        }
        PredictFormat::Table => {
            let ins: Vec<String> = inputs
                .iter()
                .map(|(n, v)| format!("{n} = {v:.4}"))
                .collect();
            writeln!(
                w,
                "{case} ({} in {}), {}",
                func.name(),
                func.unit(),
                ins.join(", ")
            )?;
            writeln!(
                w,
                "{:>8} {:>12} {:>12} {:>8}",
                "f Hz", "predicted", "analytic", "err %"
            )?;
            for p in &points {
                writeln!(
                    w,
                    "{:>8.2} {:>12.5} {:>12.5} {:>8.3}",
                    p.f_hz, p.predicted, p.analytic, p.err_pct
                )?;
            }
            writeln!(
                w,
                "max error {max:.3} %, mean {mean:.3} %{}",
                if extrapolation {
                    " (extrapolation)"
                } else {
                    ""
                }
            )?;
        }
    }
    Ok(())
}
