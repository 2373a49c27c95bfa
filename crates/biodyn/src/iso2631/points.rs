//! Comfort at the other points of a seated person (ISO 2631-1:1997 §8.2.2,
//! §8.2.3, Table 1): the backrest, the feet and the seat's rotations, each
//! channel weighted and multiplied by its factor k, as [`super::AXES`] is
//! the table for the seat surface's translations.
//!
//! Per point, its vibration total value a_v = √Σ(k·a_w)² over its channels
//! (§8.2.3, equation (9)); over the points, the overall vibration total
//! value, the root-sum-of-squares of the points' totals, the seat's
//! translational one among them (§8.2.3: where comfort is affected at
//! several points, seat, backrest and feet). Squares add, so it is also
//! √Σ(k·a_w)² over every channel measured. Annex C's words judge it.

use super::metrics::Accumulator;
use super::verdict::comfort;
use super::weighting::{Weighting, WeightingFilter};
use crate::time::{Axis, Frame, PerPoint, Point, PointAxis, PointRow, Row};

/// Wc (backrest, x) and We (rotations), ISO 2631-1 Table 1.
const WC: Weighting = Weighting::Wc;
const WE: Weighting = Weighting::We;

/// One channel's row of the table.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointRule {
    pub channel: PointAxis,
    pub weighting: Weighting,
    /// The comfort factor k (for rotations in m/rad: k·a_w is then m/s²).
    pub k: f64,
}

const fn rule(point: Point, axis: Axis, weighting: Weighting, k: f64) -> PointRule {
    PointRule {
        channel: PointAxis { point, axis },
        weighting,
        k,
    }
}

/// ISO 2631-1:1997 Table 1 and §8.2.2, seated, comfort: backrest x Wc 0.8,
/// y Wd 0.5, z Wd 0.4; feet x, y, z Wk 0.25, 0.25, 0.4; the seat's
/// rotations rx, ry, rz We 0.63, 0.4, 0.2 m/rad. In [`PointAxis::ALL`] order.
pub const POINTS: [PointRule; 9] = [
    rule(Point::Backrest, Axis::X, WC, 0.8),
    rule(Point::Backrest, Axis::Y, Weighting::Wd, 0.5),
    rule(Point::Backrest, Axis::Z, Weighting::Wd, 0.4),
    rule(Point::Feet, Axis::X, Weighting::Wk, 0.25),
    rule(Point::Feet, Axis::Y, Weighting::Wk, 0.25),
    rule(Point::Feet, Axis::Z, Weighting::Wk, 0.4),
    rule(Point::Rotation, Axis::X, WE, 0.63),
    rule(Point::Rotation, Axis::Y, WE, 0.4),
    rule(Point::Rotation, Axis::Z, WE, 0.2),
];

/// The rule for `channel`.
pub fn point_rule(channel: PointAxis) -> &'static PointRule {
    &POINTS[channel.slot()]
}

/// One channel of a point: a_w before k.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointAxisComfort {
    pub rule: PointRule,
    /// Weighted r.m.s., m/s² (rad/s² for a rotation).
    pub aw: f64,
}

impl PointAxisComfort {
    /// k·a_w, m/s².
    pub fn weighted(&self) -> f64 {
        self.rule.k * self.aw
    }
}

/// One point: its channels and its vibration total value.
#[derive(Debug, Clone, PartialEq)]
pub struct PointComfort {
    pub point: Point,
    pub axes: Vec<PointAxisComfort>,
    /// a_v = √Σ(k·a_w)², m/s².
    pub total: f64,
}

/// Comfort at every point a record has.
#[derive(Debug, Clone, PartialEq)]
pub struct PointsComfort {
    /// The other points, in [`Point::ALL`] order, each with a channel.
    pub points: Vec<PointComfort>,
    /// The seat surface's translational total (the seat vector sum), m/s².
    pub seat: f64,
    /// √(seat² + Σ point totals²), m/s².
    pub overall: f64,
    /// Annex C's words for the overall value.
    pub words: Vec<&'static str>,
}

