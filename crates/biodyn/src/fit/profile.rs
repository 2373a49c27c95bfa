//! Profile-likelihood interval ends: walking one parameter away from a
//! minimum while the others are minimised again at every step.
//!
//! The profile of parameter j is P(t) = min Σr² over the other free
//! parameters with ln p_j held at t. Its 95 % interval is where
//! P(t) ≤ cost + Δ_j (the threshold is the report's: F(0.95; 1, m − p)
//! times the residual variance that parameter sees). Each end is found by
//! stepping t outward from the minimum, each step a Levenberg–Marquardt run
//! of the others warm-started from the previous step's, the step sized by a
//! quadratic through the minimum and the last point, until P crosses the
//! threshold; the crossing is then bracketed and found by regula falsi
//! (Illinois), to 1e-4 in ln p or 0.1 % of Δ. A walk that reaches the
//! parameter's bound inside the threshold has no end there: the data allow
//! the parameter that far, and the box, not the data, stops it.
//!
//! Other minima the starts found are walked from too, when the data do
//! not reject them: when their cost lies inside the joint 95 % region of
//! all p parameters, cost + p·F(0.95; p, m − p)·s². Each such minimum gets
//! its own interval, by the same threshold above its own cost: if the truth
//! lies in that basin, that is the interval that holds it 95 % of the
//! time. The 95 % set is the union of these intervals (overlapping ones
//! merged); where it has gaps the data cannot choose between the minima.

use super::lm::{self, Residuals, Workspace};
use std::sync::atomic::{AtomicBool, Ordering};

/// Steps of one walk before it gives up and calls the end unbounded.
const MAX_STEPS: usize = 200;
/// Regula-falsi iterations for one crossing.
const MAX_BISECT: usize = 40;
/// A crossing is located to this width in ln p …
const T_TOL: f64 = 1e-4;
/// … or to this fraction of Δ in cost.
const COST_TOL: f64 = 1e-3;
/// Each profile point's minimisation stops at this many iterations or when
/// a step gains less than this fraction of the cost: Δ is some 1e-2 of the
/// cost, and the crossing is wanted to 1e-3 of Δ.
const STEP_ITER: usize = 150;
const STEP_FTOL: f64 = 1e-8;
/// The first step in ln p is the curvature's estimate of the crossing,
/// kept within these (a factor of 1.001 to e).
const FIRST_STEP: (f64, f64) = (1e-3, 1.0);

/// The walk was stopped by the caller.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Stopped;

/// One parameter's profile problem: the box in ln p, the best point and
/// its cost, the other starts' end points, the threshold.
pub(crate) struct Task<'a> {
    pub lo: &'a [f64],
    pub hi: &'a [f64],
    pub best: &'a [f64],
    pub cost: f64,
    /// Every start's (cost, end point), the best one among them or not.
    pub minima: &'a [(f64, Vec<f64>)],
    /// A minimum whose cost is at most this is one the data do not reject.
    pub plausible: f64,
    pub stop: &'a AtomicBool,
}

/// One interval of the 95 % set, in ln p; `None` where it reaches the box.
pub(crate) type Piece = (Option<f64>, Option<f64>);

/// What was found for one parameter: the 95 % set as disjoint intervals in
/// increasing order (one, mostly).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Ends {
    pub pieces: Vec<Piece>,
    /// Another start's minimum added to or widened the set.
    pub other_minimum: bool,
}

impl Ends {
    pub fn low(&self) -> Option<f64> {
        self.pieces.first().and_then(|p| p.0)
    }

    pub fn high(&self) -> Option<f64> {
        self.pieces.last().and_then(|p| p.1)
    }
}

/// Two start ends are the same minimum when no parameter differs by more
/// than this in ln p.
const SAME_POINT: f64 = 1e-3;

