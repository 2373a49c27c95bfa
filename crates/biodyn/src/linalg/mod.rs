//! Small complex solves shared by the frequency response and the fit: one
//! algorithm per file, allocation-free on storage the caller owns.
//!
//! - [`thomas`]: complex symmetric tridiagonal systems (a chain of links
//!   between neighbours), O(n), no pivoting.
//! - [`lu`]: dense complex systems of any topology, LU with partial
//!   pivoting, O(n³).

pub(crate) mod lu;
pub(crate) mod thomas;

use num_complex::Complex64;

/// 1/z as z̄/|z|²: one division by a real, the form both solvers use (their
/// results depend on its bits).
#[inline]
pub(crate) fn recip(z: Complex64) -> Complex64 {
    let d = z.norm_sqr();
    Complex64::new(z.re / d, -z.im / d)
}
