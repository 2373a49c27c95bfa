//! ISO 2631-5:2018: whole-body vibration containing multiple shocks, seated,
//! vertical (SPEC §10). The seat's z acceleration passes the seat-to-spine
//! transfer ([`SpineFilter`], §5.2); the positive peaks of the response give
//! the acceleration dose Dz and the daily dose Dzd ([`PeakDose`], §5.3); and
//! Annex C turns Dzd into the daily compressive stress, the risk factor R
//! over the years of exposure and the probability of injury ([`risk`]).
//!
//! [`SpineAccumulator`] does it in the stream of an assessment: one filter
//! step and one comparison a sample, the largest peaks kept for a figure.

mod dose;
mod error;
mod risk;
mod transfer;

pub use dose::{DOSE_FACTOR, Dose, Peak, PeakDose, TOP, daily, daily_of};
pub use error::SpineError;
pub use risk::{Band, Constants, GRAVITY, MAX_AGE, MIN_AGE, Person, Risk, SU_0, Sex, risk};
pub use transfer::{POLES, SpineFilter, ZERO, transfer};

/// Shortest record judged, s: the response to one shock rings for about
/// 0.5 s (the slowest pole pair, 31 rad/s = 4.9 Hz, ζ 0.21: 1/(ζω) = 0.15 s
/// a time constant).
pub const MIN_RECORD_S: f64 = 1.0;

/// Lowest sampling rate judged, Hz: fs/2 above the 80 Hz of a record's
/// band (and the transfer's highest pole, 420 rad/s = 67 Hz).
pub const MIN_FS: f64 = 160.0;

/// A mean above this share of the largest response peak is refused: the
/// transfer passes the mean (H(0) = 1), shifting every peak by it.
pub const MEAN_REFUSED: f64 = 0.05;

/// A mean above this share is reported: the dose moves by about as much.
pub const MEAN_NOTED: f64 = 0.01;

/// The spine's part of an assessment's stream.
#[derive(Debug, Clone)]
pub struct SpineAccumulator {
    filter: SpineFilter,
    dose: PeakDose,
    sum: f64,
    n: u64,
    last: f64,
}

impl SpineAccumulator {
    pub fn new(fs: f64) -> SpineAccumulator {
        SpineAccumulator {
            filter: SpineFilter::new(fs),
            dose: PeakDose::new(),
            sum: 0.0,
            n: 0,
            last: 0.0,
        }
    }

    /// The next seat z sample, m/s². The filter's output is one sample
    /// late; its first output (before any input) is dropped.
    #[inline(always)]
    pub fn push(&mut self, a: f64) {
        let y = self.filter.process(a);
        if self.n > 0 {
            self.dose.push(y);
        }
        self.sum += a;
        self.n += 1;
        self.last = a;
    }

    /// The record has ended: its dose Dz, with its length (s), its mean
    /// (m/s²) and the notes; refused where the method cannot judge it.
    pub fn measure(mut self) -> Result<Measure, SpineError> {
        if self.n > 0 {
            // The compensator looks one sample ahead: the last sample's
            // response, with the input held at its last value.
            let y = self.filter.process(self.last);
            self.dose.push(y);
        }
        let n = self.n;
        let fs = self.filter.fs;
        if fs < MIN_FS {
            return Err(SpineError::LowRate(fs));
        }
        let duration_s = n as f64 / fs;
        if duration_s < MIN_RECORD_S {
            return Err(SpineError::TooShort(duration_s));
        }
        let mean = self.sum / n as f64;
        let dose = self.dose.finish();
        let pct = if dose.largest > 0.0 {
            100.0 * mean.abs() / dose.largest
        } else if mean != 0.0 {
            f64::INFINITY
        } else {
            0.0
        };
        if pct > 100.0 * MEAN_REFUSED {
            return Err(SpineError::Mean { mean, pct });
        }
        let mut notes = Vec::new();
        if pct > 100.0 * MEAN_NOTED {
            notes.push(format!(
                "the seat's z mean is {mean:.4} m/s², {pct:.1} % of the largest peak: the dose moves by about as much; ISO 2631-5 takes a zero-mean record"
            ));
        }
        if dose.count == 0 {
            notes.push("no positive spinal response peak: no shock in the record, Dz = 0".into());
        }
        Ok(Measure {
            dose,
            duration_s,
            mean_m_s2: mean,
            notes,
            fs,
        })
    }

    /// The record has ended: its dose, judged for `person` over
    /// `exposure_h` hours a day.
    pub fn finish(self, person: &Person, exposure_h: f64) -> Result<Spine, SpineError> {
        let m = self.measure()?;
        let dzd = daily(m.dose.dz, exposure_h * 3600.0, m.duration_s);
        Ok(Spine {
            person: *person,
            duration_s: m.duration_s,
            exposure_h,
            mean_m_s2: m.mean_m_s2,
            dzd,
            risk: risk(dzd, person),
            dose: m.dose,
            notes: m.notes,
            fs: m.fs,
        })
    }
}

/// A record's dose before any person: what a day's operation carries.
#[derive(Debug, Clone, PartialEq)]
pub struct Measure {
    pub dose: Dose,
    pub duration_s: f64,
    pub mean_m_s2: f64,
    pub notes: Vec<String>,
    pub fs: f64,
}

/// ISO 2631-5's assessment of one record for one person.
#[derive(Debug, Clone, PartialEq)]
pub struct Spine {
    pub person: Person,
    pub fs: f64,
    /// t_m: the record's length, s.
    pub duration_s: f64,
    /// t_d: hours a day of this exposure.
    pub exposure_h: f64,
    /// The seat z record's mean, m/s² (ought to be zero).
    pub mean_m_s2: f64,
    /// Dz and its peaks.
    pub dose: Dose,
    /// Dzd = Dz·(t_d/t_m)^⅙, m/s².
    pub dzd: f64,
    pub risk: Risk,
    pub notes: Vec<String>,
}

impl Spine {
    /// The largest peaks, largest first, at most `n` (of [`TOP`]):
    /// (time from the record's start s, m/s²).
    pub fn largest(&self, n: usize) -> Vec<(f64, f64)> {
        self.dose
            .top
            .iter()
            .take(n)
            .map(|p| (p.sample as f64 / self.fs, p.value))
            .collect()
    }
}
