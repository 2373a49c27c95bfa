//! The caps a day file's numbers are held to, as a record's cells are held
//! to [`MAX_ACC`]: past them a value is a unit slip, and it would carry the
//! day's sums out of what a float holds (`aw_m_s2 = 1e308` squared is
//! `inf`, and `inf` points would reach the sheet with exit status 0).
//!
//! - a_w: [`MAX_ACC`], 1e4 m/s² (≈ 1000 g), a record cell's own cap;
//! - VDV and ISO 2631-5's dose Dz: 1e6 (m/s^1.75, m/s²): a record within
//!   the caps (10^8 samples, none over 1e4 m/s²) gives at most
//!   1e4·(10^6 s)^¼ ≈ 3.2e5 m/s^1.75 at 100 Hz, and Dz ≤ 1.07·1e4·(10^8)^⅙
//!   ≈ 2.3e5 m/s² for peaks at the cap; with these, VDV⁴ and Dz⁶ stay
//!   far inside a float;
//! - `measured_s`: 2 s to 1e6 s, a record's own least length
//!   ([`MIN_RECORD_S`]) to 10^8 samples at 100 Hz: a shorter one would
//!   scale a VDV by (T/T_meas)^¼ past any float (T_meas = 1e-300 s);
//! - a record's `fs`: over 0 and at most [`MAX_FS`] (1e6 Hz), as `--fs`.

use crate::iso2631::MIN_RECORD_S;
use crate::time::{MAX_ACC, MAX_FS};

/// Largest measured a_w, m/s² (before k).
pub const MAX_AW: f64 = MAX_ACC;

/// Largest measured VDV, m/s^1.75 (before k).
pub const MAX_VDV: f64 = 1e6;

/// Largest ISO 2631-5 acceleration dose Dz, m/s².
pub const MAX_DZ: f64 = 1e6;

/// Shortest and longest `measured_s`, s.
pub const MIN_MEASURED_S: f64 = MIN_RECORD_S;
pub const MAX_MEASURED_S: f64 = 1e6;

/// Highest sampling rate a record operation may give, Hz.
pub const MAX_RECORD_FS: f64 = MAX_FS;

/// The cap of a day file's field (`aw_m_s2`, `vdv_m_s175`, `dz_m_s2`)
/// and its unit.
pub fn cap(field: &str) -> (f64, &'static str) {
    match field {
        "vdv_m_s175" => (MAX_VDV, "m/s^1.75"),
        "dz_m_s2" => (MAX_DZ, "m/s²"),
        _ => (MAX_AW, "m/s²"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The caps keep the day's sums finite: the worst operation at the caps
    /// over 24 h, measured over the shortest time, gives finite A(8),
    /// points, VDV⁴ and Dz⁶·t_d/t_m.
    #[test]
    fn the_caps_keep_every_sum_finite() {
        let (h, t) = (24.0_f64, MIN_MEASURED_S);
        let a8 = 1.4 * MAX_AW * (h / 8.0).sqrt();
        let points = 100.0 * (a8 / 0.5).powi(2);
        let vdv = 1.4 * MAX_VDV * (h * 3600.0 / t).powf(0.25);
        let vdv4_day = 1000.0 * vdv.powi(4);
        let dzd6 = 1000.0 * MAX_DZ.powi(6) * h * 3600.0 / t;
        for v in [a8, points, vdv4_day, dzd6] {
            assert!(v.is_finite() && v < 1e300, "{v}");
        }
    }
}
