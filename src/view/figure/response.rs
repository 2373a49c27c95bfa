//! The response figure `biodyn plot --format svg` writes and the Responses
//! and Study tabs export as `.svg`: one function's magnitude or phase over
//! frequency, the model's curve or a study's, its peaks, measured data with
//! their standard deviations, a compared model beneath.

use super::{Axis, Curve, Figure, Look, Panel, Points};
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
        },
        y: Axis {
            title: axis_title(f, r.phase),
            log: r.log_y,
            floor_zero: !r.phase,
        },
        curves,
        points,
        bars: Vec::new(),
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
    let nearest = |f: f64| {
        model
            .iter()
            .min_by(|a, b| (a.0 - f).abs().total_cmp(&(b.0 - f).abs()))
            .map(|p| p.1)
    };
    Some(
        m.f_hz
            .iter()
            .zip(&col.values)
            .enumerate()
            .filter_map(|(i, (&f, v))| v.map(|v| (i, f, v)))
            .map(|(i, f, v)| {
                let sd = col.sd.as_ref().and_then(|s| s.get(i).copied().flatten());
                let v = match (phase, nearest(f)) {
                    (true, Some(at)) => v + 360.0 * ((at - v) / 360.0).round(),
                    _ => v,
                };
                (f, v, sd)
            })
            .collect(),
    )
}
