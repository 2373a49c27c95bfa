//! `biodyn predict`: a trained network's curve beside the analytic one.

use super::args::{BandArgs, Format, ModelArgs, parse_set, quote};
use crate::view::format::num;
use crate::view::report::{Report, csv, json, render};
use anyhow::Context;
use biodyn::ann::{self, Case, Comparison, Group, K4_BODY_MASS};
use biodyn::io::Short;
use biodyn::{Band, Body, Param};
use serde::Serialize;
use std::fmt::Write as _;
use std::path::PathBuf;

#[derive(clap::Args, Debug, Clone)]
#[command(
    after_help = "Examples:\n  biodyn predict --net mass-dpmi.json --body-mass 70\n  biodyn predict --net k4-stht.json --set k4=72000 --from 1 --to 10 --format csv\n  biodyn predict --net boileau-apms.json\n\nA network trained on a model (biodyn train --preset/--body-mass/--set) predicts\non that model when no --preset is given: --body-mass and --set change it."
)]
pub struct PredictArgs {
    /// A network file written by `biodyn train --save`.
    #[arg(long)]
    pub net: PathBuf,
    /// The body (default: the model the network was trained on, else the
    /// paper's at 75 kg).
    #[command(flatten)]
    pub model: ModelArgs,
    /// The band (default 0.5 to 20 Hz at 0.1 Hz).
    #[command(flatten)]
    pub band: BandArgs,
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
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

/// The result, and the summary that follows it on stderr when the result
/// is CSV (the table carries it itself).
pub fn run(a: &PredictArgs) -> anyhow::Result<(String, Vec<String>)> {
    let net = ann::load_network(&a.net)?;
    let case = net.case;
    // Warnings wait until the model has loaded: a refused model gets only
    // its error line and hint.
    let mut warnings = Vec::new();
    let trained_kg = net.base().map_or(K4_BODY_MASS, |b| b.get(Param::BodyMass));
    if case.group() == Group::K4 && a.model.body_mass.is_some_and(|m| m != trained_kg) {
        warnings.push(format!(
            "warning: {case} was trained at {} kg and does not see body mass; \
             the analytic curve uses the new mass, the network cannot",
            num(trained_kg, 6)
        ));
    }
    let mut seen = |body: &Body, param: Param| {
        let seen = match case.group() {
            Group::Mass => matches!(param, Param::Mass(_) | Param::BodyMass),
            Group::K4 => param == Param::Stiffness(3),
        };
        if !seen {
            warnings.push(format!(
                "warning: {case} does not see {}: only the analytic curve changes",
                body.label(param)
            ));
        }
    };
    let body = match net.base() {
        Some(base) if a.model.preset.is_none() => on_base(base, &a.model, &mut seen)?,
        _ => {
            a.model
                .load_with(&mut |p, param| seen(&p.body, param))?
                .0
                .body
        }
    };
    for w in &warnings {
        super::out::note!("{w}");
    }
    let band = a.band.band(Band::default())?;
    // A prediction that is not a number is the file's fault: name it.
    let c = net
        .compare_body(&body, &band)
        .with_context(|| a.net.display().to_string())?;
    if c.extrapolation {
        let (lo, hi) = net.value_range();
        super::out::note!(
            "note: {} = {} {} lies outside the trained range {}–{}: this is extrapolation",
            case.param_name(),
            num(c.value, 6),
            case.param_unit(),
            num(lo, 6),
            num(hi, 6)
        );
    }
    if c.beyond_grid {
        let g = &net.settings.grid;
        super::out::note!(
            "note: {}–{} Hz reaches outside the trained frequencies {}–{} Hz: the network extrapolates there",
            Short(band.from),
            Short(band.to),
            Short(g.from),
            Short(g.to)
        );
    }
    let inputs_at = net.inputs_for(&body, 0.0)?;
    let names = net.input_names();
    let inputs = names[..names.len() - 1]
        .iter()
        .map(|n| n.to_string())
        .zip(inputs_at)
        .collect();
    // The summary a table ends with, kept off the data stream.
    let summary = match a.format {
        Format::Csv => vec![format!(
            "{case}: max error {:.3} %, mean {:.3} %",
            c.max_err_pct, c.mean_err_pct
        )],
        _ => Vec::new(),
    };
    Ok((render(&Prediction { case, inputs, c }, a.format)?, summary))
}

/// The network's own model with --body-mass (built as training builds
/// it: by the shares, else in proportion) and every --set applied.
fn on_base(base: &Body, m: &ModelArgs, seen: &mut dyn FnMut(&Body, Param)) -> anyhow::Result<Body> {
    m.refuse_twice(base)?;
    let mut body = match m.body_mass {
        Some(kg) => ann::at_body_mass(base, kg).context("--body-mass")?,
        None => base.clone(),
    };
    for s in &m.set {
        let (name, value) = parse_set(s)?;
        let q = quote(s);
        let param = body.param(name).with_context(|| format!("--set {q}"))?;
        body.set(param, value)
            .with_context(|| format!("--set {q}"))?;
        seen(&body, param);
    }
    Ok(body)
}

/// A network's prediction beside the analytic curve.
struct Prediction {
    case: Case,
    /// The network's inputs other than the frequency, by name.
    inputs: Vec<(String, f64)>,
    c: Comparison,
}

impl Prediction {
    fn points(&self) -> Vec<Point> {
        let c = &self.c;
        (0..c.freqs.len())
            .map(|i| Point {
                f_hz: c.freqs[i],
                predicted: c.predicted[i],
                analytic: c.analytic[i],
                err_pct: c.err_pct[i],
            })
            .collect()
    }
}

impl Report for Prediction {
    fn table(&self) -> String {
        let (case, c) = (self.case, &self.c);
        let func = case.function();
        let ins: Vec<String> = self
            .inputs
            .iter()
            .map(|(n, v)| format!("{n} = {v:.4}"))
            .collect();
        let mut w = format!(
            "{case} ({} in {}), {}\n",
            func.name(),
            func.unit(),
            ins.join(", ")
        );
        let _ = writeln!(
            w,
            "{:>8} {:>12} {:>12} {:>8}",
            "f Hz", "predicted", "analytic", "err %"
        );
        for p in self.points() {
            let _ = writeln!(
                w,
                "{:>8.2} {:>12.5} {:>12.5} {:>8.3}",
                p.f_hz, p.predicted, p.analytic, p.err_pct
            );
        }
        let _ = writeln!(
            w,
            "max error {:.3} %, mean {:.3} %{}",
            c.max_err_pct,
            c.mean_err_pct,
            if c.extrapolation {
                " (extrapolation)"
            } else {
                ""
            }
        );
        w
    }

    fn csv(&self) -> Option<String> {
        let c = &self.c;
        Some(csv::numbers(
            &["f_hz", "predicted", "analytic", "err_pct"],
            (0..c.freqs.len())
                .map(|i| vec![c.freqs[i], c.predicted[i], c.analytic[i], c.err_pct[i]]),
        ))
    }

    fn json(&self) -> Result<String, serde_json::Error> {
        let func = self.case.function();
        json::pretty(&JsonOut {
            case: self.case.key(),
            function: func.name(),
            unit: func.unit(),
            inputs: self
                .inputs
                .iter()
                .map(|(n, v)| (n.clone(), serde_json::Value::from(*v)))
                .collect(),
            max_err_pct: self.c.max_err_pct,
            mean_err_pct: self.c.mean_err_pct,
            extrapolation: self.c.extrapolation,
            points: &self.points(),
        })
    }
}
