//! `biodyn day`: a working day's exposure from a day file, as the HSE
//! calculator's sheet (per operation and axis, per axis for the day, the
//! day's highest axis with the EU verdicts); with `--week`, several days
//! and the week (UK SI 2005/1093 Schedule 2).

use super::args::{Format, table_or_json};
use super::report::ReportArgs;
use crate::view::figure::{self, Figure, day::DAY_TITLE, response::file_name};
use crate::view::report::spine;
use crate::view::report::table::{fx, table};
use crate::view::report::{Report, html, json, render};
use anyhow::{Context as _, Result, bail};
use biodyn::exposure::{
    Day, DayFile, DaySpine, MAX_DAYS, Measured, RecordSource, Source, Week, axes_text,
    measure_record,
};
use biodyn::iso2631::{A8_ACTION, A8_LIMIT, VDV_ACTION, VDV_LIMIT};
use biodyn::time::PerAxis;
use biodyn::time::TimeError;
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
    #[arg(long, default_value = "table", value_parser = table_or_json())]
    pub format: Format,
    /// Also write the day's figure (SVG): points per operation on its
    /// highest axis and the day's, against 100 (action) and 529 (limit);
    /// with --week, one panel per day.
    #[arg(long, value_name = "FILE.svg")]
    pub plot: Option<PathBuf>,
    #[command(flatten)]
    pub report: ReportArgs,
}

/// A record operation's a_w, VDV and duration per axis (before k).
fn record_axes(src: &RecordSource) -> Result<PerAxis<Measured>> {
    Ok(measure_record(src).map_err(TimeError::from)?)
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
    let mut files = Vec::with_capacity(a.files.len());
    for path in &a.files {
        files.push(DayFile::load(path)?);
    }
    // The report file is checked before the records are read: not onto a
    // day file nor any record one names.
    let records = files.iter().flat_map(|f| {
        f.operations.iter().filter_map(|o| match &o.source {
            Source::Record(r) => Some(r.resolved.clone()),
            _ => None,
        })
    });
    let inputs: Vec<PathBuf> = a.files.iter().cloned().chain(records).collect();
    let page = a.report.check(&inputs)?;
    let figure_file = super::figure_file::check(
        a.plot.as_ref(),
        &inputs,
        a.report.report.as_ref(),
        "day.svg",
    )?;
    let mut days = Vec::with_capacity(files.len());
    for file in files {
        let day = file.evaluate(record_axes).map_err(anyhow::Error::new)?;
        days.push((file, day));
    }
    let report = if a.week {
        let list: Vec<Day> = days.iter().map(|(_, d)| d.clone()).collect();
        let week = Week::of(&list).context("a week needs 1 to 7 days")?;
        DayReport {
            json: json!({
                "days": days.iter().map(|(f, d)| day_json(f, d)).collect::<Vec<_>>(),
                "week": week_json(&week),
            }),
            table: days
                .iter()
                .map(|(f, d)| day_text(f, d))
                .collect::<Vec<_>>()
                .join("\n")
                + "\n"
                + &week_text(&week, days.len()),
        }
    } else {
        let (f, d) = &days[0];
        DayReport {
            json: day_json(f, d),
            table: day_text(f, d),
        }
    };
    let out = render(&report, a.format)?;
    let drawn = (figure_file.is_some() || page.is_some()).then(|| day_figure(&days, a.week));
    if let (Some(file), Some(fig)) = (figure_file, &drawn) {
        file.write(&fig.svg(), &out)?;
    }
    if let Some(page) = page {
        let figures: Vec<String> = drawn.iter().map(|f| f.inline_svg()).collect();
        page.write(&html::day::page_of(&report.json, &figures), &out)?;
    }
    Ok(out)
}

/// The days' figure: one day under its title; a week, a panel per day
/// named by its file.
fn day_figure(days: &[(DayFile, Day)], week: bool) -> Figure {
    let titled: Vec<(String, &Day)> = days
        .iter()
        .enumerate()
        .map(|(i, (f, d))| {
            let title = if week {
                format!("day {}, {}: {DAY_TITLE}", i + 1, file_name(&f.origin))
            } else {
                DAY_TITLE.to_string()
            };
            (title, d)
        })
        .collect();
    figure::day::figure(&titled)
}

struct DayReport {
    json: Value,
    table: String,
}

