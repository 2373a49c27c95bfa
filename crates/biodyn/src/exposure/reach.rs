//! The hours of a vibration that reach the Directive's values, as the HSE
//! calculator gives them (SPEC §9, §12; Directive 2002/44/EC Art. 3): the
//! one place `biodyn day` (per operation and axis) and `biodyn assess`
//! (per axis of a record or signal) take them from.
//!
//! - By A(8): k·a_w·√(T/8 h) = V at T = 8 h·(V/(k·a_w))².
//! - By VDV: VDV grows as the fourth root of time for steady vibration
//!   (ISO 2631-1 §6.3.2), k·VDV_m·(T/T_m)^¼ = V at T = T_m·(V/(k·VDV_m))⁴,
//!   VDV_m measured (before k) over T_m.

use crate::iso2631::{A8_ACTION, A8_LIMIT, AxisResult, VDV_ACTION, VDV_LIMIT};

/// The reference duration of A(8), hours.
pub const REFERENCE_H: f64 = 8.0;

/// HSE points of an A(8): 100·(A(8)/0.5)², so 100 at the action value and
/// 529 at the limit ((1.15/0.5)² = 5.29).
pub fn points(a8: f64) -> f64 {
    100.0 * (a8 / A8_ACTION).powi(2)
}

/// Hours at k·a_w that reach the value `v`: 8 h·(v/(k·a_w))²; None when
/// k·a_w is 0 (the value is never reached).
pub fn hours_to_reach(v: f64, kaw: f64) -> Option<f64> {
    (kaw > 0.0).then(|| REFERENCE_H * (v / kaw).powi(2))
}

/// Hours that bring k·VDV_m, measured over `measured_s`, to the value `v`:
/// T_m·(v/(k·VDV_m))⁴ in hours; None when k·VDV_m is 0 (never).
pub fn hours_to_reach_vdv(v: f64, kvdv: f64, measured_s: f64) -> Option<f64> {
    (kvdv > 0.0).then(|| measured_s / 3600.0 * (v / kvdv).powi(4))
}

/// The hours to the VDV action and limit values (9.1 and 21 m/s^1.75);
/// each None when k·VDV is 0 (never reached).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VdvHours {
    pub to_eav: Option<f64>,
    pub to_elv: Option<f64>,
}

impl VdvHours {
    /// Of k·VDV_m, VDV_m (before k) measured over `measured_s`; None when
    /// the VDV or its duration is not known (or the duration is not over
    /// 0): not judged, never a number.
    pub fn of(k: f64, vdv: Option<f64>, measured_s: Option<f64>) -> Option<VdvHours> {
        let (vdv, t) = (vdv?, measured_s?);
        (t > 0.0).then(|| VdvHours {
            to_eav: hours_to_reach_vdv(VDV_ACTION, k * vdv, t),
            to_elv: hours_to_reach_vdv(VDV_LIMIT, k * vdv, t),
        })
    }
}

/// One axis of a record or signal as the HSE calculator reads it: the
/// points of its A(8) over the exposure and the hours to each value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AxisReach {
    /// 100·(A(8)/0.5)² of the A(8) over the exposure.
    pub points: f64,
    pub hours_to_eav: Option<f64>,
    pub hours_to_elv: Option<f64>,
    /// The VDV's hours: a record's VDV is always known.
    pub vdv: VdvHours,
}

