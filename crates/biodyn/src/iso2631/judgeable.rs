//! Whether a record that was read can be judged by ISO 2631-1 at all: its
//! sampling rate must carry the weighting's band, and a mean far beyond
//! vibration (the 1 g of a DC-coupled accelerometer, an offset) must not
//! be judged through the weighting's start-up.
//!
//! **The rate.** The weighted r.m.s. needs the band's content: ISO 2631-1
//! judges 0.5–80 Hz (Wk, Wd), and a signal sampled at fs holds nothing
//! above fs/2, so fs must exceed twice the band's top: 160 Hz. A clock in
//! ms read as seconds gives fs/1000 and is caught here too.
//!
//! **The mean.** The weightings start at rest; a record whose channel
//! carries an offset m from its first sample is, to the filter, a step of m
//! at t = 0 on top of the vibration, and the high-pass rings on it; an
//! offset that starts later is a step there. The step taken is the larger
//! of the level the record starts with and keeps and the level it holds
//! through most of it ([`Mean::offset`]); a one-sided shock in a record
//! that starts at rest, or slow vibration below the band, has a mean but
//! neither. With s(t) the weighting's response to a
//! unit step, E₂ = ∫s² dt and E₄ = ∫s⁴ dt over the record, Minkowski's
//! inequality bounds what the step can add to the measured values:
//! |Δa_w| ≤ |m|·√(E₂/T) and |ΔVDV| ≤ |m|·E₄^¼. A share of the measured
//! a_w or VDV above [`OFFSET_REFUSED`] (5 %, the ISO 2631-5 path's rule for
//! its mean) is refused with the way to remove the mean; above
//! [`OFFSET_NOTED`] (1 %) it is said. For Wk, E₂ = 0.0451 s and
//! E₄^¼ = 0.353 s^¼ (scripts/reference/step_energies.py): 1 g on z may move
//! a 10 s record's a_w by 0.66 m/s² and its VDV by 3.5 m/s^1.75.

use super::metrics::Metrics;
use super::weighting::Weighting;
use crate::io::excerpt::num;
use crate::time::{Axis, G_N};

/// A mean whose start-up step may move a_w or VDV by more than this share
/// of the measured value is refused.
pub const OFFSET_REFUSED: f64 = 0.05;

/// … and by more than this share, said beside the results.
pub const OFFSET_NOTED: f64 = 0.01;

/// A mean below this, m/s² (about 0.1 µg, under any accelerometer's
/// resolution; what is left of a mean removed, in rounding), is no offset.
pub const MEAN_FLOOR: f64 = 1e-6;

/// The longest stretch of the step response summed, s: the weightings'
/// slowest pole in the health band (0.4 Hz, Q 0.71) has decayed by e⁻⁵⁰
/// long before.
const STEP_SPAN_S: f64 = 30.0;

/// Why a record that was read is not judged.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum JudgeError {
    #[error(
        "sampling rate {} Hz cannot carry {weighting}'s band to {} Hz: ISO 2631-1 needs more than {} Hz, twice the band's top (content above fs/2 is lost); record faster, or, if the time column is in ms or µs, name it so (t_ms, t_us)",
        sig6(*.fs),
        num(*.top_hz),
        num(2.0 * *.top_hz)
    )]
    Rate {
        fs: f64,
        weighting: &'static str,
        top_hz: f64,
    },
    #[error(
        "the {axis} axis is sampled at {} Hz and its weighted r.m.s. ({weighting}) is {} % of its unweighted one: its content lies far above ISO 2631-1's band, where no seat vibration is; is the time column in seconds but named ms or µs (t_ms, t_us)? Name it t_s",
        sig6(*.fs),
        pct(*.share)
    )]
    OutOfBand {
        axis: Axis,
        fs: f64,
        weighting: &'static str,
        share: f64,
    },
    #[error(
        "the {axis} axis carries a level of {} m/s² ({} g) through the record: gravity or an offset, not vibration; its start-up step through {weighting} could move a_w by up to {} % and VDV by up to {} % (over {} % is refused): remove each channel's mean (remove_mean) and judge again; if the level starts or stops inside the record, cut the record there first (removing the mean would leave a step)",
        num_short(*.mean),
        num_short(*.mean / G_N),
        pct(*.aw_share),
        pct(*.vdv_share),
        pct(OFFSET_REFUSED)
    )]
    Offset {
        axis: Axis,
        mean: f64,
        weighting: &'static str,
        aw_share: f64,
        vdv_share: f64,
    },
}

