//! The frequency weightings of ISO 2631-1 Annex A (ISO 8041-1 Table 3): Wk
//! (vertical, seated), Wd (horizontal), Wf (motion sickness), as the analog
//! formula and as digital filters.
//!
//! Each analog second-order section becomes a biquad one of two ways, the one
//! that fits better over the weighting's band at this rate: the bilinear
//! transform prewarped at the section's own frequency (exact in shape far
//! below Nyquist), or a magnitude-matched design (Vicanek 2016: poles by the
//! matched z-transform, numerator fitted to the analog magnitude at DC, at
//! Nyquist and at the section's frequency). A plain bilinear Wk is 3 % low at
//! 80 Hz for fs = 1000 Hz; this design holds the analog |W| within about
//! 0.1 % there (tests/iso2631.rs proves 1 % from 0.5 to 80 Hz).

use crate::time::biquad::{Biquad, Cascade, prewarp};
use num_complex::Complex64;
use std::f64::consts::PI;

/// A weighting of ISO 2631-1.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Weighting {
    /// Vertical, seated: health, comfort, perception.
    Wk,
    /// Horizontal (x, y), seated.
    Wd,
    /// Motion sickness, vertical.
    Wf,
}

/// The parameters of one weighting, frequencies in Hz; `f3 = ∞` is `None`.
#[derive(Debug, Clone, Copy)]
struct Params {
    f1: f64,
    f2: f64,
    f3: Option<f64>,
    f4: f64,
    q4: f64,
    /// Upward step (f5, Q5, f6, Q6), absent for Wd.
    step: Option<(f64, f64, f64, f64)>,
}

/// An analog section (n0 + n1 s + n2 s²)/(d0 + d1 s + d2 s²) and the
/// frequency that characterises it.
#[derive(Debug, Clone, Copy)]
struct Section {
    n: [f64; 3],
    d: [f64; 3],
    f0: f64,
}

impl Section {
    fn at(&self, f_hz: f64) -> Complex64 {
        let s = Complex64::new(0.0, 2.0 * PI * f_hz);
        (self.n[0] + s * self.n[1] + s * s * self.n[2])
            / (self.d[0] + s * self.d[1] + s * s * self.d[2])
    }
}

const Q12: f64 = std::f64::consts::FRAC_1_SQRT_2;

impl Weighting {
    pub const ALL: [Weighting; 3] = [Weighting::Wk, Weighting::Wd, Weighting::Wf];

    pub fn name(self) -> &'static str {
        match self {
            Weighting::Wk => "Wk",
            Weighting::Wd => "Wd",
            Weighting::Wf => "Wf",
        }
    }

    pub fn parse(s: &str) -> Option<Weighting> {
        Weighting::ALL
            .into_iter()
            .find(|w| w.name().eq_ignore_ascii_case(s.trim()))
    }

    /// The frequency band the weighting is defined over, Hz.
    pub fn band(self) -> (f64, f64) {
        match self {
            Weighting::Wk | Weighting::Wd => (0.5, 80.0),
            Weighting::Wf => (0.1, 0.5),
        }
    }

    fn params(self) -> Params {
        match self {
            Weighting::Wk => Params {
                f1: 0.4,
                f2: 100.0,
                f3: Some(12.5),
                f4: 12.5,
                q4: 0.63,
                step: Some((2.37, 0.91, 3.35, 0.91)),
            },
            Weighting::Wd => Params {
                f1: 0.4,
                f2: 100.0,
                f3: Some(2.0),
                f4: 2.0,
                q4: 0.63,
                step: None,
            },
            Weighting::Wf => Params {
                f1: 0.08,
                f2: 0.63,
                f3: None,
                f4: 0.25,
                q4: 0.86,
                step: Some((0.0625, 0.80, 0.1, 0.80)),
            },
        }
    }

    fn sections(self) -> Vec<Section> {
        let p = self.params();
        let w = |f: f64| 2.0 * PI * f;
        let (w1, w2, w4) = (w(p.f1), w(p.f2), w(p.f4));
        let mut v = vec![
            // High-pass 1/(1 + ω1/(Q1 s) + (ω1/s)²) = s²/(s² + ω1 s/Q1 + ω1²).
            Section {
                n: [0.0, 0.0, 1.0],
                d: [w1 * w1, w1 / Q12, 1.0],
                f0: p.f1,
            },
            // Low-pass 1/(1 + s/(Q2 ω2) + (s/ω2)²).
            Section {
                n: [1.0, 0.0, 0.0],
                d: [1.0, 1.0 / (Q12 * w2), 1.0 / (w2 * w2)],
                f0: p.f2,
            },
            // Acceleration–velocity transition (1 + s/ω3)/(1 + s/(Q4 ω4) + (s/ω4)²).
            Section {
                n: [1.0, p.f3.map_or(0.0, |f3| 1.0 / w(f3)), 0.0],
                d: [1.0, 1.0 / (p.q4 * w4), 1.0 / (w4 * w4)],
                f0: p.f4,
            },
        ];
        if let Some((f5, q5, f6, q6)) = p.step {
            let (w5, w6) = (w(f5), w(f6));
            let g = (w5 / w6).powi(2);
            v.push(Section {
                n: [g, g / (q5 * w5), g / (w5 * w5)],
                d: [1.0, 1.0 / (q6 * w6), 1.0 / (w6 * w6)],
                f0: f6,
            });
        }
        v
    }

    /// The analog weighting W(j2πf), the formula of ISO 2631-1 Annex A.
    pub fn analog(self, f_hz: f64) -> Complex64 {
        self.sections().iter().map(|s| s.at(f_hz)).product()
    }

    /// The digital filter for sampling rate `fs` (fs > 0, finite).
    pub fn digital(self, fs: f64) -> WeightingFilter {
        let (lo, hi) = self.band();
        let top = hi.min(0.45 * fs);
        let grid: Vec<f64> = (0..=200)
            .map(|i| lo * (top / lo).max(1.0).powf(i as f64 / 200.0))
            .collect();
        let sections = self
            .sections()
            .iter()
            .map(|s| {
                let err = |b: &Biquad| {
                    grid.iter()
                        .map(|&f| (b.response(f, fs).norm() / s.at(f).norm() - 1.0).abs())
                        .fold(0.0, f64::max)
                };
                let bil = Biquad::bilinear(s.n, s.d, prewarp(s.f0.min(0.4 * fs), fs));
                match matched(s, fs) {
                    Some(m) if err(&m) < err(&bil) => m,
                    _ => bil,
                }
            })
            .collect();
        WeightingFilter {
            weighting: self,
            fs,
            cascade: Cascade::new(sections),
        }
    }
}

