//! A seat's figures for a floor PSD G(f), in the frequency domain:
//!
//!   a_w,floor = √∫ G |W_k|² df,   a_w,pan = √∫ G |T|² |W_k|² df,
//!   SEAT % = 100 · a_w,pan / a_w,floor,
//!   r.m.s. travel = √∫ G |X_rel / A_floor|² df,  X_rel/A_floor = (H_s − 1)/(−ω²),
//!
//! T = H_pan the seat's transmissibility, H_s the motion of the suspension's
//! upper end per unit floor motion, W_k the ISO 2631-1 weighting (ISO 8041-1
//! Formula (5), band limits included).
//!
//! The integrals run over the PSD's range within [`MIN_HZ`]–[`MAX_HZ`]
//! (|W_k| < 0.032 below 0.1 Hz and < 1.3e-4 above 1 kHz: a floor's energy
//! there is weighted by under 0.1 % and 2e-8 of the main band's), on the
//! quadrature of [`super::quadrature`]: a PSD file exactly as its rows say
//! (linear between them), the body's and the weighting's Φ interpolated on a
//! grid even in ln f. Each integral is taken at step h and at 2h (the even
//! nodes of the same evaluation) and h is halved until the two agree to
//! [`TOLERANCE`] (the finer one's error is then about an eighth of that);
//! the first h is also at most the smallest damping ratio of the model's
//! modes in the range, so no resonance falls between the nodes of both.

use super::error::SeatError;
use super::psd::FloorPsd;
use super::quadrature::{self, H0, Level, MAX_LEVEL};
use crate::body::model::Body;
use crate::freq::response::Solver;
use crate::iso2631::Weighting;
use std::f64::consts::PI;
use std::sync::OnceLock;

/// Lowest frequency integrated, Hz: |W_k(0.1 Hz)| = 0.031.
pub const MIN_HZ: f64 = 0.1;

/// Highest frequency integrated, Hz: |W_k(1 kHz)| = 1.25e-4.
pub const MAX_HZ: f64 = 1000.0;

/// Two successive grids' integrals agree to this share of the finer.
pub const TOLERANCE: f64 = 1e-6;

/// The quadrature of one floor PSD over its integrated range, each level's
/// nodes and weights built once, when first needed. G is held relative to
/// its largest value, `scale`: SEAT does not depend on the PSD's level, and
/// a density of 1e-320 or 1e300 then loses no precision to subnormals or
/// overflow (the a_w and travel are scaled back).
#[derive(Debug, Clone)]
pub struct SeatGrid {
    range: (f64, f64),
    scale: f64,
    levels: Vec<OnceLock<Level>>,
    /// ∫ (G/scale)|W_k|² df.
    weighted: f64,
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

/// The integrated range of `psd`: its own within [`MIN_HZ`]–[`MAX_HZ`].
pub fn integrated_range(psd: &FloorPsd) -> Result<(f64, f64), SeatError> {
    let (lo, hi) = psd.range();
    let range = (lo.max(MIN_HZ), hi.min(MAX_HZ));
    if range.0 >= range.1 {
        return Err(SeatError::OutsideRange {
            from_hz: lo,
            to_hz: hi,
        });
    }
    Ok(range)
}

impl SeatGrid {
    /// The quadrature of `psd`, and its floor a_w.
    pub fn new(psd: &FloorPsd) -> Result<SeatGrid, SeatError> {
        let (lo, hi) = integrated_range(psd)?;
        let scale = match psd {
            FloorPsd::Table { rows, .. } => rows.iter().map(|r| r.1).fold(0.0, f64::max),
            FloorPsd::Class(_) => quadrature::nodes(lo, hi, 0)
                .iter()
                .map(|&f| psd.at(f))
                .fold(0.0, f64::max),
        };
        let mut grid = SeatGrid {
            range: (lo, hi),
            scale,
            levels: (0..=MAX_LEVEL).map(|_| OnceLock::new()).collect(),
            weighted: 0.0,
            floor_aw: 0.0,
            psd: psd.clone(),
        };
        if scale > 0.0 {
            grid.weighted = grid
                .integrate(1, |f| [Weighting::Wk.analog(f).norm_sqr()])
                .ok_or(SeatError::Unresolved {
                    what: "the floor's weighted r.m.s.",
                })?[0];
        }
        // √scale apart: scale·Σ would be subnormal for a tiny PSD.
        grid.floor_aw = scale.sqrt() * grid.weighted.sqrt();
        if !(grid.floor_aw.is_finite() && grid.floor_aw > 0.0) {
            return Err(SeatError::NoWeightedInput {
                from_hz: lo,
                to_hz: hi,
            });
        }
        Ok(grid)
    }

    /// The PSD the grid integrates.
    pub fn psd(&self) -> &FloorPsd {
        &self.psd
    }

