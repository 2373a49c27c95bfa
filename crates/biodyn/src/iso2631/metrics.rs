//! The metrics of a weighted acceleration (SPEC §7), accumulated one sample
//! at a time: r.m.s., peak, crest factor, MTVV (1 s linear running r.m.s.)
//! and VDV; then the daily exposure A(8) and VDV over the exposure.

/// What ISO 2631-1 reports of one weighted signal.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Metrics {
    /// Weighted r.m.s. a_w, m/s².
    pub aw: f64,
    /// Largest |a_w(t)|, m/s².
    pub peak: f64,
    /// peak / a_w (0 for a silent record).
    pub crest: f64,
    /// Maximum transient vibration value, m/s².
    pub mtvv: f64,
    /// Vibration dose value over the record, m/s^1.75.
    pub vdv: f64,
    /// Duration of the record, s.
    pub duration_s: f64,
}

/// The metrics scaled to an exposure.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Exposure {
    /// A(8) = a_w √(T_exp / 8 h), m/s².
    pub a8: f64,
    /// VDV (T_exp / T)^¼, m/s^1.75.
    pub vdv: f64,
}

impl Metrics {
    /// Daily exposure over `hours` of this vibration.
    pub fn exposure(&self, hours: f64) -> Exposure {
        Exposure {
            a8: self.aw * (hours / 8.0).sqrt(),
            vdv: if self.duration_s > 0.0 {
                self.vdv * (hours * 3600.0 / self.duration_s).powf(0.25)
            } else {
                0.0
            },
        }
    }

    /// VDV / (a_w T^¼): above 1.75 the basic method underestimates.
    pub fn vdv_ratio(&self) -> f64 {
        let d = self.aw * self.duration_s.powf(0.25);
        if d > 0.0 { self.vdv / d } else { 0.0 }
    }

    /// MTVV / a_w: above 1.5 the basic method underestimates.
    pub fn mtvv_ratio(&self) -> f64 {
        if self.aw > 0.0 {
            self.mtvv / self.aw
        } else {
            0.0
        }
    }
}

/// Accumulates the metrics of a stream sampled at fs.
#[derive(Debug, Clone)]
pub struct Accumulator {
    h: f64,
    n: u64,
    sum2: f64,
    sum4: f64,
    peak: f64,
    /// Squares over the last second, a ring; `wsum` their running sum,
    /// recomputed exactly once per lap so rounding cannot drift.
    ring: Vec<f64>,
    pos: usize,
    wsum: f64,
    max_window: f64,
}

impl Accumulator {
    /// For rate `fs` Hz (> 0): the MTVV window is round(fs) samples, at least 1.
    pub fn new(fs: f64) -> Accumulator {
        let w = (fs.round() as usize).max(1);
        Accumulator {
            h: 1.0 / fs,
            n: 0,
            sum2: 0.0,
            sum4: 0.0,
            peak: 0.0,
            ring: vec![0.0; w],
            pos: 0,
            wsum: 0.0,
            max_window: 0.0,
        }
    }

    #[inline(always)]
    pub fn push(&mut self, a: f64) {
        let a2 = a * a;
        self.n += 1;
        self.sum2 += a2;
        self.sum4 += a2 * a2;
        self.peak = self.peak.max(a.abs());
        let w = self.ring.len();
        let old = std::mem::replace(&mut self.ring[self.pos], a2);
        self.wsum += a2 - old;
        self.pos += 1;
        if self.pos == w {
            self.pos = 0;
            self.wsum = self.ring.iter().sum();
        }
        if self.n >= w as u64 && self.wsum > self.max_window {
            self.max_window = self.wsum;
        }
    }

    pub fn metrics(&self) -> Metrics {
        if self.n == 0 {
            return Metrics {
                aw: 0.0,
                peak: 0.0,
                crest: 0.0,
                mtvv: 0.0,
                vdv: 0.0,
                duration_s: 0.0,
            };
        }
        let n = self.n as f64;
        let aw = (self.sum2 / n).sqrt();
        let w = self.ring.len() as u64;
        // A record shorter than the window: its own r.m.s. is the only value.
        let mtvv = if self.n >= w {
            (self.max_window.max(0.0) / w as f64).sqrt()
        } else {
            aw
        };
        Metrics {
            aw,
            peak: self.peak,
            crest: if aw > 0.0 { self.peak / aw } else { 0.0 },
            mtvv,
            vdv: (self.sum4 * self.h).powf(0.25),
            duration_s: n * self.h,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn m(aw: f64, vdv: f64, duration_s: f64) -> Metrics {
        Metrics {
            aw,
            peak: 0.0,
            crest: 0.0,
            mtvv: 3.0,
            vdv,
            duration_s,
        }
    }

    #[test]
    fn the_ratios_of_iso_2631_1_6_3_3() {
        // VDV/(a_w T^¼): 12/(2·16^¼) = 12/4 = 3; MTVV/a_w = 3/2.
        let x = m(2.0, 12.0, 16.0);
        assert_eq!(x.vdv_ratio(), 3.0);
        assert_eq!(x.mtvv_ratio(), 1.5);
        assert_eq!(m(0.0, 1.0, 16.0).vdv_ratio(), 0.0);
        assert_eq!(m(0.0, 1.0, 16.0).mtvv_ratio(), 0.0);
    }

    #[test]
    fn exposure_scales_a_w_by_the_root_and_vdv_by_the_fourth_root() {
        // 2 h of a_w 1: A(8) = √(2/8) = 0.5; VDV 10 over 450 s for 2 h: 10·16^¼ = 20.
        let e = m(1.0, 10.0, 450.0).exposure(2.0);
        assert_eq!(e.a8, 0.5);
        assert!((e.vdv - 20.0).abs() < 1e-12);
        // A record of no time has no VDV to scale (not infinity).
        assert_eq!(m(1.0, 10.0, 0.0).exposure(2.0).vdv, 0.0);
    }

    #[test]
    fn a_silent_record_has_no_crest_factor() {
        // peak/a_w is 0/0 there: reported as 0, never NaN.
        let mut acc = Accumulator::new(100.0);
        for _ in 0..300 {
            acc.push(0.0);
        }
        let x = acc.metrics();
        assert_eq!((x.aw, x.crest, x.mtvv), (0.0, 0.0, 0.0));
        assert_eq!(x.duration_s, 3.0);
    }
}
