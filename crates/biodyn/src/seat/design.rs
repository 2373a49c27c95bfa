//! Seat design: the one or two parameters of a box (a suspension's k and c,
//! say) that give the lowest SEAT while the r.m.s. travel keeps a limit.
//!
//! The box is mapped on a grid even in ln p ([`MAP_POINTS`] per axis), then
//! a compass search in ln p refines from the three best feasible grid
//! points: the axis and diagonal steps of the grid's spacing, halved when
//! no step improves, down to 10⁻⁶ of the box's log-width. A step is taken
//! only to a feasible point with a lower SEAT, so the result is never worse
//! than the best grid point, and lands between grid points where the
//! optimum is (often on the travel limit itself).

use super::error::SeatError;
use super::figures::{SeatFigures, SeatGrid};
use crate::body::model::{Body, Param};
use crate::io::excerpt::num;

/// Most parameters one search varies.
pub const MAX_VARIED: usize = 2;

/// Grid points per axis of the map: one axis, two axes.
pub const MAP_POINTS: [usize; 2] = [41, 21];

/// Smallest compass step, as a share of the box's log-width.
const MIN_STEP: f64 = 1e-6;

/// One parameter of the box: its name as the user wrote it (`suspension.c`).
#[derive(Debug, Clone, PartialEq)]
pub struct Vary {
    pub name: String,
    pub param: Param,
    pub lo: f64,
    pub hi: f64,
}

/// A point of the box with its figures.
#[derive(Debug, Clone, PartialEq)]
pub struct DesignPoint {
    /// One value per varied parameter, in the order given.
    pub values: Vec<f64>,
    pub figures: SeatFigures,
}

/// SEAT and travel over the map's grid: `axes[0]` the first parameter's
/// values; with two, row-major with the first parameter the slower index.
#[derive(Debug, Clone, PartialEq)]
pub struct DesignMap {
    pub axes: Vec<Vec<f64>>,
    pub seat_pct: Vec<f64>,
    pub stroke_rms_m: Vec<f64>,
}

/// The search's answer.
#[derive(Debug, Clone, PartialEq)]
pub struct Design {
    pub vary: Vec<Vary>,
    pub stroke_rms_max_m: f64,
    pub best: DesignPoint,
    pub map: DesignMap,
    /// Figures computed in all (map and refinement).
    pub evaluations: usize,
}

impl Vary {
    /// `name=LO..HI` resolved against `body`; the box is checked at its corners.
    pub fn new(body: &Body, name: &str, lo: f64, hi: f64) -> Result<Vary, SeatError> {
        let param = body.param(name).map_err(|e| SeatError::BadVary {
            name: name.to_string(),
            why: e.to_string(),
        })?;
        if param == Param::BodyMass {
            return Err(SeatError::BadVary {
                name: name.to_string(),
                why: "the person is not the seat's to choose: vary a seat link's k or c, or a seat segment's mass".into(),
            });
        }
        if !(lo.is_finite() && hi.is_finite() && lo > 0.0 && lo < hi) {
            return Err(SeatError::BadRange {
                name: name.to_string(),
                lo,
                hi,
            });
        }
        for v in [lo, hi] {
            body.clone()
                .set(param, v)
                .map_err(|source| SeatError::Model {
                    name: name.to_string(),
                    value: v,
                    source: Box::new(source),
                })?;
        }
        Ok(Vary {
            name: name.to_string(),
            param,
            lo,
            hi,
        })
    }

    /// The value at t ∈ [0, 1] of the box's log-width (the ends exactly).
    fn at(&self, t: f64) -> f64 {
        match t {
            0.0 => self.lo,
            1.0 => self.hi,
            _ => (self.lo.ln() + t * (self.hi / self.lo).ln()).exp(),
        }
    }
}

/// The lowest SEAT in the box whose r.m.s. travel is within `stroke_rms_max`.
pub fn design(
    body: &Body,
    grid: &SeatGrid,
    vary: &[Vary],
    stroke_rms_max: f64,
) -> Result<Design, SeatError> {
    design_with(body, grid, vary, stroke_rms_max, &mut |_, _| {})
}

