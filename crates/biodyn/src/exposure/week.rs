//! A week of days (UK SI 2005/1093 Schedule 2, Part 2): per axis
//! A(8)week = √(⅕ Σ_days A(8)_day²); the VDV stays a day's, so the week
//! names the days whose VDV passes a value.

use super::day::{Day, DayVdv};
use super::reach::points;
use crate::iso2631::{A8_ACTION, A8_LIMIT, Verdict};
use crate::time::{Axis, PerAxis};

/// Most days a week holds.
pub const MAX_DAYS: usize = 7;

/// A week of days (UK SI 2005/1093 Schedule 2, Part 2): per axis
/// A(8)week = √(⅕ Σ_days A(8)_day²), the five-day week's average energy;
/// the highest axis named. The VDV has no weekly value (the Directive's
/// VDV is a day's): each day's stands, so the week names the days whose
/// VDV passes a value.
#[derive(Debug, Clone, PartialEq)]
pub struct Week {
    pub axes: PerAxis<f64>,
    pub a8: f64,
    pub a8_axis: Axis,
    /// Points of the weekly A(8) (100 at the action value).
    pub points: f64,
    pub eu_a8: Verdict,
    /// Each day's VDV verdict, in the order of the days.
    pub days_vdv: Vec<DayVdv>,
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
            days_vdv: days.iter().map(|d| d.vdv_verdict).collect(),
        })
    }

    /// The days (0-based) whose VDV passes the action value, exactly or by
    /// its known part alone (then the day's VDV passes it too), with it.
    pub fn vdv_passing(&self) -> Vec<(usize, DayVdv)> {
        self.days_vdv
            .iter()
            .enumerate()
            .filter(|(_, v)| {
                v.value()
                    .is_some_and(|(_, _, at)| at != Verdict::BelowAction)
            })
            .map(|(i, v)| (i, *v))
            .collect()
    }

    /// The days whose VDV verdict is open (some operation lacks a VDV and
    /// the known part is below the limit value), or not known at all.
    pub fn vdv_open(&self) -> Vec<usize> {
        self.days_vdv
            .iter()
            .enumerate()
            .filter(|(_, v)| v.decided().is_none())
            .map(|(i, _)| i)
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exposure::{Measured, Operation};

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
        // No VDVs: every day's is open, none passes a value.
        assert_eq!(w.vdv_open(), vec![0, 1, 2]);
        assert!(w.vdv_passing().is_empty());
    }

    /// The week names the days whose VDV passes a value, exactly or by the
    /// known part: 1.0·10 over the whole operation is 10 > 9.1; 25 > 21
    /// with an operation lacking one; 5 < 9.1.
    #[test]
    fn a_week_names_the_days_whose_vdv_passes_a_value() {
        use Axis::*;
        let one = |vdv: f64, lacking: bool| {
            let mut ops = vec![Operation::new(
                "a",
                600.0 / 3600.0,
                &axes(&[(Z, 0.5, Some(vdv))]),
            )];
            if lacking {
                ops.push(Operation::new("b", 1.0, &axes(&[(Z, 0.5, None)])));
            }
            Day::of(ops).unwrap()
        };
        let w = Week::of(&[
            one(10.0, false),
            one(5.0, false),
            one(25.0, true),
            one(12.0, true),
        ])
        .unwrap();
        let passing: Vec<(usize, Option<Verdict>)> = w
            .vdv_passing()
            .iter()
            .map(|(i, v)| (*i, v.decided()))
            .collect();
        assert_eq!(
            passing,
            vec![
                (0, Some(Verdict::AboveAction)),
                (2, Some(Verdict::AboveLimit)),
                (3, None)
            ]
        );
        // Day 4 is at least above the action value; whether above the limit is open.
        assert_eq!(w.vdv_open(), vec![3]);
    }
}
