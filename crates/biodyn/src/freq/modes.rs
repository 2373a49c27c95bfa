//! Modes of the body with the seat held still (SPEC §2).
//!
//! The damped modes come from the eigenvalues of the 2n×2n state matrix
//! [[0, I], [−M⁻¹K, −M⁻¹C]]; a complex-conjugate pair is one oscillatory mode,
//! a real root is an overdamped mode and is reported, never dropped (the
//! paper's model has four). Undamped natural frequencies come from M⁻¹K.

use crate::body::model::Body;
use crate::freq::banded::Banded;
use crate::freq::topology::Graph;
use crate::freq::tree::Tree;
use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;
use serde::Serialize;
use std::f64::consts::PI;

/// Largest model analysed: the 2n×2n state matrix's eigenvalues cost
/// O(n³) time (3.3 s for a 400-segment chain in a release build, so about
/// 6.5 s at 500) and 32·n² bytes. Responses and peaks have no such limit.
pub const MODES_MAX: usize = 500;

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

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ModesError {
    #[error(
        "the eigenvalue solver did not converge for this model: check for extreme parameter ratios"
    )]
    NoConvergence,
    #[error(
        "modes of a {segments}-segment model are not computed: the state-matrix eigenvalue solve grows as n³ (limit {max} segments, several seconds there); responses and peaks work at any size"
    )]
    TooBig { segments: usize, max: usize },
    #[error(
        "mode near {} Hz cannot be trusted (relative residual {residual:.1e}, limit {limit:.0e}): the model's masses and stiffnesses span too many orders of magnitude for the eigenvalue solve; bring the extreme values closer (e.g. a rigid joint is well modelled by 1e9 N/m)",
        hz_text(*.hz)
    )]
    Untrusted { hz: f64, residual: f64, limit: f64 },
    #[error(
        "mode near {} Hz cannot be trusted: the state matrix puts it at {} Hz, the pencil K + λC + λ²M at {} Hz (relative gap {drift:.1e}, more than its neighbours allow): the model's masses and stiffnesses span too many orders of magnitude for the eigenvalue solve; bring the extreme values closer",
        hz_text(*.hz),
        hz_exact(*.hz0),
        hz_exact(*.hz)
    )]
    Drift { hz: f64, hz0: f64, drift: f64 },
    #[error(
        "the links of this model form loops too wide for the band solver used to refine the modes: use fewer cross links"
    )]
    LoopsTooWide,
}

/// One eigenvalue of the state matrix, classified.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum ModeKind {
    /// A complex pair λ, λ̄: the body rings at `damped_hz`.
    Oscillatory {
        damped_hz: f64,
        natural_hz: f64,
        damping_ratio: f64,
    },
    /// A real root λ = −rate (1/s): decays without oscillating.
    Overdamped { rate_per_s: f64, natural_hz: f64 },
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Mode {
    #[serde(skip)]
    pub eigenvalue: Complex64,
    #[serde(flatten)]
    pub kind: ModeKind,
    /// Displacement of each segment, scaled so the largest is 1 (complex for
    /// a damped oscillatory mode; magnitudes in `shape_mag`).
    #[serde(skip)]
    pub shape: Vec<Complex64>,
    pub shape_mag: Vec<f64>,
}

impl Mode {
    pub fn natural_hz(&self) -> f64 {
        match self.kind {
            ModeKind::Oscillatory { natural_hz, .. } | ModeKind::Overdamped { natural_hz, .. } => {
                natural_hz
            }
        }
    }
}

/// An undamped normal mode: frequency and real shape (largest entry 1).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct UndampedMode {
    pub natural_hz: f64,
    pub shape: Vec<f64>,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Modes {
    /// Damped modes, by natural frequency.
    pub damped: Vec<Mode>,
    /// Undamped modes, by frequency.
    pub undamped: Vec<UndampedMode>,
}

