//! The fit dialog's state: which parameters are free (the library's own
//! names and default), how many starts and which seed, the fit running on
//! its own thread (progress through the tab's mailbox, a cancel flag), and
//! the result until it is applied or discarded.

use crate::tui::event::Mailbox;
use biodyn::{Body, Param};
use biodyn::fit::{self, Fit, FitError, Free, Measured, Progress, Settings};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

/// Progress messages at most this often (the last one always goes).
const REPORT_EVERY: Duration = Duration::from_millis(30);
/// The elapsed time on screen moves at this pace between starts (a start of
/// a large fit can take seconds).
const TICK: Duration = Duration::from_millis(250);

/// What the fit thread sends back.
#[derive(Debug)]
pub enum FitMsg {
    Progress(Progress),
    /// Nothing new but the time: redraw the elapsed seconds.
    Tick,
    Done(Box<Fit>),
    Cancelled,
    Failed(String),
}

/// One row of the setup list.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Row {
    Param(Param),
    Starts,
    Seed,
}

/// A fit on its thread.
#[derive(Debug)]
pub struct Running {
    pub started: Instant,
    pub last: Option<Progress>,
    pub starts: usize,
    pub cancelling: bool,
    cancel: Arc<AtomicBool>,
    thread: Option<JoinHandle<()>>,
}

impl Running {
    pub fn cancel(&mut self) {
        self.cancel.store(true, Ordering::Relaxed);
        self.cancelling = true;
    }

    /// Cancels and waits for the thread (on quit, on another model).
    pub fn stop(&mut self) {
        self.cancel();
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
    }
}

#[derive(Debug)]
pub enum Stage {
    /// Choosing the free parameters, starts and seed.
    Setup,
    Running(Running),
    /// The result, shown until Enter applies it or Esc drops it.
    Result {
        fit: Box<Fit>,
        scroll: u16,
    },
}

#[derive(Debug)]
pub struct FitDialog {
    pub rows: Vec<Row>,
    /// Free parameters, in the library's order (body mass, m, k, c).
    pub free: Vec<Param>,
    pub sel: usize,
    pub starts: usize,
    pub seed: u64,
    pub stage: Stage,
    /// Why the last start was refused, or that it was cancelled.
    pub note: Option<String>,
}

impl FitDialog {
    /// Every m, k and c (and body mass when every segment has a share),
    /// the library's default free set selected.
    pub fn new(body: &Body) -> FitDialog {
        let mut rows = Vec::new();
        if body.segments.iter().all(|s| s.share.is_some()) {
            rows.push(Row::Param(Param::BodyMass));
        }
        rows.extend((0..body.n()).map(|i| Row::Param(Param::Mass(i))));
        rows.extend((0..body.links.len()).map(|i| Row::Param(Param::Stiffness(i))));
        rows.extend((0..body.links.len()).map(|i| Row::Param(Param::Damping(i))));
        rows.extend([Row::Starts, Row::Seed]);
        let d = Settings::default();
        FitDialog {
            rows,
            free: default_free(body),
            sel: 0,
            starts: d.starts,
            seed: d.seed,
            stage: Stage::Setup,
            note: None,
        }
    }

    pub fn row(&self) -> Option<Row> {
        self.rows.get(self.sel).copied()
    }

    pub fn is_free(&self, p: Param) -> bool {
        self.free.contains(&p)
    }

    pub fn step(&mut self, up: bool) {
        let n = self.rows.len().max(1);
        self.sel = if up {
            (self.sel + n - 1) % n
        } else {
            (self.sel + 1) % n
        };
    }

    /// Space: frees or fixes the parameter of the selected row.
    pub fn toggle(&mut self) {
        if let Some(Row::Param(p)) = self.row() {
            match self.free.iter().position(|&q| q == p) {
                Some(i) => {
                    self.free.remove(i);
                }
                None => self.free.push(p),
            }
            self.note = None;
        }
    }

    /// Every parameter free, or back to the default.
    pub fn select_all(&mut self, body: &Body, all: bool) {
        self.free = if all {
            fit::resolve(body, &[Free::All]).unwrap_or_default()
        } else {
            default_free(body)
        };
        self.note = None;
    }

    /// ←→ on the starts or seed row.
    pub fn nudge(&mut self, up: bool) {
        match self.row() {
            Some(Row::Starts) if up => self.starts = (self.starts + 1).min(fit::MAX_STARTS),
            Some(Row::Starts) => self.starts = self.starts.saturating_sub(1).max(1),
            Some(Row::Seed) if up => self.seed = self.seed.saturating_add(1),
            Some(Row::Seed) => self.seed = self.seed.saturating_sub(1),
            _ => {}
        }
    }

    /// The free parameters' names, comma-separated in row order.
    pub fn free_list(&self, body: &Body) -> String {
        self.rows
            .iter()
            .filter_map(|r| match r {
                Row::Param(p) if self.is_free(*p) => Some(fit::name_of(body, *p)),
                _ => None,
            })
            .collect::<Vec<_>>()
            .join(",")
    }

    pub fn settings(&self) -> Settings {
        Settings {
            starts: self.starts,
            seed: self.seed,
            ..Settings::default()
        }
    }

