//! Training on its own thread, for the TUI.
//!
//! Progress goes out over an `mpsc::Sender` the caller owns, wrapped by the
//! caller's `map` so it can land in the TUI's own event enum. Messages are
//! rate-limited to one per `MIN_INTERVAL` (about 30 a second) whatever the
//! training speed, plus one when a pause is taken and one when it ends
//! (`paused` true, then false, at the same epoch); `send` on an mpsc channel never blocks, so a slow
//! receiver cannot slow the training. Pause, resume and cancel are atomics;
//! a pause is taken at an epoch's end, a cancel (and the time limit) is
//! seen inside an epoch too, every few milliseconds of work. Every time
//! the worker reads (the time limit, paused time, the throttle) comes from
//! the [`Clock`] it was started on: the real one, or a test's manual one.

use super::case::Case;
use super::error::AnnError;
use super::metrics::EpochStats;
use super::settings::Settings;
use super::stop::{Flow, StopReason};
use super::train::{Outcome, train_with};
use crate::clock::Clock;
use std::cell::Cell;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::Sender;
use std::thread::{self, JoinHandle};
use std::time::{Duration, Instant};

/// Shortest time between two progress messages (≈ 30 per second).
pub const MIN_INTERVAL: Duration = Duration::from_millis(33);
/// Points kept in the loss history: enough for any terminal-wide chart.
pub const HISTORY_POINTS: usize = 512;

/// One point of the loss curve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HistoryPoint {
    /// Epochs since the start of the run, over all ensemble members.
    pub total_epoch: u64,
    pub member: usize,
    pub rms: f64,
    pub mpre_pct: f64,
}

/// The loss curve, decimated: when full, every other point goes and the
/// sampling stride doubles, so the whole run always fits in `HISTORY_POINTS`.
#[derive(Debug, Clone, Default)]
pub struct History {
    stride: u64,
    pub points: Vec<HistoryPoint>,
}

impl History {
    pub fn new() -> History {
        History {
            stride: 1,
            points: Vec::new(),
        }
    }

    pub fn push(&mut self, p: HistoryPoint) {
        if self.stride == 0 {
            self.stride = 1;
        }
        if p.total_epoch % self.stride != 0 {
            return;
        }
        self.points.push(p);
        if self.points.len() > HISTORY_POINTS {
            self.stride *= 2;
            let s = self.stride;
            self.points.retain(|q| q.total_epoch % s == 0);
        }
    }
}

/// A progress report.
#[derive(Debug, Clone)]
pub struct Progress {
    pub case: Case,
    /// Current ensemble member (0-based) and the ensemble size.
    pub member: usize,
    pub members: usize,
    /// Epoch of the current member and its limit.
    pub epoch: u64,
    pub max_epochs: u64,
    pub rms: f64,
    pub mpre_pct: f64,
    pub share_right: f64,
    /// Epochs per second since the previous message.
    pub epochs_per_s: f64,
    pub elapsed_s: f64,
    pub paused: bool,
    /// The whole run's loss curve so far, decimated.
    pub history: Vec<HistoryPoint>,
}

/// The end of a run, in short; the trained net comes from `Worker::join`.
#[derive(Debug, Clone)]
pub struct Finished {
    pub case: Case,
    pub stop: StopReason,
    pub epochs: u64,
    pub rms: Option<f64>,
    pub mpre_pct: Option<f64>,
    pub share_right: Option<f64>,
    pub train_seconds: f64,
}

/// What the worker sends.
#[derive(Debug, Clone)]
pub enum Event {
    Progress(Progress),
    Finished(Finished),
    /// Training could not run; the message says why.
    Failed(String),
}

#[derive(Debug, Default)]
struct Ctl {
    paused: AtomicBool,
    cancelled: AtomicBool,
}

/// Handle of a training thread. Dropping it cancels the run and waits for it.
#[derive(Debug)]
pub struct Worker {
    ctl: Arc<Ctl>,
    handle: Option<JoinHandle<Result<Outcome, AnnError>>>,
}

