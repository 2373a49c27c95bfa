//! The whole-body frequency weightings of ISO 8041-1:2017 (Wb, Wc, Wd, We,
//! Wf, Wj, Wk, Wm), as the analog formula and as digital filters.
//!
//! The analog weighting is ISO 8041-1 Formula (5), s = j2πf, ωi = 2πfi:
//! W(s) = Hh·Hl·Ht·Hs with the band limits Hh = 1/(1 + ω1/(Q1 s) + (ω1/s)²),
//! Hl = 1/(1 + s/(Q2 ω2) + (s/ω2)²), the transition
//! Ht = K (1 + s/ω3)/(1 + s/(Q4 ω4) + (s/ω4)²) and the upward step
//! Hs = (1 + s/(Q5 ω5) + (s/ω5)²)/(1 + s/(Q6 ω6) + (s/ω6)²)·(ω5/ω6)²; a stage
//! whose frequencies the table gives as ∞ is 1. The parameters are one table
//! ([`table`]).
//!
//! The digital form is that weighting discretised exactly for an input
//! linear between samples (Van Loan's matrix exponential, as for the body)
//! in parallel form, one biquad per pole pair ([`parallel`]), plus a 3-tap
//! zero-phase FIR that undoes the hold's sinc² droop ([`filter`]). A plain
//! bilinear Wk is 3 % low at 80 Hz for fs = 1000 Hz; this one is within
//! 0.1 % in magnitude with exact phase (tests/physics/iso2631.rs).

mod filter;
mod parallel;
mod table;

pub use filter::WeightingFilter;
pub use table::{Definition, Params, Quantity, Step, TABLE};

use num_complex::Complex64;
use std::f64::consts::PI;

/// A whole-body weighting of ISO 8041-1, in the order of its Table 3.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Weighting {
    /// Vertical, rail vehicles (ISO 2631-4).
    Wb,
    /// Backrest, x.
    Wc,
    /// Horizontal (x, y).
    Wd,
    /// Rotations, rad/s².
    We,
    /// Motion sickness, vertical.
    Wf,
    /// Head, recumbent.
    Wj,
    /// Vertical, seated: health, comfort, perception.
    Wk,
    /// Buildings (ISO 2631-2).
    Wm,
}

/// An analog section (n0 + n1 s + n2 s²)/(d0 + d1 s + d2 s²).
#[derive(Debug, Clone, Copy)]
struct Section {
    n: [f64; 3],
    d: [f64; 3],
}

impl Section {
    fn at_s(&self, s: Complex64) -> Complex64 {
        (self.n[0] + s * self.n[1] + s * s * self.n[2])
            / (self.d[0] + s * self.d[1] + s * s * self.d[2])
    }
}

