//! The analog weighting in parallel form, W(s) = d + Σ (b1 s + b0)/(s² + a1 s + a0),
//! one term per section's pole pair: the form the digital filter discretises
//! term by term.
//!
//! With N(s) the product of every numerator (K included) and Q_j(s) = d2 Π_{k≠j} D_k(s)
//! the denominator without section j's pair (s − p)(s − q):
//! - distinct p ≠ q (a complex pair, or two real poles): residues
//!   r_p = N(p)/((p − q) Q_j(p)) and r_q alike, and the term is
//!   ((r_p + r_q) s − (r_p q + r_q p))/(s² − (p + q) s + p q);
//! - a double pole p (Q = 1/2, Wm's transition): with G = N/Q_j,
//!   W = G(p)/(s − p)² + G′(p)/(s − p) + …, so the term is
//!   (r1 s + r2 − r1 p)/(s² − 2 p s + p²), r1 = G′(p), r2 = G(p), G′ from the
//!   polynomials' exact derivatives.
//!
//! Poles of different sections must differ (true of every row of the table).

use super::section::Section;
use num_complex::Complex64;

/// One term (b0, b1, a0, a1) of the parallel form.
pub type Term = [f64; 4];

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

/// The terms and the direct part d of `gain` × Π sections.
pub fn parallel(secs: &[Section], gain: f64) -> (Vec<Term>, f64) {
    let num = secs.iter().fold(vec![gain], |acc, s| mul(&acc, &s.n));
    let mut terms = Vec::with_capacity(secs.len());
    for (j, sj) in secs.iter().enumerate() {
        let [d0, d1, d2] = sj.d;
        let others = secs
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
    let d = gain * secs.iter().map(|s| s.n[2] / s.d[2]).product::<f64>();
    (terms, d)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The parallel form sums back to the product, for a complex pair, two
    /// real poles and a double pole with and without its zero.
    #[test]
    fn the_terms_sum_to_the_product() {
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