/// `v` to six significant digits, as short as they allow: a rate read
/// from a clock (0.5000000000000001 Hz) prints as 0.5.
fn sig6(v: f64) -> String {
    format!("{:.5e}", v)
        .parse::<f64>()
        .map_or_else(|_| num(v), num)
}

fn num_short(v: f64) -> String {
    format!("{v:.4}")
}

fn pct(share: f64) -> String {
    if share.is_finite() {
        format!("{:.1}", 100.0 * share)
    } else {
        "∞".into()
    }
}

/// Refuses a rate that cannot carry `w`'s band: fs must exceed twice its top.
pub fn check_rate(w: Weighting, fs: f64) -> Result<(), JudgeError> {
    let (_, top_hz) = w.band();
    if fs > 2.0 * top_hz {
        return Ok(());
    }
    Err(JudgeError::Rate {
        fs,
        weighting: w.name(),
        top_hz,
    })
}

/// A level is read over blocks of this length, s: twice the period of
/// Wk's and Wd's 0.4 Hz band edge, so that in-band vibration averages out
/// of a block (a 0.5 Hz sine to under 13 % of its amplitude).
const LEVEL_BLOCK_S: f64 = 5.0;

/// Above this rate a record whose weighted r.m.s. is under
/// [`OUT_OF_BAND_SHARE`] of its unweighted one is refused: a clock in s
/// named ms reads 1000 times too fast and puts the vibration far above the
/// band (no whole-body logger we know samples above 20 kHz).
pub const OUT_OF_BAND_FS: f64 = 20_000.0;

/// … the share of the unweighted r.m.s. left by the weighting.
pub const OUT_OF_BAND_SHARE: f64 = 0.01;

/// Refuses a fast record whose content the weighting all but removes.
pub fn check_band(
    axis: Axis,
    w: Weighting,
    fs: f64,
    mean: &Mean,
    metrics: &Metrics,
) -> Result<(), JudgeError> {
    let raw = mean.rms();
    if fs > OUT_OF_BAND_FS && raw > 0.0 && metrics.aw < OUT_OF_BAND_SHARE * raw {
        return Err(JudgeError::OutOfBand {
            axis,
            fs,
            weighting: w.name(),
            share: metrics.aw / raw,
        });
    }
    Ok(())
}

/// A channel's raw samples summed: its mean over the record and over its
/// first second, and its level block by block.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Mean {
    sum: f64,
    /// Σa², for the unweighted r.m.s.
    sum_sq: f64,
    n: u64,
    /// Samples in the first second, and their sum.
    first_n: u64,
    first_sum: f64,
    /// Samples in a level block, the running block's sum, and each
    /// finished block's mean.
    block_n: u64,
    block_sum: f64,
    blocks: Vec<f64>,
}

impl Mean {
    /// For a channel sampled at `fs` Hz.
    pub fn new(fs: f64) -> Mean {
        Mean {
            first_n: fs.ceil().max(1.0) as u64,
            block_n: (LEVEL_BLOCK_S * fs).ceil().max(1.0) as u64,
            ..Mean::default()
        }
    }

    #[inline(always)]
    pub fn push(&mut self, a: f64) {
        self.sum += a;
        self.sum_sq += a * a;
        self.n += 1;
        if self.n <= self.first_n {
            self.first_sum += a;
        }
        self.block_sum += a;
        if self.block_n > 0 && self.n % self.block_n == 0 {
            self.blocks.push(self.block_sum / self.block_n as f64);
            self.block_sum = 0.0;
        }
    }

    /// The mean, 0 before any sample.
    pub fn value(&self) -> f64 {
        if self.n == 0 {
            0.0
        } else {
            self.sum / self.n as f64
        }
    }

