//! One operation on one axis: the HSE calculator's row (SPEC §9).
//!
//! From the measured weighted r.m.s. a_w (before k) and the hours T of the
//! operation: k·a_w; the partial exposure A(8) = k·a_w·√(T / 8 h); points
//! = 100·(A(8)/0.5)², so 100 at the action value and 529 at the limit
//! ((1.15/0.5)² = 5.29); the hours that reach a value V, 8 h·(V/(k·a_w))²
//! (the T at which k·a_w·√(T/8) = V); and, where a VDV was measured over
//! T_meas, the VDV over the operation k·VDV·(T/T_meas)^¼ (ISO 2631-1 §6.3.2:
//! VDV grows with the fourth root of time for steady vibration) and the
//! hours that reach the VDV values, T_meas·(V/(k·VDV))⁴ ([`super::reach`]).

use super::reach::{REFERENCE_H, VdvHours, hours_to_reach, points};
use crate::iso2631::{A8_ACTION, A8_LIMIT, rule};
use crate::time::Axis;

/// What was measured on one axis, before k: the weighted r.m.s. a_w (m/s²),
/// the VDV (m/s^1.75) if known and the duration it was measured over (s);
/// on z, ISO 2631-5's acceleration dose Dz (m/s²) over the same duration,
/// where known.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Measured {
    pub aw: f64,
    pub vdv: Option<f64>,
    pub measured_s: Option<f64>,
    pub dz: Option<f64>,
}

/// One operation's exposure on one axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AxisExposure {
    /// k·a_w, m/s² (k from ISO 2631-1 §7.2.3: 1.4 on x and y, 1.0 on z).
    pub kaw: f64,
    /// The partial A(8) of this operation, m/s².
    pub a8: f64,
    /// HSE points of the partial A(8).
    pub points: f64,
    /// Hours of this operation that reach the action value (None when
    /// k·a_w = 0: never).
    pub hours_to_eav: Option<f64>,
    /// Hours that reach the limit value.
    pub hours_to_elv: Option<f64>,
    /// k·VDV over the operation's hours, m/s^1.75, where a VDV is known.
    pub vdv_exposure: Option<f64>,
    /// Hours of this operation that reach the VDV action and limit values,
    /// where a VDV is known (None: not judged, no number).
    pub hours_to_vdv: Option<VdvHours>,
}

impl AxisExposure {
    /// The row for `axis`, measured `m`, lasting `hours`.
    pub fn of(axis: Axis, m: &Measured, hours: f64) -> AxisExposure {
        let k = rule(axis).k_health;
        let kaw = k * m.aw;
        let a8 = partial_a8(kaw, hours);
        let vdv_exposure = match (m.vdv, m.measured_s) {
            (Some(vdv), Some(t)) if t > 0.0 => Some(k * vdv * (hours * 3600.0 / t).powf(0.25)),
            _ => None,
        };
        AxisExposure {
            kaw,
            a8,
            points: points(a8),
            hours_to_eav: hours_to_reach(A8_ACTION, kaw),
            hours_to_elv: hours_to_reach(A8_LIMIT, kaw),
            vdv_exposure,
            hours_to_vdv: VdvHours::of(k, m.vdv, m.measured_s),
        }
    }
}

