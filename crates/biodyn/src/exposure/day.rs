//! The day: every operation summed per axis, then the Directive's highest
//! axis (SPEC §9; Directive 2002/44/EC Annex B; UK SI 2005/1093 Schedule 2).
//!
//! Per axis, A(8) = √(Σ A_i(8)²) = √((1/8 h) Σ (k·a_wi)² T_i), so the
//! points add (points ∝ A(8)²); VDV = (Σ VDV_i⁴)^¼, known only when every
//! operation on the axis has one. The day's exposure is the highest axis,
//! ties to the first of x, y, z ([`PerAxis::highest`]).

use super::operation::{AxisExposure, Measured, points};
use super::spine::DaySpine;
use crate::iso2631::{A8_ACTION, A8_LIMIT, VDV_ACTION, VDV_LIMIT, Verdict};
use crate::time::{Axis, PerAxis};

/// One operation, evaluated on each axis it has.
#[derive(Debug, Clone, PartialEq)]
pub struct Operation {
    pub name: String,
    pub hours: f64,
    pub axes: PerAxis<AxisExposure>,
}

impl Operation {
    /// Evaluates `measured` (before k) over `hours`.
    pub fn new(name: &str, hours: f64, measured: &PerAxis<Measured>) -> Operation {
        Operation {
            name: name.to_string(),
            hours,
            axes: measured.map(|a, m| AxisExposure::of(a, m, hours)),
        }
    }
}

/// One axis over the day.
#[derive(Debug, Clone, PartialEq)]
pub struct AxisDay {
    /// √(Σ partial A(8)²), m/s².
    pub a8: f64,
    /// Σ points.
    pub points: f64,
    /// (Σ VDV_i⁴)^¼, m/s^1.75, when every operation on the axis has a VDV.
    pub vdv: Option<f64>,
    /// The operations on this axis without a VDV (indices into the day's
    /// operations); empty when `vdv` is known.
    pub lacking_vdv: Vec<usize>,
}

/// The day's exposure: the highest axis, named, with the EU verdicts.
#[derive(Debug, Clone, PartialEq)]
pub struct Day {
    pub operations: Vec<Operation>,
    pub axes: PerAxis<AxisDay>,
    /// The highest axis's A(8) and that axis.
    pub a8: f64,
    pub a8_axis: Axis,
    /// The points of the highest axis (the day's points).
    pub points: f64,
    pub eu_a8: Verdict,
    /// The highest axis's VDV, when every axis with vibration has a day VDV:
    /// a VDV missing on one axis could be the highest, so none is judged.
    pub vdv: Option<(Axis, f64)>,
    pub eu_vdv: Option<Verdict>,
    /// ISO 2631-5's daily dose and risk, when the day file names a person.
    pub spine: Option<DaySpine>,
}

impl Day {
    /// Sums `operations`. None when no operation has any axis.
    pub fn of(operations: Vec<Operation>) -> Option<Day> {
        let mut axes: PerAxis<AxisDay> = PerAxis::default();
        for axis in Axis::ALL {
            let on: Vec<(usize, &AxisExposure)> = operations
                .iter()
                .enumerate()
                .filter_map(|(i, o)| o.axes.get(axis).map(|e| (i, e)))
                .collect();
            if on.is_empty() {
                continue;
            }
            let a8 = on.iter().map(|(_, e)| e.a8 * e.a8).sum::<f64>().sqrt();
            let lacking_vdv: Vec<usize> = on
                .iter()
                .filter(|(_, e)| e.vdv_exposure.is_none())
                .map(|(i, _)| *i)
                .collect();
            let vdv = lacking_vdv.is_empty().then(|| {
                on.iter()
                    .filter_map(|(_, e)| e.vdv_exposure)
                    .map(|v| v.powi(4))
                    .sum::<f64>()
                    .powf(0.25)
            });
            axes.set(
                axis,
                AxisDay {
                    a8,
                    points: on.iter().map(|(_, e)| e.points).sum(),
                    vdv,
                    lacking_vdv,
                },
            );
        }
        let (a8_axis, a8) = axes.map(|_, d| d.a8).highest()?;
        let points = axes.get(a8_axis).map_or(0.0, |d| d.points);
        let vdvs: Option<Vec<(Axis, f64)>> =
            axes.iter().map(|(a, d)| d.vdv.map(|v| (a, v))).collect();
        let vdv = vdvs.and_then(|v| {
            let mut p = PerAxis::default();
            for (a, x) in v {
                p.set(a, x);
            }
            p.highest()
        });
        Some(Day {
            operations,
            axes,
            a8,
            a8_axis,
            points,
            eu_a8: Verdict::judge(a8, A8_ACTION, A8_LIMIT),
            eu_vdv: vdv.map(|(_, v)| Verdict::judge(v, VDV_ACTION, VDV_LIMIT)),
            vdv,
            spine: None,
        })
    }
}

