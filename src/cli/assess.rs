//! `biodyn assess`: ISO 2631-1 exposure of the seat record and what the
//! model says reaches the head; EU 2002/44/EC verdicts and comfort words.

use super::args::{Format, ModelArgs, table_or_json};
use super::input::{InputArgs, Samples, Source};
use crate::view::report::points;
use crate::view::report::table::{fx, table};
use crate::view::report::{Report, json, render};
use anyhow::Result;
use biodyn::iso2631::{
    A8_ACTION, A8_LIMIT, Assessment, AxisResult, Channel, VDV_ACTION, VDV_LIMIT, assess_axes,
    assess_points,
};
use clap::Args;
use serde_json::{Value, json};

#[derive(Debug, Args)]
#[command(
    after_help = "Examples:\n  biodyn assess --signal sine:freq=5,amp=1\n  biodyn assess --signal random:rms=0.8,band=1-20,seed=1+shock:peak=15,width=0.1,at=30 --duration 60\n  biodyn assess --input seat.csv --exposure 6 --format json"
)]
pub struct AssessArgs {
    #[command(flatten)]
    pub model: ModelArgs,
    #[command(flatten)]
    pub input: InputArgs,
    /// Hours a day of this vibration, for A(8) and the VDV over the exposure.
    #[arg(
        long,
        value_name = "HOURS",
        default_value_t = 8.0,
        allow_negative_numbers = true
    )]
    pub exposure: f64,
    #[arg(long, default_value = "table", value_parser = table_or_json())]
    pub format: Format,
}

