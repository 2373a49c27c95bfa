//! The 95 % intervals of a fit: the curvature at the best minimum, and the
//! profile-likelihood walks that start from it.
//!
//! **Curvature.** The covariance of ln p is the least-squares one, (JᵀJ)⁻¹
//! scaled by the residual variance, with one refinement: each data column
//! gets its own residual variance s_c² = Σ_c r² / (m_c (m − p)/m), since a
//! measured STHT is rarely exactly as noisy as a measured APMS. The
//! covariance is then (JᵀJ)⁻¹ (Σ s_c² J_iᵀJ_i) (JᵀJ)⁻¹, which is s²(JᵀJ)⁻¹
//! when every column has the same s² = Σr²/(m − p). The inverse is taken on
//! JᵀJ scaled to unit diagonal, through its eigenvalues; a direction whose
//! eigenvalue is below 1e-12 of the largest is one the data do not see, and
//! every parameter with a share in it gets an unbounded interval. The
//! curvature interval is ln p ± t(0.975; m − p)·σ.
//!
//! **Profile.** Each parameter's interval is where the cost, minimised over
//! the others, stays within Δ_j = F(0.95; 1, m − p)·s_j² of the best
//! ([`super::profile`] walks it). s_j² is the residual variance parameter j
//! sees: the ratio of its sandwich variance to its (JᵀJ)⁻¹ variance, which
//! is s² when all columns are equally noisy; so a parameter that phases
//! determine is judged by the phases' scatter, not by an average with the
//! magnitudes'. With the threshold from F rather than χ², few degrees of
//! freedom widen the interval as they should (3 values for 2 parameters: F
//! = 161, not 3.84).
//!
//! Another start's minimum within the joint 95 % region (cost within
//! p·F(0.95; p, m − p)·s² of the best) is a model the data do not reject:
//! its own profile interval joins the set ([`super::profile`]).
//!
//! Either way an end that reaches the parameter's box is no end: `None`.

use super::lm::{Workspace, normal_equations};
use super::profile::{self, Ends, Stopped, Task};
use super::quantile::{fisher_f, student_t};
use super::residual::Engine;
use nalgebra::{DMatrix, SymmetricEigen};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::mpsc;
use std::time::Duration;

/// The confidence level of every interval.
pub const LEVEL: f64 = 0.95;

/// How often the caller is asked whether to go on while the walks run.
const POLL: Duration = Duration::from_millis(50);

/// What the curvature at the best point says.
pub(crate) struct Curvature {
    pub cost: f64,
    pub s2: f64,
    /// t(0.975; m − p).
    pub t: f64,
    /// p·F(0.95; p, m − p)·s²: the joint 95 % region's reach above the
    /// best cost; a minimum inside it is one the data do not reject.
    pub joint: f64,
    /// Sandwich standard error of ln p (infinite where unseen).
    pub sd_ln: Vec<f64>,
    /// Residual variance each parameter sees (s² where unseen).
    pub s2_param: Vec<f64>,
    pub corr: Vec<Vec<f64>>,
    /// Residuals at the best point.
    pub r: Vec<f64>,
}

impl Curvature {
    /// F(0.95; 1, m − p) = t².
    pub fn q(&self) -> f64 {
        self.t * self.t
    }

    /// Profile threshold of parameter j above the best cost.
    pub fn delta(&self, j: usize) -> f64 {
        self.q() * self.s2_param[j]
    }

    /// The curvature interval of parameter j at `theta`, in ln p, cut at
    /// the box: None where it reaches it.
    pub fn ends(&self, j: usize, theta: f64, lo: f64, hi: f64) -> Ends {
        let half = self.t * self.sd_ln[j];
        let inside = |x: f64| half.is_finite() && x > lo && x < hi;
        let (l, h) = (theta - half, theta + half);
        Ends {
            pieces: vec![(inside(l).then_some(l), inside(h).then_some(h))],
            other_minimum: false,
        }
    }
}

