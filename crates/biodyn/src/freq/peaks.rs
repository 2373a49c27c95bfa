//! Resonance peaks of a response magnitude, refined off the grid.
//!
//! The grid maximum is only as good as the step; each local maximum is
//! refined by golden-section search on the analytic response between its
//! neighbours, to 1e-6 Hz.

use crate::band::Band;
use crate::freq::function::{Function, Response};
use crate::freq::response::Solver;
use serde::Serialize;

/// Frequency tolerance of the refined peak.
pub const PEAK_TOL_HZ: f64 = 1e-6;

#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Peak {
    pub function: Function,
    pub f_hz: f64,
    pub mag: f64,
    /// True when the largest value sits at a band edge (no interior maximum):
    /// the curve is still rising or falling there, so it is not a resonance.
    pub at_edge: bool,
    /// True when the resonance has no damping at all (the model is undamped,
    /// or this mode works no damper): the response grows without bound at
    /// `f_hz`, and `mag` is only its value where the search stopped, not a
    /// property of the body. Say "unbounded (undamped)", not the number.
    pub unbounded: bool,
}

/// Interior local maxima of |function| over the band, each refined, by frequency.
pub fn find_peaks(solver: &Solver, band: &Band, function: Function) -> Vec<Peak> {
    let curve = solver.sweep(band);
    find_peaks_in(solver, &curve, function)
}

/// As `find`, reusing a sweep already computed on a grid.
pub fn find_peaks_in(solver: &Solver, curve: &[Response], function: Function) -> Vec<Peak> {
    let mags: Vec<f64> = curve.iter().map(|r| r.mag(function)).collect();
    let mut peaks = Vec::new();
    for i in 1..mags.len().saturating_sub(1) {
        if mags[i] > mags[i - 1] && mags[i] >= mags[i + 1] {
            let (f_hz, mag) = refine(
                |f| solver.at(f).mag(function),
                curve[i - 1].f_hz,
                curve[i + 1].f_hz,
            );
            peaks.push(Peak {
                function,
                f_hz,
                mag,
                at_edge: false,
                unbounded: unbounded(solver, function, f_hz, mag),
            });
        }
    }
    peaks
}

/// The highest interior peak or, when there is none, the larger band edge
/// (flagged `at_edge`). None only for an empty curve.
pub fn main_peak(solver: &Solver, curve: &[Response], function: Function) -> Option<Peak> {
    let interior = find_peaks_in(solver, curve, function)
        .into_iter()
        .max_by(|a, b| a.mag.total_cmp(&b.mag));
    interior.or_else(|| {
        let first = curve.first()?;
        let last = curve.last()?;
        let edge = if first.mag(function) >= last.mag(function) {
            first
        } else {
            last
        };
        Some(Peak {
            function,
            f_hz: edge.f_hz,
            mag: edge.mag(function),
            at_edge: true,
            unbounded: false,
        })
    })
}

/// Loss factor below which a pole-like peak counts as undamped: a mode with
/// damping ratio ζ dissipates about 2ζ of what it stores per radian.
const UNDAMPED_LOSS: f64 = 1e-9;

/// A pole: |H| at the refined peak dwarfs |H| 1 mHz either side (a damped
/// peak that sharp needs ζ below about 1e-5), and the motion there works no
/// damper. Non-finite magnitudes are poles hit exactly.
fn unbounded(solver: &Solver, function: Function, f_hz: f64, mag: f64) -> bool {
    if mag.is_finite() {
        let near = solver
            .at(f_hz - 1e-3)
            .mag(function)
            .max(solver.at(f_hz + 1e-3).mag(function));
        let pole = mag > 100.0 * near;
        if !pole {
            return false;
        }
    }
    // NaN (a pole hit exactly) counts as no damping.
    let damped = solver.loss_factor(f_hz) > UNDAMPED_LOSS;
    solver.undamped() || !damped
}

/// Golden-section search for the maximum of a unimodal `g` on [a, b].
fn refine(g: impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> (f64, f64) {
    let r = (5f64.sqrt() - 1.0) / 2.0;
    let mut x1 = b - r * (b - a);
    let mut x2 = a + r * (b - a);
    let mut g1 = g(x1);
    let mut g2 = g(x2);
    while b - a > PEAK_TOL_HZ {
        if g1 < g2 {
            a = x1;
            x1 = x2;
            g1 = g2;
            x2 = a + r * (b - a);
            g2 = g(x2);
        } else {
            b = x2;
            x2 = x1;
            g2 = g1;
            x1 = b - r * (b - a);
            g1 = g(x1);
        }
    }
    let f = 0.5 * (a + b);
    (f, g(f))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::body::model::Body;

    #[test]
    fn refine_finds_parabola_top() {
        let (f, g) = refine(|x| 3.0 - (x - 1.2345678).powi(2), 1.0, 1.5);
        assert!((f - 1.2345678).abs() < 1e-6 && (g - 3.0).abs() < 1e-12);
    }

    #[test]
    fn peaks_are_off_grid_and_beat_the_grid_samples() {
        let s = Solver::new(&Body::paper(75.0).unwrap());
        let band = Band::default();
        let curve = s.sweep(&band);
        for func in Function::ALL {
            let p = main_peak(&s, &curve, func).unwrap();
            assert!(!p.at_edge);
            let grid_max = curve.iter().map(|r| r.mag(func)).fold(0.0, f64::max);
            assert!(p.mag >= grid_max, "{func:?}");
            // Neighbours 1e-4 Hz away are lower: a true maximum.
            assert!(s.at(p.f_hz - 1e-4).mag(func) < p.mag);
            assert!(s.at(p.f_hz + 1e-4).mag(func) < p.mag);
        }
    }
}