/// √Σv², the vibration total value of factored values.
pub fn total_value(values: impl IntoIterator<Item = f64>) -> f64 {
    values.into_iter().map(|v| v * v).sum::<f64>().sqrt()
}

impl PointsComfort {
    /// The points' totals and the overall value, from each channel's a_w
    /// and the seat's translational total.
    pub fn of(channels: &[(PointAxis, f64)], seat: f64) -> PointsComfort {
        let points: Vec<PointComfort> = Point::ALL
            .into_iter()
            .filter_map(|point| {
                let axes: Vec<PointAxisComfort> = channels
                    .iter()
                    .filter(|(c, _)| c.point == point)
                    .map(|&(c, aw)| PointAxisComfort {
                        rule: *point_rule(c),
                        aw,
                    })
                    .collect();
                let total = total_value(axes.iter().map(PointAxisComfort::weighted));
                (!axes.is_empty()).then_some(PointComfort { point, axes, total })
            })
            .collect();
        let overall = total_value(std::iter::once(seat).chain(points.iter().map(|p| p.total)));
        PointsComfort {
            points,
            seat,
            overall,
            words: comfort(overall),
        }
    }
}

/// What an assessment reads at each instant: the seat's row and, where the
/// record has them, the other points' channels. A seat row alone carries
/// none, so the seat-only stream is what it was.
pub trait Sample {
    fn seat(&self) -> Row;
    /// Pushes the other points' channels onto `out` (a seat row: nothing).
    fn keep_points(&self, out: &mut Vec<PointRow>);
}

impl Sample for Row {
    #[inline(always)]
    fn seat(&self) -> Row {
        *self
    }

    #[inline(always)]
    fn keep_points(&self, _: &mut Vec<PointRow>) {}
}

impl Sample for Frame {
    #[inline(always)]
    fn seat(&self) -> Row {
        self.0
    }

    #[inline(always)]
    fn keep_points(&self, out: &mut Vec<PointRow>) {
        out.push(self.1);
    }
}

/// The weighted r.m.s. of each channel at the other points, streaming:
/// each present channel through its weighting into its accumulator.
#[derive(Debug, Clone)]
pub struct PointsAccumulator {
    lanes: Vec<(PointAxis, WeightingFilter, Accumulator)>,
}

impl PointsAccumulator {
    /// For the channels `present` at `fs` Hz.
    pub fn new(present: &PerPoint<()>, fs: f64) -> PointsAccumulator {
        PointsAccumulator {
            lanes: present
                .channels()
                .map(|c| {
                    let w = point_rule(c).weighting.digital(fs);
                    (c, w, Accumulator::new(fs))
                })
                .collect(),
        }
    }

    /// No channel to weigh.
    pub fn is_empty(&self) -> bool {
        self.lanes.is_empty()
    }

    #[inline(always)]
    pub fn push(&mut self, row: &PointRow) {
        for (c, f, acc) in &mut self.lanes {
            acc.push(f.process(row[c.slot()]));
        }
    }

    /// Every row of a block, in order (nothing without a channel).
    #[inline(always)]
    pub fn push_all(&mut self, rows: &[PointRow]) {
        if !self.is_empty() {
            for r in rows {
                self.push(r);
            }
        }
    }

    /// Each channel's a_w, in [`PointAxis::ALL`] order.
    pub fn aw(&self) -> Vec<(PointAxis, f64)> {
        self.lanes
            .iter()
            .map(|(c, _, acc)| (*c, acc.metrics().aw))
            .collect()
    }

    /// Comfort at every point, beside the seat's translational total
    /// `seat`; None without a channel.
    pub fn results(&self, seat: f64) -> Option<PointsComfort> {
        (!self.is_empty()).then(|| PointsComfort::of(&self.aw(), seat))
    }
}

#[cfg(test)]
mod tests;
