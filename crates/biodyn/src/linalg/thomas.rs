//! Thomas' algorithm for a complex symmetric tridiagonal system A x = b.
//!
//! With diagonal dᵢ and off-diagonal eᵢ = A[i][i+1] = A[i+1][i], Gaussian
//! elimination without pivoting gives A = L U with unit lower bidiagonal L
//! and upper bidiagonal U:
//!
//! ```text
//! u₀ = d₀,   lᵢ = eᵢ₋₁ / uᵢ₋₁,   uᵢ = dᵢ − lᵢ eᵢ₋₁          (i = 1 … n−1)
//! forward:  yᵢ = bᵢ − lᵢ yᵢ₋₁
//! back:     xₙ₋₁ = yₙ₋₁ / uₙ₋₁,  xᵢ = (yᵢ − eᵢ xᵢ₊₁) / uᵢ
//! ```
//!
//! [`Factor`] keeps 1/uᵢ, lᵢ and eᵢ, so one factorisation serves several
//! right-hand sides (the fit solves three per frequency). Cost: n
//! reciprocals and about 3n complex multiply-adds to factor, 3n per solve.
//! Without pivoting a uᵢ can cancel: [`Factor::factor`] can refuse a pivot
//! that lost most of its digits, and the caller then pivots (see [`super::lu`]).

use super::recip;
use num_complex::Complex64;

const ZERO: Complex64 = Complex64::new(0.0, 0.0);

/// The factors of one A, on storage `S` of at least n entries each (a stack
/// array on the response's hot path, vectors in the fit).
#[derive(Debug, Clone)]
pub(crate) struct Factor<S> {
    /// 1/uᵢ.
    inv: S,
    /// lᵢ (entry 0 unused).
    l: S,
    /// eᵢ.
    off: S,
}

impl<S: AsRef<[Complex64]> + AsMut<[Complex64]>> Factor<S> {
    /// Storage for the factors; the entries need no initial value.
    pub(crate) fn new(inv: S, l: S, off: S) -> Factor<S> {
        Factor { inv, l, off }
    }

    /// Factors the n×n A with `diag(i)` = dᵢ and `off(i)` = eᵢ. With
    /// `min_ratio` = Some(ε) it stops and answers false at the first pivot
    /// with |uᵢ|² ≤ ε·|dᵢ|² (cancellation) or not finite; with None it never
    /// refuses (a zero pivot then gives non-finite x, which the caller sees).
    #[inline]
    pub(crate) fn factor(
        &mut self,
        n: usize,
        diag: impl Fn(usize) -> Complex64,
        off: impl Fn(usize) -> Complex64,
        min_ratio: Option<f64>,
    ) -> bool {
        let (inv, l, e) = (self.inv.as_mut(), self.l.as_mut(), self.off.as_mut());
        let mut prev = ZERO;
        for i in 0..n {
            let mut u = diag(i);
            let scale = if min_ratio.is_some() {
                u.norm_sqr()
            } else {
                0.0
            };
            if i > 0 {
                let o = off(i - 1);
                e[i - 1] = o;
                let li = o * prev;
                l[i] = li;
                u -= li * o;
            }
            if let Some(eps) = min_ratio {
                let uu = u.norm_sqr();
                if !(uu > eps * scale && uu.is_finite()) {
                    return false;
                }
            }
            prev = recip(u);
            inv[i] = prev;
        }
        true
    }

    /// Solves A x = b in place (`x` holds b on entry), n ≥ 1.
    #[inline]
    pub(crate) fn solve(&self, n: usize, x: &mut [Complex64]) {
        let x = &mut x[..n];
        let (inv, l, e) = (
            &self.inv.as_ref()[..n],
            &self.l.as_ref()[..n],
            &self.off.as_ref()[..n],
        );
        let mut prev = x[0];
        for i in 1..n {
            prev = x[i] - l[i] * prev;
            x[i] = prev;
        }
        let mut next = x[n - 1] * inv[n - 1];
        x[n - 1] = next;
        for i in (0..n - 1).rev() {
            next = (x[i] - e[i] * next) * inv[i];
            x[i] = next;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn thomas_solves_a_complex_symmetric_tridiagonal_system() {
        let c = |re: f64, im: f64| Complex64::new(re, im);
        let d = [c(4.0, 1.0), c(5.0, -0.5), c(3.0, 0.25), c(6.0, 2.0)];
        let e = [c(-1.0, 0.5), c(-2.0, 0.0), c(-0.5, -0.25)];
        let x_true = [c(1.0, 2.0), c(-0.5, 0.25), c(0.0, -1.0), c(3.0, 0.5)];
        let mut b = [ZERO; 4];
        for i in 0..4 {
            b[i] = d[i] * x_true[i];
            if i > 0 {
                b[i] += e[i - 1] * x_true[i - 1];
            }
            if i < 3 {
                b[i] += e[i] * x_true[i + 1];
            }
        }
        let mut f = Factor::new([ZERO; 4], [ZERO; 4], [ZERO; 4]);
        assert!(f.factor(4, |i| d[i], |i| e[i], Some(1e-20)));
        f.solve(4, &mut b);
        for (u, v) in b.iter().zip(&x_true) {
            assert!((u - v).norm() < 1e-14, "{u} vs {v}");
        }
        // [[1, 1], [1, 1]] loses its second pivot entirely.
        let one = c(1.0, 0.0);
        assert!(!f.factor(2, |_| one, |_| one, Some(1e-20)));
        assert!(f.factor(2, |_| one, |_| one, None));
    }
}
