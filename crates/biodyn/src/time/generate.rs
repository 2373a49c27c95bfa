//! Sampling a [`Signal`]: a streaming source of seat acceleration, the same
//! bits on every platform for a given seed.
//!
//! Random noise: Gaussian white noise (each sample the sum of eight 16-bit
//! uniforms from the seeded xoshiro256**, centred: no libm in the random
//! path) through a 4th-order Butterworth high-pass at LO and a 4th-order
//! low-pass at HI, after a warm-up so the record starts stationary. Its r.m.s.
//! is then exactly the one asked for: a first pass measures the filtered
//! noise, the second scales it; two passes over the generator instead of the
//! record in memory.

use super::biquad::{Biquad, Cascade, butterworth, prewarp};
use super::class::InputClass;
use super::discrete::MAX_FS;
use super::error::TimeError;
use super::limits::MAX_SAMPLES;
use super::signal::{Component, Signal, SignalError};
use crate::io::excerpt::num;
use crate::rng::Rng;
use std::f64::consts::PI;

/// Longest random record kept in memory between the probe and the replay
/// (2^22 samples, 32 MiB: over an hour at 1 kHz); longer ones are generated twice.
const KEEP_MAX: usize = 1 << 22;

/// Filtered Gaussian noise before scaling.
#[derive(Debug, Clone)]
struct Noise {
    rng: Rng,
    filter: Cascade,
}

impl Noise {
    fn new(seed: u64, lo: f64, hi: f64, fs: f64) -> Noise {
        let mut sections = butterworth(4, lo, fs, true).sections;
        sections.extend(butterworth(4, hi, fs, false).sections);
        Noise::through(seed, sections, lo, fs)
    }

    /// White noise through an input spectral class's shape filter: each
    /// analog section bilinear, prewarped at its own corner (|d0/d2|^½ rad/s).
    fn class(seed: u64, class: &InputClass, fs: f64) -> Noise {
        let sections = class
            .sections()
            .iter()
            .map(|s| {
                let w = if s.d[2] != 0.0 {
                    (s.d[0] / s.d[2]).sqrt()
                } else {
                    s.d[0] / s.d[1]
                };
                Biquad::bilinear(s.n, s.d, prewarp(w / (2.0 * PI), fs))
            })
            .collect();
        Noise::through(seed, sections, class.highpass.0, fs)
    }

    fn through(seed: u64, sections: Vec<Biquad>, lo: f64, fs: f64) -> Noise {
        let mut n = Noise {
            rng: Rng::new(seed),
            filter: Cascade::new(sections),
        };
        // Settle the filters: four periods of the low edge, at most 2^20 samples.
        let warm = ((4.0 / lo) * fs).ceil().min((1u32 << 20) as f64) as usize;
        for _ in 0..warm {
            n.next();
        }
        n
    }

    /// Zero-mean, unit-variance, near-Gaussian: the sum of eight uniforms
    /// (16-bit, from two draws), centred and scaled by √(12/8). Its kurtosis
    /// is 2.85; the band-pass then averages many samples, so the noise that
    /// comes out has a kurtosis of 3 within its sampling scatter (tests/time.rs).
    #[inline]
    fn white(&mut self) -> f64 {
        let mut sum = 0u64;
        for _ in 0..2 {
            let r = self.rng.next_u64();
            sum += (r & 0xffff) + ((r >> 16) & 0xffff) + ((r >> 32) & 0xffff) + (r >> 48);
        }
        // Each 16-bit u stands for (u + 1/2)/65536: mean exactly 1/2.
        ((sum as f64 + 4.0) / 65536.0 - 4.0) * 1.5f64.sqrt()
    }

    #[inline]
    fn next(&mut self) -> f64 {
        let w = self.white();
        self.filter.process(w)
    }
}

#[derive(Debug, Clone)]
enum Part {
    Sine {
        cycles_per_sample: f64,
        amp: f64,
        phase: f64,
    },
    Sweep {
        from: f64,
        rate: f64,
        amp: f64,
    },
    Random {
        noise: Noise,
        scale: f64,
    },
    /// The same noise, sample for sample, replayed from the probe pass.
    Kept {
        noise: Vec<f64>,
        scale: f64,
    },
    Shock {
        peak: f64,
        width: f64,
        at: f64,
    },
}

/// A sampled signal, one f64 at a time, `len` samples at `fs`.
#[derive(Debug, Clone)]
pub struct Generator {
    parts: Vec<Part>,
    fs: f64,
    len: usize,
    k: usize,
}

/// Number of samples in `duration` s at `fs`, checked against the cap.
pub fn sample_count(duration: f64, fs: f64) -> Result<usize, TimeError> {
    if !(fs.is_finite() && fs > 0.0 && fs <= MAX_FS) {
        return Err(TimeError::BadFs(fs));
    }
    if !(duration.is_finite() && duration > 0.0) {
        return Err(TimeError::BadDuration(duration));
    }
    let n = (duration * fs).round();
    if n > MAX_SAMPLES as f64 {
        return Err(TimeError::TooLong {
            samples: n,
            cap: MAX_SAMPLES,
        });
    }
    if n < 2.0 {
        return Err(TimeError::TooShort { duration, fs });
    }
    Ok(n as usize)
}