/// Most days a week holds.
pub const MAX_DAYS: usize = 7;

/// A week of days (UK SI 2005/1093 Schedule 2, Part 2): per axis
/// A(8)week = √(⅕ Σ_days A(8)_day²), the five-day week's average energy;
/// the highest axis named.
#[derive(Debug, Clone, PartialEq)]
pub struct Week {
    pub axes: PerAxis<f64>,
    pub a8: f64,
    pub a8_axis: Axis,
    /// Points of the weekly A(8) (100 at the action value).
    pub points: f64,
    pub eu_a8: Verdict,
}

impl Week {
    /// The week of `days` (1 to [`MAX_DAYS`]); None outside that.
    pub fn of(days: &[Day]) -> Option<Week> {
        if days.is_empty() || days.len() > MAX_DAYS {
            return None;
        }
        let mut axes = PerAxis::default();
        for axis in Axis::ALL {
            let on: Vec<f64> = days
                .iter()
                .filter_map(|d| d.axes.get(axis).map(|a| a.a8))
                .collect();
            if !on.is_empty() {
                axes.set(axis, (on.iter().map(|a| a * a).sum::<f64>() / 5.0).sqrt());
            }
        }
        let (a8_axis, a8) = axes.highest()?;
        Some(Week {
            axes,
            a8,
            a8_axis,
            points: points(a8),
            eu_a8: Verdict::judge(a8, A8_ACTION, A8_LIMIT),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64, tol: f64) {
        assert!((a - b).abs() <= tol, "{a} vs {b}");
    }

    fn axes(v: &[(Axis, f64, Option<f64>)]) -> PerAxis<Measured> {
        let mut p = PerAxis::default();
        for &(a, aw, vdv) in v {
            p.set(
                a,
                Measured {
                    aw,
                    vdv,
                    measured_s: vdv.map(|_| 600.0),
                    dz: None,
                },
            );
        }
        p
    }

    /// Haul road 3.25 h (x 0.36, y 0.21, z 0.52) and loading 2.5 h (x 0.30,
    /// z 0.80): worked by hand.
    fn two_operations() -> Day {
        use Axis::*;
        Day::of(vec![
            Operation::new(
                "haul road",
                3.25,
                &axes(&[(X, 0.36, Some(5.1)), (Y, 0.21, None), (Z, 0.52, Some(7.0))]),
            ),
            Operation::new(
                "loading",
                2.5,
                &axes(&[(X, 0.30, None), (Z, 0.80, Some(9.0))]),
            ),
        ])
        .unwrap()
    }

    #[test]
    fn partials_add_in_quadrature_and_points_add() {
        let d = two_operations();
        let z = d.axes.get(Axis::Z).unwrap();
        // z: 0.52²·3.25/8 + 0.80²·2.5/8 = 0.10985 + 0.2 = 0.30985; √ = 0.556642…
        close(z.a8, 0.309_85f64.sqrt(), 1e-12);
        // points: 43.94 + 100·0.2/0.25 = 43.94 + 80 = 123.94
        close(z.points, 123.94, 1e-9);
        let x = d.axes.get(Axis::X).unwrap();
        // x: (0.504²·3.25 + 0.42²·2.5)/8 = (0.825552 + 0.441)/8 = 0.158319; √ = 0.397893…
        close(x.a8, 0.158_319f64.sqrt(), 1e-12);
        // y: 0.294²·3.25/8 = 0.0351146…; √ = 0.187389…
        close(
            d.axes.get(Axis::Y).unwrap().a8,
            (0.294f64.powi(2) * 3.25 / 8.0).sqrt(),
            1e-12,
        );
        // The highest is z, 0.5566 > 0.5: above the action value.
        assert_eq!(d.a8_axis, Axis::Z);
        close(d.a8, 0.309_85f64.sqrt(), 1e-12);
        close(d.points, 123.94, 1e-9);
        assert_eq!(d.eu_a8, Verdict::AboveAction);
    }

    #[test]
    fn vdv_is_known_only_where_every_operation_has_one() {
        let d = two_operations();
        // z: 7.0·19.5^¼ = 14.7098, 9.0·15^¼ = 17.7119; (14.7098⁴ + 17.7119⁴)^¼ = 19.5217
        let z1 = 7.0 * 19.5f64.powf(0.25);
        let z2 = 9.0 * 15f64.powf(0.25);
        let z = d.axes.get(Axis::Z).unwrap();
        close(z.vdv.unwrap(), (z1.powi(4) + z2.powi(4)).powf(0.25), 1e-9);
        close(z.vdv.unwrap(), 19.5217, 1e-3);
        // x lacks loading's (operation 1), y lacks haul road's (operation 0).
        assert_eq!(d.axes.get(Axis::X).unwrap().lacking_vdv, vec![1]);
        assert_eq!(d.axes.get(Axis::Y).unwrap().lacking_vdv, vec![0]);
        // So no day VDV is judged: x or y might be the highest.
        assert_eq!((d.vdv, d.eu_vdv), (None, None));
    }

    #[test]
    fn the_day_vdv_is_the_highest_axis_when_all_are_known() {
        use Axis::*;
        // One operation of 600 s measured for 600 s: VDV_exp = k·VDV.
        // x 1.4·16 = 22.4 > z 20: x is highest, above the limit 21.
        let d = Day::of(vec![Operation::new(
            "shocks",
            600.0 / 3600.0,
            &axes(&[(X, 0.1, Some(16.0)), (Z, 0.1, Some(20.0))]),
        )])
        .unwrap();
        let (axis, v) = d.vdv.unwrap();
        assert_eq!(axis, X);
        close(v, 22.4, 1e-12);
        assert_eq!(d.eu_vdv, Some(Verdict::AboveLimit));
    }

    #[test]
    fn ties_go_to_x_and_k_decides_between_horizontal_and_vertical() {
        use Axis::*;
        // x 0.5/1.4 × 1.4 = 0.5 = z 0.5: a tie, x first; both 8 h → 100 points.
        let d = Day::of(vec![Operation::new(
            "tie",
            8.0,
            &axes(&[(X, 0.5 / 1.4, None), (Z, 0.5, None)]),
        )])
        .unwrap();
        assert_eq!(d.a8_axis, X);
        close(d.points, 100.0, 1e-9);
        // 0.5 is not over the action value (the Directive acts when exceeded).
        assert_eq!(d.eu_a8, Verdict::BelowAction);
        assert!(Day::of(vec![]).is_none());
    }

    #[test]
    fn a_week_averages_energy_over_five_days() {
        use Axis::*;
        // Three days at z 1.0 m/s² for 8 h: A(8)week = √(3·1²/5) = √0.6 = 0.774597…
        let day = || {
            Day::of(vec![Operation::new(
                "d",
                8.0,
                &axes(&[(Z, 1.0, None), (Y, 0.1, None)]),
            )])
            .unwrap()
        };
        let w = Week::of(&[day(), day(), day()]).unwrap();
        assert_eq!(w.a8_axis, Z);
        close(w.a8, 0.6f64.sqrt(), 1e-12);
        // y: √(3·0.14²/5) = 0.14·√0.6
        close(*w.axes.get(Y).unwrap(), 0.14 * 0.6f64.sqrt(), 1e-12);
        // points 100·0.6/0.25 = 240
        close(w.points, 240.0, 1e-9);
        assert_eq!(w.eu_a8, Verdict::AboveAction);
        assert!(Week::of(&[]).is_none());
        assert!(Week::of(&vec![day(); 8]).is_none());
        // Seven days is a week still (the most there are): the bound is inclusive.
        let seven = Week::of(&vec![day(); MAX_DAYS]).expect("seven days");
        close(seven.a8, (7.0f64 / 5.0).sqrt() * day().a8, 1e-12);
    }
}
