//! A weighting and its analog formula, ISO 8041-1 Formula (5), from its row
//! of the table.

use super::table::{Definition, Params, Quantity, TABLE};
use crate::time::foh::Section;
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
        self.definition().name
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
    pub(super) fn sections(self) -> Vec<Section> {
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
}