impl Worker {
    /// Validates the settings, then trains `case` on a new thread, sending
    /// `map(event)` over `tx`.
    pub fn start<M, F>(
        case: Case,
        settings: Settings,
        tx: Sender<M>,
        map: F,
    ) -> Result<Worker, AnnError>
    where
        M: Send + 'static,
        F: Fn(Event) -> M + Send + 'static,
    {
        Worker::start_on(case, settings, Clock::Real, tx, map)
    }

    /// [`Worker::start`] on `clock`: the time limit, the paused time, the
    /// elapsed seconds and the message-rate throttle all read it (a test
    /// moves a manual clock by hand instead of sleeping).
    pub fn start_on<M, F>(
        case: Case,
        settings: Settings,
        clock: Clock,
        tx: Sender<M>,
        map: F,
    ) -> Result<Worker, AnnError>
    where
        M: Send + 'static,
        F: Fn(Event) -> M + Send + 'static,
    {
        settings.validate(case)?;
        // The run's clock starts here, in the caller's thread: whatever
        // the caller does to the clock after `start_on` returns counts.
        let start = clock.now();
        let ctl = Arc::new(Ctl::default());
        let c = Arc::clone(&ctl);
        let handle = thread::Builder::new()
            .name(format!("train-{case}"))
            .spawn(move || run(case, settings, (&clock, start), &c, &tx, &map))
            .map_err(|e| AnnError::Io {
                action: "start a training thread for",
                path: case.key().into(),
                source: e,
            })?;
        Ok(Worker {
            ctl,
            handle: Some(handle),
        })
    }

    pub fn pause(&self) {
        self.ctl.paused.store(true, Ordering::Relaxed);
    }

    pub fn resume(&self) {
        self.ctl.paused.store(false, Ordering::Relaxed);
        if let Some(h) = &self.handle {
            h.thread().unpark();
        }
    }

    pub fn cancel(&self) {
        self.ctl.cancelled.store(true, Ordering::Relaxed);
        if let Some(h) = &self.handle {
            h.thread().unpark();
        }
    }

    pub fn is_paused(&self) -> bool {
        self.ctl.paused.load(Ordering::Relaxed)
    }

    /// True once the thread has ended (`join` will not block).
    pub fn is_finished(&self) -> bool {
        self.handle.as_ref().is_none_or(JoinHandle::is_finished)
    }

    /// Waits for the end and returns the outcome with the trained net.
    pub fn join(mut self) -> Result<Outcome, AnnError> {
        match self.handle.take() {
            Some(h) => h.join().map_err(|_| AnnError::WorkerPanicked)?,
            None => Err(AnnError::WorkerPanicked),
        }
    }
}

impl Drop for Worker {
    fn drop(&mut self) {
        if let Some(h) = self.handle.take() {
            self.ctl.cancelled.store(true, Ordering::Relaxed);
            h.thread().unpark();
            let _ = h.join();
        }
    }
}