impl AxisReach {
    /// From an assessment's axis: T_m is the record's or signal's length,
    /// VDV_m its VDV before k.
    pub fn of(r: &AxisResult) -> AxisReach {
        let k = r.rule.k_health;
        let kaw = k * r.metrics.aw;
        AxisReach {
            points: points(r.a8),
            hours_to_eav: hours_to_reach(A8_ACTION, kaw),
            hours_to_elv: hours_to_reach(A8_LIMIT, kaw),
            // A record of no length has no VDV rate: never, not infinity.
            vdv: VdvHours::of(k, Some(r.metrics.vdv), Some(r.metrics.duration_s)).unwrap_or(
                VdvHours {
                    to_eav: None,
                    to_elv: None,
                },
            ),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::iso2631::Metrics;
    use crate::time::Axis;

    fn close(a: f64, b: f64, tol: f64) {
        assert!((a - b).abs() <= tol, "{a} vs {b}");
    }

    fn metrics(aw: f64, vdv: f64) -> Metrics {
        Metrics {
            aw,
            peak: 0.0,
            crest: 0.0,
            mtvv: 0.0,
            vdv,
            duration_s: 60.0,
        }
    }

    /// examples/day.toml's haul road on x: k·VDV = 1.4·5.1 = 7.14 over
    /// 600 s. To 9.1 (Directive 2002/44/EC Art. 3): 600 s·(9.1/7.14)⁴ =
    /// 600·1.274510⁴ = 600·2.638595 = 1583.157 s = 0.439766 h; to 21:
    /// 600·(21/7.14)⁴ = 600·2.941176⁴ = 600·74.8315 = 44898.9 s = 12.4719 h.
    #[test]
    fn hours_to_the_vdv_values_grow_as_the_fourth_power() {
        let h = VdvHours::of(1.4, Some(5.1), Some(600.0)).unwrap();
        close(
            h.to_eav.unwrap(),
            600.0 * (9.1f64 / 7.14).powi(4) / 3600.0,
            1e-12,
        );
        close(h.to_eav.unwrap(), 0.439_766, 1e-6);
        close(h.to_elv.unwrap(), 12.4719, 1e-4);
        // Exposed that long, the VDV is the value: k·VDV·(T/T_m)^¼ = 9.1.
        let t = h.to_eav.unwrap() * 3600.0;
        close(7.14 * (t / 600.0).powf(0.25), 9.1, 1e-12);
    }

    #[test]
    fn no_vdv_is_not_judged_and_zero_never_reaches() {
        assert_eq!(VdvHours::of(1.0, None, Some(600.0)), None);
        assert_eq!(VdvHours::of(1.0, Some(3.0), None), None);
        assert_eq!(VdvHours::of(1.0, Some(3.0), Some(0.0)), None);
        assert_eq!(
            VdvHours::of(1.0, Some(0.0), Some(600.0)),
            Some(VdvHours {
                to_eav: None,
                to_elv: None
            })
        );
    }

    /// A record's axis: z (k 1) a_w 0.776, VDV 5.05 over 60 s, 8 h: A(8)
    /// 0.776 → 100·(0.776/0.5)² = 240.8704 points; 8·(0.5/0.776)² =
    /// 3.321288 h; to VDV 21: 60 s·(21/5.05)⁴/3600 = 60·299.0279/3600 =
    /// 4.983798 h.
    #[test]
    fn an_assessed_axis_reads_as_the_calculator() {
        let r = AxisResult::new(Axis::Z, metrics(0.776, 5.05), 8.0);
        let h = AxisReach::of(&r);
        close(h.points, 240.8704, 1e-9);
        close(h.hours_to_eav.unwrap(), 3.321_288, 1e-6);
        close(
            h.hours_to_elv.unwrap(),
            8.0 * (1.15f64 / 0.776).powi(2),
            1e-12,
        );
        close(
            h.vdv.to_elv.unwrap(),
            60.0 * (21.0f64 / 5.05).powi(4) / 3600.0,
            1e-12,
        );
        close(h.vdv.to_elv.unwrap(), 4.983_798, 1e-6);
        // x carries k = 1.4 (ISO 2631-1 §7.2.3) in both.
        let x = AxisReach::of(&AxisResult::new(Axis::X, metrics(0.5, 2.0), 2.0));
        close(x.hours_to_eav.unwrap(), 8.0 * (0.5f64 / 0.7).powi(2), 1e-12);
        close(x.vdv.to_eav.unwrap(), (9.1f64 / 2.8).powi(4) / 60.0, 1e-12);
        // The points are of the A(8) over the exposure: 0.7·√(2/8) = 0.35 → 49.
        close(x.points, 49.0, 1e-9);
    }
}
