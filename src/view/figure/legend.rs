//! Where a panel's legend goes: the plot's corner whose box covers the
//! fewest drawn cells, and, when every corner covers something, how much
//! higher a linear y axis must reach for the box to sit above the data.

use super::model::Panel;
use crate::view::axis::Plan;
use plotters::prelude::SeriesLabelPosition;

/// A legend row's height and the box's frame, pixels (plotters' defaults
/// with our font), and the sample's width beside the names.
const ROW_PX: f64 = 20.0;
const FRAME_PX: f64 = 20.0;
const SAMPLE_PX: f64 = 60.0;
/// Lines are sampled every this share of the plot, so a long straight
/// segment (a limit line drawn by its two ends) counts along its length.
const STEP: f64 = 0.02;

/// Whether the panel draws a legend: more than one named entry.
pub fn shown(p: &Panel) -> bool {
    p.curves.len() + p.points.len() + p.bars.len() + usize::from(!p.marks.is_empty()) > 1
}

/// Every name a legend (or a map's key) lists, in its order: the cells'
/// shades, the curves, the points, the bars, then the marks.
pub fn names(p: &Panel) -> impl Iterator<Item = &str> {
    p.cells
        .iter()
        .map(|c| c.name.as_str())
        .chain(p.curves.iter().map(|c| c.name.as_str()))
        .chain(p.points.iter().map(|d| d.name.as_str()))
        .chain(p.bars.iter().map(|b| b.name.as_str()))
        .chain((!p.marks.is_empty()).then_some(p.marks_name.as_str()))
}

/// The legend's size as fractions of the plot: its longest name plus the
/// sample, a row per entry. `label_px` estimates a name's width.
pub fn size(p: &Panel, plot_px: (f64, f64), label_px: impl Fn(&str) -> f64) -> (f64, f64) {
    let names = names(p);
    let (mut rows, mut widest) = (0usize, 0.0f64);
    for n in names {
        rows += 1;
        widest = widest.max(label_px(n));
    }
    let w = (widest + SAMPLE_PX) / plot_px.0.max(1.0);
    let h = (rows as f64 * ROW_PX + FRAME_PX) / plot_px.1.max(1.0);
    (w.min(1.0), h.min(1.0))
}

/// Everything the panel draws as fractions of the plot (0..1 on each
/// axis): curves along their length, points with their error bars, bars
/// over their tops and down their middles, marks.
pub fn occupied(p: &Panel, x: &Plan, y: &Plan) -> Vec<(f64, f64)> {
    let (xl, yl) = (p.x.log, p.y.log);
    let on = |v: f64, log: bool| v.is_finite() && (!log || v > 0.0);
    let frac = |v: f64, plan: &Plan, log: bool| {
        let v = if log { v.log10() } else { v };
        (v - plan.lo) / (plan.hi - plan.lo)
    };
    let at =
        |px: f64, py: f64| (on(px, xl) && on(py, yl)).then(|| (frac(px, x, xl), frac(py, y, yl)));
    let mut out = Vec::new();
    let line = |pts: &mut dyn Iterator<Item = (f64, f64)>, out: &mut Vec<(f64, f64)>| {
        let mut last: Option<(f64, f64)> = None;
        for q in pts.filter_map(|(a, b)| at(a, b)) {
            if let Some(l) = last {
                let n = ((q.0 - l.0).hypot(q.1 - l.1) / STEP).ceil().min(1000.0) as usize;
                for k in 1..n {
                    let t = k as f64 / n as f64;
                    out.push((l.0 + (q.0 - l.0) * t, l.1 + (q.1 - l.1) * t));
                }
            }
            out.push(q);
            last = Some(q);
        }
    };
    for c in &p.curves {
        line(&mut c.points.iter().copied(), &mut out);
    }
    for d in &p.points {
        for &(px, py, sd) in &d.points {
            let s = sd.unwrap_or(0.0);
            line(&mut [(px, py - s), (px, py + s)].into_iter(), &mut out);
            out.extend(at(px, py));
        }
    }
    let base = if yl {
        None
    } else {
        Some(y.lo.max(0.0).min(y.hi))
    };
    for b in &p.bars {
        for &(a, z, v) in &b.bars {
            line(&mut [(a, v), (z, v)].into_iter(), &mut out);
            if let Some(y0) = base {
                line(
                    &mut [((a + z) / 2.0, y0), ((a + z) / 2.0, v)].into_iter(),
                    &mut out,
                );
            }
        }
    }
    out.extend(p.marks.iter().filter_map(|&(a, b)| at(a, b)));
    out
}

/// The corner where a box of `size` covers the fewest `cells`, and how
/// many it covers there.
pub fn corner(cells: &[(f64, f64)], size: (f64, f64)) -> (SeriesLabelPosition, usize) {
    let count = |right: bool, top: bool| {
        cells
            .iter()
            .filter(|(x, y)| {
                let in_x = if right {
                    *x >= 1.0 - size.0
                } else {
                    *x <= size.0
                };
                let in_y = if top {
                    *y >= 1.0 - size.1
                } else {
                    *y <= size.1
                };
                in_x && in_y
            })
            .count()
    };
    let options = [
        (SeriesLabelPosition::UpperRight, count(true, true)),
        (SeriesLabelPosition::UpperLeft, count(false, true)),
        (SeriesLabelPosition::LowerRight, count(true, false)),
        (SeriesLabelPosition::LowerLeft, count(false, false)),
    ];
    let best = options.iter().map(|o| o.1).min().unwrap_or(0);
    options
        .into_iter()
        .find(|o| o.1 == best)
        .unwrap_or((SeriesLabelPosition::UpperRight, 0))
}

/// The top a linear y axis planned as `y` must reach for a legend `h` of
/// the plot high to sit above everything drawn (axis units, a margin of
/// 3 % of the plot beneath the box).
pub fn headroom(cells: &[(f64, f64)], y: &Plan, h: f64) -> Option<f64> {
    let top = cells.iter().map(|c| c.1).fold(f64::NEG_INFINITY, f64::max);
    let room = 1.0 - h - 0.03;
    (top.is_finite() && room > 0.2).then(|| y.lo + (y.hi - y.lo) * top / room)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_box_over_a_long_line_is_seen_between_its_ends() {
        let plan = Plan {
            lo: 0.0,
            hi: 1.0,
            ticks: Vec::new(),
        };
        let p = Panel {
            curves: vec![super::super::model::Curve {
                name: "limit".into(),
                points: vec![(0.0, 0.9), (1.0, 0.9)],
                look: super::super::style::Look::Series(0),
            }],
            ..Panel::default()
        };
        let cells = occupied(&p, &plan, &plan);
        assert!(cells.len() > 40, "{}", cells.len());
        // A box of 0.3 × 0.3 in any top corner covers part of the line.
        let (_, n) = corner(&cells, (0.3, 0.3));
        assert_eq!(n, 0, "a lower corner is free");
        let both: Vec<(f64, f64)> = cells.iter().flat_map(|&c| [c, (c.0, c.1 - 0.8)]).collect();
        assert!(
            corner(&both, (0.3, 0.3)).1 > 0,
            "lines at 0.1 and 0.9 reach every corner"
        );
        // Raised so that 0.9 sits beneath a box of 0.3 with 3 % to spare.
        let hi = headroom(&cells, &plan, 0.3).expect("room");
        assert!((0.9 / hi - 0.67).abs() < 1e-9, "{hi}");
    }
}