pub(crate) fn curvature(engine: &mut Engine, columns: usize, best: &[f64]) -> Curvature {
    let (m, p) = (engine.m(), engine.p());
    let mut r = vec![0.0; m];
    let mut jac = vec![0.0; m * p];
    let cost = engine.eval(best, &mut r, Some(&mut jac));
    let s2 = cost / (m - p) as f64;
    let mut h = vec![0.0; p * p];
    let mut g = vec![0.0; p];
    normal_equations(&jac, &r, m, p, &mut h, &mut g);
    // Residual variance per column, the p degrees of freedom shared in proportion.
    let mut per = vec![(0.0, 0usize); columns];
    for (e, res) in engine.entries.iter().zip(&r) {
        per[e.column].0 += res * res;
        per[e.column].1 += 1;
    }
    let dof = (m - p) as f64 / m as f64;
    let s2_col: Vec<f64> = per
        .iter()
        .map(|&(ss, n)| if n > 0 { ss / (n as f64 * dof) } else { 0.0 })
        .collect();
    let mut meat = vec![0.0; p * p];
    for a in 0..p {
        for b in 0..p {
            meat[a * p + b] = engine
                .entries
                .iter()
                .enumerate()
                .map(|(i, e)| s2_col[e.column] * jac[a * m + i] * jac[b * m + i])
                .sum();
        }
    }
    let cov = covariance(&h, &meat, p);
    let s2_param = cov
        .var
        .iter()
        .zip(&cov.naive)
        .map(|(&v, &n)| {
            let s = v / n;
            if s.is_finite() && s > 0.0 { s } else { s2 }
        })
        .collect();
    Curvature {
        cost,
        s2,
        t: student_t(LEVEL, (m - p) as f64),
        joint: p as f64 * fisher_f(LEVEL, p as f64, (m - p) as f64) * s2,
        sd_ln: cov.var.iter().map(|v| v.sqrt()).collect(),
        s2_param,
        corr: cov.corr,
        r,
    }
}

/// The profile ends of every parameter, walked on up to `threads` threads
/// (each parameter's walk depends on nothing but its index: which thread
/// runs it changes no bit). `go` is asked after each parameter and at
/// least every 50 ms; false stops the walks (within one minimisation).
#[allow(clippy::too_many_arguments)]
pub(crate) fn profiles(
    engine: &Engine,
    curv: &Curvature,
    lo: &[f64],
    hi: &[f64],
    best: &[f64],
    minima: &[(f64, Vec<f64>)],
    threads: usize,
    go: &mut dyn FnMut(usize) -> bool,
) -> Result<Vec<Ends>, Stopped> {
    let (m, p) = (engine.m(), engine.p());
    let stop = AtomicBool::new(false);
    let next = AtomicUsize::new(0);
    let task = Task {
        lo,
        hi,
        best,
        cost: curv.cost,
        minima,
        plausible: curv.cost + curv.joint,
        stop: &stop,
    };
    let run = |j: usize, engine: &mut Engine, ws: &mut Workspace| {
        profile::ends(engine, ws, &task, j, curv.delta(j), curv.t * curv.sd_ln[j])
    };
    let mut out: Vec<Option<Ends>> = vec![None; p];
    let mut done = 0;
    let mut stopped = false;
    std::thread::scope(|scope| {
        let (tx, rx) = mpsc::channel::<(usize, Result<Ends, Stopped>)>();
        let mut spawned = 0;
        for _ in 0..threads.clamp(1, p) {
            let (tx, mut engine, next, run) = (tx.clone(), engine.clone(), &next, &run);
            let worker = std::thread::Builder::new().spawn_scoped(scope, move || {
                let mut ws = Workspace::new(m, p);
                loop {
                    let j = next.fetch_add(1, Ordering::Relaxed);
                    if j >= p {
                        break;
                    }
                    let e = run(j, &mut engine, &mut ws);
                    let failed = e.is_err();
                    if tx.send((j, e)).is_err() || failed {
                        break;
                    }
                }
            });
            spawned += usize::from(worker.is_ok());
        }
        drop(tx);
        if spawned == 0 {
            // No thread to be had: walk here, asking between parameters.
            let (mut engine, mut ws) = (engine.clone(), Workspace::new(m, p));
            for (j, slot) in out.iter_mut().enumerate() {
                match run(j, &mut engine, &mut ws) {
                    Ok(e) => *slot = Some(e),
                    Err(Stopped) => stopped = true,
                }
                done += 1;
                if stopped || !go(done) {
                    stopped = true;
                    return;
                }
            }
            return;
        }
        while done < p {
            match rx.recv_timeout(POLL) {
                Ok((j, Ok(e))) => {
                    out[j] = Some(e);
                    done += 1;
                }
                Ok((_, Err(Stopped))) | Err(mpsc::RecvTimeoutError::Disconnected) => {
                    stopped = true;
                    break;
                }
                Err(mpsc::RecvTimeoutError::Timeout) => {}
            }
            if !go(done) {
                stopped = true;
                break;
            }
        }
        stop.store(true, Ordering::Relaxed);
    });
    if stopped {
        return Err(Stopped);
    }
    out.into_iter().map(|e| e.ok_or(Stopped)).collect()
}

