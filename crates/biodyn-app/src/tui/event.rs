//! Messages and the threads that produce them. One input thread and the
//! training worker send into one `mpsc` channel; the main loop blocks on it,
//! so an idle app sleeps instead of polling.

use ratatui::crossterm::event::{self, Event, KeyEvent, KeyEventKind};
use std::sync::mpsc::{Receiver, Sender, channel};
use std::thread;

/// Everything that can change the app's state.
#[derive(Debug)]
pub enum Msg {
    Key(KeyEvent),
    Resize(u16, u16),
    /// A report from the training worker.
    Train(super::training::TrainMsg),
    /// SIGTERM, SIGHUP, SIGINT or SIGQUIT: leave cleanly, restoring the terminal.
    Signal(i32),
}

/// The channel, with the input thread already reading into it.
pub struct Events {
    pub tx: Sender<Msg>,
    pub rx: Receiver<Msg>,
}

impl Events {
    pub fn start() -> std::io::Result<Events> {
        let (tx, rx) = channel();
        let input = tx.clone();
        thread::Builder::new()
            .name("input".into())
            .spawn(move || input_loop(&input))?;
        #[cfg(unix)]
        {
            use signal_hook::consts::{SIGHUP, SIGINT, SIGQUIT, SIGTERM};
            let mut signals =
                signal_hook::iterator::Signals::new([SIGTERM, SIGHUP, SIGINT, SIGQUIT])?;
            let sig_tx = tx.clone();
            thread::Builder::new()
                .name("signals".into())
                .spawn(move || {
                    // A kill or a closed SSH session ends the app through the
                    // normal path, so the terminal is restored, not left raw.
                    if let Some(sig) = signals.forever().next() {
                        let _ = sig_tx.send(Msg::Signal(sig));
                    }
                })?;
        }
        Ok(Events { tx, rx })
    }
}

/// Blocks in `event::read`; only key presses (not repeats' releases) and
/// resizes go on. Ends when the receiver is gone or the terminal errors.
fn input_loop(tx: &Sender<Msg>) {
    while let Ok(ev) = event::read() {
        let msg = match ev {
            Event::Key(k) if k.kind == KeyEventKind::Press => Msg::Key(k),
            Event::Resize(w, h) => Msg::Resize(w, h),
            _ => continue,
        };
        if tx.send(msg).is_err() {
            break;
        }
    }
}
