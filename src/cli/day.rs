//! `biodyn day`: a working day's exposure from a day file, as the HSE
//! calculator's sheet (per operation and axis, per axis for the day, the
//! day's highest axis with the EU verdicts); with `--week`, several days
//! and the week (UK SI 2005/1093 Schedule 2).

use super::args::Format;
use super::report::ReportArgs;
use crate::view::figure::{self, Figure, response::file_name};
use crate::view::report::day::verdicts::{lacking_names, vdv_text, week_json, week_text};
use crate::view::report::day::{OPERATION_HEADINGS, hours_cell, vdv_hours_cells};
use crate::view::report::spine;
use crate::view::report::table::{fx, table};
use crate::view::report::{Report, html, json, meta as report_meta, render};
use anyhow::{Context as _, Result, bail};
use biodyn::exposure::hours_text;
use biodyn::exposure::{
    Day, DayFile, DaySpine, DayVdv, MAX_DAYS, MeasureError, Measured, RecordSource, Source, Week,
    axes_text, measure_record_noted,
};
use biodyn::iso2631::{A8_ACTION, A8_LIMIT};
use biodyn::time::PerAxis;
use biodyn::time::{RecordError, TimeError};
use clap::Args;
use serde_json::{Map, Value, json};
use std::path::PathBuf;

#[derive(Debug, Args)]
#[command(
    after_help = "Examples:\n  biodyn day examples/day.toml\n  biodyn day examples/day.toml --format json\n  biodyn day mon.toml tue.toml wed.toml --week\n  biodyn day examples/day.toml --report day.html\n\nA day file lists [[operation]] tables: name, hours, and aw_m_s2 = { x = .., y = .., z = .. }\n(measured a_w before k) or record = \"FILE.csv\". See docs/cli-day.md."
)]
pub struct DayArgs {
    /// The day file (TOML); with --week, one file per day (at most 7).
    #[arg(value_name = "DAY.toml", required = true)]
    pub files: Vec<PathBuf>,
    /// Several days and the weekly A(8) = √(⅕ Σ A(8)_day²).
    #[arg(long)]
    pub week: bool,
    /// csv: the HSE calculator's sheet of one day (as the Day tab exports
    /// it); not with --week.
    #[arg(long, value_enum, default_value = "table")]
    pub format: Format,
    /// Also write the day's figure (SVG): points per operation on its
    /// highest axis and the day's, against 100 (action) and 529 (limit);
    /// with --week, one panel per day.
    #[arg(long, value_name = "FILE.svg")]
    pub plot: Option<PathBuf>,
    #[command(flatten)]
    pub report: ReportArgs,
}

/// A record operation's a_w, VDV and duration per axis (before k). A
/// record without a time column is told of the operation's `fs` key (the
/// reader's own words name `--fs`'s sampling rate).
fn record_axes(src: &RecordSource) -> Result<(PerAxis<Measured>, Vec<String>)> {
    measure_record_noted(src).map_err(|e| match e {
        MeasureError::Record(RecordError::NeedFs { path }) => anyhow::anyhow!(
            "{}: no time column (t_s, t_ms, t, time …): give the record's sampling rate in the operation, e.g. fs = 1000 (Hz), or add a t_s column",
            path.display()
        ),
        MeasureError::Record(r) => TimeError::from(r).into(),
        // The day file's key, where the library names the field.
        e @ MeasureError::Judge { .. } => anyhow::anyhow!(
            "{}",
            e.to_string()
                .replace("(remove_mean)", "(remove_mean = true in the operation)")
        ),
    })
}