    /// The frequencies integrated over, Hz: the PSD's own range within
    /// [`MIN_HZ`]–[`MAX_HZ`].
    pub fn range(&self) -> (f64, f64) {
        self.range
    }

    /// a_w of the floor, m/s².
    pub fn floor_aw(&self) -> f64 {
        self.floor_aw
    }

    /// The first grid's frequencies (step [`H0`]/2 in ln f), Hz.
    pub fn freqs(&self) -> &[f64] {
        &self.level(1).f
    }

    fn level(&self, k: usize) -> &Level {
        self.levels[k]
            .get_or_init(|| quadrature::level(&self.psd, self.range.0, self.range.1, self.scale, k))
    }

    /// ∫ (G/scale)·Φ_j df of each of Φ's N components, from level `first`
    /// up until level k and level k−1 agree to [`TOLERANCE`] for every one;
    /// None when even the finest level does not.
    fn integrate<const N: usize>(
        &self,
        first: usize,
        phi: impl Fn(f64) -> [f64; N],
    ) -> Option<[f64; N]> {
        let mut values: Vec<[f64; N]> = Vec::new();
        for k in first.max(1)..=MAX_LEVEL {
            let l = self.level(k);
            // Level k−1's nodes are this level's even ones: evaluated already
            // when k > first.
            values = if values.is_empty() {
                l.f.iter().map(|&f| phi(f)).collect()
            } else {
                l.f.iter()
                    .enumerate()
                    .map(|(i, &f)| if i % 2 == 0 { values[i / 2] } else { phi(f) })
                    .collect()
            };
            let sum = |w: &[f64], step: usize| {
                let mut s = [0.0; N];
                for (w, v) in w.iter().zip(values.iter().step_by(step)) {
                    for j in 0..N {
                        s[j] += w * v[j];
                    }
                }
                s
            };
            let fine = sum(&l.w, 1);
            let coarse = sum(&self.level(k - 1).w, 2);
            let agree = (0..N).all(|j| {
                fine[j].is_finite() && (fine[j] - coarse[j]).abs() <= TOLERANCE * fine[j].abs()
            });
            if agree {
                return Some(fine);
            }
        }
        None
    }

    /// The first level fine enough for `body`: its step in ln f at most the
    /// smallest damping ratio of the oscillatory modes whose natural
    /// frequency is in the range (a resonance spans about ζ in ln f).
    pub(super) fn first_level(&self, body: &Body) -> usize {
        let Ok(modes) = crate::freq::analyse_modes(body) else {
            return 1;
        };
        let (lo, hi) = self.range;
        let zeta = modes
            .damped
            .iter()
            .filter(|m| m.eigenvalue.im != 0.0)
            .filter(|m| (lo..=hi).contains(&m.natural_hz()))
            .map(|m| -m.eigenvalue.re / m.eigenvalue.norm())
            .fold(f64::INFINITY, f64::min);
        (1..=MAX_LEVEL)
            .find(|&k| H0 / f64::from(1u32 << k) <= zeta)
            .unwrap_or(MAX_LEVEL)
    }

    /// SEAT, the pan's a_w and the r.m.s. travel of `body`'s seat.
    pub fn figures(&self, body: &Body) -> Result<SeatFigures, SeatError> {
        let seat = body.seat.as_ref().ok_or(SeatError::NoSeat)?;
        let upper = body.links[seat.suspension].upper;
        let solver = Solver::new(body);
        let [pan, travel] = self
            .integrate(self.first_level(body), |f| {
                let h = solver.transfer(f);
                let w2 = (2.0 * PI * f).powi(2);
                [
                    Weighting::Wk.analog(f).norm_sqr() * h[seat.pan].norm_sqr(),
                    (h[upper] - 1.0).norm_sqr() / (w2 * w2),
                ]
            })
            .ok_or(SeatError::Unresolved {
                what: "the pan's weighted r.m.s. and the suspension's travel",
            })?;
        let root = self.scale.sqrt();
        Ok(SeatFigures {
            seat_pct: 100.0 * (pan / self.weighted).sqrt(),
            pan_aw_m_s2: root * pan.sqrt(),
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

    /// The first grid is even in ln f over the PSD's range, with exact ends.
    #[test]
    fn the_grid_is_log_spaced_over_the_psds_range_with_exact_ends() {
        let psd = FloorPsd::Class(&CLASSES[0]);
        let (lo, hi) = psd.range();
        let g = SeatGrid::new(&psd).unwrap();
        assert_eq!(g.range(), (lo, hi));
        let f = g.freqs();
        assert_eq!((f[0], f[f.len() - 1]), (lo, hi));
        let du = (hi / lo).ln() / (f.len() - 1) as f64;
        assert!(du <= H0 / 2.0);
        for w in f.windows(2) {
            assert!(((w[1] / w[0]).ln() - du).abs() < 1e-12, "{w:?}");
        }
    }
}
