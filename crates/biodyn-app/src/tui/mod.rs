//! The full-screen terminal app (ratatui + crossterm).
//!
//! State + `update` + view: `app.rs` holds the state and the one `update`;
//! each tab draws itself from a borrowed `&App`; `event.rs` feeds one channel
//! from the input thread and the training worker; the loop below blocks on
//! that channel, so an idle app uses no CPU.

pub mod app;
pub mod event;
pub mod field;
pub mod frame;
pub mod keys;
pub mod model;
pub mod responses;
pub mod strings;
pub mod study;
pub mod terminal;
pub mod theme;
pub mod training;

#[cfg(test)]
mod tests;

use std::sync::mpsc::RecvTimeoutError;
use std::time::Duration;

/// Options the command line passes to the TUI.
#[derive(Debug, Clone, Default)]
pub struct TuiOptions {
    /// Preset file or built-in name to open; None for the built-in default.
    pub preset: Option<String>,
    /// Plain ASCII chart markers and borders.
    pub ascii: bool,
}

/// Draws the whole app into the frame.
pub fn draw(frame: &mut ratatui::Frame, app: &app::App) {
    frame.render_widget(app, frame.area());
}

/// Runs the TUI until the user quits. The terminal is restored on every exit path.
pub fn run(opts: TuiOptions) -> anyhow::Result<()> {
    let theme = theme::Theme::from_env(opts.ascii);
    // Load before touching the terminal, so a bad preset is reported as a
    // normal one-line error.
    let mut app = match &opts.preset {
        Some(p) => app::App::open(p, theme)?,
        None => app::App::new(biodyn::Preset::builtin_default(), None, theme),
    };
    let mut guard = terminal::Guard::init()?;
    let events = event::Events::start()?;
    app.tx = Some(events.tx.clone());
    guard.terminal.draw(|f| draw(f, &app))?;
    loop {
        let msg = match events.rx.recv_timeout(Duration::from_secs(1)) {
            Ok(m) => m,
            Err(RecvTimeoutError::Timeout) => continue,
            Err(RecvTimeoutError::Disconnected) => break,
        };
        app::update(&mut app, msg);
        // Take whatever else is queued before drawing once.
        while !app.quit {
            match events.rx.try_recv() {
                Ok(m) => app::update(&mut app, m),
                Err(_) => break,
            }
        }
        if app.quit {
            break;
        }
        guard.terminal.draw(|f| draw(f, &app))?;
    }
    training::stop(&mut app);
    drop(guard);
    Ok(())
}