    /// The offset the record carries, as a step the weighting sees: the
    /// larger of
    /// - the level it starts with and keeps: the smaller of its mean and
    ///   its first second's, where they have one sign (a DC-coupled
    ///   accelerometer's 1 g);
    /// - the level it holds through most of it: the smaller of the median
    ///   of its 5 s block means and its mean, where they have one sign (a
    ///   logger started before its sensor: the 1 g from t = 1 s on).
    ///
    /// A one-sided shock in a record that starts at rest has a mean but
    /// neither; so has slow vibration below the band (a ship's 0.25 Hz
    /// heave), whose blocks' means swing about zero. A level that holds
    /// for less than half the record is not found: such a record is cut.
    pub fn offset(&self) -> f64 {
        let n = self.n.min(self.first_n);
        if n == 0 {
            return 0.0;
        }
        let all = self.value();
        let one_sign = |a: f64, b: f64| {
            if a * b <= 0.0 {
                0.0
            } else if a.abs() <= b.abs() {
                a
            } else {
                b
            }
        };
        let start = one_sign(all, self.first_sum / n as f64);
        let held = self.median().map_or(0.0, |m| one_sign(m, all));
        if held.abs() > start.abs() {
            held
        } else {
            start
        }
    }

    /// The unweighted r.m.s. about the mean, 0 before any sample.
    pub fn rms(&self) -> f64 {
        if self.n == 0 {
            return 0.0;
        }
        let m = self.value();
        (self.sum_sq / self.n as f64 - m * m).max(0.0).sqrt()
    }

    /// The median of the 5 s block means, with three blocks or more.
    fn median(&self) -> Option<f64> {
        if self.blocks.len() < 3 {
            return None;
        }
        let mut b = self.blocks.clone();
        b.sort_by(f64::total_cmp);
        let k = b.len() / 2;
        Some(if b.len() % 2 == 1 {
            b[k]
        } else {
            0.5 * (b[k - 1] + b[k])
        })
    }
}

/// E₂ = ∫s² dt and E₄^¼ = (∫s⁴ dt)^¼ of `w`'s response s to a unit step,
/// digital at `fs`, over the first `t_s` seconds (at most 30 s).
pub fn step_energies(w: Weighting, fs: f64, t_s: f64) -> (f64, f64) {
    let mut f = w.digital(fs);
    let n = (t_s.min(STEP_SPAN_S) * fs).ceil().max(1.0) as usize;
    let (mut e2, mut e4) = (0.0, 0.0);
    // The filter answers one sample late: one more sample, then every output.
    f.process(1.0);
    for _ in 0..n {
        let s = f.process(1.0);
        let s2 = s * s;
        e2 += s2;
        e4 += s2 * s2;
    }
    (e2 / fs, (e4 / fs).powf(0.25))
}

/// What a mean's start-up step could do to a channel: the bounds on Δa_w
/// and ΔVDV as shares of the measured values.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OffsetShare {
    pub mean: f64,
    pub aw: f64,
    pub vdv: f64,
}

/// The shares for `axis` weighted by `w` at `fs`, with mean `mean` and the
/// measured `metrics`.
pub fn offset_share(w: Weighting, fs: f64, mean: f64, metrics: &Metrics) -> OffsetShare {
    let share = |bound: f64, measured: f64| {
        if bound == 0.0 {
            0.0
        } else if measured > 0.0 {
            bound / measured
        } else {
            f64::INFINITY
        }
    };
    if mean.abs() < MEAN_FLOOR {
        return OffsetShare {
            mean,
            aw: 0.0,
            vdv: 0.0,
        };
    }
    let t = metrics.duration_s.max(1.0 / fs);
    let (e2, e4q) = step_energies(w, fs, t);
    OffsetShare {
        mean,
        aw: share(mean.abs() * (e2 / t).sqrt(), metrics.aw),
        vdv: share(mean.abs() * e4q, metrics.vdv),
    }
}

/// Judges `axis`'s mean: refused above [`OFFSET_REFUSED`], a note above
/// [`OFFSET_NOTED`], nothing below.
pub fn check_offset(
    axis: Axis,
    w: Weighting,
    fs: f64,
    mean: f64,
    metrics: &Metrics,
) -> Result<Option<String>, JudgeError> {
    let s = offset_share(w, fs, mean, metrics);
    let worst = s.aw.max(s.vdv);
    if worst > OFFSET_REFUSED {
        return Err(JudgeError::Offset {
            axis,
            mean,
            weighting: w.name(),
            aw_share: s.aw,
            vdv_share: s.vdv,
        });
    }
    Ok((worst > OFFSET_NOTED).then(|| {
        format!(
            "the {axis} axis carries a level of {} m/s²: if it is an offset, its start-up step through {} could move a_w by up to {} % and VDV by up to {} %; remove the mean to be sure",
            num_short(mean),
            w.name(),
            pct(s.aw),
            pct(s.vdv)
        )
    }))
}

#[cfg(test)]
mod tests;