/// [`design`], calling `progress(evaluations, map)` before the first
/// evaluation and after each: `map` is the number of the map's grid points,
/// done first; the compass search's evaluations follow, their number not
/// known ahead (`evaluations` then passes `map`). The same result as
/// [`design`].
pub fn design_with(
    body: &Body,
    grid: &SeatGrid,
    vary: &[Vary],
    stroke_rms_max: f64,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<Design, SeatError> {
    if body.seat.is_none() {
        return Err(SeatError::NoSeat);
    }
    match vary.len() {
        0 => return Err(SeatError::NothingVaried),
        n if n > MAX_VARIED => return Err(SeatError::TooManyVaried { count: n }),
        _ => {}
    }
    for (i, v) in vary.iter().enumerate() {
        if vary[..i].iter().any(|w| w.param == v.param) {
            return Err(SeatError::VariedTwice(v.name.clone()));
        }
    }
    if !(stroke_rms_max.is_finite() && stroke_rms_max > 0.0) {
        return Err(SeatError::BadLimit(stroke_rms_max));
    }
    let dims = vary.len();
    let n = MAP_POINTS[dims - 1];
    let map_points = n.pow(dims as u32);
    progress(0, map_points);
    let mut evaluations = 0;
    let mut eval = |t: &[f64]| -> Result<DesignPoint, SeatError> {
        let mut b = body.clone();
        let values: Vec<f64> = vary.iter().zip(t).map(|(v, &t)| v.at(t)).collect();
        for (v, &x) in vary.iter().zip(&values) {
            b.set(v.param, x).map_err(|source| SeatError::Model {
                name: v.name.clone(),
                value: x,
                source: Box::new(source),
            })?;
        }
        let figures = grid.figures(&b)?;
        evaluations += 1;
        progress(evaluations, map_points);
        Ok(DesignPoint { figures, values })
    };
    // The map.
    let ts: Vec<f64> = (0..n).map(|i| i as f64 / (n - 1) as f64).collect();
    let mut cells: Vec<(Vec<f64>, DesignPoint)> = Vec::with_capacity(n.pow(dims as u32));
    if dims == 1 {
        for &t in &ts {
            cells.push((vec![t], eval(&[t])?));
        }
    } else {
        for &t0 in &ts {
            for &t1 in &ts {
                cells.push((vec![t0, t1], eval(&[t0, t1])?));
            }
        }
    }
    let map = DesignMap {
        axes: vary
            .iter()
            .map(|v| ts.iter().map(|&t| v.at(t)).collect())
            .collect(),
        seat_pct: cells.iter().map(|c| c.1.figures.seat_pct).collect(),
        stroke_rms_m: cells.iter().map(|c| c.1.figures.stroke_rms_m).collect(),
    };
    let feasible = |p: &DesignPoint| p.figures.stroke_rms_m <= stroke_rms_max;
    let mut starts: Vec<&(Vec<f64>, DesignPoint)> =
        cells.iter().filter(|c| feasible(&c.1)).collect();
    if starts.is_empty() {
        let least = cells.iter().min_by(|a, b| {
            a.1.figures
                .stroke_rms_m
                .total_cmp(&b.1.figures.stroke_rms_m)
        });
        let (least, at) = least
            .map(|c| (c.1.figures.stroke_rms_m, where_(vary, &c.1.values)))
            .unwrap_or((f64::NAN, String::new()));
        return Err(SeatError::Infeasible {
            limit: stroke_rms_max,
            least,
            at,
        });
    }
    starts.sort_by(|a, b| a.1.figures.seat_pct.total_cmp(&b.1.figures.seat_pct));
    // The compass directions: each axis, and for two the diagonals.
    let mut dirs: Vec<Vec<f64>> = Vec::new();
    for i in 0..dims {
        for s in [-1.0, 1.0] {
            let mut d = vec![0.0; dims];
            d[i] = s;
            dirs.push(d);
        }
    }
    if dims == 2 {
        for (a, b) in [(1.0, 1.0), (1.0, -1.0), (-1.0, 1.0), (-1.0, -1.0)] {
            dirs.push(vec![a, b]);
        }
    }
    let starts: Vec<(Vec<f64>, DesignPoint)> = starts.into_iter().take(3).cloned().collect();
    let mut best: Option<DesignPoint> = None;
    for (t0, p0) in starts {
        let (mut t, mut p) = (t0, p0);
        let mut step = 1.0 / (n - 1) as f64;
        while step >= MIN_STEP {
            let mut moved = false;
            for d in &dirs {
                let next: Vec<f64> = t.iter().zip(d).map(|(t, d)| t + d * step).collect();
                if next.iter().any(|x| !(0.0..=1.0).contains(x)) {
                    continue;
                }
                let q = eval(&next)?;
                if feasible(&q) && q.figures.seat_pct < p.figures.seat_pct {
                    (t, p) = (next, q);
                    moved = true;
                    break;
                }
            }
            if !moved {
                step /= 2.0;
            }
        }
        if best
            .as_ref()
            .is_none_or(|b| p.figures.seat_pct < b.figures.seat_pct)
        {
            best = Some(p);
        }
    }
    let best = best.ok_or(SeatError::NothingVaried)?;
    Ok(Design {
        vary: vary.to_vec(),
        stroke_rms_max_m: stroke_rms_max,
        best,
        map,
        evaluations,
    })
}

/// "suspension.k = 8000, suspension.c = 600".
fn where_(vary: &[Vary], values: &[f64]) -> String {
    vary.iter()
        .zip(values)
        .map(|(v, x)| format!("{} = {}", v.name, num(*x)))
        .collect::<Vec<_>>()
        .join(", ")
}
