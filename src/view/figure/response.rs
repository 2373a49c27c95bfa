//! The response figure `biodyn plot --format svg` writes and the Responses
//! and Study tabs export as `.svg`: one function's magnitude or phase over
//! frequency, the model's curve or a study's, its peaks, measured data with
//! their standard deviations, a compared model beneath.

use super::model::{Axis, Curve, Figure, Panel, Points};
use super::style::Look;
use crate::view::chart::Series;
use crate::view::format::axis_title;
use biodyn::Function;
use biodyn::fit::{Measured, Quantity};

/// A measured point: (f, value, standard deviation where known).
pub type Measurement = (f64, f64, Option<f64>);

/// What a response figure shows.
#[derive(Debug, Clone, Copy)]
pub struct ResponseFigure<'a> {
    pub function: Function,
    pub phase: bool,
    pub log_x: bool,
    pub log_y: bool,
    /// The model's curve, or a study's curves in order.
    pub series: &'a [Series],
    /// Peaks to mark (magnitude only).
    pub marks: &'a [(f64, f64)],
    /// Measured points: (legend name, (f, value, sd)).
    pub data: Option<(&'a str, &'a [Measurement])>,
    /// A compared model, drawn beneath the others.
    pub reference: Option<&'a Series>,
    pub size: (u32, u32),
}

pub fn figure(r: &ResponseFigure) -> Figure {
    let f = r.function;
    let mut curves: Vec<Curve> = r
        .series
        .iter()
        .enumerate()
        .map(|(i, s)| Curve {
            name: s.name.clone(),
            points: s.points.clone(),
            look: Look::Series(i),
        })
        .collect();
    if let Some(c) = r.reference {
        curves.push(Curve {
            name: format!("{} (compared)", c.name),
            points: c.points.clone(),
            look: Look::Reference,
        });
    }
    let points = r
        .data
        .map(|(name, pts)| Points {
            name: name.to_string(),
            points: pts.to_vec(),
        })
        .into_iter()
        .collect();
    let panel = Panel {
        title: format!("{} — {}", f.name(), f.long_name()),
        x: Axis {
            title: "f (Hz)".into(),
            log: r.log_x,
            floor_zero: false,
            names: Vec::new(),
        },
        y: Axis {
            title: axis_title(f, r.phase),
            log: r.log_y,
            floor_zero: !r.phase,
            names: Vec::new(),
        },
        curves,
        points,
        bars: Vec::new(),
        cells: Vec::new(),
        marks: if r.phase {
            Vec::new()
        } else {
            r.marks.to_vec()
        },
        marks_name: "peak".into(),
    };
    Figure::single(panel, r.size)
}

/// The measured points of `function`'s magnitude or phase with their
/// standard deviations; None when the file has no such column. A phase is
/// moved by whole turns next to `model` (its value at the nearest
/// frequency), as the fit compares phases (wrapped difference).
pub fn measured(
    m: &Measured,
    function: Function,
    phase: bool,
    model: &[(f64, f64)],
) -> Option<Vec<Measurement>> {
    let q = if phase {
        Quantity::Phase
    } else {
        Quantity::Mag
    };
    let col = m
        .columns
        .iter()
        .find(|c| c.channel.function == function && c.channel.quantity == q)?;
    Some(
        m.f_hz
            .iter()
            .zip(&col.values)
            .enumerate()
            .filter_map(|(i, (&f, v))| v.map(|v| (i, f, v)))
            .map(|(i, f, v)| {
                let sd = col.sd.as_ref().and_then(|s| s.get(i).copied().flatten());
                let v = match (phase, nearest(model, f)) {
                    (true, Some(at)) => v + 360.0 * ((at - v) / 360.0).round(),
                    _ => v,
                };
                (f, v, sd)
            })
            .collect(),
    )
}

/// The model's value at the grid point nearest `f` (the grid is sorted, so
/// a binary search finds it).
fn nearest(pts: &[(f64, f64)], f: f64) -> Option<f64> {
    let i = pts.partition_point(|p| p.0 < f);
    let after = pts.get(i);
    let before = i.checked_sub(1).and_then(|j| pts.get(j));
    match (before, after) {
        (Some(a), Some(b)) if (f - a.0).abs() <= (b.0 - f).abs() => Some(a.1),
        (_, Some(b)) => Some(b.1),
        (Some(a), None) => Some(a.1),
        (None, None) => None,
    }
}

/// The legend's name of a data file: "data: " and its `file_name`.
pub fn data_name(path: &str) -> String {
    format!("data: {}", file_name(path))
}

/// A file's name as a figure prints it: the last part of `path`, control
/// characters shown as U+FFFD (XML text may not hold them: the SVG would
/// not open).
pub fn file_name(path: &str) -> String {
    let p = std::path::Path::new(path);
    let name = p
        .file_name()
        .map_or_else(|| path.to_string(), |n| n.to_string_lossy().into_owned());
    name.chars()
        .map(|c| if c.is_control() { '\u{FFFD}' } else { c })
        .collect()
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_data_files_name_is_its_file_name_without_control_characters() {
        assert_eq!(super::data_name("/x/y/m.csv"), "data: m.csv");
        assert_eq!(
            super::data_name("a\u{1b}[31m<b>.csv"),
            "data: a\u{FFFD}[31m<b>.csv"
        );
    }
}
