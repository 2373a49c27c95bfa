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
use refine::{Pencil, refine};
use serde::Serialize;
use std::f64::consts::PI;

mod error;
mod refine;

pub use error::ModesError;

/// Largest model analysed: the 2n×2n state matrix's eigenvalues cost
/// O(n³) time (3.3 s for a 400-segment chain in a release build, so about
/// 6.5 s at 500) and 32·n² bytes. Responses and peaks have no such limit.
pub const MODES_MAX: usize = 500;

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

/// Eigen-analysis of a valid body; refuses above `MODES_MAX` segments and
/// whenever an eigenpair fails the residual or drift check.
pub fn analyse_modes(body: &Body) -> Result<Modes, ModesError> {
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

fn normalise_real(v: Vec<f64>) -> Vec<f64> {
    let big = v
        .iter()
        .copied()
        .max_by(|a, b| a.abs().total_cmp(&b.abs()))
        .unwrap_or(1.0);
    v.into_iter().map(|x| x / big).collect()
}

#[cfg(test)]
mod tests;
