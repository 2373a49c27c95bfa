//! A frequency band: from, to, step in hertz, and the grid it spans.

use serde::{Deserialize, Serialize};

/// The lowest frequency a band may start at, Hz: a thousandth of a hertz is
/// a 17-minute period, slower than any vehicle or building moves a body.
pub const MIN_HZ: f64 = 1e-3;

/// The highest frequency a band may reach, Hz: 100 kHz is far above any
/// whole-body vibration (80 Hz) and keeps ω²·m finite for any model the
/// limits allow (above about 1e150 Hz the responses were NaN).
pub const MAX_HZ: f64 = 1e5;

/// Grids longer than this are refused: they would take memory for no insight.
pub const MAX_POINTS: usize = 1_000_000;

/// Most segment × frequency-point products one sweep takes: a tree of links
/// costs about 50 ns per segment and point, so this is about 10 s of work.
pub const MAX_SWEEP_WORK: f64 = 2e8;

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum BandError {
    #[error(
        "{points} frequency points for a {segments}-segment model is {work:.1e} segment-points of work, over the limit of {max:.0e} (about 10 s): use a step of at least {step_hint} Hz, a narrower band or fewer segments",
        max = MAX_SWEEP_WORK
    )]
    TooMuchWork {
        segments: usize,
        points: usize,
        work: f64,
        step_hint: f64,
    },
    #[error("{field} = {} Hz is not a finite number > 0: give a frequency in hertz", num(*.value))]
    NotPositive { field: &'static str, value: f64 },
    #[error(
        "{field} = {} Hz is outside the band a model is computed over, 0.001 Hz to 100 kHz",
        num(*.value)
    )]
    OutOfRange { field: &'static str, value: f64 },
    #[error("the band runs from {} Hz to {} Hz: 'from' must be below 'to'", num(*.from), num(*.to))]
    Reversed { from: f64, to: f64 },
    #[error("step = {} Hz: the step must be a finite number > 0", num(*.0))]
    BadStep(f64),
    #[error("{} points from {} to {} Hz at step {}: more than {max}; use a larger step", num(*.points), num(*.from), num(*.to), num(*.step), max = MAX_POINTS)]
    TooManyPoints {
        from: f64,
        to: f64,
        step: f64,
        points: f64,
    },
}

/// A number for an error message: as typed for ordinary values, in short
/// form past them (1e300, not 301 digits).
fn num(v: f64) -> String {
    if v == 0.0 || !v.is_finite() || (1e-4..1e7).contains(&v.abs()) {
        format!("{v}")
    } else {
        crate::io::excerpt::num(v)
    }
}

/// Frequency band in Hz; the default is the ISO 5982 band at 0.1 Hz.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Band {
    pub from: f64,
    pub to: f64,
    pub step: f64,
}

impl Default for Band {
    fn default() -> Self {
        Band {
            from: 0.5,
            to: 20.0,
            step: 0.1,
        }
    }
}

/// Checks one frequency a model is computed at (named `field` in the
/// message): finite, > 0, within [`MIN_HZ`, `MAX_HZ`], as a band's ends.
pub fn check_freq(field: &'static str, value: f64) -> Result<f64, BandError> {
    if !(value.is_finite() && value > 0.0) {
        return Err(BandError::NotPositive { field, value });
    }
    if !(MIN_HZ..=MAX_HZ).contains(&value) {
        return Err(BandError::OutOfRange { field, value });
    }
    Ok(value)
}

impl Band {
    pub fn new(from: f64, to: f64, step: f64) -> Result<Band, BandError> {
        let b = Band { from, to, step };
        b.validate()?;
        Ok(b)
    }

    pub fn validate(&self) -> Result<(), BandError> {
        for (field, value) in [("from", self.from), ("to", self.to)] {
            check_freq(field, value)?;
        }
        if self.from >= self.to {
            return Err(BandError::Reversed {
                from: self.from,
                to: self.to,
            });
        }
        if !(self.step.is_finite() && self.step > 0.0) {
            return Err(BandError::BadStep(self.step));
        }
        let points = ((self.to - self.from) / self.step).floor() + 1.0;
        if points > MAX_POINTS as f64 {
            return Err(BandError::TooManyPoints {
                from: self.from,
                to: self.to,
                step: self.step,
                points,
            });
        }
        Ok(())
    }

    /// Refuses a sweep of a `segments`-segment model over this band that
    /// would take more than `MAX_SWEEP_WORK` (call before sweeping a big model).
    pub fn check_work(&self, segments: usize) -> Result<(), BandError> {
        let points = self.len();
        let work = segments as f64 * points as f64;
        if work <= MAX_SWEEP_WORK {
            return Ok(());
        }
        let fit = (MAX_SWEEP_WORK / segments.max(1) as f64).floor() - 1.0;
        let step_hint = if fit >= 1.0 {
            let raw = (self.to - self.from) / fit;
            let scale = 10f64.powf(raw.log10().floor() - 1.0);
            (raw / scale).ceil() * scale
        } else {
            f64::INFINITY
        };
        Err(BandError::TooMuchWork {
            segments,
            points,
            work,
            step_hint,
        })
    }

