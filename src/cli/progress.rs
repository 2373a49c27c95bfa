//! The progress line of a long command (`train`, `fit`, `simulate`,
//! `assess`, `study`, `response`, `seat --vary`): one `indicatif` bar or
//! spinner on standard error, **only when standard error is a terminal**.
//! In a pipe or a file, with `CI` set (non-empty) or with `--quiet`, a
//! [`Progress`] is hidden and costs a branch per update; the output on
//! stdout is the same either way, so a script never sees a progress line.
//!
//! The line is drawn once when it is made, before any work, so even a short
//! run shows it (and a test under a pseudo-terminal sees it without waiting
//! on the clock); after that at most every [`EVERY`]. Dropping it clears the
//! line, on success and on an error alike, so the result or the error line
//! starts on a clean line. While a line is on the screen, Ctrl-C (SIGINT,
//! SIGTERM, SIGHUP) clears it before the process dies of the signal as it
//! would have without a line: the shell's prompt starts on an empty line.

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

/// `--quiet`, set once when the command line is parsed.
static QUIET: AtomicBool = AtomicBool::new(false);

/// A terminating signal arrived: no more redraws over the cleared line.
static STOPPING: AtomicBool = AtomicBool::new(false);

/// Most redraws: every 50 ms (20 a second, indicatif's own default rate).
pub const EVERY: Duration = Duration::from_millis(50);

/// Records `--quiet` for the whole run (progress lines, "saved …" notes and
/// closing summaries then stay off stderr; warnings and errors do not).
pub fn set_quiet(quiet: bool) {
    QUIET.store(quiet, Ordering::Relaxed);
}

/// Whether `--quiet` was given.
pub fn quiet() -> bool {
    QUIET.load(Ordering::Relaxed)
}

/// Whether a progress line may be drawn: stderr is a terminal, `CI` is
/// unset or empty, and `--quiet` was not given.
pub fn shown() -> bool {
    !quiet()
        && std::env::var_os("CI").is_none_or(|v| v.is_empty())
        && std::io::stderr().is_terminal()
}

/// One progress line; hidden where [`shown`] is false.
pub struct Progress {
    bar: Option<ProgressBar>,
    last: Instant,
}

impl Progress {
    /// A bar of `total` steps: `what` first, then the bar, the message
    /// (the caller's counts and figures) and the time left. Short, so it
    /// fits 80 columns: a line that wraps cannot be redrawn in place.
    /// `first` is the message of the first draw.
    pub fn bar(what: &str, total: u64, first: String) -> Progress {
        Progress::new(
            what,
            Some(total),
            first,
            "{prefix} [{bar:16}] {msg} eta {eta}",
        )
    }

    /// A spinner for work of unknown size: `what`, the message, the time so far.
    pub fn spinner(what: &str, first: String) -> Progress {
        Progress::new(what, None, first, "{prefix} {spinner} {msg} {elapsed}")
    }

    fn new(what: &str, total: Option<u64>, first: String, template: &str) -> Progress {
        let now = Instant::now();
        if !shown() {
            return Progress {
                bar: None,
                last: now,
            };
        }
        let style = ProgressStyle::with_template(template)
            .unwrap_or_else(|_| ProgressStyle::default_bar())
            .progress_chars("#>-");
        let target = ProgressDrawTarget::stderr_with_hz(20);
        let bar = ProgressBar::with_draw_target(total, target)
            .with_style(style)
            .with_prefix(what.to_string())
            .with_message(first);
        interrupt_clears_line();
        // The first draw, before any work: deterministic, whatever the clock.
        bar.tick();
        Progress {
            bar: Some(bar),
            last: now,
        }
    }

    /// `done` steps; `msg` (built only when a redraw is due) after the counts.
    pub fn update(&mut self, done: u64, msg: impl FnOnce() -> String) {
        let Some(bar) = &self.bar else { return };
        if self.last.elapsed() < EVERY || STOPPING.load(Ordering::Relaxed) {
            return;
        }
        self.last = Instant::now();
        bar.set_message(msg());
        bar.set_position(done);
    }

    /// A new total (work whose size becomes known as it goes).
    pub fn set_total(&mut self, total: u64) {
        if let Some(bar) = self.bar.as_ref().filter(|b| b.length() != Some(total)) {
            bar.set_length(total);
        }
    }
}

impl Drop for Progress {
    /// Clears the line, so what follows starts on a clean line.
    fn drop(&mut self) {
        if let Some(bar) = self.bar.take() {
            bar.finish_and_clear();
        }
    }
}

/// Counts the samples of a stream into a [`Progress`], looking at the clock
/// only every 4096 samples (an update per sample would cost more than the
/// filter it reports on).
pub struct Counted<I> {
    inner: I,
    done: u64,
    total: Option<u64>,
    progress: Progress,
}

impl<I: Iterator> Counted<I> {
    /// `what`'s samples, `total` of them when known (a bar with its time
    /// left), else a spinner with the count.
    pub fn new(inner: I, what: &str, total: Option<u64>) -> Counted<I> {
        let first = samples_message(0, total);
        let progress = match total {
            Some(n) => Progress::bar(what, n, first),
            None => Progress::spinner(what, first),
        };
        Counted {
            inner,
            done: 0,
            total,
            progress,
        }
    }
}

/// "4096/600000 samples", or "4096 samples" when the total is unknown.
fn samples_message(done: u64, total: Option<u64>) -> String {
    match total {
        Some(n) => of(done, n, "samples"),
        None => format!("{done} samples"),
    }
}

/// "120/4000 frequencies": a count of a total, with its unit.
pub fn of(done: impl std::fmt::Display, total: impl std::fmt::Display, unit: &str) -> String {
    format!("{done}/{total} {unit}")
}

/// A bar over a library's `(done, total)` callback: the total is the
/// callback's (known from its first call), `unit` names what is counted.
pub fn counting(what: &'static str, unit: &'static str) -> impl FnMut(usize, usize) {
    let mut bar: Option<Progress> = None;
    move |done, total| {
        let line = bar.get_or_insert_with(|| Progress::bar(what, total as u64, of(0, total, unit)));
        line.update(done as u64, || of(done, total, unit));
    }
}

impl<I: Iterator> Iterator for Counted<I> {
    type Item = I::Item;

    fn next(&mut self) -> Option<I::Item> {
        let item = self.inner.next();
        if item.is_some() {
            self.done += 1;
            if self.done % 4096 == 0 {
                let (done, total) = (self.done, self.total);
                self.progress.update(done, || samples_message(done, total));
            }
        }
        item
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        self.inner.size_hint()
    }
}

/// With a line on the screen, a terminating signal first clears it, then
/// ends the process as the signal's default action would (the same exit
/// status as without a line: the shell sees the signal). Installed once.
fn interrupt_clears_line() {
    #[cfg(unix)]
    {
        static ONCE: std::sync::Once = std::sync::Once::new();
        ONCE.call_once(|| {
            use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
            let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP])
            else {
                return; // no handler: the default action, as before
            };
            let _ = std::thread::Builder::new()
                .name("progress-signals".into())
                .spawn(move || {
                    if let Some(sig) = signals.forever().next() {
                        use std::io::Write as _;
                        STOPPING.store(true, Ordering::Relaxed);
                        // Carriage return, erase the line: the ^C echo too.
                        let _ = write!(std::io::stderr(), "\r\x1b[2K");
                        let _ = std::io::stderr().flush();
                        let _ = signal_hook::low_level::emulate_default_handler(sig);
                        std::process::exit(128 + sig);
                    }
                });
        });
    }
}
