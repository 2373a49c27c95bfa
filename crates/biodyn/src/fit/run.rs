//! The multi-start fit: Levenberg–Marquardt from the start model and from
//! seeded points around it, keeping the best; then the intervals (the
//! profile walks, on the same threads, under the same cancel).

use super::data::Measured;
use super::error::FitError;
use super::free::FreeParam;
use super::interval;
use super::lm::{self, Residuals, Workspace};
use super::profile::Ends;
use super::report::{self, Fit};
use super::residual::Engine;
use super::settings::Intervals;
use crate::body::model::Body;
use crate::rng::Rng;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::mpsc;
use std::time::Instant;

/// Starts after the first are drawn uniformly in ln p within this factor of
/// the start model (then put inside the bounds).
pub const SPREAD: f64 = 3.0;
/// A start "reached the best cost" when its cost is within this fraction of
/// the best (plus 1e-12 per value, for data a model fits exactly).
pub const SAME_COST: f64 = 1e-6;

/// Most threads a fit runs its starts on (this one included).
pub const MAX_THREADS: usize = 4;

use super::settings::{MAX_STARTS, Settings};

/// Reported after each start: start `done` of `starts` finished; then,
/// while the profile intervals are walked, `profiled` of `profiles`
/// parameters done (reported after each and at least every 50 ms, so a
/// caller can cancel; `profiles` is 0 for curvature intervals).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Progress {
    pub done: usize,
    pub starts: usize,
    pub best_cost: f64,
    pub profiled: usize,
    pub profiles: usize,
}

impl Residuals for Engine {
    fn m(&self) -> usize {
        Engine::m(self)
    }
    fn p(&self) -> usize {
        Engine::p(self)
    }
    fn eval(&mut self, theta: &[f64], r: &mut [f64], jac: Option<&mut [f64]>) -> f64 {
        Engine::eval(self, theta, r, jac)
    }
}

/// The starts of one fit, shared by the threads that run them: each thread
/// claims the next start index. A start depends only on its index (its
/// point comes from `Rng::derived(seed, index)`), so which thread runs it
/// changes no bit.
struct Job<'a> {
    lo: &'a [f64],
    hi: &'a [f64],
    centre: &'a [f64],
    seed: u64,
    starts: usize,
    next: AtomicUsize,
    stop: AtomicBool,
}

impl Job<'_> {
    /// Runs the next unclaimed start: (index, cost, end point); None when
    /// every start is claimed or the fit was cancelled.
    fn claim_and_run(
        &self,
        engine: &mut Engine,
        ws: &mut Workspace,
    ) -> Option<(usize, f64, Vec<f64>)> {
        if self.stop.load(Ordering::Relaxed) {
            return None;
        }
        let s = self.next.fetch_add(1, Ordering::Relaxed);
        if s >= self.starts {
            return None;
        }
        let mut theta = self.centre.to_vec();
        if s > 0 {
            let mut rng = Rng::derived(self.seed, s as u64);
            for t in &mut theta {
                *t += rng.symmetric(SPREAD.ln());
            }
        }
        let out = lm::minimise(engine, &mut theta, self.lo, self.hi, ws);
        Some((s, out.cost, theta))
    }
}

/// Fits `free` parameters of `body` to `data`.
pub fn fit(
    body: &Body,
    data: &Measured,
    free: &[FreeParam],
    settings: Settings,
) -> Result<Fit, FitError> {
    fit_with(body, data, free, settings, &mut |_| true)
}

/// As [`fit`], calling `progress` after every start and during the
/// interval walks; when it returns false the fit stops with
/// [`FitError::Cancelled`] (within one start, or one minimisation of a
/// walk). Same seed, same bits.
///
/// The starts run on up to `MAX_THREADS` threads; `progress` is still
/// called on the calling thread, once per start, in start order (`done`
/// counts them), and the best start is the lowest cost, the earliest start
/// on a tie, exactly as one thread would choose.
pub fn fit_with(
    body: &Body,
    data: &Measured,
    free: &[FreeParam],
    settings: Settings,
    progress: &mut dyn FnMut(Progress) -> bool,
) -> Result<Fit, FitError> {
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    fit_on(
        body,
        data,
        free,
        settings,
        progress,
        threads.min(MAX_THREADS),
    )
}

