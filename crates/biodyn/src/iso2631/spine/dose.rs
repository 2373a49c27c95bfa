//! The acceleration dose of ISO 2631-5:2018 §5.3: the positive peaks A_i of
//! the spinal response (each the largest value between two consecutive zero
//! crossings, positive ones only), Dz = 1.07·(Σ A_i⁶)^⅙ (Formula 3), and the
//! daily dose Dzd = Dz·(t_d/t_m)^⅙ (Formula 4). The sixth-power sums are
//! [`PowerSum`]s: finite wherever the root is (1e60 m/s² gives 1e60, not inf).

use crate::iso2631::power_sum::PowerSum;

/// Formula 3's factor: the spine's amplitude response to the dose.
pub const DOSE_FACTOR: f64 = 1.07;

/// The largest peaks kept, for the table and the figure (the dose counts
/// all of them; the sixth power makes the largest few rule it).
pub const TOP: usize = 10;

/// One positive response peak: its sample and its value, m/s².
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Peak {
    pub sample: u64,
    pub value: f64,
}

/// Accumulates the peaks of a response stream, one sample at a time.
#[derive(Debug, Clone)]
pub struct PeakDose {
    n: u64,
    /// The open positive run: its largest value and where.
    run: Option<Peak>,
    count: u64,
    /// Σ A_i⁶, overflow-safe.
    sum6: PowerSum,
    /// The largest [`TOP`] peaks so far, largest first.
    top: Vec<Peak>,
}

impl Default for PeakDose {
    fn default() -> PeakDose {
        PeakDose::new()
    }
}

impl PeakDose {
    pub fn new() -> PeakDose {
        PeakDose {
            n: 0,
            run: None,
            count: 0,
            sum6: PowerSum::new(6),
            top: Vec::new(),
        }
    }

    /// The next response sample. A sample at or below zero closes a run.
    #[inline(always)]
    pub fn push(&mut self, a: f64) {
        let k = self.n;
        self.n += 1;
        if a > 0.0 {
            match &mut self.run {
                Some(p) if p.value >= a => {}
                Some(p) => {
                    *p = Peak {
                        sample: k,
                        value: a,
                    }
                }
                None => {
                    self.run = Some(Peak {
                        sample: k,
                        value: a,
                    })
                }
            }
        } else if let Some(p) = self.run.take() {
            self.close(p);
        }
    }

    fn close(&mut self, p: Peak) {
        self.count += 1;
        self.sum6.add(p.value);
        if self.top.len() < TOP || self.top.last().is_some_and(|l| p.value > l.value) {
            let at = self.top.partition_point(|q| q.value >= p.value);
            self.top.insert(at, p);
            self.top.truncate(TOP);
        }
    }

    /// The record ends: a run still open is closed by the end (its largest
    /// value so far is the peak), then the dose.
    pub fn finish(mut self) -> Dose {
        if let Some(p) = self.run.take() {
            self.close(p);
        }
        Dose {
            dz: DOSE_FACTOR * self.sum6.root(),
            count: self.count,
            largest: self.top.first().map_or(0.0, |p| p.value),
            top: self.top,
        }
    }
}

/// The dose of one record.
#[derive(Debug, Clone, PartialEq)]
pub struct Dose {
    /// Dz = 1.07·(Σ A_i⁶)^⅙, m/s².
    pub dz: f64,
    /// How many positive peaks.
    pub count: u64,
    /// The largest peak, m/s².
    pub largest: f64,
    /// The largest [`TOP`] peaks, largest first (earlier first among equals).
    pub top: Vec<Peak>,
}

/// Dzd = Dz·(t_d/t_m)^⅙ (Formula 4): a dose measured over `measured_s`
/// scaled to `daily_s` of the same exposure a day.
pub fn daily(dz: f64, daily_s: f64, measured_s: f64) -> f64 {
    dz * (daily_s / measured_s).powf(1.0 / 6.0)
}

