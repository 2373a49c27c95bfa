//! What ISO 2631-1 does with each axis at the seat surface, seated
//! (§7.2.2, §8.2.3, Table 1): the weighting, the health factor k (applied
//! before the Directive's highest-axis rule) and the comfort factor.

use super::weighting::Weighting;
use crate::time::Axis;

/// One axis's row of the table.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AxisRule {
    pub axis: Axis,
    pub weighting: Weighting,
    /// Health: k·a_w is compared across axes (ISO 2631-1 §7.2.3).
    pub k_health: f64,
    /// Comfort, seat surface (ISO 2631-1 §8.2.3): the vector sum's factors.
    pub k_comfort: f64,
}

/// Seated, seat surface: x and y Wd with k 1.4 for health, z Wk with 1.0;
/// comfort factors all 1.0.
pub const AXES: [AxisRule; 3] = [
    AxisRule {
        axis: Axis::X,
        weighting: Weighting::Wd,
        k_health: 1.4,
        k_comfort: 1.0,
    },
    AxisRule {
        axis: Axis::Y,
        weighting: Weighting::Wd,
        k_health: 1.4,
        k_comfort: 1.0,
    },
    AxisRule {
        axis: Axis::Z,
        weighting: Weighting::Wk,
        k_health: 1.0,
        k_comfort: 1.0,
    },
];

/// The rule for `axis`.
pub fn rule(axis: Axis) -> &'static AxisRule {
    &AXES[axis.index()]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// ISO 2631-1:1997 §7.2.3 and Table 1: Wd/1.4 on x and y, Wk/1.0 on z.
    #[test]
    fn the_table_is_the_standards() {
        for (r, a) in AXES.iter().zip(Axis::ALL) {
            assert_eq!(r.axis, a);
            assert_eq!(rule(a), r);
            assert_eq!(r.k_comfort, 1.0);
        }
        assert_eq!((AXES[0].weighting, AXES[0].k_health), (Weighting::Wd, 1.4));
        assert_eq!((AXES[1].weighting, AXES[1].k_health), (Weighting::Wd, 1.4));
        assert_eq!((AXES[2].weighting, AXES[2].k_health), (Weighting::Wk, 1.0));
    }
}