pub fn run(a: &DayArgs) -> Result<String> {
    if a.files.len() > 1 && !a.week {
        bail!(
            "{} day files given; one day file, or --week with one file per day",
            a.files.len()
        );
    }
    if a.files.len() > MAX_DAYS {
        bail!(
            "{} day files given with --week; a week holds at most {MAX_DAYS} days",
            a.files.len()
        );
    }
    if a.week && a.format == Format::Csv {
        bail!("--format csv is one day's sheet; with --week, --format table or json");
    }
    let mut files = Vec::with_capacity(a.files.len());
    for path in &a.files {
        files.push(DayFile::load(path)?);
    }
    // --meta over a day file's [report], key by key; with --week each day
    // keeps its own and --meta is the week's.
    let meta = a.report.meta()?;
    // The report file is checked before the records are read: not onto a
    // day file nor any record one names.
    let records = files.iter().flat_map(|f| {
        f.operations.iter().filter_map(|o| match &o.source {
            Source::Record(r) => Some(r.resolved.clone()),
            _ => None,
        })
    });
    let inputs: Vec<PathBuf> = a.report.inputs(a.files.iter().cloned().chain(records));
    let page = a.report.check(&inputs)?;
    let figure_file = super::figure_file::check(
        a.plot.as_ref(),
        &inputs,
        a.report.report.as_ref(),
        "day.svg",
    )?;
    let mut days = Vec::with_capacity(files.len());
    // What each record's reading must say (a unit assumed, a mean removed),
    // once per note.
    let mut notes: Vec<String> = Vec::new();
    for file in files {
        let day = file
            .evaluate(|src| {
                let (m, said) = record_axes(src)?;
                for n in said {
                    if !notes.contains(&n) {
                        notes.push(n);
                    }
                }
                Ok::<_, anyhow::Error>(m)
            })
            .map_err(anyhow::Error::new)?;
        days.push((file, day));
    }
    let mut report = if a.week {
        let list: Vec<Day> = days.iter().map(|(_, d)| d.clone()).collect();
        let week = Week::of(&list).context("a week needs 1 to 7 days")?;
        let mut json = json!({
            "days": days.iter().map(|(f, d)| day_json(f, d)).collect::<Vec<_>>(),
            "week": week_json(&week, &days),
        });
        if let Some(m) = report_meta::json(&meta) {
            json["meta"] = m;
        }
        DayReport {
            json,
            table: report_meta::text(&meta)
                + &days
                    .iter()
                    .map(|(f, d)| day_text(f, d))
                    .collect::<Vec<_>>()
                    .join("\n")
                + "\n"
                + &week_text(&week, &days),
            csv: None,
        }
    } else {
        let (f, d) = &days[0];
        let meta = f.report.merged(&meta);
        let mut json = day_json(f, d);
        if let Some(m) = report_meta::json(&meta) {
            json["meta"] = m;
        }
        DayReport {
            json,
            table: report_meta::text(&meta) + &day_text(f, d),
            csv: Some(crate::view::report::day::csv(d)),
        }
    };
    if !notes.is_empty() {
        report.table.push_str("\nnotes on the records:\n");
        for n in &notes {
            report.table.push_str(&format!("  - {n}\n"));
        }
        report.json["notes"] = json!(notes);
    }
    let out = render(&report, a.format)?;
    let drawn = (figure_file.is_some() || page.is_some()).then(|| day_figure(&days, a.week));
    let mut written = Vec::new();
    if let (Some(file), Some(fig)) = (figure_file, &drawn) {
        written.push(file.write(&fig.svg(), &out)?);
    }
    if let Some(page) = page {
        let figures: Vec<String> = drawn.iter().map(|f| f.inline_svg()).collect();
        page.write_after(&html::day::page_of(&report.json, &figures), &out, &written)?;
    }
    Ok(out)
}

/// The days' figure: one day; a week, each day named by its file.
fn day_figure(days: &[(DayFile, Day)], week: bool) -> Figure {
    let named: Vec<(Option<String>, &Day)> = days
        .iter()
        .enumerate()
        .map(|(i, (f, d))| {
            let name = week.then(|| format!("day {}, {}", i + 1, file_name(&f.origin)));
            (name, d)
        })
        .collect();
    figure::day::figure(&named)
}

struct DayReport {
    json: Value,
    table: String,
    csv: Option<String>,
}

impl Report for DayReport {
    fn table(&self) -> String {
        self.table.clone()
    }

    fn csv(&self) -> Option<String> {
        self.csv.clone()
    }

    fn json(&self) -> Result<String, serde_json::Error> {
        json::pretty(&self.json)
    }
}