    /// Starts the fit: on its own thread reporting through `mailbox`, or
    /// here and now when there is no channel (tests, benches). Refusals
    /// (nothing free, a zero start value) stay in `note`.
    pub fn start(&mut self, body: &Body, data: &Measured, mailbox: &Mailbox) {
        let chosen: Vec<Free> = self.free.iter().map(|&p| Free::Param(p)).collect();
        let free = match fit::free_params(body, &chosen, &[]) {
            Ok(f) => f,
            Err(FitError::EmptyFree) => {
                self.note = Some("refused: choose at least one free parameter (space)".into());
                return;
            }
            Err(e) => {
                self.note = Some(format!("refused: {e}"));
                return;
            }
        };
        self.note = None;
        let settings = self.settings();
        let Some((tx, wrap)) = mailbox.wrap::<FitMsg>() else {
            let msg = outcome(fit::fit(body, data, &free, settings));
            self.finish(msg);
            return;
        };
        let cancel = Arc::new(AtomicBool::new(false));
        let stop = Arc::clone(&cancel);
        let ended = Arc::new(AtomicBool::new(false));
        let (end, tick_end, tick_tx) = (Arc::clone(&ended), Arc::clone(&ended), tx.clone());
        let tick = mailbox.wrap::<FitMsg>().map(|(_, w)| w);
        let (body, data) = (body.clone(), data.clone());
        let spawned = std::thread::Builder::new()
            .name("fit".into())
            .spawn(move || {
                let mut last: Option<Instant> = None;
                let r = fit::fit_with(&body, &data, &free, settings, &mut |p| {
                    let due = last.is_none_or(|t| t.elapsed() >= REPORT_EVERY);
                    // The last start and the last interval always go.
                    let edge = (p.done == p.starts && p.profiled == 0) || p.profiled == p.profiles;
                    if due || edge {
                        last = Some(Instant::now());
                        let _ = tx.send(wrap(FitMsg::Progress(p)));
                    }
                    !stop.load(Ordering::Relaxed)
                });
                end.store(true, Ordering::Relaxed);
                let _ = tx.send(wrap(outcome(r)));
            });
        // The ticker ends by itself within a tick of the fit's end; nobody waits for it.
        if spawned.is_ok()
            && let Some(tick) = tick
        {
            let _ = std::thread::Builder::new()
                .name("fit-tick".into())
                .spawn(move || {
                    loop {
                        std::thread::sleep(TICK);
                        if tick_end.load(Ordering::Relaxed)
                            || tick_tx.send(tick(FitMsg::Tick)).is_err()
                        {
                            break;
                        }
                    }
                });
        }
        match spawned {
            Ok(t) => {
                self.stage = Stage::Running(Running {
                    started: Instant::now(),
                    last: None,
                    starts: settings.starts,
                    cancelling: false,
                    cancel,
                    thread: Some(t),
                })
            }
            Err(e) => self.note = Some(format!("cannot start the fit thread: {e}")),
        }
    }

    /// Takes a message of the fit thread; the line for the status bar.
    pub fn on_msg(&mut self, msg: FitMsg) -> Option<String> {
        match (&mut self.stage, msg) {
            (Stage::Running(r), FitMsg::Progress(p)) => {
                r.last = Some(p);
                None
            }
            (_, FitMsg::Tick) => None,
            (Stage::Running(_), m) => Some(self.finish(m)),
            _ => None,
        }
    }

    /// The end of a fit (the thread has sent its last message).
    fn finish(&mut self, msg: FitMsg) -> String {
        if let Stage::Running(r) = &mut self.stage
            && let Some(t) = r.thread.take()
        {
            let _ = t.join();
        }
        match msg {
            FitMsg::Done(fit) => {
                let s = format!(
                    "fit done: cost {}, {} of {} starts reached it; Enter applies, Esc discards",
                    crate::view::format::num(fit.cost, 4),
                    fit.converged_starts,
                    fit.settings.starts
                );
                self.stage = Stage::Result { fit, scroll: 0 };
                s
            }
            FitMsg::Cancelled => {
                self.stage = Stage::Setup;
                self.note = Some("cancelled; the model is unchanged".into());
                "fit cancelled; the model is unchanged".into()
            }
            FitMsg::Failed(why) => {
                self.stage = Stage::Setup;
                self.note = Some(why.clone());
                format!("fit failed: {why}")
            }
            FitMsg::Progress(_) | FitMsg::Tick => String::new(),
        }
    }

    pub fn running(&self) -> bool {
        matches!(self.stage, Stage::Running(_))
    }

    /// Stops a running fit and waits for its thread.
    pub fn shutdown(&mut self) {
        if let Stage::Running(r) = &mut self.stage {
            r.stop();
        }
    }
}

/// The library's default free set (every k and c).
fn default_free(body: &Body) -> Vec<Param> {
    fit::resolve(body, &[Free::Links]).unwrap_or_default()
}

fn outcome(r: Result<Fit, FitError>) -> FitMsg {
    match r {
        Ok(f) => FitMsg::Done(Box::new(f)),
        Err(FitError::Cancelled) => FitMsg::Cancelled,
        Err(e) => FitMsg::Failed(e.to_string()),
    }
}
