//! What is computed from the model: the curves, peaks and modes every tab
//! reads. Small models are computed at once; a large one on a background
//! thread, in two parts (curves first, then modes), so the screen and `q`
//! never wait for the solver.

use crate::view::chart::Series;
use biodyn::freq::{self, Modes, Peak};
use biodyn::{Band, Body, Function, Response, Solver};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

/// Models with more segments than this are computed in the background.
/// At the paper's 4 segments a full refresh takes well under a millisecond.
pub const BACKGROUND_ABOVE_SEGMENTS: usize = 16;

/// True when `body` is computed off the main thread.
pub fn in_background(body: &Body) -> bool {
    body.segments.len() > BACKGROUND_ABOVE_SEGMENTS
}

/// One function's curves and peaks.
#[derive(Debug, Clone)]
pub struct FunctionCurves {
    pub function: Function,
    pub mag: Series,
    pub phase: Series,
    /// Every interior peak, and the main one.
    pub peaks: Vec<Peak>,
    pub main: Option<Peak>,
}

/// The sweep over the band and everything read from it.
#[derive(Debug, Clone)]
pub struct Derived {
    pub solver: Solver,
    pub curve: Vec<Response>,
    /// In `Function::ALL` order.
    pub functions: Vec<FunctionCurves>,
}

impl Derived {
    pub fn compute(body: &Body, band: &Band) -> Derived {
        let solver = Solver::new(body);
        let curve = solver.sweep(band);
        let series = |f: Function, phase: bool| Series {
            name: f.name().to_string(),
            points: curve
                .iter()
                .map(|r| (r.f_hz, if phase { r.phase_deg(f) } else { r.mag(f) }))
                .collect(),
        };
        let functions = Function::ALL
            .iter()
            .map(|&f| FunctionCurves {
                function: f,
                mag: series(f, false),
                phase: series(f, true),
                peaks: freq::find_peaks_in(&solver, &curve, f),
                main: freq::main_peak(&solver, &curve, f),
            })
            .collect();
        Derived {
            solver,
            curve,
            functions,
        }
    }

    /// The main peak of the first function (STHT), where the cursor starts.
    pub fn first_main(&self) -> Option<Peak> {
        self.functions.first().and_then(|c| c.main)
    }
}

/// The modes, or why there are none.
pub fn modes_of(body: &Body) -> Result<Modes, String> {
    freq::analyse_modes(body).map_err(|e| e.to_string())
}

/// A part of a background computation, as it arrives on the channel.
#[derive(Debug)]
pub enum Part {
    Curves(Box<Derived>),
    /// The last part; None when the job was cancelled before the modes.
    Modes(Option<Result<Modes, String>>),
}

/// A running background computation. `cancel` makes it skip the modes
/// (the solver itself cannot be interrupted); its last part still comes.
#[derive(Debug)]
pub struct Job {
    pub generation: u64,
    cancel: Arc<AtomicBool>,
}

impl Job {
    /// Starts computing `body` on its own thread; `send` delivers each part
    /// (and returns false once nobody listens).
    pub fn start(
        generation: u64,
        body: Body,
        band: Band,
        send: impl Fn(Part) -> bool + Send + 'static,
    ) -> std::io::Result<Job> {
        let cancel = Arc::new(AtomicBool::new(false));
        let flag = Arc::clone(&cancel);
        std::thread::Builder::new()
            .name("derived".into())
            .spawn(move || {
                let d = Derived::compute(&body, &band);
                if !send(Part::Curves(Box::new(d))) {
                    return;
                }
                // The last part always comes: it tells the app the job ended.
                let modes = (!flag.load(Ordering::Relaxed)).then(|| modes_of(&body));
                send(Part::Modes(modes));
            })?;
        Ok(Job { generation, cancel })
    }

    /// Asks the thread to skip what it has not started yet.
    pub fn cancel(&self) {
        self.cancel.store(true, Ordering::Relaxed);
    }
}
