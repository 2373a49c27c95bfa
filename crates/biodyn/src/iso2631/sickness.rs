//! Motion sickness, ISO 2631-1:1997 §9 and Annex D (SPEC §10): the z
//! acceleration weighted with Wf (0.1–0.5 Hz), the motion sickness dose
//! value MSDV_z = (∫ a_wf² dt)^½ (m/s^1.5, Formula D.1), and for an exposure
//! of T0 of the same motion MSDV = a_wf·T0^½ (Formula D.2). About K_m·MSDV
//! per cent of unadapted adults, men and women, may vomit (D.3), K_m = 1/3.
//!
//! That estimate is linear in MSDV without end, but Annex D bases it on
//! exposures of up to about 6 h and on percentages up to about 70 %: past
//! [`VOMIT_PCT_MAX`] the number is kept (JSON) and flagged, and every front
//! prints words instead of it ("more than 70 % of unadapted adults may vomit:
//! beyond the range of Annex D's estimate"), never "118.5 % may vomit".

use super::weighting::{Weighting, WeightingFilter};

/// K_m of ISO 2631-1 Annex D: per cent who may vomit per m/s^1.5.
pub const K_M: f64 = 1.0 / 3.0;

/// The largest share Annex D's estimate K_m·MSDV is based on, %: its data
/// reach about 70 % vomiting.
pub const VOMIT_PCT_MAX: f64 = 70.0;

/// Shortest record whose MSDV is stated without a note, s: Wf's band
/// starts at 0.1 Hz, so a record holds at least two of its slowest cycles.
pub const MIN_SICKNESS_S: f64 = 20.0;

/// Accumulates ∫ a_wf² dt of one stream.
#[derive(Debug, Clone)]
pub struct SicknessAccumulator {
    filter: WeightingFilter,
    h: f64,
    n: u64,
    sum2: f64,
}

impl SicknessAccumulator {
    pub fn new(fs: f64) -> SicknessAccumulator {
        SicknessAccumulator {
            filter: Weighting::Wf.digital(fs),
            h: 1.0 / fs,
            n: 0,
            sum2: 0.0,
        }
    }

    #[inline(always)]
    pub fn push(&mut self, a: f64) {
        let w = self.filter.process(a);
        self.sum2 += w * w;
        self.n += 1;
    }

    /// The dose of the record and over `exposure_h` hours of it.
    pub fn sickness(&self, exposure_h: f64) -> Sickness {
        let t = self.n as f64 * self.h;
        let aw = if self.n > 0 {
            (self.sum2 / self.n as f64).sqrt()
        } else {
            0.0
        };
        let msdv_exposure = aw * (exposure_h * 3600.0).sqrt();
        Sickness {
            aw,
            msdv: (self.sum2 * self.h).sqrt(),
            msdv_exposure,
            vomit_pct: K_M * msdv_exposure,
            beyond_annex_d: K_M * msdv_exposure > VOMIT_PCT_MAX,
            short: t < MIN_SICKNESS_S,
        }
    }
}

/// Motion sickness of one z signal.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sickness {
    /// Wf-weighted r.m.s., m/s².
    pub aw: f64,
    /// MSDV over the record, m/s^1.5.
    pub msdv: f64,
    /// MSDV over the exposure, a_wf·T0^½, m/s^1.5.
    pub msdv_exposure: f64,
    /// K_m·MSDV over the exposure: per cent of unadapted adults who may vomit.
    pub vomit_pct: f64,
    /// `vomit_pct` is over [`VOMIT_PCT_MAX`]: past what Annex D's estimate
    /// rests on, so [`Sickness::vomit_share`] gives words, not the number.
    pub beyond_annex_d: bool,
    /// The record is under [`MIN_SICKNESS_S`]: Wf's slow band is barely in it.
    pub short: bool,
}