fn day_json(f: &DayFile, d: &Day) -> Value {
    let operations: Vec<Value> = d
        .operations
        .iter()
        .zip(&f.operations)
        .map(|(o, spec)| {
            let mut axes = Map::new();
            for (a, e) in o.axes.iter() {
                let mut m = Map::new();
                m.insert("kaw_m_s2".into(), json!(e.kaw));
                m.insert("a8_m_s2".into(), json!(e.a8));
                m.insert("points".into(), json!(e.points));
                m.insert("hours_to_eav".into(), json!(e.hours_to_eav));
                m.insert("hours_to_elv".into(), json!(e.hours_to_elv));
                if let Some(v) = e.vdv_exposure {
                    m.insert("vdv_exposure_m_s175".into(), json!(v));
                }
                // Absent without a VDV (not judged); null when never reached.
                if let Some(h) = e.hours_to_vdv {
                    m.insert("hours_to_vdv_eav".into(), json!(h.to_eav));
                    m.insert("hours_to_vdv_elv".into(), json!(h.to_elv));
                }
                axes.insert(a.name().into(), Value::Object(m));
            }
            let mut m = Map::new();
            m.insert("name".into(), json!(o.name));
            m.insert("hours".into(), json!(o.hours));
            if let Source::Record(r) = &spec.source {
                m.insert("record".into(), json!(r.path));
                if let Some(ax) = &r.axes {
                    m.insert("record_axes".into(), json!(axes_text(ax)));
                }
            }
            m.insert("axes".into(), Value::Object(axes));
            Value::Object(m)
        })
        .collect();
    let mut axes = Map::new();
    for (a, x) in d.axes.iter() {
        let mut m = Map::new();
        m.insert("a8_m_s2".into(), json!(x.a8));
        m.insert("points".into(), json!(x.points));
        if let Some(v) = x.vdv {
            m.insert("vdv_exposure_m_s175".into(), json!(v));
        } else if let Some(v) = x.vdv_known {
            m.insert("vdv_at_least_m_s175".into(), json!(v));
        }
        if !x.lacking_vdv.is_empty() {
            m.insert(
                "vdv_lacking".into(),
                json!(lacking_names(d, &x.lacking_vdv)),
            );
        }
        axes.insert(a.name().into(), Value::Object(m));
    }
    let mut daily = Map::new();
    daily.insert("axes".into(), Value::Object(axes));
    daily.insert("a8_m_s2".into(), json!(d.a8));
    daily.insert("a8_axis".into(), json!(d.a8_axis.name()));
    daily.insert("points".into(), json!(d.points));
    daily.insert("eu_a8".into(), json!(d.eu_a8.words()));
    match d.vdv_verdict {
        DayVdv::Known { axis, vdv, verdict } => {
            daily.insert("vdv_exposure_m_s175".into(), json!(vdv));
            daily.insert("vdv_axis".into(), json!(axis.name()));
            daily.insert("eu_vdv".into(), json!(verdict.words()));
        }
        DayVdv::AtLeast {
            axis,
            vdv,
            at_least,
        } => {
            // A lower bound: eu_vdv only where the missing VDVs cannot
            // change it (above the limit value).
            daily.insert("vdv_at_least_m_s175".into(), json!(vdv));
            daily.insert("vdv_axis".into(), json!(axis.name()));
            daily.insert("eu_vdv_at_least".into(), json!(at_least.words()));
            if let Some(eu) = d.vdv_verdict.decided() {
                daily.insert("eu_vdv".into(), json!(eu.words()));
            }
        }
        DayVdv::Unknown => {}
    }
    let mut v = json!({
        "file": f.origin,
        "hours": d.operations.iter().map(|o| o.hours).sum::<f64>(),
        "operations": operations,
        "daily": Value::Object(daily),
    });
    if let Some(sp) = &d.spine {
        v["spine"] = spine_json(d, sp);
    }
    if let Some(m) = report_meta::json(&f.report) {
        v["meta"] = m;
    }
    v
}

/// The day's ISO 2631-5 block: each operation's dose and the day's.
fn spine_json(d: &Day, sp: &DaySpine) -> Value {
    let parts: Vec<Value> = sp
        .parts
        .iter()
        .map(|p| {
            json!({
                "operation": d.operations.get(p.operation).map(|o| o.name.as_str()),
                "dz_m_s2": p.dz,
                "measured_s": p.measured_s,
                "hours": p.hours,
                "dzd_m_s2": p.dzd,
            })
        })
        .collect();
    let mut o = spine::annex_c(&sp.person, sp.dzd, &sp.risk);
    o.insert("operations".into(), json!(parts));
    Value::Object(o)
}