/// [`fit_with`] on at most `threads` threads (1: this one alone).
fn fit_on(
    body: &Body,
    data: &Measured,
    free: &[FreeParam],
    settings: Settings,
    progress: &mut dyn FnMut(Progress) -> bool,
    threads: usize,
) -> Result<Fit, FitError> {
    let clock = Instant::now();
    if settings.starts == 0 || settings.starts > MAX_STARTS {
        return Err(FitError::BadStarts {
            starts: settings.starts,
            max: MAX_STARTS,
        });
    }
    if free.is_empty() {
        return Err(FitError::EmptyFree);
    }
    let params: Vec<_> = free.iter().map(|f| f.param).collect();
    let mut engine = Engine::new(body, data, &params)?;
    let (m, p) = (engine.m(), engine.p());
    if m <= p {
        return Err(FitError::TooFewValues {
            path: data.path.clone(),
            values: m,
            params: p,
        });
    }
    let lo: Vec<f64> = free.iter().map(|f| f.lo.ln()).collect();
    let hi: Vec<f64> = free.iter().map(|f| f.hi.ln()).collect();
    let centre: Vec<f64> = free.iter().map(|f| f.start.ln()).collect();
    let starts = settings.starts;
    let profiles = match settings.intervals {
        Intervals::Profile => p,
        Intervals::Curvature => 0,
    };
    let job = Job {
        lo: &lo,
        hi: &hi,
        centre: &centre,
        seed: settings.seed,
        starts,
        next: AtomicUsize::new(0),
        stop: AtomicBool::new(false),
    };
    // Finished starts, by index; reported (and the best chosen) in start
    // order on this thread, whichever thread ran them.
    let mut done: Vec<Option<(f64, Vec<f64>)>> = vec![None; starts];
    let mut reported = 0;
    let mut best = vec![0.0; p];
    let mut best_cost = f64::INFINITY;
    let mut costs = Vec::with_capacity(starts);
    let mut ends = Vec::with_capacity(starts);
    let mut cancelled = false;
    let helpers = threads.clamp(1, starts) - 1;
    std::thread::scope(|scope| {
        let (tx, rx) = mpsc::channel::<(usize, f64, Vec<f64>)>();
        for _ in 0..helpers {
            let (tx, job, mut engine) = (tx.clone(), &job, engine.clone());
            // A helper that cannot be spawned leaves its starts to this thread.
            let _ = std::thread::Builder::new().spawn_scoped(scope, move || {
                let mut ws = Workspace::new(m, p);
                while let Some((s, cost, theta)) = job.claim_and_run(&mut engine, &mut ws) {
                    if tx.send((s, cost, theta)).is_err() {
                        break;
                    }
                }
            });
        }
        drop(tx);
        let mut ws = Workspace::new(m, p);
        while reported < starts {
            // Run a start here while any is left, else wait for a helper's.
            match job.claim_and_run(&mut engine, &mut ws) {
                Some((s, cost, theta)) => done[s] = Some((cost, theta)),
                None => match rx.recv() {
                    Ok((s, cost, theta)) => done[s] = Some((cost, theta)),
                    Err(_) => break,
                },
            }
            while let Ok((s, cost, theta)) = rx.try_recv() {
                done[s] = Some((cost, theta));
            }
            while let Some((cost, theta)) = done.get_mut(reported).and_then(Option::take) {
                if cost < best_cost {
                    best_cost = cost;
                    best.copy_from_slice(&theta);
                }
                costs.push(cost);
                ends.push(theta);
                reported += 1;
                let go = progress(Progress {
                    done: reported,
                    starts,
                    best_cost,
                    profiled: 0,
                    profiles,
                });
                if !go {
                    cancelled = true;
                    job.stop.store(true, Ordering::Relaxed);
                    return;
                }
            }
        }
    });
    if cancelled {
        return Err(FitError::Cancelled);
    }
    if !best_cost.is_finite() {
        return Err(FitError::Unsolvable {
            path: data.path.clone(),
        });
    }
    let tol = SAME_COST * best_cost + 1e-12 * m as f64;
    let converged = costs.iter().filter(|&&c| c - best_cost <= tol).count();
    let curv = interval::curvature(&mut engine, data.columns.len(), &best);
    let ends: Vec<Ends> = match settings.intervals {
        Intervals::Curvature => (0..p)
            .map(|j| curv.ends(j, best[j], lo[j], hi[j]))
            .collect(),
        Intervals::Profile => {
            let minima: Vec<(f64, Vec<f64>)> = costs.iter().copied().zip(ends).collect();
            let mut go = |profiled| {
                progress(Progress {
                    done: starts,
                    starts,
                    best_cost,
                    profiled,
                    profiles,
                })
            };
            interval::profiles(&engine, &curv, &lo, &hi, &best, &minima, threads, &mut go)
                .map_err(|_| FitError::Cancelled)?
        }
    };
    report::build(
        body,
        data,
        free,
        &mut engine,
        &best,
        curv,
        &ends,
        costs,
        converged,
        settings,
        clock,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fit::{Free, free_params};
    use crate::{Band, Function, Solver};

    /// Two or three threads give the bits of one: same costs in start
    /// order, same best point, progress in start order on this thread.
    #[test]
    fn threads_change_no_bit() {
        let mut truth = Body::paper(75.0).unwrap();
        truth.links[0].k *= 1.5;
        truth.links[2].c *= 0.6;
        let mut text = String::from("f_hz,stht_mag,stht_phase_deg,apms_mag\n");
        let band = Band::new(0.5, 20.0, 0.5).unwrap();
        for r in Solver::new(&truth).sweep(&band) {
            let wobble = 1.0 + 0.02 * (r.f_hz * 7.0).sin();
            text += &format!(
                "{},{},{},{}\n",
                r.f_hz,
                r.mag(Function::Stht) * wobble,
                r.phase_deg(Function::Stht),
                r.mag(Function::Apms) / wobble
            );
        }
        let data = Measured::parse(&text, "t.csv").unwrap();
        let start = Body::paper(75.0).unwrap();
        let free = free_params(&start, &[Free::Links], &[]).unwrap();
        let settings = Settings {
            starts: 6,
            seed: 3,
            ..Settings::default()
        };
        let run = |threads| {
            let mut seen = Vec::new();
            let caller = std::thread::current().id();
            let f = fit_on(
                &start,
                &data,
                &free,
                settings,
                &mut |p| {
                    assert_eq!(std::thread::current().id(), caller);
                    if p.profiled == 0 && seen.last() != Some(&p.done) {
                        seen.push(p.done);
                    }
                    true
                },
                threads,
            )
            .unwrap();
            (f, seen)
        };
        let (one, seen1) = run(1);
        for threads in [2, 3] {
            let (many, seen) = run(threads);
            assert_eq!(seen, (1..=6).collect::<Vec<_>>());
            assert_eq!(seen1, seen);
            let bits = |f: &Fit| {
                let mut v: Vec<u64> = f.start_costs.iter().map(|c| c.to_bits()).collect();
                v.push(f.cost.to_bits());
                v.extend(f.params.iter().map(|p| p.value.to_bits()));
                // The profile walks too, on whichever threads.
                for p in &f.params {
                    v.extend(
                        [p.ci95_low, p.ci95_high]
                            .map(|e| e.map(f64::to_bits))
                            .iter()
                            .flatten(),
                    );
                }
                v
            };
            assert_eq!(bits(&one), bits(&many));
        }
        // Cancelling after the second start stops the fit on any thread count.
        for threads in [1, 2] {
            let mut calls = 0;
            let r = fit_on(
                &start,
                &data,
                &free,
                settings,
                &mut |_| {
                    calls += 1;
                    calls < 2
                },
                threads,
            );
            assert!(matches!(r, Err(FitError::Cancelled)));
            assert_eq!(calls, 2);
        }
        // … and a cancel during the profile walks stops them: at the first
        // call after the starts (the walks have begun), none is finished.
        for threads in [1, 2] {
            let mut profiling = 0;
            let r = fit_on(
                &start,
                &data,
                &free,
                settings,
                &mut |p| {
                    profiling += usize::from(p.done == p.starts);
                    assert_eq!(p.profiles, 8);
                    profiling < 2
                },
                threads,
            );
            assert!(matches!(r, Err(FitError::Cancelled)), "{r:?}");
            assert_eq!(profiling, 2);
        }
    }
}
