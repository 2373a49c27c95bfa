//! The design search's figure (`biodyn seat --vary … --plot`, and the map
//! panel of the Seat tab's `.svg`): SEAT % over the box, the cells whose
//! r.m.s. travel passes the limit in grey, the best point the search found
//! and the seat as it is.
//!
//! Two parameters: one map, the second parameter across and the first up
//! (the TUI's orientation), both log, each grid node's cell reaching half
//! way (in ln p) to its neighbours, the shades binned at round SEAT values.
//! One parameter: SEAT % and the r.m.s. travel over it, the limit drawn.

use super::model::{Axis, Cells, Curve, Panel, Points};
use super::style::{Fill, Look, SHADES};
use crate::view::axis::{self as ax, Scale};
use crate::view::format::num;
use biodyn::seat::{Design, SeatFigures, Vary};

/// One map's panel size, pixels (the key beside it takes about 380 of the width).
pub const MAP_PX: (u32, u32) = (1000, 560);
/// One parameter's two panels, each.
pub const LINE_PX: (u32, u32) = (800, 380);

/// What the design figure shows besides the search.
#[derive(Debug, Clone, Copy)]
pub struct DesignFigure<'a> {
    pub design: &'a Design,
    /// The varied parameters' values in the model now, in `design.vary`
    /// order, and the seat's figures there.
    pub now: &'a [f64],
    pub now_figures: &'a SeatFigures,
    /// The floor's name ("EM6", a PSD file's name).
    pub floor: &'a str,
}

fn axis_title(v: &Vary) -> String {
    format!("{} ({})", v.name, v.param.unit())
}

/// Cell edges of `nodes` (rising, log-spaced): half way in ln p between
/// neighbours, and as far again beyond the ends.
fn edges(nodes: &[f64]) -> Vec<f64> {
    let n = nodes.len();
    if n < 2 {
        return nodes.iter().flat_map(|&v| [v / 1.1, v * 1.1]).collect();
    }
    let mid = |a: f64, b: f64| (a * b).sqrt();
    let mut e = vec![nodes[0] * nodes[0] / mid(nodes[0], nodes[1])];
    e.extend(nodes.windows(2).map(|w| mid(w[0], w[1])));
    e.push(nodes[n - 1] * nodes[n - 1] / mid(nodes[n - 2], nodes[n - 1]));
    e
}

/// Round bin edges over [lo, hi], at most `SHADES` bins.
fn bins(lo: f64, hi: f64) -> Vec<f64> {
    let fits = |_: f64, _: f64, t: &[ax::Tick]| t.len() <= SHADES.len() + 1;
    let plan = ax::plan(
        lo,
        hi,
        Scale::Linear {
            pad: 0.0,
            floor_zero: false,
        },
        &fits,
    );
    let mut e: Vec<f64> = plan.ticks.iter().map(|t| t.at).collect();
    if e.first().is_none_or(|&a| a > lo) {
        e.insert(0, plan.lo.min(lo));
    }
    if e.last().is_none_or(|&b| b < hi) {
        e.push(plan.hi.max(hi));
    }
    e
}

/// The seat as it is, at (x, y).
fn now_points(f: &DesignFigure, x: f64, y: f64) -> Points {
    Points {
        name: format!("the seat now: SEAT {} %", num(f.now_figures.seat_pct, 3)),
        points: vec![(x, y, None)],
    }
}

