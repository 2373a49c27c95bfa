//! One training run and the worker's lifecycle: start on its own thread
//! (reports come back through the tab's mailbox), pause, resume, stop,
//! and the end (join, keep the outcome, predict).

use super::predict::{Prediction, predict};
use crate::tui::event::Mailbox;
use biodyn::ann::{Case, Event, Finished, Outcome, Progress, Settings, Worker};
use std::collections::VecDeque;

/// Progress messages kept for the "recent" chart (about 3 s at 30 a second).
const RECENT: usize = 90;

/// One run: live while the worker trains, kept after it ends.
#[derive(Debug)]
pub struct Run {
    pub case: Case,
    pub settings: Settings,
    pub last: Option<Progress>,
    /// (epoch over the whole run, RMS) of the latest progress messages.
    pub recent: VecDeque<(f64, f64)>,
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
        let w = Worker::start(case, settings.clone(), tx, wrap).map_err(|e| e.to_string())?;
        Ok(Run {
            case,
            settings: settings.clone(),
            last: None,
            recent: VecDeque::new(),
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
    pub fn toggle_pause(&self) -> Option<bool> {
        let w = self.worker.as_ref()?;
        if w.is_paused() {
            w.resume();
            Some(false)
        } else {
            w.pause();
            Some(true)
        }
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
                let total = p
                    .history
                    .last()
                    .map_or(p.epoch as f64, |h| h.total_epoch as f64);
                self.recent.push_back((total, p.rms));
                if self.recent.len() > RECENT {
                    self.recent.pop_front();
                }
                self.last = Some(p);
                Ended::Not
            }
            Event::Finished(f) => {
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
