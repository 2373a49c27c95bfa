//! The Day tab's export (`x`): the sheet as CSV (per operation and axis
//! k·a_w, partial A(8), points and hours to the action and limit values,
//! then the day per axis, the JSON's numbers of `biodyn day`), or the
//! figure (`.svg`: points per operation against 100 and 529, as `biodyn
//! day DAY.toml --plot` writes it for the same day). Only a day whose every
//! operation is evaluated: a figure of part of a day would show a verdict
//! the day does not have.

use super::DayTab;
use crate::tui::effect::{Effect, Export, Format};
use crate::view::figure::day::figure;
use biodyn::exposure::Day;

pub fn effects(t: &DayTab) -> Vec<Effect> {
    let Some(day) = t.sheet.day.as_ref() else {
        return vec![Effect::Error(
            "nothing to export: no operation has an a_w yet (Enter types one, or a record)".into(),
        )];
    };
    if !t.sheet.complete() {
        let n = t.sheet.left_out.len();
        return vec![Effect::Error(format!(
            "not exported: {n} operation{} not evaluated yet (a record measuring or unreadable, or no a_w); the day would be judged without {}",
            if n == 1 { " is" } else { "s are" },
            if n == 1 { "it" } else { "them" }
        ))];
    }
    let stem = t
        .path
        .as_ref()
        .and_then(|p| p.file_stem())
        .map_or("my-day".to_string(), |s| s.to_string_lossy().into_owned());
    vec![Effect::Export(Export {
        what: "the day".into(),
        path_hint: format!("{stem}-sheet.csv"),
        formats: vec![
            Format {
                ext: "csv",
                what: "sheet",
                contents: csv(day),
            },
            Format {
                ext: "svg",
                what: "figure",
                contents: figure(&[(None, day)]).svg(),
            },
        ],
    })]
}

/// A name in a CSV cell: quoted when it holds a separator, a quote or a
/// line break.
fn cell(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

fn hours(h: Option<f64>) -> String {
    h.map_or(String::new(), |h| h.to_string())
}

/// One row per operation and axis, then one per axis for the day (hours
/// empty), then the day's highest axis (`axis` "day: z").
pub fn csv(day: &Day) -> String {
    let mut out = String::from(
        "operation,axis,hours,kaw_m_s2,a8_m_s2,points,hours_to_eav,hours_to_elv\n",
    );
    for o in &day.operations {
        for (a, e) in o.axes.iter() {
            out.push_str(&format!(
                "{},{},{},{},{},{},{},{}\n",
                cell(&o.name),
                a.name(),
                o.hours,
                e.kaw,
                e.a8,
                e.points,
                hours(e.hours_to_eav),
                hours(e.hours_to_elv)
            ));
        }
    }
    for (a, d) in day.axes.iter() {
        out.push_str(&format!("the day,{},,,{},{},,\n", a.name(), d.a8, d.points));
    }
    out.push_str(&format!(
        "the day,highest: {},,,{},{},,\n",
        day.a8_axis.name(),
        day.a8,
        day.points
    ));
    out
}
