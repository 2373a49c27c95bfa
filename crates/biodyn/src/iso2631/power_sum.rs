//! The p-th root of a sum of p-th powers, (Σ x_i^p)^(1/p) of x_i ≥ 0: the
//! dose sums of ISO 2631-5 (Dz = 1.07·(Σ A_i⁶)^⅙, Formula 5's day, Annex C's
//! R) and a day's VDV = (Σ VDV_i⁴)^¼ (ISO 2631-1 §6.3.2).
//!
//! Raised to the sixth power, a value above 1.8e308^⅙ ≈ 2.4e51 overflows and
//! one below 1e-51 underflows, though the root of the sum would be a plain
//! number: 1e60 m/s² gave Dzd = inf. So the sum is also kept relative to its
//! largest term s, as a Euclidean norm is computed without overflow (LAPACK's
//! dnrm2): (Σ x_i^p)^(1/p) = s·(Σ (x_i/s)^p)^(1/p), every term in (0, 1].
//! Where the plain sum stays well inside the float range (above 1e-250, finite)
//! it is the answer, bit for bit as before; otherwise the scaled one. A root
//! past the largest float is `inf` still: the caller refuses it.

/// Accumulates (Σ x_i^p)^(1/p) one term at a time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PowerSum {
    p: i32,
    /// Σ x_i^p as it comes.
    plain: f64,
    /// The largest term so far.
    scale: f64,
    /// Σ (x_i/scale)^p.
    scaled: f64,
}

/// Below this the plain sum may have lost terms to underflow.
const PLAIN_FLOOR: f64 = 1e-250;

impl PowerSum {
    /// An empty sum of `p`-th powers (p ≥ 1).
    pub fn new(p: i32) -> PowerSum {
        PowerSum {
            p,
            plain: 0.0,
            scale: 0.0,
            scaled: 0.0,
        }
    }

    /// One term, x ≥ 0 (0 adds nothing).
    #[inline]
    pub fn add(&mut self, x: f64) {
        if x <= 0.0 {
            return;
        }
        self.plain += x.powi(self.p);
        if x > self.scale {
            self.scaled = 1.0 + self.scaled * (self.scale / x).powi(self.p);
            self.scale = x;
        } else {
            self.scaled += (x / self.scale).powi(self.p);
        }
    }

    /// (Σ x_i^p)^(1/p); 0 for no terms; `inf` only when the root itself is
    /// past the largest float.
    pub fn root(&self) -> f64 {
        let inv = 1.0 / f64::from(self.p);
        if self.plain.is_finite() && self.plain >= PLAIN_FLOOR {
            self.plain.powf(inv)
        } else if self.scale > 0.0 {
            self.scale * self.scaled.powf(inv)
        } else {
            0.0
        }
    }
}

/// (Σ x_i^p)^(1/p) of `terms`.
pub fn power_root(p: i32, terms: impl IntoIterator<Item = f64>) -> f64 {
    let mut s = PowerSum::new(p);
    for x in terms {
        s.add(x);
    }
    s.root()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// In the normal range the plain formula's bits are kept.
    #[test]
    fn normal_values_give_the_plain_formulas_bits() {
        let v = [3.0, 0.5, 7.0, 24.5, 8.2];
        let plain = v
            .iter()
            .map(|x: &f64| x.powi(6))
            .sum::<f64>()
            .powf(1.0 / 6.0);
        assert_eq!(power_root(6, v).to_bits(), plain.to_bits());
        let plain4 = v.iter().map(|x: &f64| x.powi(4)).sum::<f64>().powf(0.25);
        assert_eq!(power_root(4, v).to_bits(), plain4.to_bits());
        assert_eq!(power_root(6, []), 0.0);
        assert_eq!(power_root(6, [0.0, 0.0]), 0.0);
    }

    /// 1e60 and 1e-60 are plain numbers whose sixth powers are not:
    /// (2·x⁶)^⅙ = x·2^⅙ at both ends, where the plain sum gives inf and 0.
    #[test]
    fn huge_and_tiny_terms_give_finite_roots() {
        for x in [1e60, 1e-60, 1e300, 1e-300] {
            let r = power_root(6, [x, x]);
            assert!(((r / x) - 2f64.powf(1.0 / 6.0)).abs() < 1e-15, "{x}: {r}");
            let r4 = power_root(4, [x, x, x]);
            assert!(((r4 / x) - 3f64.powf(0.25)).abs() < 1e-15, "{x}: {r4}");
        }
        // A small term beside a huge one counts for nothing, as it should.
        assert_eq!(power_root(6, [1e60, 1.0]), 1e60);
        // The scaled sum when the largest comes last, first, or between.
        let want = 1e70 * (1.0 + 2f64.powi(-6) + 4f64.powi(-6)).powf(1.0 / 6.0);
        for order in [
            [0.25e70, 0.5e70, 1e70],
            [1e70, 0.5e70, 0.25e70],
            [0.5e70, 1e70, 0.25e70],
        ] {
            let r = power_root(6, order);
            assert!((r / want - 1.0).abs() < 1e-15, "{order:?}: {r}");
        }
        // Past the largest float, the root is inf: the caller refuses it.
        assert_eq!(power_root(6, [f64::MAX, f64::MAX]), f64::INFINITY);
    }
}
