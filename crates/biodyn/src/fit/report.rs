//! What a fit found: values, 95 % intervals (profile likelihood or
//! curvature, [`super::interval`]), correlations, residuals per column and
//! the main peaks, from the best start.

use super::data::{Measured, Quantity};
use super::error::FitError;
use super::free::FreeParam;
use super::interval::Curvature;
use super::profile::Ends;
use super::residual::Engine;
use super::settings::Settings;
use crate::body::model::{Body, Param};
use crate::freq::function::Function;
use crate::freq::peaks::main_peak;
use crate::freq::response::Solver;
use std::time::Instant;

/// A parameter is determined when its interval lies within this factor of its value.
pub const DETERMINED_FACTOR: f64 = 2.0;

/// One fitted parameter.
#[derive(Debug, Clone, PartialEq)]
pub struct ParamFit {
    pub name: String,
    pub param: Param,
    pub unit: &'static str,
    pub start: f64,
    pub value: f64,
    /// Standard error of ln value from the curvature (infinite when the
    /// data do not see it).
    pub sd_ln: f64,
    /// The 95 % interval's ends; `None` where the interval reaches the
    /// parameter's box (the data do not bound it on that side). A finite
    /// end is always inside the box, so never 0 and never below the
    /// model's limits.
    pub ci95_low: Option<f64>,
    pub ci95_high: Option<f64>,
    /// The 95 % set as disjoint intervals in increasing order, ends as
    /// above: one, [low, high], unless another minimum the data do not
    /// reject has an interval of its own apart from the best's.
    pub ci95_pieces: Vec<(Option<f64>, Option<f64>)>,
    /// Both ends finite and within a factor of 2 of the value.
    pub determined: bool,
    /// The value sits on a bound of its box.
    pub at_bound: bool,
    /// The interval takes in another start's minimum that fits the data as
    /// well, within their scatter: the data cannot choose between them.
    pub other_minimum: bool,
}

impl ParamFit {
    /// Whether `x` lies in the 95 % set (an open end holds everything).
    pub fn covers(&self, x: f64) -> bool {
        self.ci95_pieces
            .iter()
            .any(|&(l, h)| l.is_none_or(|l| l <= x) && h.is_none_or(|h| x <= h))
    }

    /// Whether `x` lies between the ends, gaps of the set included.
    pub fn spans(&self, x: f64) -> bool {
        self.ci95_low.is_none_or(|l| l <= x) && self.ci95_high.is_none_or(|h| x <= h)
    }
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
    /// F(0.95; 1, values − parameters), the profile threshold over s²
    /// (its square root is the curvature interval's t).
    pub q95: f64,
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
    curv: Curvature,
    ends: &[Ends],
    start_costs: Vec<f64>,
    converged_starts: usize,
    settings: Settings,
    clock: Instant,
) -> Result<Fit, FitError> {
    let r = &curv.r;
    let mut fitted = body.clone();
    let mut params = Vec::with_capacity(free.len());
    for ((j, f), e) in free.iter().enumerate().zip(ends) {
        // On a bound, the bound itself (exp(ln x) need not give x back).
        let value = if best[j] == f.lo.ln() {
            f.lo
        } else if best[j] == f.hi.ln() {
            f.hi
        } else {
            best[j].exp()
        };
        fitted.set(f.param, value)?;
        // Inside the box (exp of an inner ln p may round onto it).
        let inside = |x: Option<f64>| x.map(|x| x.exp().clamp(f.lo, f.hi));
        let pieces: Vec<_> = e
            .pieces
            .iter()
            .map(|&(l, h)| (inside(l), inside(h)))
            .collect();
        let low = inside(e.low()).map(|l| l.min(value));
        let high = inside(e.high()).map(|h| h.max(value));
        let within = |x: Option<f64>, ok: &dyn Fn(f64) -> bool| x.is_some_and(ok);
        params.push(ParamFit {
            name: f.name.clone(),
            param: f.param,
            unit: f.param.unit(),
            start: f.start,
            value,
            sd_ln: curv.sd_ln[j],
            ci95_low: low,
            ci95_high: high,
            ci95_pieces: pieces,
            determined: within(low, &|l| l >= value / DETERMINED_FACTOR)
                && within(high, &|h| h <= value * DETERMINED_FACTOR),
            at_bound: value <= f.lo * (1.0 + 1e-12) || value >= f.hi * (1.0 - 1e-12),
            other_minimum: e.other_minimum,
        });
    }

    // Unweighted residuals per column.
    let mut sums = vec![(0.0, 0usize); data.columns.len()];
    for (e, res) in engine.entries.iter().zip(r) {
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
        correlations: curv.corr.clone(),
        cost: curv.cost,
        s2: curv.s2,
        q95: curv.q(),
        start_costs,
        converged_starts,
        settings,
        seconds: clock.elapsed().as_secs_f64(),
        points: data.f_hz.len(),
        values: r.len(),
        columns: data.column_names(),
        residual_rms,
        peaks,
    })
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
