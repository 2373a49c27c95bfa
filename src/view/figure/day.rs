//! The working day's figure (`biodyn day --plot`, the Day tab's `.svg`,
//! the day report): HSE points per operation on its highest axis, then the
//! day's, against the action value (100 points) and the limit (529), each
//! bar filled by the verdict on the A(8) it stands for.
//!
//! Points of different axes never add (the Directive judges x, y and z
//! apart), so an operation's bar is its highest axis alone, named under
//! it; the day's bar is the day's highest axis, the sum of its operations'
//! points on that axis (points add as A(8)² do).
//!
//! Beside it, the VDV (where the day has any): each operation's highest
//! VDV over its hours, then the day's, against 9.1 (action) and 21
//! (limit) m/s^1.75, each bar filled by its VDV verdict; a VDV over the
//! limit shows though the A(8) is low. A day whose operations do not all
//! have a VDV shows the known part, a lower bound, named "at least".

use super::model::{Axis, Bars, Curve, Figure, Panel};
use super::style::{Fill, Look};
use biodyn::exposure::{Day, DayVdv, points};
use biodyn::iso2631::{A8_ACTION, A8_LIMIT, VDV_ACTION, VDV_LIMIT, Verdict};

/// One day's panel size, pixels.
pub const PANEL_PX: (u32, u32) = (800, 460);

/// The fill of a bar whose A(8) is `a8`.
fn fill(a8: f64) -> Fill {
    fill_of(Verdict::judge(a8, A8_ACTION, A8_LIMIT))
}

fn fill_of(v: Verdict) -> Fill {
    match v {
        Verdict::BelowAction => Fill::Plain,
        Verdict::AboveAction => Fill::Action,
        Verdict::AboveLimit => Fill::Limit,
    }
}

/// The legend's words for a fill.
fn fill_name(f: Fill) -> &'static str {
    match f {
        Fill::Action => "A(8) above the action value",
        Fill::Limit => "A(8) above the limit value",
        _ => "A(8) at or below the action value",
    }
}

/// (category name, points, A(8)) per operation and the day's last.
fn columns(day: &Day) -> Vec<(String, f64, f64)> {
    let mut out: Vec<(String, f64, f64)> = day
        .operations
        .iter()
        .map(|o| {
            let best = o
                .axes
                .iter()
                .fold(None, |m: Option<(_, f64, f64)>, (a, e)| match m {
                    Some(b) if b.1 >= e.points => Some(b),
                    _ => Some((a, e.points, e.a8)),
                });
            match best {
                Some((a, p, a8)) => (format!("{} ({})", o.name, a.name()), p, a8),
                None => (o.name.clone(), 0.0, 0.0),
            }
        })
        .collect();
    out.push((
        format!("the day ({})", day.a8_axis.name()),
        day.points,
        day.a8,
    ));
    out
}

/// The bars of `heights` (None: no bar), one set per fill, named.
fn bars_of(heights: &[Option<(f64, Fill)>], name: fn(Fill) -> &'static str) -> Vec<Bars> {
    let mut bars: Vec<Bars> = Vec::new();
    for f in [Fill::Plain, Fill::Action, Fill::Limit] {
        let of: Vec<(f64, f64, f64)> = heights
            .iter()
            .enumerate()
            .filter_map(|(i, c)| c.filter(|c| c.1 == f).map(|c| (i, c.0)))
            .map(|(i, h)| (i as f64 - 0.35, i as f64 + 0.35, h))
            .collect();
        if !of.is_empty() {
            bars.push(Bars {
                name: name(f).into(),
                bars: of,
                fill: f,
            });
        }
    }
    bars
}

/// The panel of one day, titled `title`.
pub fn panel(day: &Day, title: &str) -> Panel {
    let cols = columns(day);
    let heights: Vec<Option<(f64, Fill)>> = cols.iter().map(|c| Some((c.1, fill(c.2)))).collect();
    let bars = bars_of(&heights, fill_name);
    let across = |v: f64| vec![(-0.6, v), (cols.len() as f64 - 0.4, v)];
    Panel {
        title: title.into(),
        x: Axis {
            title: "operation (its highest axis), then the day".into(),
            names: cols.iter().map(|c| c.0.clone()).collect(),
            ..Axis::default()
        },
        y: Axis {
            title: "HSE points".into(),
            floor_zero: true,
            ..Axis::default()
        },
        curves: vec![
            Curve {
                name: "action value: 100 points (0.5 m/s²)".into(),
                points: across(points(A8_ACTION)),
                // Amber and vermillion, as the bars above each value.
                look: Look::Series(4),
            },
            Curve {
                name: "limit value: 529 points (1.15 m/s²)".into(),
                points: across(points(A8_LIMIT)),
                look: Look::Series(1),
            },
        ],
        bars,
        ..Panel::default()
    }
}

/// The legend's words for a VDV bar's fill.
fn vdv_fill_name(f: Fill) -> &'static str {
    match f {
        Fill::Action => "VDV above the action value",
        Fill::Limit => "VDV above the limit value",
        _ => "VDV at or below the action value",
    }
}