/// The day's ISO 2631-5 block in words.
fn spine_text(d: &Day, sp: &DaySpine) -> String {
    let rows: Vec<Vec<String>> = sp
        .parts
        .iter()
        .map(|p| {
            vec![
                d.operations
                    .get(p.operation)
                    .map_or(String::new(), |o| o.name.clone()),
                fx(p.dz, 2),
                biodyn::io::num(p.measured_s),
                biodyn::io::num(p.hours),
                fx(p.dzd, 2),
            ]
        })
        .collect();
    format!(
        "\nThe spine (ISO 2631-5:2018, z; {}):\n{}  the day: Dzd = (Σ Dz⁶·t_d/t_m)^⅙ = {} m/s², Sd {} MPa, R {}, P {:.2}\n  {}\n",
        sp.person,
        table(
            &["operation", "Dz m/s²", "over s", "hours", "Dzd alone m/s²"],
            &rows
        ),
        fx(sp.dzd, 2),
        fx(sp.risk.sd, 3),
        fx(sp.risk.r, 2),
        sp.risk.probability,
        sp.risk.band.words()
    )
}

fn day_text(f: &DayFile, d: &Day) -> String {
    let total: f64 = d.operations.iter().map(|o| o.hours).sum();
    let n = d.operations.len();
    let mut s = format!(
        "{}: {n} operation{}, {}\n\n",
        f.origin,
        if n == 1 { "" } else { "s" },
        hours_text(total)
    );
    let mut rows = Vec::new();
    for o in &d.operations {
        for (i, (a, e)) in o.axes.iter().enumerate() {
            let first = i == 0;
            rows.push(vec![
                if first { o.name.clone() } else { String::new() },
                if first {
                    hours_text(o.hours)
                } else {
                    String::new()
                },
                a.name().into(),
                fx(e.kaw, 3),
                fx(e.a8, 3),
                fx(e.points, 1),
                hours_cell(e.hours_to_eav),
                hours_cell(e.hours_to_elv),
                e.vdv_exposure.map_or("-".into(), |v| fx(v, 2)),
            ]);
            rows.last_mut()
                .expect("the row just pushed")
                .extend(vdv_hours_cells(e.hours_to_vdv));
        }
    }
    s.push_str(&table(&OPERATION_HEADINGS, &rows));
    s.push_str("\nThe day, per axis (A(8) = √Σ partial A(8)², points add):\n");
    let rows: Vec<Vec<String>> = d
        .axes
        .iter()
        .map(|(a, x)| {
            vec![
                format!("{a} ({})", a.direction()),
                fx(x.a8, 3),
                fx(x.points, 1),
                match (x.vdv, x.vdv_known) {
                    (Some(v), _) => fx(v, 2),
                    (None, Some(v)) => format!("≥ {}", fx(v, 2)),
                    (None, None) => "-".into(),
                },
            ]
        })
        .collect();
    s.push_str(&table(
        &["axis", "A(8) m/s²", "points", "VDV m/s^1.75"],
        &rows,
    ));
    s.push_str(&format!(
        "\nDaily exposure (EU 2002/44/EC, the highest axis): {} ({})\n  A(8) {:.3} m/s², {:.0} points: {} (action {A8_ACTION}, limit {A8_LIMIT})\n",
        d.a8_axis,
        d.a8_axis.direction(),
        d.a8,
        d.points,
        d.eu_a8.words()
    ));
    s.push_str(&vdv_text(d));
    if let Some(sp) = &d.spine {
        s.push_str(&spine_text(d, sp));
    }
    s
}

/// What to try next after a day file is refused.
pub fn hint(cause: &(dyn std::error::Error + 'static)) -> Option<String> {
    use biodyn::exposure::{DayError, EvalError};
    if let Some(e) = cause.downcast_ref::<EvalError<anyhow::Error>>() {
        return Some(match e {
            EvalError::Record { .. } => {
                "a record's path is from the day file's folder, and it is read as assess --input reads it: name its columns with axes = \"x=ax,y=ay,z=az\", their unit with unit = \"g\" and a rate without a time column with fs = 1000 in the operation, or give its measured aw_m_s2 = { x = .., y = .., z = .. } instead".into()
            }
            EvalError::Day(_) => DAY_HINT.into(),
        });
    }
    cause.downcast_ref::<DayError>().map(|_| DAY_HINT.into())
}

const DAY_HINT: &str = "each [[operation]] has name, hours (over 0, the day at most 24 h) and aw_m_s2 = { z = .. } or record = \"FILE.csv\"; see docs/cli-day.md";
