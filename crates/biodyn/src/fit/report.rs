//! What a fit found: values, approximate 95 % intervals, correlations,
//! residuals per column and the main peaks, from the best start.
//!
//! The covariance of ln p is the least-squares one, (JᵀJ)⁻¹ scaled by the
//! residual variance, with one refinement: each data column gets its own
//! residual variance s_c² = Σ_c r² / (m_c (m − p)/m), since a measured STHT
//! is rarely exactly as noisy as a measured APMS. The covariance is then
//! (JᵀJ)⁻¹ (Σ s_c² J_iᵀJ_i) (JᵀJ)⁻¹, which is s²(JᵀJ)⁻¹ when every column
//! has the same s² = Σr²/(m − p). The inverse is taken on JᵀJ scaled to unit
//! diagonal, through its eigenvalues; a direction whose eigenvalue is below
//! 1e-12 of the largest is one the data do not see, and every parameter with
//! a share in it gets an unbounded interval.
//!
//! A linearised interval sees one minimum only. When another start ends in
//! a different minimum whose cost is within χ²₁(95 %)·s² of the best, its
//! values lie inside each parameter's profile-likelihood 95 % interval, so
//! the reported interval is widened to take them in (`widened`): the data
//! cannot choose between the two, and the report must say so.

use super::data::{Measured, Quantity};
use super::error::FitError;
use super::free::FreeParam;
use super::lm::normal_equations;
use super::residual::Engine;
use super::settings::Settings;
use crate::body::model::{Body, Param};
use crate::freq::function::Function;
use crate::freq::peaks::main_peak;
use crate::freq::response::Solver;
use nalgebra::{DMatrix, SymmetricEigen};
use std::time::Instant;

/// z of a two-sided 95 % normal interval.
pub const Z95: f64 = 1.959_963_984_540_054;
/// A parameter is determined when its interval lies within this factor of its value.
pub const DETERMINED_FACTOR: f64 = 2.0;
/// 95 % quantile of χ² with one degree of freedom (= Z95²).
pub const CHI2_1_95: f64 = Z95 * Z95;

/// One fitted parameter.
#[derive(Debug, Clone, PartialEq)]
pub struct ParamFit {
    pub name: String,
    pub param: Param,
    pub unit: &'static str,
    pub start: f64,
    pub value: f64,
    /// Standard error of ln value (infinite when the data do not see it).
    pub sd_ln: f64,
    pub ci95_low: f64,
    /// Infinite when not determined at all.
    pub ci95_high: f64,
    /// The interval lies within a factor of 2 of the value.
    pub determined: bool,
    /// The value sits on a bound of its box.
    pub at_bound: bool,
    /// The interval was widened to reach another start's minimum that fits
    /// the data as well, within the noise.
    pub widened: bool,
}

/// Residual r.m.s. of one data column, unweighted: for a magnitude the
/// r.m.s. of ln(model/data) (≈ a relative error), for a phase in degrees.
#[derive(Debug, Clone, PartialEq)]
pub struct ColumnRms {
    pub column: String,
    pub rms: f64,
}

/// The main peak of a measured magnitude and of the fitted model, side by side.
#[derive(Debug, Clone, PartialEq)]
pub struct PeakPair {
    pub function: Function,
    pub data_f_hz: f64,
    pub data_mag: f64,
    /// The data's largest value is at an end of its range, not a resonance.
    pub data_at_edge: bool,
    pub model_f_hz: f64,
    pub model_mag: f64,
    pub model_at_edge: bool,
}

/// The result of a fit.
#[derive(Debug, Clone, PartialEq)]
pub struct Fit {
    /// The start body with the fitted values.
    pub body: Body,
    pub params: Vec<ParamFit>,
    /// Correlations of the ln p estimates, in `params` order (NaN where a
    /// parameter is not determined at all).
    pub correlations: Vec<Vec<f64>>,
    /// Σr² at the best start.
    pub cost: f64,
    /// Residual variance s² = cost / (values − parameters).
    pub s2: f64,
    /// The final cost of every start, in order.
    pub start_costs: Vec<f64>,
    /// Starts whose cost is within `SAME_COST` (relative to the best cost) of the best.
    pub converged_starts: usize,
    pub settings: Settings,
    pub seconds: f64,
    /// Rows of the data file and measured values in it.
    pub points: usize,
    pub values: usize,
    pub columns: Vec<String>,
    pub residual_rms: Vec<ColumnRms>,
    pub peaks: Vec<PeakPair>,
}

impl Fit {
    /// The parameters the data do not determine.
    pub fn undetermined(&self) -> Vec<&ParamFit> {
        self.params.iter().filter(|p| !p.determined).collect()
    }
}

