//! The Day tab's export (`x`): the sheet as CSV (`biodyn day --format
//! csv`'s: per operation and axis k·a_w, partial A(8), points, hours to
//! the action and limit values, the VDV and the hours to its values, then
//! the day per axis and its highest axes, the JSON's numbers), or the
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

/// The sheet: `biodyn day --format csv`'s writer, byte for byte.
pub fn csv(day: &Day) -> String {
    crate::view::report::day::csv(day)
}
