//! Second-order sections: the building block of the noise band-pass, the
//! ISO 2631-1 weightings and the one-third-octave filter bank.

use num_complex::Complex64;
use std::f64::consts::PI;

/// One section in transposed direct form II (good round-off, two states):
/// y = b0 x + s1; s1 = b1 x − a1 y + s2; s2 = b2 x − a2 y.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Biquad {
    /// Numerator b0, b1, b2 (powers of z⁻¹).
    pub b: [f64; 3],
    /// Denominator a1, a2 (a0 = 1).
    pub a: [f64; 2],
    s1: f64,
    s2: f64,
}

impl Biquad {
    pub fn new(b: [f64; 3], a: [f64; 2]) -> Biquad {
        Biquad {
            b,
            a,
            s1: 0.0,
            s2: 0.0,
        }
    }

    /// Filters one sample.
    #[inline(always)]
    pub fn process(&mut self, x: f64) -> f64 {
        let y = self.b[0] * x + self.s1;
        self.s1 = self.b[1] * x - self.a[0] * y + self.s2;
        self.s2 = self.b[2] * x - self.a[1] * y;
        y
    }

    /// Back to rest.
    pub fn reset(&mut self) {
        self.s1 = 0.0;
        self.s2 = 0.0;
    }

    /// Frequency response at `f_hz` for sampling rate `fs`.
    pub fn response(&self, f_hz: f64, fs: f64) -> Complex64 {
        let zi = Complex64::from_polar(1.0, -2.0 * PI * f_hz / fs);
        let zi2 = zi * zi;
        (self.b[0] + zi * self.b[1] + zi2 * self.b[2]) / (1.0 + zi * self.a[0] + zi2 * self.a[1])
    }

    /// The bilinear transform of the analog section
    /// (n0 + n1 s + n2 s²)/(d0 + d1 s + d2 s²) with s = k (1 − z⁻¹)/(1 + z⁻¹);
    /// k = 2 fs plainly, or ω / tan(ω / 2fs) to make frequency ω exact (prewarping).
    pub fn bilinear(n: [f64; 3], d: [f64; 3], k: f64) -> Biquad {
        let k2 = k * k;
        let poly = |c: [f64; 3]| {
            [
                c[2] * k2 + c[1] * k + c[0],
                2.0 * (c[0] - c[2] * k2),
                c[2] * k2 - c[1] * k + c[0],
            ]
        };
        let (nb, da) = (poly(n), poly(d));
        Biquad::new(
            [nb[0] / da[0], nb[1] / da[0], nb[2] / da[0]],
            [da[1] / da[0], da[2] / da[0]],
        )
    }
}

/// The bilinear constant that makes `f_hz` map exactly (prewarping).
pub fn prewarp(f_hz: f64, fs: f64) -> f64 {
    let w = 2.0 * PI * f_hz;
    w / (w / (2.0 * fs)).tan()
}

/// Sections in series.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Cascade {
    pub sections: Vec<Biquad>,
}

impl Cascade {
    pub fn new(sections: Vec<Biquad>) -> Cascade {
        Cascade { sections }
    }

    #[inline]
    pub fn process(&mut self, x: f64) -> f64 {
        self.sections.iter_mut().fold(x, |v, s| s.process(v))
    }

    pub fn reset(&mut self) {
        self.sections.iter_mut().for_each(Biquad::reset);
    }

    pub fn response(&self, f_hz: f64, fs: f64) -> Complex64 {
        self.sections.iter().map(|s| s.response(f_hz, fs)).product()
    }
}

/// Butterworth low-pass (`high` false) or high-pass of even `order` at
/// `f_hz` (−3 dB), bilinear with the corner prewarped.
pub fn butterworth(order: usize, f_hz: f64, fs: f64, high: bool) -> Cascade {
    let w = 2.0 * PI * f_hz;
    let k = prewarp(f_hz, fs);
    let sections = (0..order / 2)
        .map(|i| {
            let q = 1.0 / (2.0 * ((2 * i + 1) as f64 * PI / (2 * order) as f64).sin());
            let d = [1.0, 1.0 / (q * w), 1.0 / (w * w)];
            let n = if high {
                [0.0, 0.0, 1.0 / (w * w)]
            } else {
                [1.0, 0.0, 0.0]
            };
            Biquad::bilinear(n, d, k)
        })
        .collect();
    Cascade::new(sections)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn butterworth_is_minus_3db_at_the_corner_and_flat_inside() {
        let fs = 1000.0;
        let lp = butterworth(4, 100.0, fs, false);
        assert!((lp.response(100.0, fs).norm() - 0.5f64.sqrt()).abs() < 1e-12);
        assert!((lp.response(1.0, fs).norm() - 1.0).abs() < 1e-9);
        let hp = butterworth(4, 2.0, fs, true);
        assert!((hp.response(2.0, fs).norm() - 0.5f64.sqrt()).abs() < 1e-9);
        assert!((hp.response(200.0, fs).norm() - 1.0).abs() < 1e-6);
    }

    #[test]
    fn filtering_a_sine_gives_the_response() {
        let fs = 500.0;
        let mut lp = butterworth(2, 20.0, fs, false);
        let f = 30.0;
        let mut peak: f64 = 0.0;
        for k in 0..5000 {
            let y = lp.process((2.0 * PI * f * k as f64 / fs).sin());
            if k > 4000 {
                peak = peak.max(y.abs());
            }
        }
        assert!((peak - lp.response(f, fs).norm()).abs() < 2e-3);
    }
}
