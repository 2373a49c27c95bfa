//! One training run and the worker's lifecycle: start on its own thread
//! (reports come back through the tab's mailbox), pause, resume, stop,
//! and the end (join, keep the outcome, predict).

use super::predict::{Prediction, predict};
use crate::tui::event::Mailbox;
use biodyn::Clock;
use biodyn::ann::{Case, Event, Finished, Outcome, Progress, Settings, Worker};
use std::collections::VecDeque;
use std::time::{Duration, Instant};

/// Progress messages kept for the "recent" chart (about 3 s at 30 a second).
const RECENT: usize = 90;

/// One run: live while the worker trains, kept after it ends.
#[derive(Debug)]
pub struct Run {
    pub case: Case,
    pub settings: Settings,
    pub last: Option<Progress>,
    /// (epoch of the current member, RMS) of the latest progress messages.
    pub recent: VecDeque<(f64, f64)>,
    /// Time spent paused so far, and since when it is paused now. The
    /// worker's clock counts pauses; the panel's times leave them out.
    paused_for: Duration,
    paused_at: Option<Instant>,
    /// The worker's clock, which the paused time is read on too.
    clock: Clock,
    pub finished: Option<Finished>,
    pub failed: Option<String>,
    pub outcome: Option<Outcome>,
    /// Prediction vs analytic at the chosen held-out value.
    pub prediction: Option<Prediction>,
    worker: Option<Worker>,
}

/// What a worker's report changed, for the status line.
pub enum Ended {
    Not,
    Finished(String),
    Failed(String),
}

impl Run {
    /// Starts training `case` on a new thread.
    pub fn start(case: Case, settings: &Settings, mailbox: &Mailbox) -> Result<Run, String> {
        let (tx, wrap) = mailbox
            .wrap::<Event>()
            .ok_or("no event channel: cannot train here")?;
        let clock = mailbox.clock.clone();
        let w = Worker::start_on(case, settings.clone(), clock.clone(), tx, wrap)
            .map_err(|e| e.to_string())?;
        Ok(Run {
            case,
            settings: settings.clone(),
            last: None,
            recent: VecDeque::new(),
            paused_for: Duration::ZERO,
            paused_at: None,
            clock,
            finished: None,
            failed: None,
            outcome: None,
            prediction: None,
            worker: Some(w),
        })
    }

    pub fn running(&self) -> bool {
        self.worker.is_some()
    }

    pub fn paused(&self) -> bool {
        self.worker.as_ref().is_some_and(Worker::is_paused)
    }

    /// Pauses or resumes; None when no worker runs. Some(true) = now paused.
    pub fn toggle_pause(&mut self) -> Option<bool> {
        let w = self.worker.as_ref()?;
        if w.is_paused() {
            w.resume();
            self.end_pause();
            Some(false)
        } else {
            w.pause();
            self.paused_at = Some(self.clock.now());
            Some(true)
        }
    }

    fn end_pause(&mut self) {
        if let Some(t) = self.paused_at.take() {
            self.paused_for += self.clock.since(t);
        }
    }

    /// Seconds paused so far (up to now while paused).
    pub fn paused_s(&self) -> f64 {
        let now = self.paused_at.map_or(Duration::ZERO, |t| self.clock.since(t));
        (self.paused_for + now).as_secs_f64()
    }

    /// Working time: `clock_s` (the worker's, pauses included) less the pauses.
    pub fn working_s(&self, clock_s: f64) -> f64 {
        (clock_s - self.paused_s()).max(0.0)
    }

    /// Asks the worker to stop; false when none runs.
    pub fn cancel(&self) -> bool {
        self.worker.as_ref().map(Worker::cancel).is_some()
    }

    /// Cancels and waits for the thread (on quit).
    pub fn shutdown(&mut self) {
        if let Some(w) = self.worker.take() {
            w.cancel();
            drop(w);
        }
    }

    /// Takes a report from the worker; `holdout` is the value to predict at.
    pub fn on_event(&mut self, ev: Event, holdout: f64) -> Ended {
        match ev {
            Event::Progress(p) => {
                // The recent window follows one ensemble member at a time.
                if self.last.as_ref().is_some_and(|l| l.member != p.member) {
                    self.recent.clear();
                }
                self.recent.push_back((p.epoch as f64, p.rms));
                if self.recent.len() > RECENT {
                    self.recent.pop_front();
                }
                self.last = Some(p);
                Ended::Not
            }
            Event::Finished(f) => {
                self.end_pause();
                let stop = f.stop.to_string();
                self.finished = Some(f);
                // The worker sends Finished last: joining does not wait long.
                if let Some(w) = self.worker.take() {
                    match w.join() {
                        Ok(out) => self.outcome = Some(out),
                        Err(e) => self.failed = Some(e.to_string()),
                    }
                }
                self.predict_at(holdout);
                Ended::Finished(format!("training {} ended: {stop}", self.case))
            }
            Event::Failed(why) => {
                self.end_pause();
                if let Some(w) = self.worker.take() {
                    let _ = w.join();
                }
                self.failed = Some(why.clone());
                Ended::Failed(format!("training failed: {why}"))
            }
        }
    }

    /// Redraws the prediction at another held-out value.
    pub fn predict_at(&mut self, value: f64) {
        self.prediction = self
            .outcome
            .as_ref()
            .and_then(|out| predict(out, value));
    }
}
