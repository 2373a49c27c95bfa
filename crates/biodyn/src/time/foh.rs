//! An analog transfer function given as a product of quadratic sections,
//! turned into parallel second-order terms and each term discretised exactly
//! for an input linear between samples (first-order hold, the convention of
//! `lsim` and of the body's own step).
//!
//! W(s) = Π (n0 + n1 s + n2 s²)/(d0 + d1 s + d2 s²)
//!      = d + Σ (b1 s + b0)/(s² + a1 s + a0),
//! one term per section's pole pair (the sections' denominators must be
//! coprime: no two sections share a pole). A pair may be complex, real and
//! distinct, or real and double (Q = ½: critically damped). The ISO 2631-1
//! and ISO 8041-1 weightings and ISO 2631-5's seat-to-spine transfer are
//! built on it.

use super::biquad::Biquad;
use nalgebra::DMatrix;
use num_complex::Complex64;
use std::f64::consts::PI;

/// An analog section (n0 + n1 s + n2 s²)/(d0 + d1 s + d2 s²).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Section {
    pub n: [f64; 3],
    pub d: [f64; 3],
}

/// One parallel term (b1 s + b0)/(s² + a1 s + a0), as [b0, b1, a0, a1].
pub type Term = [f64; 4];

impl Section {
    /// The section at complex frequency `s`.
    pub fn at_s(&self, s: Complex64) -> Complex64 {
        (self.n[0] + s * self.n[1] + s * s * self.n[2])
            / (self.d[0] + s * self.d[1] + s * s * self.d[2])
    }

    /// The section at s = j2πf.
    pub fn at(&self, f_hz: f64) -> Complex64 {
        self.at_s(Complex64::new(0.0, 2.0 * PI * f_hz))
    }
}

/// The product of `sections` at s = j2πf.
pub fn product(sections: &[Section], f_hz: f64) -> Complex64 {
    sections.iter().map(|s| s.at(f_hz)).product()
}

/// Ascending coefficients of the product of two polynomials.
fn mul(a: &[f64], b: &[f64]) -> Vec<f64> {
    let mut out = vec![0.0; a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] += x * y;
        }
    }
    out
}

/// The polynomial and its derivative at `s` (Horner).
fn eval(c: &[f64], s: Complex64) -> (Complex64, Complex64) {
    let mut p = Complex64::new(0.0, 0.0);
    let mut dp = Complex64::new(0.0, 0.0);
    for &x in c.iter().rev() {
        dp = dp * s + p;
        p = p * s + x;
    }
    (p, dp)
}

/// Two roots closer than this, relative to their size, are one double root:
/// Q = 1/2 exactly gives a discriminant of a few rounding errors.
const DOUBLE: f64 = 1e-9;

/// The parallel form of `gain` × the product of `sections` (each with
/// d2 ≠ 0): the terms, one per section, and the direct part
/// d = gain·Π n2/d2.
///
/// With N(s) the product of every numerator (the gain included) and
/// Q_j(s) = d2 Π_{k≠j} D_k(s) the denominator without section j's pair
/// (s − p)(s − q):
/// - distinct p ≠ q (a complex pair, or two real poles): residues
///   r_p = N(p)/((p − q) Q_j(p)) and r_q alike, and the term is
///   ((r_p + r_q) s − (r_p q + r_q p))/(s² − (p + q) s + p q);
/// - a double pole p (Q = ½): with G = N/Q_j, W = G(p)/(s − p)² +
///   G′(p)/(s − p) + …, so the term is (r1 s + r2 − r1 p)/(s² − 2ps + p²),
///   r1 = G′(p), r2 = G(p), G′ from the polynomials' exact derivatives.
pub fn parallel(sections: &[Section], gain: f64) -> (Vec<Term>, f64) {
    let num = sections.iter().fold(vec![gain], |acc, s| mul(&acc, &s.n));
    let mut terms = Vec::with_capacity(sections.len());
    for (j, sj) in sections.iter().enumerate() {
        let [d0, d1, d2] = sj.d;
        let others = sections
            .iter()
            .enumerate()
            .filter(|&(k, _)| k != j)
            .fold(vec![d2], |acc, (_, s)| mul(&acc, &s.d));
        let disc = d1 * d1 - 4.0 * d2 * d0;
        if disc.abs() <= DOUBLE * d1 * d1 {
            let p = Complex64::new(-d1 / (2.0 * d2), 0.0);
            let (n, dn) = eval(&num, p);
            let (q, dq) = eval(&others, p);
            let r2 = n / q;
            let r1 = (dn * q - n * dq) / (q * q);
            terms.push([(r2 - r1 * p).re, r1.re, (p * p).re, -2.0 * p.re]);
        } else {
            let root = Complex64::new(disc, 0.0).sqrt();
            let p = (-d1 + root) / (2.0 * d2);
            let q = (-d1 - root) / (2.0 * d2);
            let res = |x: Complex64, y: Complex64| eval(&num, x).0 / ((x - y) * eval(&others, x).0);
            let (rp, rq) = (res(p, q), res(q, p));
            terms.push([-(rp * q + rq * p).re, (rp + rq).re, (p * q).re, -(p + q).re]);
        }
    }
    let d = gain * sections.iter().map(|s| s.n[2] / s.d[2]).product::<f64>();
    (terms, d)
}