/// Dzd = (Σ Dz_j⁶·t_dj/t_mj)^⅙ (Formula 5): several exposure conditions in
/// one day, each (Dz, daily s, measured s). Where the sum of sixth powers
/// leaves the float range, the same sum as (Σ Dzd_j⁶)^⅙ of each condition's
/// own Dzd_j = Dz_j·(t_dj/t_mj)^⅙, scaled ([`PowerSum`]); `inf` only when the
/// day's dose itself is past the largest float.
pub fn daily_of(conditions: &[(f64, f64, f64)]) -> f64 {
    let plain = conditions
        .iter()
        .map(|&(dz, td, tm)| dz.powi(6) * td / tm)
        .sum::<f64>();
    if plain.is_finite() && plain >= 1e-250 {
        return plain.powf(1.0 / 6.0);
    }
    crate::iso2631::power_sum::power_root(
        6,
        conditions.iter().map(|&(dz, td, tm)| daily(dz, td, tm)),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dose_of(samples: &[f64]) -> Dose {
        let mut p = PeakDose::new();
        for &a in samples {
            p.push(a);
        }
        p.finish()
    }

    /// Only the ten largest are kept, largest first, whatever the count.
    #[test]
    fn the_top_ten_are_kept_in_order() {
        let mut s = Vec::new();
        for k in 0..1000 {
            s.extend([((k * 37) % 1000) as f64 + 1.0, -1.0]);
        }
        let d = dose_of(&s);
        assert_eq!(d.count, 1000);
        let v: Vec<f64> = d.top.iter().map(|p| p.value).collect();
        assert_eq!(v, (991..=1000).rev().map(f64::from).collect::<Vec<_>>());
        assert_eq!(d.largest, 1000.0);
    }

    /// ISO 2631-5:2018 Annex C's example: five peaks of 40 m/s² give
    /// Dz = 1.07·40·5^⅙ = 55.97 m/s².
    #[test]
    fn five_peaks_of_40_give_the_annex_c_dose() {
        let mut s = Vec::new();
        for _ in 0..5 {
            s.extend([0.0, 10.0, 40.0, 25.0, 0.0, -30.0, -5.0]);
        }
        let d = dose_of(&s);
        assert_eq!(d.count, 5);
        assert_eq!(d.largest, 40.0);
        assert_eq!((d.dz * 100.0).round() / 100.0, 55.97);
        assert!((d.dz - 1.07 * 40.0 * 5f64.powf(1.0 / 6.0)).abs() < 1e-12);
    }

    /// A peak is the largest value between crossings; negative runs count
    /// nothing; a run open at the end is closed by it; zero closes a run.
    #[test]
    fn peaks_are_the_positive_runs_maxima() {
        let d = dose_of(&[1.0, 3.0, 2.0, -1.0, -9.0, 0.5, 0.0, 2.0, 7.0]);
        let v: Vec<(u64, f64)> = d.top.iter().map(|p| (p.sample, p.value)).collect();
        assert_eq!(v, [(8, 7.0), (1, 3.0), (5, 0.5)]);
        let hand = 1.07 * (3f64.powi(6) + 0.5f64.powi(6) + 7f64.powi(6)).powf(1.0 / 6.0);
        assert!((d.dz - hand).abs() < 1e-12);
        assert_eq!(dose_of(&[-1.0, -2.0, 0.0]).count, 0);
        assert_eq!(dose_of(&[]).dz, 0.0);
    }

    /// Formula 4 and Formula 5 by hand; one condition of 5 is Formula 4.
    #[test]
    fn daily_doses_scale_by_the_sixth_root() {
        assert!((daily(60.0, 8.0 * 3600.0, 450.0) - 60.0 * 64f64.powf(1.0 / 6.0)).abs() < 1e-12);
        assert!((daily(60.0, 8.0 * 3600.0, 450.0) - 120.0).abs() < 1e-12);
        let one = daily_of(&[(60.0, 28800.0, 450.0)]);
        assert!((one - 120.0).abs() < 1e-12);
        let two = daily_of(&[(60.0, 14400.0, 450.0), (30.0, 14400.0, 60.0)]);
        let hand = (60f64.powi(6) * 32.0 + 30f64.powi(6) * 240.0).powf(1.0 / 6.0);
        assert!((two - hand).abs() < 1e-9);
    }

    /// Peaks and doses whose sixth powers leave the float range give the
    /// dose still: 1e60 is 1e60, 1e-60 is 1e-60 (Formulas 3 to 5).
    #[test]
    fn doses_past_the_sixth_powers_range_are_finite() {
        let d = dose_of(&[1e60, -1.0, 1e60, -1.0]);
        assert!(
            (d.dz / (1.07e60 * 2f64.powf(1.0 / 6.0)) - 1.0).abs() < 1e-15,
            "{}",
            d.dz
        );
        let d = dose_of(&[1e-60, -1.0]);
        assert!((d.dz / 1.07e-60 - 1.0).abs() < 1e-15, "{}", d.dz);
        // One condition: the day is that condition's Formula 4.
        let one = daily_of(&[(1e60, 7200.0, 600.0)]);
        assert!(
            (one / daily(1e60, 7200.0, 600.0) - 1.0).abs() < 1e-15,
            "{one}"
        );
        assert!((one / (1e60 * 12f64.powf(1.0 / 6.0)) - 1.0).abs() < 1e-15);
        let two = daily_of(&[(1e60, 3600.0, 600.0), (1e-60, 3600.0, 600.0)]);
        assert!((two / one - 0.5f64.powf(1.0 / 6.0)).abs() < 1e-15);
        let tiny = daily_of(&[(1e-60, 7200.0, 600.0), (1e-60, 7200.0, 600.0)]);
        assert!(
            (tiny / (1e-60 * 24f64.powf(1.0 / 6.0)) - 1.0).abs() < 1e-15,
            "{tiny}"
        );
        // Past the largest float: inf, which the day refuses.
        assert!(daily_of(&[(1e308, 28800.0, 1.0)]).is_infinite());
    }
}