/// Q(s) = K + sC + s²M solved by the fastest exact route for the topology.
enum Pencil {
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

/// Eigen-analysis of a valid body; refuses above `MODES_MAX` segments and
/// whenever an eigenpair fails the residual or drift check.
pub fn analyse(body: &Body) -> Result<Modes, ModesError> {
    let n = body.n();
    if n > MODES_MAX {
        return Err(ModesError::TooBig {
            segments: n,
            max: MODES_MAX,
        });
    }
    let m: Vec<f64> = body.segments.iter().map(|s| s.mass).collect();
    let graph = Graph::of(body);
    let pencil = match Tree::of(&graph, &m, body.head) {
        Some(t) => Pencil::Tree(t),
        None => {
            let b = Banded::of(&graph, &m);
            if !b.affordable() {
                return Err(ModesError::LoopsTooWide);
            }
            Pencil::Band(b)
        }
    };
    let (k, c) = dense(&graph);

    // Mass-normalised coordinates y = M^½ x give K̃ = M^-½ K M^-½ (and C̃),
    // and balancing the state matrix evens out rows that a light, stiff
    // segment would otherwise make dominate every other mode's digits.
    let s = DVector::from_iterator(n, m.iter().map(|x| 1.0 / x.sqrt()));
    let kt = DMatrix::from_fn(n, n, |i, j| s[i] * k[(i, j)] * s[j]);
    let ct = DMatrix::from_fn(n, n, |i, j| s[i] * c[(i, j)] * s[j]);
    let mut a = DMatrix::<f64>::zeros(2 * n, 2 * n);
    for i in 0..n {
        a[(i, n + i)] = 1.0;
        for j in 0..n {
            a[(n + i, j)] = -kt[(i, j)];
            a[(n + i, n + j)] = -ct[(i, j)];
        }
    }
    nalgebra::linalg::balancing::balance_parlett_reinsch(&mut a);
    let eig = a
        .try_schur(1e-14, 10_000 + 100 * n)
        .ok_or(ModesError::NoConvergence)?
        .complex_eigenvalues();

    let mut damped = Vec::new();
    let gap_of = |l: Complex64| {
        eig.iter()
            .map(|&o| (o - l).norm())
            .filter(|&d| d > 0.0)
            .fold(f64::INFINITY, f64::min)
    };
    for &lambda0 in eig.iter() {
        let mag = lambda0.norm();
        let real = lambda0.im.abs() <= 1e-9 * mag.max(1.0);
        if !real && lambda0.im < 0.0 {
            continue; // the conjugate of a pair already listed
        }
        let lambda0 = if real {
            Complex64::new(lambda0.re, 0.0)
        } else {
            lambda0
        };
        let (lambda, shape) = refine(&pencil, &graph, &m, lambda0, gap_of(lambda0))?;
        let mag = lambda.norm();
        let kind = if real {
            ModeKind::Overdamped {
                rate_per_s: -lambda.re,
                natural_hz: mag / (2.0 * PI),
            }
        } else {
            ModeKind::Oscillatory {
                damped_hz: lambda.im / (2.0 * PI),
                natural_hz: mag / (2.0 * PI),
                damping_ratio: -lambda.re / mag,
            }
        };
        damped.push(Mode {
            eigenvalue: lambda,
            kind,
            shape_mag: shape.iter().map(|z| z.norm()).collect(),
            shape,
        });
    }
    damped.sort_by(|x, y| x.natural_hz().total_cmp(&y.natural_hz()));

    // Undamped: symmetric form M^-1/2 K M^-1/2 keeps the eigenvectors
    // orthogonal; each is then refined and checked on K − ω²M like the
    // damped ones (a light segment's tiny entries need it).
    let mut stiff = graph.clone();
    for e in &mut stiff.edges {
        e.c = 0.0;
    }
    let pencil_u = match pencil {
        Pencil::Tree(_) => {
            Pencil::Tree(Tree::of(&stiff, &m, body.head).ok_or(ModesError::NoConvergence)?)
        }
        Pencil::Band(_) => Pencil::Band(Banded::of(&stiff, &m)),
    };
    let se = kt.symmetric_eigen();
    let roots: Vec<f64> = se
        .eigenvalues
        .iter()
        .map(|&w2| w2.max(0.0).sqrt())
        .collect();
    let mut undamped = Vec::with_capacity(n);
    for &w in &roots {
        // ±jω are the pencil's eigenvalues: the nearest neighbour of jω is
        // another root or −jω.
        let gap = roots
            .iter()
            .map(|&o| (o - w).abs())
            .filter(|&d| d > 0.0)
            .fold(2.0 * w, f64::min);
        let lambda0 = Complex64::new(0.0, w);
        let (lambda, shape) = refine(&pencil_u, &stiff, &m, lambda0, gap)?;
        undamped.push(UndampedMode {
            natural_hz: lambda.im.abs() / (2.0 * PI),
            shape: normalise_real(shape.iter().map(|z| z.re).collect()),
        });
    }
    undamped.sort_by(|x, y| x.natural_hz.total_cmp(&y.natural_hz));
    Ok(Modes { damped, undamped })
}

/// Dense K and C from the merged links.
fn dense(graph: &Graph) -> (DMatrix<f64>, DMatrix<f64>) {
    let n = graph.n;
    let mut k = DMatrix::zeros(n, n);
    let mut c = DMatrix::zeros(n, n);
    for e in &graph.edges {
        k[(e.a, e.a)] += e.k;
        c[(e.a, e.a)] += e.c;
        if let Some(b) = e.b {
            k[(b, b)] += e.k;
            c[(b, b)] += e.c;
            k[(e.a, b)] -= e.k;
            k[(b, e.a)] -= e.k;
            c[(e.a, b)] -= e.c;
            c[(b, e.a)] -= e.c;
        }
    }
    (k, c)
}

/// Inverse iteration on the pencil from the state matrix's λ0, then the
/// two-sided Rayleigh functional (vᵀQ(λ)v = 0, the pencil being complex
/// symmetric), twice. Refuses when the result drifted from λ0 or its
/// residual is not small: then the state matrix cannot be trusted.
fn refine(
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

fn normalise_real(v: Vec<f64>) -> Vec<f64> {
    let big = v
        .iter()
        .copied()
        .max_by(|a, b| a.abs().total_cmp(&b.abs()))
        .unwrap_or(1.0);
    v.into_iter().map(|x| x / big).collect()
}

/// A frequency for a message, 4 significant digits: fixed decimals read
/// 0.000000 Hz for a mode near 1e-7 Hz.
fn hz_text(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let a = v.abs();
    if !(1e-3..1e6).contains(&a) {
        return format!("{v:.3e}");
    }
    let decimals = (3 - a.log10().floor() as i32).max(0) as usize;
    format!("{v:.decimals$}")
}

/// A frequency with 7 significant digits, where two close values are compared.
fn hz_exact(v: f64) -> String {
    format!("{v:.6e}")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::body::model::{Body, Segment};
    use crate::freq::response::Solver;

    #[test]
    fn a_mode_message_gives_four_significant_digits_at_any_size() {
        let e = |hz| {
            ModesError::Untrusted {
                hz,
                residual: 1e-3,
                limit: 1e-8,
            }
            .to_string()
        };
        assert!(
            e(1.234e-7).starts_with("mode near 1.234e-7 Hz"),
            "{}",
            e(1.234e-7)
        );
        assert!(e(5.2).starts_with("mode near 5.200 Hz"), "{}", e(5.2));
        assert!(e(1432.0).starts_with("mode near 1432 Hz"), "{}", e(1432.0));
    }

    fn br1998() -> Body {
        let masses = [5.31, 28.49, 8.62, 12.78];
        let segs = crate::body::model::PAPER_SEGMENTS
            .iter()
            .zip(masses)
            .map(|(n, m)| Segment {
                name: n.to_string(),
                mass: m,
                share: None,
            })
            .collect();
        Body::chain(
            segs,
            &crate::body::model::PAPER_K,
            &crate::body::model::PAPER_C,
        )
    }

    #[test]
    fn boileau_rakheja_modes_match_reference() {
        let modes = analyse(&br1998()).unwrap();
        let und: Vec<f64> = modes.undamped.iter().map(|u| u.natural_hz).collect();
        for (got, want) in und.iter().zip([5.11, 18.61, 35.42, 42.52]) {
            assert!((got - want).abs() < 0.006, "{und:?}");
        }
        let osc: Vec<(f64, f64)> = modes
            .damped
            .iter()
            .filter_map(|m| match m.kind {
                // The reference quotes |λ|/2π, the damped mode's natural frequency.
                ModeKind::Oscillatory {
                    natural_hz,
                    damping_ratio,
                    ..
                } => Some((natural_hz, damping_ratio)),
                _ => None,
            })
            .collect();
        assert_eq!(osc.len(), 2, "{osc:?}");
        assert!((osc[0].0 - 5.13).abs() < 0.006 && (osc[0].1 - 0.394).abs() < 6e-4);
        assert!((osc[1].0 - 41.1).abs() < 0.06 && (osc[1].1 - 0.186).abs() < 6e-4);
        let mut rates: Vec<f64> = modes
            .damped
            .iter()
            .filter_map(|m| match m.kind {
                ModeKind::Overdamped { rate_per_s, .. } => Some(rate_per_s),
                _ => None,
            })
            .collect();
        rates.sort_by(f64::total_cmp);
        for (got, want) in rates.iter().zip([37.8, 45.5, 311.7, 1342.9]) {
            assert!((got - want).abs() < 0.06, "{rates:?}");
        }
    }

    #[test]
    fn shapes_are_null_vectors_of_the_pencil() {
        let body = br1998();
        let s = Solver::new(&body);
        let modes = analyse(&body).unwrap();
        for mode in &modes.damped {
            let l = mode.eigenvalue;
            let k = s.stiffness_matrix();
            let c = s.damping_matrix();
            for i in 0..4 {
                let mut r = Complex64::new(0.0, 0.0);
                let mut scale = 0.0;
                for j in 0..4 {
                    let mut q = k[(i, j)] + l * c[(i, j)];
                    if i == j {
                        q += l * l * body.segments[i].mass;
                    }
                    r += q * mode.shape[j];
                    scale += q.norm() * mode.shape[j].norm();
                }
                assert!(r.norm() <= 1e-7 * scale, "residual {r} vs {scale}");
            }
        }
    }
}