/// The exact first-order-hold discretisation of (b1 s + b0)/(s² + a1 s + a0)
/// (a0 > 0) as a biquad: Van Loan's exponential on a scaled controllable
/// realisation (x1' = ω0 x2, x2' = −ω0 x1 − a1 x2 + ω0 u,
/// y = b0/ω0² x1 + b1/ω0 x2), then
/// H(z) = cᵀ adj(zI − Φ)(Γ0 + z Γ1) / det(zI − Φ).
pub fn foh_biquad([b0, b1, a0, a1]: Term, fs: f64) -> Biquad {
    let w0 = a0.sqrt();
    let h = 1.0 / fs;
    let mut aug = DMatrix::<f64>::zeros(4, 4);
    aug[(0, 1)] = w0 * h;
    aug[(1, 0)] = -w0 * h;
    aug[(1, 1)] = -a1 * h;
    aug[(1, 2)] = w0 * h;
    aug[(2, 3)] = 1.0;
    let e = aug.exp();
    let (f11, f12, f21, f22) = (e[(0, 0)], e[(0, 1)], e[(1, 0)], e[(1, 1)]);
    let (g1a, g1b) = (e[(0, 3)], e[(1, 3)]);
    let (g0a, g0b) = (e[(0, 2)] - g1a, e[(1, 2)] - g1b);
    let (c1, c2) = (b0 / (w0 * w0), b1 / w0);
    let n2 = c1 * g1a + c2 * g1b;
    let n1 = c1 * (g0a - f22 * g1a + f12 * g1b) + c2 * (f21 * g1a + g0b - f11 * g1b);
    let n0 = c1 * (-f22 * g0a + f12 * g0b) + c2 * (f21 * g0a - f11 * g0b);
    Biquad::new([n2, n1, n0], [-(f11 + f22), f11 * f22 - f12 * f21])
}

/// The compensator for the first-order hold's sinc² droop: the zero-phase
/// 3-tap FIR [−c, 1 + 2c, −c], c = 1/12, whose gain 1 + (1 − cos θ)/6
/// matches 1/sinc²(θ/2) = 1 + θ²/12 + O(θ⁴).
pub const FIR_C: f64 = 1.0 / 12.0;