    /// Number of grid points, both ends included when `to` lies on the grid.
    pub fn len(&self) -> usize {
        // A small slack keeps 0.5..20 at 0.1 from losing its last point to
        // rounding in (20 - 0.5) / 0.1; the check after it keeps a point that
        // lands past `to` (to = 1.2999999999) out.
        let mut n = ((self.to - self.from) / self.step + 1e-6).floor() as usize + 1;
        while n > 1 && self.freq(n - 1) > self.to + 1e-12 * self.to.abs() {
            n -= 1;
        }
        n
    }

    pub fn is_empty(&self) -> bool {
        false
    }

    /// The i-th grid frequency, snapped to the nearest 1e-9 Hz decimal so that
    /// 0.5 + 2 × 0.1 prints as 0.7 and not 0.7000000000000001.
    pub fn freq(&self, i: usize) -> f64 {
        snap(self.from + i as f64 * self.step)
    }

    pub fn freqs(&self) -> Vec<f64> {
        (0..self.len()).map(|i| self.freq(i)).collect()
    }
}

/// Rounds to 9 decimals when that moves the value by no more than float noise.
pub fn snap(x: f64) -> f64 {
    // trunc(v + 0.5) by an integer cast: one instruction where f64::round is
    // a library call on baseline x86-64. Saturation far out of range is
    // caught by the check below.
    let y = ((x * 1e9 + 0.5) as i64) as f64 / 1e9;
    if (y - x).abs() <= 1e-12 * x.abs().max(1.0) {
        y
    } else {
        x
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_band_has_196_clean_points() {
        let b = Band::default();
        let f = b.freqs();
        assert_eq!(f.len(), 196);
        assert_eq!(f[0], 0.5);
        assert_eq!(f[2], 0.7);
        assert_eq!(f[195], 20.0);
        assert_eq!(format!("{}", f[2]), "0.7");
    }

    #[test]
    fn snap_rounds_to_nine_decimals_only_within_noise() {
        assert_eq!(snap(0.5 + 2.0 * 0.1), 0.7);
        assert_eq!(snap(19.999999999999996), 20.0);
        assert_eq!(snap(1.2345678912345), 1.2345678912345);
        assert_eq!(snap(3e12 + 0.5), 3e12 + 0.5);
        assert_eq!(snap(1e300), 1e300);
    }

    #[test]
    fn fine_band_counts() {
        assert_eq!(Band::new(0.5, 20.0, 0.01).unwrap().len(), 1951);
        // 'to' off the grid is not included.
        assert_eq!(
            Band::new(1.0, 2.05, 0.1).unwrap().freqs().last(),
            Some(&2.0)
        );
    }

    #[test]
    fn sweep_work_is_capped_with_a_step_that_fits() {
        let b = Band::new(0.5, 1000.0, 0.001).unwrap();
        assert!(b.check_work(4).is_ok());
        let Err(BandError::TooMuchWork {
            points, step_hint, ..
        }) = b.check_work(1000)
        else {
            panic!("1000 segments × ~1e6 points must be refused");
        };
        assert_eq!(points, b.len());
        let narrowed = Band::new(0.5, 1000.0, step_hint).unwrap();
        assert!(narrowed.check_work(1000).is_ok(), "{step_hint}");
    }

    #[test]
    fn bad_bands_are_refused() {
        assert!(matches!(
            Band::new(5.0, 5.0, 0.1),
            Err(BandError::Reversed { .. })
        ));
        assert!(matches!(
            Band::new(1.0, 2.0, 0.0),
            Err(BandError::BadStep(_))
        ));
        assert!(matches!(
            Band::new(1.0, 2.0, -0.1),
            Err(BandError::BadStep(_))
        ));
        assert!(matches!(
            Band::new(1.0, 2.0, f64::NAN),
            Err(BandError::BadStep(_))
        ));
        assert!(matches!(
            Band::new(0.0, 2.0, 0.1),
            Err(BandError::NotPositive { .. })
        ));
        assert!(matches!(
            Band::new(0.5, 1e5, 0.01),
            Err(BandError::TooManyPoints { .. })
        ));
        // The physical limits: 0.001 Hz to 100 kHz, both ends included.
        for (from, to, field) in [
            (1e-4, 1.0, "from"),
            (1.0, 1e6, "to"),
            (1e100, 1e101, "from"),
            (1e-13, 2e-13, "from"),
        ] {
            match Band::new(from, to, to - from) {
                Err(BandError::OutOfRange { field: f, .. }) => assert_eq!(f, field),
                other => panic!("{from}–{to}: {other:?}"),
            }
        }
        assert!(Band::new(MIN_HZ, MAX_HZ, 1.0).is_ok());
        let m = Band::new(1e100, 1e101, 1e100).unwrap_err().to_string();
        assert!(
            m.contains("from = 1e100 Hz is outside") && m.contains("0.001 Hz to 100 kHz"),
            "{m}"
        );
    }
}