impl Sickness {
    /// The share who may vomit, short: "about 12.3 %", or past Annex D's
    /// range "more than 70 %".
    pub fn vomit_share(&self) -> String {
        if self.beyond_annex_d {
            format!("more than {VOMIT_PCT_MAX} %")
        } else {
            format!("about {:.1} %", self.vomit_pct)
        }
    }

    /// The share as a report says it: "about 12.3 % of unadapted adults may
    /// vomit", or "more than 70 % of unadapted adults may vomit: beyond the
    /// range of Annex D's estimate".
    pub fn vomit_words(&self) -> String {
        let s = format!("{} of unadapted adults may vomit", self.vomit_share());
        if self.beyond_annex_d {
            s + ": beyond the range of Annex D's estimate"
        } else {
            s
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    /// A 0.2 Hz sine of amplitude 1 m/s² over 500 s: a_wf = |Wf(0.2)|/√2,
    /// MSDV = a_wf·√500; over 2 h, a_wf·√7200 and a third of it in per cent.
    #[test]
    fn a_slow_sine_by_hand() {
        let fs = 50.0;
        let mut acc = SicknessAccumulator::new(fs);
        let n = (500.0 * fs) as usize;
        for k in 0..n {
            acc.push((2.0 * PI * 0.2 * k as f64 / fs).sin());
        }
        let s = acc.sickness(2.0);
        let aw = Weighting::Wf.analog(0.2).norm() / 2f64.sqrt();
        // The start-up transient of the 0.08 Hz high-pass costs a little.
        assert!((s.aw / aw - 1.0).abs() < 0.01, "{} vs {aw}", s.aw);
        assert!((s.msdv - s.aw * 500f64.sqrt()).abs() < 1e-9);
        assert!((s.msdv_exposure - s.aw * 7200f64.sqrt()).abs() < 1e-9);
        assert!((s.vomit_pct - s.msdv_exposure / 3.0).abs() < 1e-12);
        assert!(!s.short);
        let mut short = SicknessAccumulator::new(fs);
        short.push(1.0);
        assert!(short.sickness(1.0).short);
    }

    /// 5 Hz is far above Wf's band: almost nothing is counted.
    #[test]
    fn fast_vibration_makes_no_one_sick() {
        let fs = 200.0;
        let mut acc = SicknessAccumulator::new(fs);
        for k in 0..(200.0 * fs) as usize {
            acc.push(2.0 * (2.0 * PI * 5.0 * k as f64 / fs).sin());
        }
        let s = acc.sickness(1.0);
        assert!(s.aw < 0.01 * 2.0 / 2f64.sqrt(), "{}", s.aw);
    }

    /// ISO 2631-1 Annex D rests on up to about 70 % vomiting: 0.25 Hz at
    /// 4 m/s² for 8 h gives K_m·MSDV far past it (over 100 %), flagged and in
    /// words; 70 % itself is still the number.
    #[test]
    fn past_70_percent_is_words() {
        let fs = 20.0;
        let mut acc = SicknessAccumulator::new(fs);
        for k in 0..(600.0 * fs) as usize {
            acc.push(4.0 * (2.0 * PI * 0.25 * k as f64 / fs).sin());
        }
        let s = acc.sickness(8.0);
        assert!(s.vomit_pct > 100.0, "{}", s.vomit_pct);
        assert!(s.beyond_annex_d);
        assert_eq!(
            s.vomit_words(),
            "more than 70 % of unadapted adults may vomit: beyond the range of Annex D's estimate"
        );
        let at = |pct: f64| Sickness {
            vomit_pct: pct,
            beyond_annex_d: pct > VOMIT_PCT_MAX,
            ..s
        };
        assert_eq!(at(70.0).vomit_share(), "about 70.0 %");
        assert_eq!(
            at(12.34).vomit_words(),
            "about 12.3 % of unadapted adults may vomit"
        );
        // The accumulator's flag is the same rule at the boundary.
        let mut quiet = SicknessAccumulator::new(fs);
        quiet.push(0.0);
        assert!(!quiet.sickness(1.0).beyond_annex_d);
    }
}
