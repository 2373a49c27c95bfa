//! A study's exports, one function each, called by `biodyn study
//! --format csv`, `biodyn plot --study` and the TUI's export (`x`), so the
//! file a user saves from the Study tab is byte for byte what the command
//! line prints for the same model and band.

use super::csv;
use super::plot::{self, PlotText};
use crate::view::chart::Series;
use biodyn::freq::Study;

/// The curves of every variant: `variant,value,f_hz,stht_mag,…`.
pub fn curves_csv(s: &Study) -> String {
    let mut out = String::from("variant,value,");
    out += &csv::curve_header();
    out.push('\n');
    for v in &s.variants {
        let prefix = format!("{},{},", csv::text_cell(&v.label), v.value);
        csv::curve_rows(&mut out, &prefix, &v.curve);
    }
    out
}

/// The magnitude chart of `function` with one curve per variant and the
/// main peaks marked, as the lines of text `biodyn plot <f> --study …`
/// prints (monochrome; a trailing newline).
pub fn chart_text(s: &Study, o: PlotText) -> String {
    let f = o.function;
    let series: Vec<Series> = s
        .variants
        .iter()
        .map(|v| Series {
            name: v.label.clone(),
            points: v.curve.iter().map(|r| (r.f_hz, r.mag(f))).collect(),
        })
        .collect();
    let marks = s
        .variants
        .iter()
        .filter_map(|v| v.peaks.get(f.index()).copied().flatten())
        .filter(|p| !p.at_edge)
        .map(|p| (p.f_hz, p.mag))
        .collect();
    plot::chart_text(&series, marks, false, &o)
}