impl Report for DayReport {
    fn table(&self) -> String {
        self.table.clone()
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
        }
        axes.insert(a.name().into(), Value::Object(m));
    }
    let mut daily = Map::new();
    daily.insert("axes".into(), Value::Object(axes));
    daily.insert("a8_m_s2".into(), json!(d.a8));
    daily.insert("a8_axis".into(), json!(d.a8_axis.name()));
    daily.insert("points".into(), json!(d.points));
    daily.insert("eu_a8".into(), json!(d.eu_a8.words()));
    if let (Some((axis, v)), Some(eu)) = (d.vdv, d.eu_vdv) {
        daily.insert("vdv_exposure_m_s175".into(), json!(v));
        daily.insert("vdv_axis".into(), json!(axis.name()));
        daily.insert("eu_vdv".into(), json!(eu.words()));
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

fn week_json(w: &Week) -> Value {
    let mut axes = Map::new();
    for (a, v) in w.axes.iter() {
        axes.insert(a.name().into(), json!({ "a8_m_s2": v }));
    }
    json!({
        "axes": axes,
        "a8_m_s2": w.a8,
        "a8_axis": w.a8_axis.name(),
        "points": w.points,
        "eu_a8": w.eu_a8.words(),
    })
}

/// Hours in a table: "never" when the value is never reached.
fn hours_cell(h: Option<f64>) -> String {
    h.map_or("never".into(), |h| fx(h, 2))
}

fn day_text(f: &DayFile, d: &Day) -> String {
    let total: f64 = d.operations.iter().map(|o| o.hours).sum();
    let n = d.operations.len();
    let mut s = format!(
        "{}: {n} operation{}, {} h\n\n",
        f.origin,
        if n == 1 { "" } else { "s" },
        biodyn::io::num(total)
    );
    let mut rows = Vec::new();
    for o in &d.operations {
        for (i, (a, e)) in o.axes.iter().enumerate() {
            let first = i == 0;
            rows.push(vec![
                if first { o.name.clone() } else { String::new() },
                if first {
                    biodyn::io::num(o.hours)
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
        }
    }
    s.push_str(&table(&crate::view::report::OPERATION_HEADINGS, &rows));
    s.push_str("\nThe day, per axis (A(8) = √Σ partial A(8)², points add):\n");
    let rows: Vec<Vec<String>> = d
        .axes
        .iter()
        .map(|(a, x)| {
            vec![
                format!("{a} ({})", a.direction()),
                fx(x.a8, 3),
                fx(x.points, 1),
                x.vdv.map_or("-".into(), |v| fx(v, 2)),
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
    match (d.vdv, d.eu_vdv) {
        (Some((axis, v)), Some(eu)) => s.push_str(&format!(
            "  VDV {} m/s^1.75 on {axis}: {} (action {VDV_ACTION}, limit {VDV_LIMIT})\n",
            fx(v, 2),
            eu.words()
        )),
        _ => {
            let lacking: Vec<String> = d
                .axes
                .iter()
                .filter(|(_, x)| !x.lacking_vdv.is_empty())
                .map(|(a, x)| {
                    let names: Vec<String> = x
                        .lacking_vdv
                        .iter()
                        .filter_map(|&i| d.operations.get(i))
                        .map(|o| format!("'{}'", biodyn::io::short_quote(&o.name)))
                        .collect();
                    format!("{a}: {}", names.join(", "))
                })
                .collect();
            s.push_str(&format!(
                "  VDV not judged: operations without a measured VDV ({})\n",
                lacking.join("; ")
            ));
        }
    }
    if let Some(sp) = &d.spine {
        s.push_str(&spine_text(d, sp));
    }
    s
}

fn week_text(w: &Week, days: usize) -> String {
    let rows: Vec<Vec<String>> = w
        .axes
        .iter()
        .map(|(a, v)| vec![format!("{a} ({})", a.direction()), fx(*v, 3)])
        .collect();
    format!(
        "The week ({days} day{}; A(8)week = √(⅕ Σ A(8)day²), UK SI 2005/1093 Schedule 2):\n{}\nWeekly exposure: {} ({}), A(8) {:.3} m/s², {:.0} points: {}\n",
        if days == 1 { "" } else { "s" },
        table(&["axis", "A(8)week m/s²"], &rows),
        w.a8_axis,
        w.a8_axis.direction(),
        w.a8,
        w.points,
        w.eu_a8.words()
    )
}

/// What to try next after a day file is refused.
pub fn hint(cause: &(dyn std::error::Error + 'static)) -> Option<String> {
    use biodyn::exposure::{DayError, EvalError};
    if let Some(e) = cause.downcast_ref::<EvalError<anyhow::Error>>() {
        return Some(match e {
            EvalError::Record { .. } => {
                "a record's path is from the day file's folder, and it is read as assess --input reads it: name its columns with axes = \"x=ax,y=ay,z=az\" and their unit with unit = \"g\" in the operation, or give its measured aw_m_s2 = { x = .., y = .., z = .. } instead".into()
            }
            EvalError::Day(_) => DAY_HINT.into(),
        });
    }
    cause.downcast_ref::<DayError>().map(|_| DAY_HINT.into())
}

const DAY_HINT: &str = "each [[operation]] has name, hours (over 0, the day at most 24 h) and aw_m_s2 = { z = .. } or record = \"FILE.csv\"; see docs/cli-day.md";