/// (category name, VDV) per operation, its highest VDV over its hours
/// (None: no VDV measured), and the day's last: exact, or the known part
/// named "at least".
fn vdv_columns(day: &Day) -> Vec<(String, Option<f64>)> {
    let mut out: Vec<(String, Option<f64>)> = day
        .operations
        .iter()
        .map(|o| {
            let best = o
                .axes
                .iter()
                .filter_map(|(a, e)| e.vdv_exposure.map(|v| (a, v)))
                .fold(None, |m: Option<(_, f64)>, x| match m {
                    Some(b) if b.1 >= x.1 => Some(b),
                    _ => Some(x),
                });
            match best {
                Some((a, v)) => (format!("{} ({})", o.name, a.name()), Some(v)),
                None => (format!("{} (no VDV)", o.name), None),
            }
        })
        .collect();
    out.push(match day.vdv_verdict {
        DayVdv::Known { axis, vdv, .. } => (format!("the day ({})", axis.name()), Some(vdv)),
        DayVdv::AtLeast { axis, vdv, .. } => {
            (format!("the day ({}, at least)", axis.name()), Some(vdv))
        }
        DayVdv::Unknown => ("the day (no VDV)".into(), None),
    });
    out
}

/// The VDV panel of one day, titled `title`.
pub fn vdv_panel(day: &Day, title: &str) -> Panel {
    let cols = vdv_columns(day);
    let heights: Vec<Option<(f64, Fill)>> = cols
        .iter()
        .map(|c| {
            c.1.map(|v| (v, fill_of(Verdict::judge(v, VDV_ACTION, VDV_LIMIT))))
        })
        .collect();
    let across = |v: f64| vec![(-0.6, v), (cols.len() as f64 - 0.4, v)];
    Panel {
        title: title.into(),
        x: Axis {
            title: "operation (its highest axis), then the day".into(),
            names: cols.iter().map(|c| c.0.clone()).collect(),
            ..Axis::default()
        },
        y: Axis {
            title: "VDV, m/s^1.75".into(),
            floor_zero: true,
            ..Axis::default()
        },
        curves: vec![
            Curve {
                name: format!("action value: VDV {VDV_ACTION} m/s^1.75"),
                points: across(VDV_ACTION),
                look: Look::Series(4),
            },
            Curve {
                name: format!("limit value: VDV {VDV_LIMIT} m/s^1.75"),
                points: across(VDV_LIMIT),
                look: Look::Series(1),
            },
        ],
        bars: bars_of(&heights, vdv_fill_name),
        ..Panel::default()
    }
}

/// The figure of `days`: each day's points panel, then its VDV panel when
/// any day has a VDV; one under the other. A day is named (`Some`, in a
/// week) or not (a single day): its panels' titles follow.
pub fn figure(days: &[(Option<String>, &Day)]) -> Figure {
    let vdv = days.iter().any(|(_, d)| d.vdv_verdict != DayVdv::Unknown);
    let title = |name: &Option<String>, t: &str| match name {
        Some(n) => format!("{n}: {t}"),
        None => t.to_string(),
    };
    let mut panels = Vec::new();
    for (name, d) in days {
        panels.push(panel(d, &title(name, DAY_TITLE)));
        if vdv {
            panels.push(vdv_panel(d, &title(name, VDV_TITLE)));
        }
    }
    Figure {
        panels,
        columns: 1,
        panel_px: PANEL_PX,
    }
}

/// A single day's title, the same from the command line and the tab.
pub const DAY_TITLE: &str = "points per operation, its highest axis";

/// The VDV panel's title.
pub const VDV_TITLE: &str = "VDV per operation, its highest axis";

#[cfg(test)]
mod tests {
    use super::*;
    use biodyn::exposure::{Measured, Operation};
    use biodyn::time::{Axis as Ax, PerAxis};

    fn op(name: &str, hours: f64, aw: &[(Ax, f64)]) -> Operation {
        let mut m = PerAxis::default();
        for &(a, v) in aw {
            m.set(
                a,
                Measured {
                    aw: v,
                    vdv: None,
                    measured_s: None,
                    dz: None,
                },
            );
        }
        Operation::new(name, hours, &m)
    }

    #[test]
    fn each_operation_stands_on_its_highest_axis_and_the_day_on_its_own() {
        // x: 1.4·0.3 = 0.42 beats z 0.40 for "loading"; z alone for "haul".
        let day = Day::of(vec![
            op("loading", 4.0, &[(Ax::X, 0.3), (Ax::Z, 0.4)]),
            op("haul", 4.0, &[(Ax::Z, 0.9)]),
        ])
        .expect("a day");
        let cols = columns(&day);
        assert_eq!(cols.len(), 3);
        assert_eq!(cols[0].0, "loading (x)");
        assert!((cols[0].1 - day.operations[0].axes.get(Ax::X).expect("x").points).abs() < 1e-12);
        assert_eq!(cols[1].0, "haul (z)");
        assert_eq!(cols[2].0, format!("the day ({})", day.a8_axis.name()));
        assert!((cols[2].1 - day.points).abs() < 1e-12);
        let p = panel(&day, DAY_TITLE);
        // haul: 0.9·√(4/8) = 0.636 m/s², above the action value; loading
        // 0.42·√½ = 0.30, below; the day on z √(0.283² + 0.636²) = 0.70.
        let by: Vec<(Fill, usize)> = p.bars.iter().map(|b| (b.fill, b.bars.len())).collect();
        assert_eq!(by, vec![(Fill::Plain, 1), (Fill::Action, 2)]);
        assert_eq!(p.x.names.len(), 3);
        assert_eq!(p.curves[0].points[0].1, 100.0);
        assert!((p.curves[1].points[0].1 - 529.0).abs() < 0.5);
    }
}