impl Generator {
    /// Samples `signal` for `duration` s at `fs` Hz (round(duration·fs) samples).
    pub fn new(signal: &Signal, fs: f64, duration: f64) -> Result<Generator, TimeError> {
        let len = sample_count(duration, fs)?;
        signal.check(fs, duration)?;
        let t_total = len as f64 / fs;
        let parts = signal
            .parts
            .iter()
            .map(|c| -> Result<Part, TimeError> { Ok(match *c {
                Component::Sine {
                    freq,
                    amp,
                    phase_deg,
                } => Part::Sine {
                    cycles_per_sample: freq / fs,
                    amp,
                    phase: phase_deg.to_radians(),
                },
                Component::Sweep { from, to, amp } => Part::Sweep {
                    from,
                    // f(t) = from·e^{rate t}; rate = ln(to/from)/T.
                    rate: (to / from).ln() / t_total,
                    amp,
                },
                Component::Random { rms, lo, hi, seed } => {
                    let mut probe = Noise::new(seed, lo, hi, fs);
                    // Up to KEEP_MAX samples the probe's noise is kept and
                    // replayed: one pass of the filters instead of two.
                    let mut kept = Vec::new();
                    let keep = len <= KEEP_MAX && kept.try_reserve_exact(len).is_ok();
                    let mut sum = 0.0;
                    for _ in 0..len {
                        let x = probe.next();
                        sum += x * x;
                        if keep {
                            kept.push(x);
                        }
                    }
                    let measured = (sum / len as f64).sqrt();
                    // A band the filter cannot represent gives NaN or silence:
                    // refuse it rather than print NaN or zeros.
                    if !(measured.is_finite() && measured > 0.0) {
                        return Err(SignalError::Bad {
                            part: c.to_string(),
                            key: "band",
                            value: format!("{}-{}", num(lo), num(hi)),
                            why: format!(
                                "Hz gives no usable noise at {} Hz over {} s: widen the band or lengthen the duration",
                                num(fs),
                                num(duration)
                            ),
                        }
                        .into());
                    }
                    let scale = rms / measured;
                    if keep {
                        Part::Kept { noise: kept, scale }
                    } else {
                        Part::Random {
                            noise: Noise::new(seed, lo, hi, fs),
                            scale,
                        }
                    }
                }
                Component::Shock { peak, width, at } => Part::Shock { peak, width, at },
                // Unit white noise has the one-sided PSD 2/fs: scaled by
                // √(G₀·fs/2) its filtered PSD is G₀·|H|², the class's, in
                // expectation (no r.m.s. pass: the class fixes the level).
                Component::Class { class, seed } => Part::Random {
                    noise: Noise::class(seed, class, fs),
                    scale: (class.gain * fs / 2.0).sqrt(),
                },
            })})
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Generator {
            parts,
            fs,
            len,
            k: 0,
        })
    }

    pub fn fs(&self) -> f64 {
        self.fs
    }

    /// Total number of samples.
    pub fn len(&self) -> usize {
        self.len
    }

    pub fn is_empty(&self) -> bool {
        self.len == 0
    }
}

impl Iterator for Generator {
    type Item = f64;

    #[inline]
    fn next(&mut self) -> Option<f64> {
        if self.k >= self.len {
            return None;
        }
        let k = self.k;
        self.k += 1;
        let t = k as f64 / self.fs;
        let mut a = 0.0;
        for p in &mut self.parts {
            a += match p {
                Part::Sine {
                    cycles_per_sample,
                    amp,
                    phase,
                } => {
                    // Whole cycles dropped before the sine: no precision lost over an hour.
                    let c = *cycles_per_sample * k as f64;
                    *amp * (2.0 * PI * (c - c.floor()) + *phase).sin()
                }
                Part::Sweep { from, rate, amp } => {
                    let phase = if rate.abs() < 1e-300 {
                        2.0 * PI * *from * t
                    } else {
                        2.0 * PI * *from * (*rate * t).exp_m1() / *rate
                    };
                    *amp * phase.sin()
                }
                Part::Random { noise, scale } => noise.next() * *scale,
                Part::Kept { noise, scale } => noise.get(k).copied().unwrap_or(0.0) * *scale,
                Part::Shock { peak, width, at } => {
                    let u = (t - *at) / *width;
                    if (0.0..=1.0).contains(&u) {
                        *peak * (PI * u).sin()
                    } else {
                        0.0
                    }
                }
            };
        }
        Some(a)
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let r = self.len - self.k;
        (r, Some(r))
    }
}

impl ExactSizeIterator for Generator {}