/// The profile set of parameter `j` with threshold `delta` (≥ 0) above a
/// minimum's cost; `step` is the curvature's half-width in ln p (infinite
/// when the curvature does not see the parameter).
pub(crate) fn ends<R: Residuals>(
    prob: &mut R,
    ws: &mut Workspace,
    task: &Task,
    j: usize,
    delta: f64,
    step: f64,
) -> Result<Ends, Stopped> {
    let step = if step.is_finite() {
        step.clamp(FIRST_STEP.0, FIRST_STEP.1)
    } else {
        FIRST_STEP.1
    };
    let mut walker = Walker {
        prob,
        ws,
        task,
        j,
        delta,
        lo: task.lo.to_vec(),
        hi: task.hi.to_vec(),
    };
    let own = walker.piece(task.best, task.cost, step, false, false)?;
    let mut pieces = vec![own];
    let mut walked: Vec<&[f64]> = vec![task.best];
    for (c, theta) in task.minima {
        // A NaN cost is no minimum.
        if c.is_nan() || *c > task.plausible {
            continue;
        }
        let same = |w: &&[f64]| {
            w.iter()
                .zip(theta)
                .all(|(a, b)| (a - b).abs() <= SAME_POINT)
        };
        if walked.iter().any(same) {
            continue;
        }
        walked.push(theta);
        // A side the set already leaves open cannot be widened: that walk
        // is skipped and its end taken as open too (the gap, if any, is
        // filled: the set only grows).
        let open_low = pieces.iter().any(|p| p.0.is_none());
        let open_high = pieces.iter().any(|p| p.1.is_none());
        pieces.push(walker.piece(theta, *c, step, open_low, open_high)?);
    }
    let pieces = merge(pieces);
    Ok(Ends {
        other_minimum: pieces != [own],
        pieces,
    })
}

/// Sorted, with overlapping intervals joined.
fn merge(mut pieces: Vec<Piece>) -> Vec<Piece> {
    let key = |p: &Piece| p.0.unwrap_or(f64::NEG_INFINITY);
    pieces.sort_by(|a, b| key(a).total_cmp(&key(b)));
    let mut out: Vec<Piece> = Vec::with_capacity(pieces.len());
    for p in pieces {
        match out.last_mut() {
            Some(last) if last.1.is_none_or(|h| key(&p) <= h) => {
                last.1 = match (last.1, p.1) {
                    (Some(a), Some(b)) => Some(a.max(b)),
                    _ => None,
                };
            }
            _ => out.push(p),
        }
    }
    out
}

struct Walker<'a, 'b, R> {
    prob: &'a mut R,
    ws: &'a mut Workspace,
    task: &'a Task<'b>,
    j: usize,
    delta: f64,
    /// The box with parameter j pinned where it is being profiled.
    lo: Vec<f64>,
    hi: Vec<f64>,
}

/// A point on the profile: ln p_j, the whole point, the profile's cost.
struct Point {
    t: f64,
    theta: Vec<f64>,
    cost: f64,
}

impl<R: Residuals> Walker<'_, '_, R> {
    /// The interval around the minimum `from` of cost `c0`: where the
    /// profile stays within Δ of c0.
    /// A side `open_*` is not walked: it is left open (`None`).
    fn piece(
        &mut self,
        from: &[f64],
        c0: f64,
        step: f64,
        open_low: bool,
        open_high: bool,
    ) -> Result<Piece, Stopped> {
        let limit = c0 + self.delta;
        let low = if open_low {
            None
        } else {
            self.walk(from, c0, limit, -1.0, step)?
        };
        let high = if open_high {
            None
        } else {
            self.walk(from, c0, limit, 1.0, step)?
        };
        Ok((low, high))
    }

    /// The profile at t, the others warm-started from `warm`.
    fn at(&mut self, t: f64, warm: &[f64]) -> Result<Point, Stopped> {
        if self.task.stop.load(Ordering::Relaxed) {
            return Err(Stopped);
        }
        let mut theta = warm.to_vec();
        theta[self.j] = t;
        self.lo[self.j] = t;
        self.hi[self.j] = t;
        let out = lm::minimise_to(
            self.prob, &mut theta, &self.lo, &self.hi, self.ws, STEP_ITER, STEP_FTOL,
        );
        let cost = if out.cost.is_nan() {
            f64::INFINITY
        } else {
            out.cost
        };
        Ok(Point { t, theta, cost })
    }