/// The map of a two-parameter search.
fn map(f: &DesignFigure) -> Panel {
    let d = f.design;
    let limit = d.stroke_rms_max_m;
    let (rows, cols) = (&d.map.axes[0], &d.map.axes[1]);
    let (er, ec) = (edges(rows), edges(cols));
    let feasible: Vec<f64> = d
        .map
        .seat_pct
        .iter()
        .zip(&d.map.stroke_rms_m)
        .filter(|(s, t)| s.is_finite() && **t <= limit)
        .map(|(s, _)| *s)
        .collect();
    let (lo, hi) = feasible
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        });
    let e = if lo.is_finite() {
        bins(lo, hi)
    } else {
        Vec::new()
    };
    let nb = e.len().saturating_sub(1).max(1);
    // The bins' shades spread over the palette, light to dark.
    let shade = |b: usize| {
        if nb == 1 {
            0
        } else {
            b * (SHADES.len() - 1) / (nb - 1)
        }
    };
    let mut by_bin: Vec<Vec<(f64, f64, f64, f64)>> = vec![Vec::new(); nb];
    let mut off = Vec::new();
    for (i, _) in rows.iter().enumerate() {
        for (j, _) in cols.iter().enumerate() {
            let at = i * cols.len() + j;
            let (s, t) = (d.map.seat_pct[at], d.map.stroke_rms_m[at]);
            let cell = (ec[j], ec[j + 1], er[i], er[i + 1]);
            if !(t <= limit && s.is_finite()) {
                off.push(cell);
                continue;
            }
            let b = e.windows(2).position(|w| s < w[1]).unwrap_or(nb - 1);
            by_bin[b.min(nb - 1)].push(cell);
        }
    }
    let mut cells: Vec<Cells> = by_bin
        .into_iter()
        .enumerate()
        .filter(|(_, c)| !c.is_empty())
        .map(|(b, c)| Cells {
            name: format!("SEAT {}–{} %", num(e[b], 4), num(e[b + 1], 4)),
            cells: c,
            fill: Fill::Shade(shade(b)),
        })
        .collect();
    if !off.is_empty() {
        cells.push(Cells {
            name: format!("r.m.s. stroke over {} mm", num(limit * 1e3, 3)),
            cells: off,
            fill: Fill::Off,
        });
    }
    let best = &d.best;
    Panel {
        title: format!(
            "SEAT % under {} over {} and {}",
            f.floor, d.vary[0].name, d.vary[1].name
        ),
        x: Axis {
            title: axis_title(&d.vary[1]),
            log: true,
            ..Axis::default()
        },
        y: Axis {
            title: axis_title(&d.vary[0]),
            log: true,
            ..Axis::default()
        },
        cells,
        points: vec![now_points(f, f.now[1], f.now[0])],
        marks: vec![(best.values[1], best.values[0])],
        marks_name: format!(
            "lowest SEAT within the limit: {} %",
            num(best.figures.seat_pct, 3)
        ),
        ..Panel::default()
    }
}

/// SEAT and the travel over a one-parameter search.
fn lines(f: &DesignFigure) -> Vec<Panel> {
    let d = f.design;
    let v = &d.vary[0];
    let nodes = &d.map.axes[0];
    let x = Axis {
        title: axis_title(v),
        log: true,
        ..Axis::default()
    };
    let best = &d.best;
    let seat = Panel {
        title: format!("SEAT % under {} over {}", f.floor, v.name),
        x: x.clone(),
        y: Axis {
            title: "SEAT (%)".into(),
            floor_zero: true,
            ..Axis::default()
        },
        curves: vec![Curve {
            name: "SEAT %".into(),
            points: nodes
                .iter()
                .copied()
                .zip(d.map.seat_pct.iter().copied())
                .collect(),
            look: Look::Series(0),
        }],
        points: vec![now_points(f, f.now[0], f.now_figures.seat_pct)],
        marks: vec![(best.values[0], best.figures.seat_pct)],
        marks_name: format!(
            "lowest SEAT within the limit: {} %",
            num(best.figures.seat_pct, 3)
        ),
        ..Panel::default()
    };
    let ends = vec![
        (nodes[0], d.stroke_rms_max_m * 1e3),
        (nodes[nodes.len() - 1], d.stroke_rms_max_m * 1e3),
    ];
    let travel = Panel {
        title: format!("r.m.s. stroke under {} over {}", f.floor, v.name),
        x,
        y: Axis {
            title: "r.m.s. stroke (mm)".into(),
            floor_zero: true,
            ..Axis::default()
        },
        curves: vec![
            Curve {
                name: "r.m.s. stroke".into(),
                points: nodes
                    .iter()
                    .copied()
                    .zip(d.map.stroke_rms_m.iter().map(|m| m * 1e3))
                    .collect(),
                // Its own pen: the two panels' curves are different quantities.
                look: Look::Series(2),
            },
            Curve {
                name: format!("limit {} mm", num(d.stroke_rms_max_m * 1e3, 3)),
                points: ends,
                look: Look::Series(1),
            },
        ],
        points: vec![Points {
            name: "the seat now".into(),
            points: vec![(f.now[0], f.now_figures.stroke_rms_m * 1e3, None)],
        }],
        marks: vec![(best.values[0], best.figures.stroke_rms_m * 1e3)],
        marks_name: "the lowest SEAT's".into(),
        ..Panel::default()
    };
    vec![seat, travel]
}

/// The search's panels: a map for two parameters, two line panels for one.
pub fn panels(f: &DesignFigure) -> Vec<Panel> {
    match f.design.vary.len() {
        2 if f.design.map.axes.len() == 2 && f.now.len() == 2 => vec![map(f)],
        1 if f.now.len() == 1 && f.design.map.axes.first().is_some_and(|a| !a.is_empty()) => {
            lines(f)
        }
        _ => Vec::new(),
    }
}