fn run<M, F: Fn(Event) -> M>(
    case: Case,
    settings: Settings,
    (clock, start): (&Clock, Instant),
    ctl: &Ctl,
    tx: &Sender<M>,
    map: &F,
) -> Result<Outcome, AnnError> {
    // The worker keeps the time limit itself so that paused time does not count.
    let limit = settings
        .time_limit_s
        .map(|s| Duration::from_secs_f64(s.min(1e9)));
    let mut inner = settings.clone();
    inner.time_limit_s = None;
    // Read by the poll inside an epoch, added to at a pause (epoch ends).
    let paused_for = Cell::new(Duration::ZERO);
    let time_up =
        || limit.is_some_and(|l| clock.since(start).saturating_sub(paused_for.get()) >= l);
    let mut last_sent = start;
    let mut last_total = 0u64;
    let mut last_eps = 0.0;
    let mut total = 0u64;
    let mut history = History::new();
    let members = settings.ensemble;
    let max_epochs = settings.epochs;
    let progress = |s: &EpochStats, eps: f64, history: &History, paused: bool| {
        Event::Progress(Progress {
            case,
            member: s.member,
            members,
            epoch: s.epoch,
            max_epochs,
            rms: s.rms,
            mpre_pct: s.mpre_pct,
            share_right: s.share_right,
            epochs_per_s: eps,
            elapsed_s: clock.since(start).as_secs_f64(),
            paused,
            history: history.points.clone(),
        })
    };
    // Inside an epoch: cancel and the time limit (a pause waits for the
    // epoch's end, where `observe` runs).
    let poll = || {
        if ctl.cancelled.load(Ordering::Relaxed) {
            Flow::Cancel
        } else if time_up() {
            Flow::TimeUp
        } else {
            Flow::Continue
        }
    };
    let mut last_stats = None;
    let mut observe = |s: &EpochStats| {
        total += 1;
        history.push(HistoryPoint {
            total_epoch: total,
            member: s.member,
            rms: s.rms,
            mpre_pct: s.mpre_pct,
        });
        last_stats = Some(*s);
        let now = clock.now();
        if now.duration_since(last_sent) >= MIN_INTERVAL {
            let dt = now.duration_since(last_sent).as_secs_f64();
            let eps = (total - last_total) as f64 / dt;
            last_sent = now;
            last_total = total;
            last_eps = eps;
            if tx.send(map(progress(s, eps, &history, false))).is_err() {
                // Nobody listens any more: the front end has gone.
                return Flow::Cancel;
            }
        }
        if ctl.paused.load(Ordering::Relaxed) {
            // The pause starts before the report goes out, so whatever
            // time passes once the caller has it counts as paused.
            let t0 = clock.now();
            let _ = tx.send(map(progress(s, 0.0, &history, true)));
            while ctl.paused.load(Ordering::Relaxed) && !ctl.cancelled.load(Ordering::Relaxed) {
                thread::park_timeout(Duration::from_millis(50));
            }
            paused_for.set(paused_for.get() + clock.since(t0));
            last_sent = clock.now();
            last_total = total;
            // Resumed (not cancelled): say so at once, at the same epoch,
            // rather than only at the next report the throttle lets out.
            if !ctl.cancelled.load(Ordering::Relaxed) {
                let _ = tx.send(map(progress(s, last_eps, &history, false)));
            }
        }
        poll()
    };
    let result = train_with(case, &inner, clock, &mut observe, Some(&poll));
    let result = result.map(|mut out| {
        out.net.settings.time_limit_s = settings.time_limit_s;
        // On the run's clock from its start, as `elapsed_s` is.
        out.train_seconds = clock.since(start).as_secs_f64();
        out
    });
    match &result {
        Ok(out) => {
            if let Some(s) = last_stats {
                let dt = clock.since(start).as_secs_f64().max(1e-9);
                let _ = tx.send(map(progress(&s, total as f64 / dt, &history, false)));
            }
            let _ = tx.send(map(Event::Finished(Finished {
                case,
                stop: out.stop.clone(),
                epochs: out.epochs(),
                rms: out.rms,
                mpre_pct: out.mpre_pct,
                share_right: out.share_right,
                train_seconds: out.train_seconds,
            })));
        }
        Err(e) => {
            let _ = tx.send(map(Event::Failed(e.to_string())));
        }
    }
    result
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A cancel is seen inside an epoch: cancelled before the first epoch
    /// ends, the run stops at 0 epochs (it used to finish the epoch first,
    /// minutes for a large network).
    #[test]
    fn a_cancel_stops_the_run_inside_its_first_epoch() {
        let case = Case::K4Stht;
        let mut s = Settings::paper(case);
        s.layers = vec![2, 600, 600, 1];
        s.epochs = 2;
        s.stop_when_all_right = false;
        let (tx, _rx) = std::sync::mpsc::channel();
        let w = Worker::start(case, s, tx, |e| e).unwrap();
        w.cancel();
        let out = w.join().unwrap();
        assert_eq!(out.stop, StopReason::Cancelled);
        assert_eq!(out.epochs(), 0);
    }

    #[test]
    fn history_stays_bounded_and_spans_the_run() {
        let mut h = History::new();
        for e in 1..=100_000u64 {
            h.push(HistoryPoint {
                total_epoch: e,
                member: 0,
                rms: 1.0 / e as f64,
                mpre_pct: 0.0,
            });
        }
        assert!(h.points.len() <= HISTORY_POINTS);
        assert!(h.points.len() > HISTORY_POINTS / 4);
        assert!(h.points.last().unwrap().total_epoch > 90_000);
    }
}