    /// The end in direction `dir` (±1) from a minimum `from` of cost `c0`:
    /// Some(ln p) where the profile crosses the threshold, None when it
    /// stays below it up to the bound.
    fn walk(
        &mut self,
        from: &[f64],
        c0: f64,
        limit: f64,
        dir: f64,
        first: f64,
    ) -> Result<Option<f64>, Stopped> {
        let j = self.j;
        let origin = from[j];
        let bound = if dir > 0.0 {
            self.task.hi[j]
        } else {
            self.task.lo[j]
        };
        let room = (bound - origin) * dir;
        if room <= 0.0 {
            return Ok(None);
        }
        let mut inside = Point {
            t: origin,
            theta: from.to_vec(),
            cost: c0,
        };
        let mut h = first;
        for _ in 0..MAX_STEPS {
            let d = (inside.t - origin) * dir + h;
            let t = if d >= room { bound } else { origin + dir * d };
            let next = self.at(t, &inside.theta)?;
            if next.cost > limit {
                return self.crossing(inside, next, limit).map(Some);
            }
            if t == bound {
                return Ok(None);
            }
            // P ≈ c0 + a·d² through the origin and this point: the next
            // step aims a little past where that parabola crosses.
            let rise = next.cost - c0;
            let aim = if rise > 0.0 {
                d * ((limit - c0) / rise).sqrt() * 1.05
            } else {
                f64::INFINITY
            };
            h = (aim - d).clamp(0.1 * h.max(T_TOL), 2.0 * h);
            inside = next;
        }
        Ok(None)
    }