/// Sandwich variances of ln p, their correlations, and the plain (JᵀJ)⁻¹
/// variances (per unit residual variance).
struct Covariance {
    var: Vec<f64>,
    naive: Vec<f64>,
    corr: Vec<Vec<f64>>,
}

/// From H = JᵀJ and the middle term B = Σ s_c² J_iᵀJ_i: cov = H⁻¹ B H⁻¹.
fn covariance(h: &[f64], meat: &[f64], p: usize) -> Covariance {
    let d: Vec<f64> = (0..p).map(|j| h[j * p + j].sqrt()).collect();
    let live: Vec<bool> = d.iter().map(|&x| x > 0.0 && x.is_finite()).collect();
    let scale = |m: &[f64], i: usize, j: usize| {
        if live[i] && live[j] {
            m[i * p + j] / (d[i] * d[j])
        } else {
            0.0
        }
    };
    let scaled = DMatrix::from_fn(p, p, |i, j| {
        if !live[i] && i == j {
            1.0
        } else {
            scale(h, i, j)
        }
    });
    let eig = SymmetricEigen::new(scaled);
    let top = eig.eigenvalues.iter().copied().fold(0.0, f64::max);
    let mut inv = DMatrix::<f64>::zeros(p, p);
    let mut blind: Vec<bool> = live.iter().map(|l| !l).collect();
    for (k, &lambda) in eig.eigenvalues.iter().enumerate() {
        let v = eig.eigenvectors.column(k);
        if lambda > 1e-12 * top {
            inv += v * v.transpose() / lambda;
        } else {
            for j in 0..p {
                if v[j].abs() > 1e-6 {
                    blind[j] = true;
                }
            }
        }
    }
    let b = DMatrix::from_fn(p, p, |i, j| scale(meat, i, j));
    let cov = &inv * b * &inv;
    // Exactly symmetric, whatever the rounding of the products.
    let cov = (&cov + cov.transpose()) * 0.5;
    let unseen = |j: usize, x: f64| if blind[j] { f64::INFINITY } else { x };
    let var = (0..p)
        .map(|j| unseen(j, cov[(j, j)] / (d[j] * d[j])))
        .collect();
    let naive = (0..p)
        .map(|j| unseen(j, inv[(j, j)] / (d[j] * d[j])))
        .collect();
    let corr = (0..p)
        .map(|i| {
            (0..p)
                .map(|j| {
                    if blind[i] || blind[j] {
                        f64::NAN
                    } else if i == j {
                        1.0
                    } else {
                        cov[(i, j)] / (cov[(i, i)] * cov[(j, j)]).sqrt()
                    }
                })
                .collect()
        })
        .collect();
    Covariance { var, naive, corr }
}