/// A(8) of `hours` at k·a_w: k·a_w·√(T / 8 h).
pub fn partial_a8(kaw: f64, hours: f64) -> f64 {
    kaw * (hours / REFERENCE_H).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exposure::reach::hours_to_reach;

    fn close(a: f64, b: f64, tol: f64) {
        assert!((a - b).abs() <= tol, "{a} vs {b}");
    }

    /// The brief's example worked by hand: z 0.52 m/s² for 3.25 h.
    #[test]
    fn z_for_three_and_a_quarter_hours() {
        let m = Measured {
            aw: 0.52,
            vdv: None,
            measured_s: None,
            dz: None,
        };
        let e = AxisExposure::of(Axis::Z, &m, 3.25);
        // k = 1.0 on z: k·a_w = 0.52.
        close(e.kaw, 0.52, 1e-15);
        // √(3.25/8) = √0.40625 = 0.637377439…; 0.52 × 0.637377439 = 0.331436268…
        close(e.a8, 0.331_436_268, 1e-9);
        // 100 × (0.331436268/0.5)² = 100 × 0.43940 = 43.94 (= 100·0.52²·3.25/8/0.25
        // = 100 × 0.2704 × 0.40625 × 4 = 43.94 exactly).
        close(e.points, 43.94, 1e-9);
        // 8 × (0.5/0.52)² = 8 × 0.924556… = 7.396449…; 8 × (1.15/0.52)² = 8 × 4.890902… = 39.127219…
        close(e.hours_to_eav.unwrap(), 7.396_449_7, 1e-6);
        close(e.hours_to_elv.unwrap(), 39.127_218_9, 1e-6);
        assert_eq!(e.vdv_exposure, None);
        // No VDV measured: its hours are not judged, not 0.
        assert_eq!(e.hours_to_vdv, None);
    }

    /// x carries k = 1.4 (ISO 2631-1 §7.2.3): 0.36 × 1.4 = 0.504.
    #[test]
    fn x_is_multiplied_by_one_point_four() {
        let m = Measured {
            aw: 0.36,
            vdv: Some(5.1),
            measured_s: Some(600.0),
            dz: None,
        };
        let e = AxisExposure::of(Axis::X, &m, 3.25);
        close(e.kaw, 0.504, 1e-12);
        // 8 × (0.5/0.504)² = 8 × 0.984190… = 7.873520…
        close(e.hours_to_eav.unwrap(), 7.873_519_8, 1e-6);
        // 8 × (1.15/0.504)² = 8 × 2.281746…² = 8 × 5.206365… = 41.650920…
        close(e.hours_to_elv.unwrap(), 41.650_919_6, 1e-6);
        // VDV: 1.4 × 5.1 × (3.25 × 3600 / 600)^¼ = 7.14 × 19.5^¼ = 7.14 × 2.101399… = 15.00399…
        close(e.vdv_exposure.unwrap(), 15.004_0, 1e-4);
        // To 9.1 m/s^1.75 (Directive 2002/44/EC Art. 3): 600 s·(9.1/7.14)⁴
        // = 1583.157 s = 0.439766 h; the operation's 3.25 h pass it (15.00).
        let h = e.hours_to_vdv.unwrap();
        close(h.to_eav.unwrap(), 0.439_766, 1e-6);
        close(h.to_elv.unwrap(), 12.4719, 1e-4);
    }

    /// 0.5 m/s² for 8 h is 100 points, 1.15 is 529 (the HSE calculator).
    #[test]
    fn the_action_value_is_100_points_and_the_limit_529() {
        close(points(partial_a8(0.5, 8.0)), 100.0, 1e-12);
        close(points(partial_a8(1.15, 8.0)), 529.0, 1e-9);
        // Reaching the action value at k·a_w = 0.5 takes exactly 8 h.
        close(hours_to_reach(A8_ACTION, 0.5).unwrap(), 8.0, 1e-12);
    }

    #[test]
    fn no_vibration_never_reaches_a_value() {
        let m = Measured {
            aw: 0.0,
            vdv: None,
            measured_s: None,
            dz: None,
        };
        let e = AxisExposure::of(Axis::Y, &m, 4.0);
        assert_eq!((e.a8, e.points), (0.0, 0.0));
        assert_eq!((e.hours_to_eav, e.hours_to_elv), (None, None));
    }

    #[test]
    fn a_vdv_measured_over_no_time_gives_no_exposure_vdv() {
        // VDV·(T/t)^¼ with t = 0 would be infinite: no value, not inf.
        let m = |t: f64| Measured {
            aw: 0.5,
            vdv: Some(5.0),
            measured_s: Some(t),
            dz: None,
        };
        assert_eq!(AxisExposure::of(Axis::Z, &m(0.0), 2.0).vdv_exposure, None);
        // Measured for the whole operation, the VDV is its own.
        let e = AxisExposure::of(Axis::Z, &m(7200.0), 2.0).vdv_exposure;
        close(e.unwrap(), 5.0, 1e-12);
    }
}
