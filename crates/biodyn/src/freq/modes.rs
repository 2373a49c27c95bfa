//! Modes of the body with the seat held still (SPEC §2).
//!
//! The damped modes come from the eigenvalues of the 2n×2n state matrix
//! [[0, I], [−M⁻¹K, −M⁻¹C]]; a complex-conjugate pair is one oscillatory mode,
//! a real root is an overdamped mode and is reported, never dropped (the
//! paper's model has four). Undamped natural frequencies come from M⁻¹K.

use crate::body::model::Body;
use crate::freq::response::Solver;
use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;
use serde::Serialize;
use std::f64::consts::PI;

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ModesError {
    #[error(
        "the eigenvalue solver did not converge for this model: check for extreme parameter ratios"
    )]
    NoConvergence,
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

/// Eigen-analysis of a valid body.
pub fn analyse(body: &Body) -> Result<Modes, ModesError> {
    let solver = Solver::new(body);
    let n = solver.n();
    let m: Vec<f64> = body.segments.iter().map(|s| s.mass).collect();
    let k = solver.stiffness_matrix();
    let c = solver.damping_matrix();

    let mut a = DMatrix::<f64>::zeros(2 * n, 2 * n);
    for i in 0..n {
        a[(i, n + i)] = 1.0;
        for j in 0..n {
            a[(n + i, j)] = -k[(i, j)] / m[i];
            a[(n + i, n + j)] = -c[(i, j)] / m[i];
        }
    }
    let eig = a
        .clone()
        .try_schur(1e-14, 10_000)
        .ok_or(ModesError::NoConvergence)?
        .complex_eigenvalues();

    let mut damped = Vec::new();
    for &lambda in eig.iter() {
        let mag = lambda.norm();
        let real = lambda.im.abs() <= 1e-9 * mag.max(1.0);
        let kind = if real {
            ModeKind::Overdamped {
                rate_per_s: -lambda.re,
                natural_hz: mag / (2.0 * PI),
            }
        } else if lambda.im > 0.0 {
            ModeKind::Oscillatory {
                damped_hz: lambda.im / (2.0 * PI),
                natural_hz: mag / (2.0 * PI),
                damping_ratio: -lambda.re / mag,
            }
        } else {
            continue; // the conjugate of a pair already listed
        };
        let lambda = if real {
            Complex64::new(lambda.re, 0.0)
        } else {
            lambda
        };
        let shape = shape_of(&m, k, c, lambda);
        damped.push(Mode {
            eigenvalue: lambda,
            kind,
            shape_mag: shape.iter().map(|z| z.norm()).collect(),
            shape,
        });
    }
    damped.sort_by(|x, y| x.natural_hz().total_cmp(&y.natural_hz()));

    // Undamped: symmetric form M^-1/2 K M^-1/2 keeps the eigenvectors orthogonal.
    let s = DVector::from_iterator(n, m.iter().map(|x| 1.0 / x.sqrt()));
    let sym = DMatrix::from_fn(n, n, |i, j| s[i] * k[(i, j)] * s[j]);
    let se = sym.symmetric_eigen();
    let mut undamped: Vec<UndampedMode> = (0..n)
        .map(|q| {
            let v: Vec<f64> = (0..n).map(|i| s[i] * se.eigenvectors[(i, q)]).collect();
            UndampedMode {
                natural_hz: se.eigenvalues[q].max(0.0).sqrt() / (2.0 * PI),
                shape: normalise_real(v),
            }
        })
        .collect();
    undamped.sort_by(|x, y| x.natural_hz.total_cmp(&y.natural_hz));
    Ok(Modes { damped, undamped })
}

/// Null vector of the quadratic pencil K + λC + λ²M by inverse iteration.
fn shape_of(m: &[f64], k: &DMatrix<f64>, c: &DMatrix<f64>, lambda: Complex64) -> Vec<Complex64> {
    let n = m.len();
    // A shift a hair off λ keeps the matrix invertible but nearly singular.
    let mu = lambda * (1.0 + 1e-10) + Complex64::new(1e-12, 1e-12);
    let q = DMatrix::from_fn(n, n, |i, j| {
        let mut z = k[(i, j)] + mu * c[(i, j)];
        if i == j {
            z += mu * mu * m[i];
        }
        z
    });
    let lu = q.lu();
    let mut x = DVector::from_element(n, Complex64::new(1.0, 0.0));
    for _ in 0..3 {
        match lu.solve(&x) {
            Some(y) => {
                let norm = y.norm();
                if !(norm.is_finite() && norm > 0.0) {
                    break;
                }
                x = y / Complex64::new(norm, 0.0);
            }
            None => break,
        }
    }
    // Scale so the largest entry is 1 + 0j.
    let big = x
        .iter()
        .copied()
        .max_by(|a, b| a.norm().total_cmp(&b.norm()))
        .unwrap_or(Complex64::new(1.0, 0.0));
    x.iter().map(|z| z / big).collect()
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
mod tests {
    use super::*;
    use crate::body::model::{Body, Segment};

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