/// Magnitude-matched biquad of an analog section (Vicanek, "Matched
/// second order digital filters", 2016), or None when it cannot be formed.
fn matched(s: &Section, fs: f64) -> Option<Biquad> {
    let t = 1.0 / fs;
    let [d0, d1, d2] = s.d;
    // Poles of d2 s² + d1 s + d0 through z = e^{sT}. `one` is (1 − z1)(1 − z2)
    // = 1 + a1 + a2, formed with expm1 so that poles near z = 1 keep their digits.
    let disc = d1 * d1 - 4.0 * d2 * d0;
    let (a1, a2, one) = if disc < 0.0 {
        let sigma = -d1 / (2.0 * d2);
        let wd = (-disc).sqrt() / (2.0 * d2);
        let r = (sigma * t).exp();
        let th = wd * t;
        let one = (sigma * t).exp_m1().powi(2) + 4.0 * r * (th / 2.0).sin().powi(2);
        (-2.0 * r * th.cos(), r * r, one)
    } else {
        let sq = disc.sqrt();
        let p1 = (-d1 + sq) / (2.0 * d2);
        let p2 = (-d1 - sq) / (2.0 * d2);
        let (z1, z2) = ((p1 * t).exp(), (p2 * t).exp());
        (-(z1 + z2), z1 * z2, (p1 * t).exp_m1() * (p2 * t).exp_m1())
    };
    let big_a0 = one * one;
    let big_a1 = (1.0 - a1 + a2).powi(2);
    let big_a2 = -4.0 * a2;
    let mag2 = |f: f64| s.at(f).norm_sqr();
    let b0_ = big_a0 * mag2(0.0);
    let b1_ = big_a1 * mag2(fs / 2.0);
    let fm = s.f0.min(fs / 4.0);
    let phi1 = (PI * fm / fs).sin().powi(2);
    let phi0 = 1.0 - phi1;
    let phi2 = 4.0 * phi0 * phi1;
    let b2_ =
        (mag2(fm) * (big_a0 * phi0 + big_a1 * phi1 + big_a2 * phi2) - b0_ * phi0 - b1_ * phi1) / phi2;
    let (r0, r1) = (b0_.sqrt(), b1_.sqrt());
    let w = 0.5 * (r0 + r1);
    let b0 = 0.5 * (w + (w * w + b2_).max(0.0).sqrt());
    if !(b0 > 0.0) {
        return None;
    }
    let b1 = 0.5 * (r0 - r1);
    let b2 = -b2_ / (4.0 * b0);
    let bq = Biquad::new([b0, b1, b2], [a1, a2]);
    (bq.b.iter().chain(&bq.a).all(|v| v.is_finite())).then_some(bq)
}

/// A weighting as a running digital filter at one rate.
#[derive(Debug, Clone)]
pub struct WeightingFilter {
    pub weighting: Weighting,
    pub fs: f64,
    pub cascade: Cascade,
}

impl WeightingFilter {
    #[inline]
    pub fn process(&mut self, x: f64) -> f64 {
        self.cascade.process(x)
    }

    pub fn reset(&mut self) {
        self.cascade.reset();
    }

    /// The digital response at `f_hz`.
    pub fn response(&self, f_hz: f64) -> Complex64 {
        self.cascade.response(f_hz, self.fs)
    }

    /// The largest relative error of |W| against the analog formula at the
    /// one-third-octave centres of the weighting's band below fs/2.
    pub fn max_error(&self) -> f64 {
        let (lo, hi) = self.weighting.band();
        super::bands::centres()
            .filter(|&(_, f)| f >= lo * 0.99 && f <= hi * 1.01 && f < self.fs / 2.0)
            .map(|(_, f)| (self.response(f).norm() / self.weighting.analog(f).norm() - 1.0).abs())
            .fold(0.0, f64::max)
    }

    /// A warning when fs is too low for the weighting's band: content above
    /// fs/2 is lost, or the filter misses the analog |W| by more than 1 %.
    pub fn warning(&self) -> Option<String> {
        let (_, hi) = self.weighting.band();
        let name = self.weighting.name();
        if self.fs / 2.0 <= hi {
            return Some(format!(
                "fs {} Hz is too low for {name}: its band reaches {hi} Hz, above fs/2 = {} Hz; sample at 1000 Hz or more",
                self.fs,
                self.fs / 2.0
            ));
        }
        let e = self.max_error();
        (e > 0.01).then(|| {
            format!(
                "fs {} Hz is low for {name}: the digital weighting misses the analog one by {:.1} % in its band; sample at 1000 Hz or more",
                self.fs,
                e * 100.0
            )
        })
    }
}