    /// The threshold crossing between a point inside and one outside.
    fn crossing(&mut self, mut a: Point, mut b: Point, limit: f64) -> Result<f64, Stopped> {
        let tol = COST_TOL * self.delta.max(f64::MIN_POSITIVE);
        // Illinois: the function values the secant uses, halved on the side
        // that keeps its end twice running.
        let (mut fa, mut fb) = (a.cost - limit, b.cost - limit);
        let mut side = 0i8;
        for _ in 0..MAX_BISECT {
            if (b.t - a.t).abs() <= T_TOL {
                break;
            }
            let w = b.t - a.t;
            let t = if fb.is_finite() && fb > fa {
                // Never closer than 1 % of the bracket to either end.
                let (x, y) = (a.t + 0.01 * w, b.t - 0.01 * w);
                (a.t - fa * w / (fb - fa)).clamp(x.min(y), x.max(y))
            } else {
                a.t + 0.5 * w
            };
            let p = self.at(t, &a.theta)?;
            let f = p.cost - limit;
            if f.abs() <= tol {
                return Ok(p.t);
            }
            if f <= 0.0 {
                a = p;
                fa = f;
                if side == -1 {
                    fb *= 0.5;
                }
                side = -1;
            } else {
                b = p;
                fb = f;
                if side == 1 {
                    fa *= 0.5;
                }
                side = 1;
            }
        }
        // Between the last two points, by their true costs.
        let (ca, cb) = (a.cost - limit, b.cost - limit);
        let t = if cb.is_finite() && cb > ca {
            a.t - ca * (b.t - a.t) / (cb - ca)
        } else {
            0.5 * (a.t + b.t)
        };
        Ok(t)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A bowl bent into a banana: r₀ = x, r₁ = 3(y − x²).
    struct Banana;
    impl Residuals for Banana {
        fn m(&self) -> usize {
            2
        }
        fn p(&self) -> usize {
            2
        }
        fn eval(&mut self, t: &[f64], r: &mut [f64], jac: Option<&mut [f64]>) -> f64 {
            r[0] = t[0];
            r[1] = 3.0 * (t[1] - t[0] * t[0]);
            if let Some(j) = jac {
                j.copy_from_slice(&[1.0, -6.0 * t[0], 0.0, 3.0]);
            }
            r[0] * r[0] + r[1] * r[1]
        }
    }

    fn task<'a>(lo: &'a [f64], hi: &'a [f64], best: &'a [f64], stop: &'a AtomicBool) -> Task<'a> {
        Task {
            lo,
            hi,
            best,
            cost: 0.0,
            minima: &[],
            plausible: 0.0,
            stop,
        }
    }

    /// The profile of x is x² (y follows x²): the ends are ±√Δ exactly,
    /// whatever the banana. Below 0 the profile of y is 9y² (x = 0), and it
    /// stays under Δ = 4 up to a bound at y = 0.5: no upper end.
    #[test]
    fn ends_are_where_the_profile_crosses() {
        let stop = AtomicBool::new(false);
        let (lo, hi, best) = ([-5.0, -5.0], [5.0, 5.0], [0.0, 0.0]);
        let t = task(&lo, &hi, &best, &stop);
        let mut ws = Workspace::new(2, 2);
        let e = ends(&mut Banana, &mut ws, &t, 0, 4.0, 0.3).unwrap();
        let (l, h) = (e.low().unwrap(), e.high().unwrap());
        assert!((h - 2.0).abs() < 2e-3 && (l + 2.0).abs() < 2e-3, "{e:?}");
        assert!(!e.other_minimum);
        let hi = [5.0, 0.5];
        let t = task(&lo, &hi, &best, &stop);
        let e = ends(&mut Banana, &mut ws, &t, 1, 4.0, 0.3).unwrap();
        assert_eq!(e.high(), None, "{e:?}");
        assert!((e.low().unwrap() + 2.0 / 3.0).abs() < 2e-3, "{e:?}");
    }

    #[test]
    fn a_stop_ends_the_walk() {
        let stop = AtomicBool::new(true);
        let (lo, hi, best) = ([-5.0, -5.0], [5.0, 5.0], [0.0, 0.0]);
        let t = task(&lo, &hi, &best, &stop);
        let mut ws = Workspace::new(2, 2);
        assert_eq!(ends(&mut Banana, &mut ws, &t, 0, 4.0, 0.3), Err(Stopped));
    }

    /// r = x(x − 4) + b: a double well in x with minima at 0 and 4.
    struct Wells;
    impl Residuals for Wells {
        fn m(&self) -> usize {
            1
        }
        fn p(&self) -> usize {
            1
        }
        fn eval(&mut self, t: &[f64], r: &mut [f64], jac: Option<&mut [f64]>) -> f64 {
            r[0] = t[0] * (t[0] - 4.0);
            if let Some(j) = jac {
                j[0] = 2.0 * t[0] - 4.0;
            }
            r[0] * r[0]
        }
    }

    /// A second minimum the data do not reject gets its own interval;
    /// one they do is left out.
    #[test]
    fn another_plausible_minimum_gets_its_own_interval() {
        let stop = AtomicBool::new(false);
        let (lo, hi, best) = ([-50.0], [50.0], [0.0]);
        let minima = [(0.0, vec![4.0]), (0.0, vec![0.0])];
        let t = Task {
            minima: &minima,
            plausible: 1.0,
            ..task(&lo, &hi, &best, &stop)
        };
        let mut ws = Workspace::new(1, 1);
        // Δ = 1: |x(x − 4)| ≤ 1 around each well: 2 ∓ √5 to 2 ∓ √3.
        let e = ends(&mut Wells, &mut ws, &t, 0, 1.0, 0.1).unwrap();
        assert!(e.other_minimum);
        let (r3, r5) = (3f64.sqrt(), 5f64.sqrt());
        let want = [(2.0 - r5, 2.0 - r3), (2.0 + r3, 2.0 + r5)];
        assert_eq!(e.pieces.len(), 2, "{e:?}");
        for (p, w) in e.pieces.iter().zip(want) {
            assert!(
                (p.0.unwrap() - w.0).abs() < 2e-3 && (p.1.unwrap() - w.1).abs() < 2e-3,
                "{e:?}"
            );
        }
        let t = Task {
            plausible: -1.0,
            ..t
        };
        let e = ends(&mut Wells, &mut ws, &t, 0, 1.0, 0.1).unwrap();
        assert!(!e.other_minimum && e.pieces.len() == 1, "{e:?}");
    }

    #[test]
    fn pieces_merge_where_they_overlap() {
        let m = merge(vec![
            (Some(3.0), Some(5.0)),
            (None, Some(1.0)),
            (Some(0.5), Some(2.0)),
        ]);
        assert_eq!(m, vec![(None, Some(2.0)), (Some(3.0), Some(5.0))]);
        let m = merge(vec![(Some(0.0), None), (Some(1.0), Some(2.0))]);
        assert_eq!(m, vec![(Some(0.0), None)]);
    }
}