/// The FIR's gain at `f_hz` for rate `fs`.
pub fn fir_gain(f_hz: f64, fs: f64) -> f64 {
    let th = 2.0 * PI * f_hz / fs;
    1.0 + 2.0 * FIR_C * (1.0 - th.cos())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sum(terms: &[Term], d: f64, f: f64) -> Complex64 {
        let s = Complex64::new(0.0, 2.0 * PI * f);
        terms
            .iter()
            .map(|&[b0, b1, a0, a1]| (b1 * s + b0) / (s * s + a1 * s + a0))
            .sum::<Complex64>()
            + d
    }

    /// The parallel form equals the product at every frequency, for complex,
    /// real distinct and double real pole pairs together.
    #[test]
    fn parallel_equals_product_for_every_kind_of_pole_pair() {
        let w = |f: f64| 2.0 * PI * f;
        let sections = [
            // Complex pair, Q 0.63, with a zero.
            Section {
                n: [1.0, 1.0 / w(12.5), 0.0],
                d: [1.0, 1.0 / (0.63 * w(12.5)), 1.0 / (w(12.5) * w(12.5))],
            },
            // Double real pole (Q = ½) at 5.684 Hz.
            Section {
                n: [1.0, 1.0 / w(5.684), 0.0],
                d: [1.0, 2.0 / w(5.684), 1.0 / (w(5.684) * w(5.684))],
            },
            // Two distinct real poles (Q 0.3).
            Section {
                n: [0.0, 0.0, 1.0],
                d: [w(0.4) * w(0.4), w(0.4) / 0.3, 1.0],
            },
        ];
        let (terms, d) = parallel(&sections, 1.0);
        assert_eq!(terms.len(), 3);
        for f in [0.05, 0.4, 1.0, 3.3, 5.684, 12.5, 40.0, 300.0] {
            let (a, b) = (product(&sections, f), sum(&terms, d, f));
            assert!((a - b).norm() <= 1e-10 * a.norm(), "{f} Hz: {a} vs {b}");
        }
    }

    /// The biquad of a term matches the analog term times the hold's sinc²
    /// at low frequency (the hold's known droop), for a complex pair.
    #[test]
    fn the_hold_droops_as_sinc_squared() {
        let w0 = 2.0 * PI * 5.0;
        let term = [w0 * w0, 0.0, w0 * w0, w0 / 2.0];
        let fs = 1000.0;
        let b = foh_biquad(term, fs);
        for f in [0.5, 2.0, 5.0, 20.0] {
            let s = Complex64::new(0.0, 2.0 * PI * f);
            let analog = w0 * w0 / (s * s + s * w0 / 2.0 + w0 * w0);
            let x = PI * f / fs;
            let sinc2 = (x.sin() / x).powi(2);
            let got = b.response(f, fs);
            assert!((got - analog * sinc2).norm() < 1e-5 * analog.norm(), "{f}");
            // The compensator is flat to O(θ⁴): 3e-6 at 20 Hz for 1 kHz.
            assert!((got * fir_gain(f, fs) - analog).norm() < 1e-5 * analog.norm());
        }
    }

    /// The terms sum back to the product with a gain, for a complex pair, two
    /// real poles and a double pole with and without its zero.
    #[test]
    fn the_terms_sum_to_the_product_with_a_gain() {
        let secs = [
            Section {
                n: [0.0, 0.0, 1.0],
                d: [4.0, 1.0, 1.0],
            },
            Section {
                n: [1.0, 0.0, 0.0],
                d: [2.0, 3.0, 1.0],
            },
            Section {
                n: [1.0, 1.0 / 3.0, 0.0],
                d: [1.0, 2.0 / 3.0, 1.0 / 9.0],
            },
            Section {
                n: [2.0, 0.5, 0.0],
                d: [25.0, 10.0, 1.0],
            },
        ];
        let (terms, d) = parallel(&secs, 1.5);
        for w in [0.01, 0.3, 1.0, 2.7, 10.0, 300.0] {
            let s = Complex64::new(0.0, w);
            let want: Complex64 = 1.5 * secs.iter().map(|x| x.at_s(s)).product::<Complex64>();
            let got: Complex64 = terms
                .iter()
                .map(|[b0, b1, a0, a1]| (b1 * s + b0) / (s * s + a1 * s + a0))
                .sum::<Complex64>()
                + d;
            // Absolute below 1e-15: the terms, each near 1, cancel to W = 1e-6 at low ω.
            assert!(
                (got - want).norm() <= 1e-12 * want.norm() + 1e-15,
                "{w}: {got} vs {want}"
            );
        }
    }
}
