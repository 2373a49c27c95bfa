//! Dense complex LU with partial pivoting, P A = L U, for a system of any
//! topology (links that form loops or branches).
//!
//! At step k the row with the largest |a_ik|² (i ≥ k) is swapped into
//! place, then for every i > k
//!
//! ```text
//! l_ik = a_ik / a_kk,   a_ij ← a_ij − l_ik a_kj   (j > k)
//! ```
//!
//! and l_ik is stored where a_ik was: `a` ends holding L (unit diagonal,
//! below) and U (on and above). A x = b is then P b, forward substitution
//! with L, back substitution with U. Cost n³/3 complex multiply-adds to
//! factor, n² per solve; storage is the caller's row-major n×n `a` and an
//! n-vector of pivot rows, so nothing allocates.

use num_complex::Complex64;

const ZERO: Complex64 = Complex64::new(0.0, 0.0);

/// In-place complex LU with partial pivoting of the row-major n×n `a`;
/// false when a pivot is zero or not finite.
pub(crate) fn lu(a: &mut [Complex64], perm: &mut [usize], n: usize) -> bool {
    for k in 0..n {
        let mut piv = k;
        let mut best = a[k * n + k].norm_sqr();
        for i in k + 1..n {
            let v = a[i * n + k].norm_sqr();
            if v > best {
                best = v;
                piv = i;
            }
        }
        if !(best > 0.0 && best.is_finite()) {
            return false;
        }
        perm[k] = piv;
        if piv != k {
            for j in 0..n {
                a.swap(k * n + j, piv * n + j);
            }
        }
        let inv = Complex64::new(1.0, 0.0) / a[k * n + k];
        for i in k + 1..n {
            let l = a[i * n + k] * inv;
            a[i * n + k] = l;
            if l != ZERO {
                for j in k + 1..n {
                    let u = a[k * n + j];
                    a[i * n + j] -= l * u;
                }
            }
        }
    }
    true
}

/// Solves A x = b in place with the factors from [`lu`].
pub(crate) fn solve(a: &[Complex64], perm: &[usize], n: usize, x: &mut [Complex64]) {
    for (k, &pk) in perm.iter().enumerate().take(n) {
        x.swap(k, pk);
    }
    for i in 1..n {
        let mut s = x[i];
        for j in 0..i {
            s -= a[i * n + j] * x[j];
        }
        x[i] = s;
    }
    for i in (0..n).rev() {
        let mut s = x[i];
        for j in i + 1..n {
            s -= a[i * n + j] * x[j];
        }
        x[i] = s / a[i * n + i];
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lu_solves_a_system_that_needs_pivoting() {
        // A zero in the first pivot position forces a row swap.
        let c = |re: f64, im: f64| Complex64::new(re, im);
        let a0 = [c(0.0, 0.0), c(2.0, 1.0), c(1.0, -1.0), c(3.0, 0.5)];
        let x_true = [c(1.0, 2.0), c(-0.5, 0.25)];
        let b: Vec<Complex64> = (0..2)
            .map(|i| a0[2 * i] * x_true[0] + a0[2 * i + 1] * x_true[1])
            .collect();
        let mut a = a0;
        let mut perm = [0usize; 2];
        assert!(lu(&mut a, &mut perm, 2));
        let mut x = b.clone();
        solve(&a, &perm, 2, &mut x);
        for (u, v) in x.iter().zip(&x_true) {
            assert!((u - v).norm() < 1e-14, "{u} vs {v}");
        }
        let mut singular = [ZERO; 4];
        assert!(!lu(&mut singular, &mut perm, 2));
    }
}
