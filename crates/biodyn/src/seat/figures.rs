//! A seat's figures for a floor PSD G(f), in the frequency domain:
//!
//!   a_w,floor = √∫ G |W_k|² df,   a_w,pan = √∫ G |T|² |W_k|² df,
//!   SEAT % = 100 · a_w,pan / a_w,floor,
//!   r.m.s. travel = √∫ G |X_rel / A_floor|² df,  X_rel/A_floor = (H_s − 1)/(−ω²),
//!
//! T = H_pan the seat's transmissibility, H_s the motion of the suspension's
//! upper end per unit floor motion, W_k the ISO 2631-1 weighting (ISO 8041-1
//! Formula (5), band limits included). The integrals are Simpson's rule in
//! u = ln f on [`GRID_INTERVALS`] intervals over the PSD's range: a seat's
//! resonances (ζ ≳ 0.1) span tens of grid steps, and the grid is fixed per
//! PSD, so a design search compares every point on the same quadrature.

use super::error::SeatError;
use super::psd::FloorPsd;
use crate::body::model::Body;
use crate::freq::response::Solver;
use crate::iso2631::Weighting;
use std::f64::consts::PI;

/// Simpson intervals of the log-frequency grid (even).
pub const GRID_INTERVALS: usize = 400;

/// The quadrature of one floor PSD: nodes and G·|W_k|²·weight at each.
/// G is held relative to its largest node value, `scale`: SEAT does not
/// depend on the PSD's level, and a density of 1e-320 or 1e300 then loses
/// no precision to subnormals or overflow (the a_w and travel are scaled back).
#[derive(Debug, Clone)]
pub struct SeatGrid {
    f: Vec<f64>,
    /// Simpson weight × f (the Jacobian of u = ln f) × G(f)/scale.
    g_dw: Vec<f64>,
    scale: f64,
    /// Σ of the floor's weighted terms, relative to `scale`.
    weighted: f64,
    wk2: Vec<f64>,
    floor_aw: f64,
    psd: FloorPsd,
}

/// What `SeatGrid::figures` returns.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SeatFigures {
    /// 100 · a_w,pan / a_w,floor.
    pub seat_pct: f64,
    pub pan_aw_m_s2: f64,
    pub floor_aw_m_s2: f64,
    /// r.m.s. deflection of the suspension link, m.
    pub stroke_rms_m: f64,
    /// The travel end-stop to end-stop, m (the preset's `stroke_m`).
    pub stroke_available_m: f64,
}

impl SeatGrid {
    /// The grid over `psd`'s range.
    pub fn new(psd: &FloorPsd) -> Result<SeatGrid, SeatError> {
        let (lo, hi) = psd.range();
        let (u0, u1) = (lo.ln(), hi.ln());
        let n = GRID_INTERVALS;
        let du = (u1 - u0) / n as f64;
        let mut f = Vec::with_capacity(n + 1);
        let mut g = Vec::with_capacity(n + 1);
        let mut g_dw = Vec::with_capacity(n + 1);
        let mut wk2 = Vec::with_capacity(n + 1);
        for i in 0..=n {
            // The ends exactly: a table is 0 past its last row.
            let fi = match i {
                0 => lo,
                _ if i == n => hi,
                _ => (u0 + du * i as f64).exp(),
            };
            let simpson = match i {
                0 => 1.0,
                _ if i == n => 1.0,
                _ if i % 2 == 1 => 4.0,
                _ => 2.0,
            };
            f.push(fi);
            g.push(psd.at(fi));
            g_dw.push(fi * simpson * du / 3.0);
            wk2.push(Weighting::Wk.analog(fi).norm_sqr());
        }
        let scale = g.iter().copied().fold(0.0, f64::max);
        for (w, gi) in g_dw.iter_mut().zip(&g) {
            *w *= gi / scale;
        }
        let weighted: f64 = g_dw.iter().zip(&wk2).map(|(g, w)| g * w).sum();
        // √scale apart: scale·Σ would be subnormal for a tiny PSD.
        let floor_aw = scale.sqrt() * weighted.sqrt();
        if !(floor_aw.is_finite() && floor_aw > 0.0) {
            return Err(SeatError::NoWeightedInput {
                from_hz: lo,
                to_hz: hi,
            });
        }
        Ok(SeatGrid {
            f,
            g_dw,
            scale,
            weighted,
            wk2,
            floor_aw,
            psd: psd.clone(),
        })
    }

    /// The PSD the grid integrates.
    pub fn psd(&self) -> &FloorPsd {
        &self.psd
    }

    /// a_w of the floor, m/s².
    pub fn floor_aw(&self) -> f64 {
        self.floor_aw
    }

    /// The grid's frequencies, Hz.
    pub fn freqs(&self) -> &[f64] {
        &self.f
    }

    /// SEAT, the pan's a_w and the r.m.s. travel of `body`'s seat.
    pub fn figures(&self, body: &Body) -> Result<SeatFigures, SeatError> {
        let seat = body.seat.as_ref().ok_or(SeatError::NoSeat)?;
        let upper = body.links[seat.suspension].upper;
        let solver = Solver::new(body);
        let (mut pan, mut travel) = (0.0, 0.0);
        for (i, &f) in self.f.iter().enumerate() {
            let h = solver.transfer(f);
            let w2 = (2.0 * PI * f).powi(2);
            pan += self.g_dw[i] * self.wk2[i] * h[seat.pan].norm_sqr();
            travel += self.g_dw[i] * (h[upper] - 1.0).norm_sqr() / (w2 * w2);
        }
        let root = self.scale.sqrt();
        let pan_aw = root * pan.sqrt();
        Ok(SeatFigures {
            seat_pct: 100.0 * (pan / self.weighted).sqrt(),
            pan_aw_m_s2: pan_aw,
            floor_aw_m_s2: self.floor_aw,
            stroke_rms_m: root * travel.sqrt(),
            stroke_available_m: seat.stroke_m,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::time::CLASSES;

    /// The grid's floor a_w is the one its figures divide by.
    #[test]
    fn the_grids_floor_aw_is_its_figures_floor_aw() {
        let body = crate::body::preset::Preset::builtin("paper-75kg-suspension-seat")
            .expect("a built-in")
            .expect("it loads")
            .body;
        for c in CLASSES.iter().take(4) {
            let g = SeatGrid::new(&FloorPsd::Class(c)).unwrap();
            let f = g.figures(&body).unwrap();
            assert!(g.floor_aw() > 0.0);
            assert_eq!(g.floor_aw(), f.floor_aw_m_s2, "{}", c.name);
        }
    }

    /// The nodes the figures integrate over: `GRID_INTERVALS + 1` of them,
    /// equally spaced in u = ln f, from the PSD's range's ends exactly.
    #[test]
    fn the_grid_is_log_spaced_over_the_psds_range_with_exact_ends() {
        let psd = FloorPsd::Class(&CLASSES[0]);
        let (lo, hi) = psd.range();
        let g = SeatGrid::new(&psd).unwrap();
        let f = g.freqs();
        assert_eq!(f.len(), GRID_INTERVALS + 1);
        assert_eq!((f[0], f[GRID_INTERVALS]), (lo, hi));
        let du = (hi / lo).ln() / GRID_INTERVALS as f64;
        for w in f.windows(2) {
            assert!(((w[1] / w[0]).ln() - du).abs() < 1e-12, "{w:?}");
        }
    }
}
