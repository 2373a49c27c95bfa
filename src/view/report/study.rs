//! A study's exports, one function each, called by `biodyn study
//! --format csv`, `biodyn plot --study` and the TUI's export (`x`), so the
//! file a user saves from the Study tab is byte for byte what the command
//! line prints for the same model and band.

use super::csv;
use super::plot::{self, PlotText};
use crate::view::chart::Series;
use biodyn::freq::Study;
use biodyn::{Function, Response};

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

/// One curve per variant of `function` (its magnitude, or its phase in
/// degrees) and, for magnitudes, the main peaks inside the band: what
/// `biodyn plot <f> --study …` and the Study tab's `.txt` both draw.
pub fn chart_series(s: &Study, function: Function, phase: bool) -> (Vec<Series>, Vec<(f64, f64)>) {
    let value = |r: &Response| {
        if phase {
            r.phase_deg(function)
        } else {
            r.mag(function)
        }
    };
    let series = s
        .variants
        .iter()
        .map(|v| Series {
            name: v.label.clone(),
            points: v.curve.iter().map(|r| (r.f_hz, value(r))).collect(),
        })
        .collect();
    let marks = if phase {
        Vec::new()
    } else {
        s.variants
            .iter()
            .filter_map(|v| v.peaks.get(function.index()).copied().flatten())
            .filter(|p| !p.at_edge)
            .map(|p| (p.f_hz, p.mag))
            .collect()
    };
    (series, marks)
}

/// The magnitude chart of `function` with one curve per variant and the
/// main peaks marked, as the lines of text `biodyn plot <f> --study …`
/// prints (monochrome; a trailing newline).
/// The study's figure, as `biodyn plot <f> --study … --format svg` writes it.
pub fn figure_svg(s: &Study, function: Function, log: bool) -> String {
    let (series, marks) = chart_series(s, function, false);
    crate::view::figure::response::figure(&crate::view::figure::response::ResponseFigure {
        function,
        phase: false,
        log_x: log,
        log_y: log,
        series: &series,
        marks: &marks,
        data: None,
        reference: None,
        size: crate::view::figure::PANEL_PX,
    })
    .svg()
}

pub fn chart_text(s: &Study, o: PlotText) -> String {
    let (series, marks) = chart_series(s, o.function, false);
    plot::chart_text(&series, marks, false, &o)
}