pub fn run(a: &AssessArgs) -> Result<String> {
    let preset = a.model.load()?;
    let input = a.input.open()?;
    input.require_vertical()?;
    let source = input.source.clone();
    let (body, fs, axes) = (&preset.body, input.fs, &input.axes);
    let r = match input.rows {
        Samples::Seat(rows) => assess_axes(body, fs, rows, axes, a.exposure)?,
        Samples::Frames(f) => assess_points(body, fs, f, axes, &input.points, a.exposure)?,
    };
    let head_name = preset
        .body
        .segments
        .get(preset.body.head)
        .map_or("head", |s| s.name.as_str());
    let report = AssessReport {
        json: to_json(&r, &preset.name, &source),
        table: text(&r, &preset.name, &source, head_name),
    };
    render(&report, a.format)
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

fn metrics_json(c: &Channel) -> serde_json::Map<String, Value> {
    let m = &c.metrics;
    let mut o = serde_json::Map::new();
    for (k, v) in [
        ("aw_m_s2", m.aw),
        ("peak_m_s2", m.peak),
        ("crest_factor", m.crest),
        ("mtvv_m_s2", m.mtvv),
        ("vdv_m_s175", m.vdv),
        ("a8_m_s2", c.exposure.a8),
        ("vdv_exposure_m_s175", c.exposure.vdv),
    ] {
        o.insert(k.into(), json!(v));
    }
    o
}

/// One axis: its rule, its metrics before k, A(8) and VDV after it.
fn axis_json(r: &AxisResult) -> Value {
    let m = &r.metrics;
    json!({
        "weighting": r.rule.weighting.name(),
        "k_health": r.rule.k_health,
        "k_comfort": r.rule.k_comfort,
        "aw_m_s2": m.aw,
        "peak_m_s2": m.peak,
        "crest_factor": m.crest,
        "mtvv_m_s2": m.mtvv,
        "vdv_m_s175": m.vdv,
        "a8_m_s2": r.a8,
        "vdv_exposure_m_s175": r.vdv_exposure,
    })
}

pub fn to_json(r: &Assessment, model: &str, source: &Source) -> Value {
    let segments: Vec<Value> = r
        .segments
        .iter()
        .map(|(name, c)| {
            let mut o = metrics_json(c);
            o.insert("name".into(), json!(name));
            Value::Object(o)
        })
        .collect();
    let bands: Vec<Value> = r
        .bands
        .iter()
        .map(|b| json!({"f_hz": b.f_hz, "seat_m_s2": b.seat, "head_m_s2": b.head}))
        .collect();
    let mut axes = serde_json::Map::new();
    for (a, x) in r.axes.iter() {
        axes.insert(a.name().into(), axis_json(x));
    }
    let h = &r.health;
    let mut v = json!({
        "model": model,
        "input": source.json(r.fs),
        "fs_hz": r.fs,
        "duration_s": r.duration_s,
        "exposure_h": r.exposure_h,
        "seat": Value::Object(metrics_json(&r.seat)),
        "head": Value::Object(metrics_json(&r.head)),
        "segments": segments,
        "axes": axes,
        "health": {
            "a8_m_s2": h.a8,
            "a8_axis": h.a8_axis.name(),
            "vdv_exposure_m_s175": h.vdv_exposure,
            "vdv_axis": h.vdv_axis.name(),
            "eu_a8": h.eu.a8.words(),
            "eu_vdv": h.eu.vdv.words(),
        },
        "eu": {"a8": r.eu.a8.words(), "vdv": r.eu.vdv.words()},
        "comfort": {
            "vector_sum_m_s2": r.comfort_vector,
            "seat": r.comfort_seat,
            "head": r.comfort_head,
        },
        "bands": bands,
        "warnings": r.warnings,
    });
    if let Some(p) = &r.points {
        points::comfort_json(&mut v["comfort"], p);
    }
    v
}

fn hours(h: f64) -> String {
    format!("{h}")
}

fn text(r: &Assessment, model: &str, source: &Source, head: &str) -> String {
    let mut s = format!(
        "{model}: {}\n{} s at {} Hz; exposure {} h a day\n\n",
        source.line(),
        fx(r.duration_s, 3)
            .trim_end_matches('0')
            .trim_end_matches('.'),
        r.fs,
        hours(r.exposure_h)
    );
    let h = &r.health;
    s.push_str("At the seat, per axis (ISO 2631-1 seated; a_w and VDV before k, A(8) and VDV over the exposure after it):\n");
    let axis_rows: Vec<Vec<String>> = r
        .axes
        .iter()
        .map(|(a, x)| {
            let m = &x.metrics;
            let mark = if a == h.a8_axis { " *" } else { "" };
            vec![
                format!("{a}{mark}"),
                x.rule.weighting.name().to_string(),
                format!("{}", x.rule.k_health),
                fx(m.aw, 3),
                fx(m.peak, 3),
                fx(m.crest, 2),
                fx(m.mtvv, 3),
                fx(m.vdv, 2),
                fx(x.a8, 3),
                fx(x.vdv_exposure, 2),
            ]
        })
        .collect();
    let exp = format!("VDV {} h", hours(r.exposure_h));
    s.push_str(&table(
        &[
            "axis",
            "weighting",
            "k",
            "a_w m/s²",
            "peak m/s²",
            "crest",
            "MTVV m/s²",
            "VDV m/s^1.75",
            "A(8) m/s²",
            &exp,
        ],
        &axis_rows,
    ));
    s.push_str(&format!(
        "(* the highest A(8) after k: the day's exposure)\n\nEU 2002/44/EC, the highest axis at the seat:\n  A(8) {:.3} m/s² ({}): {} (action {A8_ACTION}, limit {A8_LIMIT})\n  VDV {:.2} m/s^1.75 ({}): {} (action {VDV_ACTION}, limit {VDV_LIMIT})\n",
        h.a8,
        h.a8_axis,
        h.eu.a8.words(),
        h.vdv_exposure,
        h.vdv_axis,
        h.eu.vdv.words()
    ));
    s.push_str(&format!(
        "comfort (ISO 2631-1 Annex C): seat vector sum {:.3} m/s²: {}; head {}\n",
        r.comfort_vector,
        r.comfort_seat.join(" / "),
        r.comfort_head.join(" / ")
    ));
    if let Some(p) = &r.points {
        s.push_str(&points::comfort_table(p));
    }

    s.push_str(&format!(
        "\nThe body, driven by z ({} weighting):\n",
        r.weighting.name()
    ));
    let (se, he) = (&r.seat, &r.head);
    let row = |name: &str, unit: &str, f: &dyn Fn(&Channel) -> f64, d: usize| {
        vec![
            name.to_string(),
            unit.to_string(),
            fx(f(se), d),
            fx(f(he), d),
        ]
    };
    let exp = format!("VDV over {} h", hours(r.exposure_h));
    let rows = vec![
        row("weighted r.m.s. a_w", "m/s²", &|c| c.metrics.aw, 3),
        row("peak", "m/s²", &|c| c.metrics.peak, 3),
        row("crest factor", "", &|c| c.metrics.crest, 2),
        row("MTVV (1 s running r.m.s.)", "m/s²", &|c| c.metrics.mtvv, 3),
        row("VDV", "m/s^1.75", &|c| c.metrics.vdv, 2),
        row("A(8)", "m/s²", &|c| c.exposure.a8, 3),
        row(&exp, "m/s^1.75", &|c| c.exposure.vdv, 2),
    ];
    let head_col = format!("head ({head})");
    s.push_str(&table(&["", "unit", "seat z", &head_col], &rows));

    s.push_str("\nEvery segment (weighted absolute acceleration):\n");
    let seg_rows: Vec<Vec<String>> = r
        .segments
        .iter()
        .map(|(n, c)| {
            vec![
                n.clone(),
                fx(c.metrics.aw, 3),
                fx(c.metrics.peak, 3),
                fx(c.metrics.crest, 2),
                fx(c.metrics.mtvv, 3),
                fx(c.metrics.vdv, 2),
                fx(c.exposure.a8, 3),
            ]
        })
        .collect();
    s.push_str(&table(
        &[
            "segment",
            "a_w m/s²",
            "peak m/s²",
            "crest",
            "MTVV m/s²",
            "VDV m/s^1.75",
            "A(8) m/s²",
        ],
        &seg_rows,
    ));

    s.push_str("\nOne-third-octave bands (unweighted r.m.s.):\n");
    let opt = |v: Option<f64>, d| v.map_or("-".to_string(), |v| fx(v, d));
    let band_rows: Vec<Vec<String>> = r
        .bands
        .iter()
        .map(|b| {
            let ratio = match (b.seat, b.head) {
                (Some(s), Some(h)) if s > 0.0 => fx(h / s, 2),
                _ => "-".into(),
            };
            vec![format!("{}", b.f_hz), opt(b.seat, 4), opt(b.head, 4), ratio]
        })
        .collect();
    s.push_str(&table(
        &["f Hz", "seat m/s²", "head m/s²", "head/seat"],
        &band_rows,
    ));
    if !r.warnings.is_empty() {
        s.push_str("\nwarnings:\n");
        for w in &r.warnings {
            s.push_str(&format!("  - {w}\n"));
        }
    }
    s
}