#[allow(clippy::too_many_arguments)]
pub(crate) fn build(
    body: &Body,
    data: &Measured,
    free: &[FreeParam],
    engine: &mut Engine,
    best: &[f64],
    start_costs: Vec<f64>,
    ends: &[Vec<f64>],
    converged_starts: usize,
    settings: Settings,
    clock: Instant,
) -> Result<Fit, FitError> {
    let (m, p) = (engine.m(), engine.p());
    let mut r = vec![0.0; m];
    let mut jac = vec![0.0; m * p];
    let cost = engine.eval(best, &mut r, Some(&mut jac));
    let s2 = cost / (m - p) as f64;
    let mut h = vec![0.0; p * p];
    let mut g = vec![0.0; p];
    normal_equations(&jac, &r, m, p, &mut h, &mut g);
    // Residual variance per column, the p degrees of freedom shared in proportion.
    let mut per = vec![(0.0, 0usize); data.columns.len()];
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
    let (var, corr) = covariance(&h, &meat, p);

    let mut fitted = body.clone();
    let mut params = Vec::with_capacity(p);
    for (j, f) in free.iter().enumerate() {
        // On a bound, the bound itself (exp(ln x) need not give x back).
        let value = if best[j] == f.lo.ln() {
            f.lo
        } else if best[j] == f.hi.ln() {
            f.hi
        } else {
            best[j].exp()
        };
        fitted.set(f.param, value)?;
        let sd_ln = var[j].sqrt();
        let half = Z95 * sd_ln;
        let (mut low, mut high) = if sd_ln.is_finite() {
            (value * (-half).exp(), value * half.exp())
        } else {
            (0.0, f64::INFINITY)
        };
        let mut widened = false;
        for (theta, &c) in ends.iter().zip(&start_costs) {
            if c - cost <= CHI2_1_95 * s2 {
                let other = theta[j].exp();
                if other < low || other > high {
                    widened = true;
                    low = low.min(other);
                    high = high.max(other);
                }
            }
        }
        params.push(ParamFit {
            name: f.name.clone(),
            param: f.param,
            unit: f.param.unit(),
            start: f.start,
            value,
            sd_ln,
            ci95_low: low,
            ci95_high: high,
            determined: low >= value / DETERMINED_FACTOR && high <= value * DETERMINED_FACTOR,
            at_bound: value <= f.lo * (1.0 + 1e-12) || value >= f.hi * (1.0 - 1e-12),
            widened,
        });
    }

    // Unweighted residuals per column.
    let mut sums = vec![(0.0, 0usize); data.columns.len()];
    for (e, res) in engine.entries.iter().zip(&r) {
        let mut u = res / e.weight;
        if e.quantity == Quantity::Phase {
            u = u.to_degrees();
        }
        sums[e.column].0 += u * u;
        sums[e.column].1 += 1;
    }
    let residual_rms = data
        .columns
        .iter()
        .zip(&sums)
        .map(|(c, &(s, n))| ColumnRms {
            column: c.channel.key(),
            rms: (s / n.max(1) as f64).sqrt(),
        })
        .collect();

    let solver = Solver::new(&fitted);
    let mut peaks = Vec::new();
    for col in &data.columns {
        if col.channel.quantity != Quantity::Mag {
            continue;
        }
        let pts: Vec<(f64, f64)> = data
            .f_hz
            .iter()
            .zip(&col.values)
            .filter_map(|(&f, v)| v.map(|v| (f, v)))
            .collect();
        let Some((df, dm, dedge)) = data_peak(&pts) else {
            continue;
        };
        let freqs: Vec<f64> = pts.iter().map(|q| q.0).collect();
        let curve = solver.sweep_freqs(&freqs);
        let Some(mp) = main_peak(&solver, &curve, col.channel.function) else {
            continue;
        };
        peaks.push(PeakPair {
            function: col.channel.function,
            data_f_hz: df,
            data_mag: dm,
            data_at_edge: dedge,
            model_f_hz: mp.f_hz,
            model_mag: mp.mag,
            model_at_edge: mp.at_edge,
        });
    }

    Ok(Fit {
        body: fitted,
        params,
        correlations: corr,
        cost,
        s2,
        start_costs,
        converged_starts,
        settings,
        seconds: clock.elapsed().as_secs_f64(),
        points: data.f_hz.len(),
        values: m,
        columns: data.column_names(),
        residual_rms,
        peaks,
    })
}

/// Variances of ln p and their correlations from H = JᵀJ and the middle
/// term B = Σ s_c² J_iᵀJ_i: cov = H⁻¹ B H⁻¹.
fn covariance(h: &[f64], meat: &[f64], p: usize) -> (Vec<f64>, Vec<Vec<f64>>) {
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
    let var = (0..p)
        .map(|j| {
            if blind[j] {
                f64::INFINITY
            } else {
                cov[(j, j)] / (d[j] * d[j])
            }
        })
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
    (var, corr)
}

/// The highest interior local maximum of measured points, or the larger end.
fn data_peak(pts: &[(f64, f64)]) -> Option<(f64, f64, bool)> {
    let interior = (1..pts.len().saturating_sub(1))
        .filter(|&i| pts[i].1 > pts[i - 1].1 && pts[i].1 >= pts[i + 1].1)
        .max_by(|&a, &b| pts[a].1.total_cmp(&pts[b].1));
    if let Some(i) = interior {
        return Some((pts[i].0, pts[i].1, false));
    }
    let (first, last) = (pts.first()?, pts.last()?);
    let e = if first.1 >= last.1 { first } else { last };
    Some((e.0, e.1, true))
}
