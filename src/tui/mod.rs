//! The full-screen terminal app (ratatui + crossterm).
//!
//! A key press becomes an effect and a redraw like this: `event.rs` puts it
//! on the one channel; `update.rs` hands it to the open dialog or field
//! (`popups::Popup::on_key`, which returns `popups::Act`s that
//! `App::apply_acts` carries out), else to the current tab
//! (`component::Tab::on_key`), which changes its own state and returns
//! `effect::Effect`s; `App::apply` (app.rs) carries them out in one place;
//! the loop below then draws once from `&App` (`frame.rs`, each tab's and
//! dialog's `render`). Tabs live in `tabs/`, one folder each, registered by
//! one line in `tabs/mod.rs`; dialogs in `popups/`, one file each,
//! registered by one line in `popups/mod.rs`. The loop blocks on the channel,
//! so an idle app uses no CPU; a large model's curves, peaks and modes are
//! computed on a thread (`derived.rs`), so the first frame and `q` never
//! wait for the solver.

pub mod app;
pub mod component;
pub mod derived;
pub mod effect;
pub mod event;
pub mod frame;
pub mod input;
pub mod keys;
pub mod model_check;
pub mod paths;
pub mod popups;
pub mod shared;
pub mod strings;
pub mod tabs;
pub mod terminal;
pub mod theme;
pub mod update;
pub mod widgets;

#[cfg(test)]
mod tests;

pub use frame::draw;

use std::sync::mpsc::RecvTimeoutError;
use std::time::Duration;

/// Options the command line passes to the TUI.
#[derive(Debug, Clone, Default)]
pub struct TuiOptions {
    /// Preset file or built-in name to open; None for the built-in default.
    pub preset: Option<String>,
    /// A day file to open on the Day tab.
    pub day: Option<std::path::PathBuf>,
    /// Plain ASCII chart markers and borders.
    pub ascii: bool,
}

/// How the app ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ended {
    /// The user quit (q, Ctrl-C): status 0.
    Quit,
    /// A signal (SIGTERM, SIGHUP, SIGINT, SIGQUIT) ended it, the terminal
    /// restored first.
    Signal(i32),
}

impl Ended {
    /// The process's exit status: 0, or 128 + the signal's number (143 for
    /// SIGTERM, 129 SIGHUP, 130 SIGINT, 131 SIGQUIT), what a shell reports
    /// for a command the signal killed.
    pub fn status(self) -> u8 {
        match self {
            Ended::Quit => 0,
            Ended::Signal(sig) => u8::try_from(128 + sig.clamp(0, 127)).unwrap_or(u8::MAX),
        }
    }
}

/// Runs the TUI until the user quits or a signal ends it. The terminal is
/// restored on every exit path.
pub fn run(opts: TuiOptions) -> anyhow::Result<Ended> {
    let theme = theme::Theme::from_env(opts.ascii);
    // Load before touching the terminal, so a bad preset is reported as a
    // normal one-line error.
    let (preset, path) = match &opts.preset {
        Some(p) => app::open_preset(p)?,
        None => (biodyn::Preset::builtin_default(), None),
    };
    let day = match &opts.day {
        Some(d) => Some((d.clone(), biodyn::exposure::DayFile::load(d)?)),
        None => None,
    };
    let mut guard = terminal::Guard::init()?;
    let events = event::Events::start()?;
    // A large model starts computing here, on its own thread.
    let mut app = app::App::with_channel(preset, path, theme, Some(events.tx.clone()));
    app.size = guard.terminal.size().ok().map(|s| (s.width, s.height));
    if let Some((path, file)) = day {
        app.open_day(path, file);
    }
    guard.terminal.draw(|f| draw(f, &app))?;
    loop {
        let msg = match events.rx.recv_timeout(Duration::from_secs(1)) {
            Ok(m) => m,
            // Once a second: an old message leaves the status line.
            Err(RecvTimeoutError::Timeout) => {
                if app.expire(std::time::Instant::now()) {
                    guard.terminal.draw(|f| draw(f, &app))?;
                }
                continue;
            }
            Err(RecvTimeoutError::Disconnected) => break,
        };
        update::update(&mut app, msg);
        // Take whatever else is queued before drawing once.
        while !app.quit {
            match events.rx.try_recv() {
                Ok(m) => update::update(&mut app, m),
                Err(_) => break,
            }
        }
        if app.quit {
            break;
        }
        // A busy channel (a training reports 30 times a second) never times
        // out, so old messages are also dropped here.
        app.expire(std::time::Instant::now());
        if let Err(e) = guard.set_mouse(app.mouse) {
            app.mouse = false;
            app.fail(format!("cannot switch mouse capture: {e}"));
        }
        guard.terminal.draw(|f| draw(f, &app))?;
    }
    app.shutdown();
    drop(guard);
    Ok(app.signal.map_or(Ended::Quit, Ended::Signal))
}