impl Weighting {
    pub const ALL: [Weighting; 8] = [
        Weighting::Wb,
        Weighting::Wc,
        Weighting::Wd,
        Weighting::We,
        Weighting::Wf,
        Weighting::Wj,
        Weighting::Wk,
        Weighting::Wm,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Weighting::Wb => "Wb",
            Weighting::Wc => "Wc",
            Weighting::Wd => "Wd",
            Weighting::We => "We",
            Weighting::Wf => "Wf",
            Weighting::Wj => "Wj",
            Weighting::Wk => "Wk",
            Weighting::Wm => "Wm",
        }
    }

    pub fn parse(s: &str) -> Option<Weighting> {
        Weighting::ALL
            .into_iter()
            .find(|w| w.name().eq_ignore_ascii_case(s.trim()))
    }

    /// Its row of the table: parameters, band, quantity, purpose.
    pub fn definition(self) -> &'static Definition {
        &TABLE[self as usize]
    }

    /// The parameters of ISO 8041-1 Table 3.
    pub fn params(self) -> Params {
        self.definition().params
    }

    /// The frequency band the weighting is defined over, Hz.
    pub fn band(self) -> (f64, f64) {
        self.definition().band_hz
    }

    /// What it weighs (m/s², or rad/s² for We).
    pub fn quantity(self) -> Quantity {
        self.definition().quantity
    }

    /// What it is for, one line.
    pub fn purpose(self) -> &'static str {
        self.definition().purpose
    }

    /// The exact one-third-octave centres 10^(n/10) Hz of its band
    /// (the nominal 0.5 Hz is 10^-0.3 = 0.501 Hz).
    pub fn centres(self) -> impl Iterator<Item = f64> {
        let (lo, hi) = self.band();
        let n = |f: f64| (10.0 * f.log10()).round() as i32;
        (n(lo)..=n(hi)).map(|i| 10f64.powf(f64::from(i) / 10.0))
    }

    /// The stages that are not 1, as second-order sections; K apart.
    fn sections(self) -> Vec<Section> {
        let p = self.params();
        let w = |f: f64| 2.0 * PI * f;
        let (w1, w2) = (w(p.f1), w(p.f2));
        let mut v = vec![
            // High-pass 1/(1 + ω1/(Q1 s) + (ω1/s)²) = s²/(s² + ω1 s/Q1 + ω1²).
            Section {
                n: [0.0, 0.0, 1.0],
                d: [w1 * w1, w1 / p.q1, 1.0],
            },
            // Low-pass 1/(1 + s/(Q2 ω2) + (s/ω2)²).
            Section {
                n: [1.0, 0.0, 0.0],
                d: [1.0, 1.0 / (p.q2 * w2), 1.0 / (w2 * w2)],
            },
        ];
        if let (Some(f4), Some(q4)) = (p.f4, p.q4) {
            // Acceleration–velocity transition (1 + s/ω3)/(1 + s/(Q4 ω4) + (s/ω4)²).
            let w4 = w(f4);
            v.push(Section {
                n: [1.0, p.f3.map_or(0.0, |f3| 1.0 / w(f3)), 0.0],
                d: [1.0, 1.0 / (q4 * w4), 1.0 / (w4 * w4)],
            });
        }
        if let Some(s) = p.step {
            let (w5, w6) = (w(s.f5), w(s.f6));
            let g = (w5 / w6).powi(2);
            v.push(Section {
                n: [g, g / (s.q5 * w5), g / (w5 * w5)],
                d: [1.0, 1.0 / (s.q6 * w6), 1.0 / (w6 * w6)],
            });
        }
        v
    }

    /// The analog weighting W(j2πf), ISO 8041-1 Formula (5).
    pub fn analog(self, f_hz: f64) -> Complex64 {
        let s = Complex64::new(0.0, 2.0 * PI * f_hz);
        self.params().k
            * self
                .sections()
                .iter()
                .map(|x| x.at_s(s))
                .product::<Complex64>()
    }

    /// The digital filter for sampling rate `fs` (fs > 0, finite).
    pub fn digital(self, fs: f64) -> WeightingFilter {
        let (terms, d) = parallel::parallel(&self.sections(), self.params().k);
        WeightingFilter::new(self, fs, &terms, d)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_is_in_the_order_of_all_and_fits_the_filter() {
        for (i, w) in Weighting::ALL.into_iter().enumerate() {
            assert_eq!(TABLE[i].weighting, w);
            assert_eq!(Weighting::parse(&w.name().to_lowercase()), Some(w));
            assert!(w.sections().len() <= filter::SECTIONS, "{w:?}");
            let p = w.params();
            // A zero without its pole pair would make the transition improper.
            assert!(p.f3.is_none() || p.f4.is_some(), "{w:?}");
            assert_eq!(p.f4.is_some(), p.q4.is_some(), "{w:?}");
        }
        assert_eq!(Weighting::parse("Wz"), None);
    }

    #[test]
    fn centres_are_the_exact_third_octaves_of_the_band() {
        let c: Vec<f64> = Weighting::Wk.centres().collect();
        assert_eq!(c.len(), 23);
        assert!((c[0] - 10f64.powf(-0.3)).abs() < 1e-15);
        assert!((c[22] - 10f64.powf(1.9)).abs() < 1e-12);
        assert_eq!(Weighting::Wf.centres().count(), 8);
        assert_eq!(Weighting::Wm.centres().count(), 20);
    }
}
