//! Refining one eigenvalue of the state matrix on the pencil
//! Q(λ) = K + λC + λ²M, and the checks that decide whether it is trusted.

use super::error::ModesError;
use crate::freq::banded::Banded;
use crate::freq::topology::Graph;
use crate::freq::tree::Tree;
use num_complex::Complex64;
use std::f64::consts::PI;

/// Largest componentwise relative residual of an eigenpair that is reported.
pub const MAX_RESIDUAL: f64 = 1e-8;

/// A state-matrix eigenvalue may move this far (relative) when refined on the
/// pencil K + λC + λ²M whatever its neighbours.
pub const MAX_DRIFT: f64 = 1e-6;

/// Beyond `MAX_DRIFT`, it may move at most this share of the distance to
/// its nearest neighbour (and 1e-3 relative): then inverse iteration surely
/// refined the eigenvalue the state matrix found, not a neighbour, and no
/// mode is lost or counted twice. A larger move means the state matrix lost
/// that mode's digits and others may be missing: refused.
pub const DRIFT_SHARE_OF_GAP: f64 = 0.01;

/// Q(s) = K + sC + s²M solved by the fastest exact route for the topology.
pub(super) enum Pencil {
    Tree(Tree),
    Band(Banded),
}

impl Pencil {
    fn solve(&self, s: Complex64, b: &[Complex64]) -> Option<Vec<Complex64>> {
        let zero = Complex64::new(0.0, 0.0);
        let x = match self {
            Pencil::Tree(t) => t.solve(&t.factor(s), zero, b),
            Pencil::Band(band) => band.solve(&band.factor(s)?, s, zero, b),
        };
        x.iter().all(|z| z.is_finite()).then_some(x)
    }
}

/// Inverse iteration on the pencil from the state matrix's λ0, then the
/// two-sided Rayleigh functional (vᵀQ(λ)v = 0, the pencil being complex
/// symmetric), twice. Refuses when the result drifted from λ0 or its
/// residual is not small: then the state matrix cannot be trusted.
pub(super) fn refine(
    pencil: &Pencil,
    graph: &Graph,
    m: &[f64],
    lambda0: Complex64,
    gap: f64,
) -> Result<(Complex64, Vec<Complex64>), ModesError> {
    let n = m.len();
    let hz = lambda0.norm() / (2.0 * PI);
    let untrusted = |residual: f64| ModesError::Untrusted {
        hz,
        residual,
        limit: MAX_RESIDUAL,
    };
    let mut v = vec![Complex64::new(1.0, 0.0); n];
    let mut lambda = lambda0;
    for _ in 0..2 {
        // A shift a hair off λ keeps Q invertible but nearly singular.
        let mu = lambda * (1.0 + 1e-10) + Complex64::new(1e-12, 1e-12);
        for _ in 0..3 {
            let Some(y) = pencil.solve(mu, &v) else {
                return Err(untrusted(f64::INFINITY));
            };
            let norm = y.iter().map(|z| z.norm_sqr()).sum::<f64>().sqrt();
            if !(norm.is_finite() && norm > 0.0) {
                return Err(untrusted(f64::INFINITY));
            }
            v = y.iter().map(|z| z / norm).collect();
        }
        lambda = rayleigh(graph, m, &v, lambda);
    }
    if lambda0.im == 0.0 {
        lambda.im = 0.0;
    }
    if lambda0.re == 0.0 {
        lambda.re = 0.0;
    }
    let res = residual(graph, m, &v, lambda);
    if res.is_nan() || res > MAX_RESIDUAL {
        return Err(untrusted(res));
    }
    // Relative, with a floor of 1e-6 rad/s for a zero eigenvalue (a segment
    // held by dampers alone).
    let scale = lambda.norm().max(1e-6);
    let drift = (lambda - lambda0).norm() / scale;
    let allowed = MAX_DRIFT.max((DRIFT_SHARE_OF_GAP * gap / scale).min(1e-3));
    if drift.is_nan() || drift > allowed {
        return Err(ModesError::Drift {
            hz: lambda.norm() / (2.0 * PI),
            hz0: hz,
            drift,
        });
    }
    // Scale so the largest entry is 1 + 0j.
    let big = v
        .iter()
        .copied()
        .max_by(|a, b| a.norm().total_cmp(&b.norm()))
        .unwrap_or(Complex64::new(1.0, 0.0));
    Ok((lambda, v.iter().map(|z| z / big).collect()))
}

/// The root nearest `near` of (vᵀMv)λ² + (vᵀCv)λ + vᵀKv = 0.
fn rayleigh(graph: &Graph, m: &[f64], v: &[Complex64], near: Complex64) -> Complex64 {
    let a: Complex64 = m.iter().zip(v).map(|(&m, &x)| x * x * m).sum();
    let (mut b, mut c) = (Complex64::new(0.0, 0.0), Complex64::new(0.0, 0.0));
    for e in &graph.edges {
        let d = v[e.a] - e.b.map_or(Complex64::new(0.0, 0.0), |j| v[j]);
        b += d * d * e.c;
        c += d * d * e.k;
    }
    let disc = (b * b - a * c * 4.0).sqrt();
    // The numerically stable pair of roots.
    let q = if (b.conj() * disc).re >= 0.0 {
        -(b + disc) * 0.5
    } else {
        -(b - disc) * 0.5
    };
    let r1 = q / a;
    let r2 = if q.norm_sqr() > 0.0 { c / q } else { r1 };
    if (r1 - near).norm() <= (r2 - near).norm() {
        r1
    } else {
        r2
    }
}

/// Relative residual of an eigenpair of K + λC + λ²M, force by force:
/// Σ_i |v_i|·|r_i| / Σ_i |v_i|·s_i with r = Q(λ)v and s_i the sum of the
/// magnitudes of the forces on segment i (inertia |λ²m_i v_i| and each link's
/// |z|·|v_i − v_j|, plus the rounding of that difference). Weighting by |v_i|
/// ignores segments the mode barely moves (their entries are rounding
/// noise); measuring link forces by the stretch, not by k·|v|, keeps a stiff
/// link from hiding errors in every other force, which a normwise residual
/// ‖Q(λ)v‖ / ((‖K‖ + |λ|‖C‖ + |λ|²‖M‖)‖v‖) would let through.
fn residual(graph: &Graph, m: &[f64], v: &[Complex64], lambda: Complex64) -> f64 {
    let n = m.len();
    let l2 = lambda * lambda;
    let mut r: Vec<Complex64> = (0..n).map(|i| v[i] * l2 * m[i]).collect();
    let mut scale: Vec<f64> = (0..n).map(|i| v[i].norm() * l2.norm() * m[i]).collect();
    let zero = Complex64::new(0.0, 0.0);
    for e in &graph.edges {
        let z = lambda * e.c + e.k;
        let vb = e.b.map_or(zero, |j| v[j]);
        let stretch = v[e.a] - vb;
        let f = z * stretch;
        let fs = z.norm() * (stretch.norm() + 4.0 * f64::EPSILON * (v[e.a].norm() + vb.norm()));
        r[e.a] += f;
        scale[e.a] += fs;
        if let Some(j) = e.b {
            r[j] -= f;
            scale[j] += fs;
        }
    }
    let (mut num, mut den) = (0.0, 0.0);
    for i in 0..n {
        let w = v[i].norm();
        num += w * r[i].norm();
        den += w * scale[i];
    }
    if den > 0.0 { num / den } else { f64::INFINITY }
}
