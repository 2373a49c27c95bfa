//! Messages and the threads that produce them. One input thread, the
//! background jobs and the tabs' workers send into one `mpsc` channel; the
//! main loop blocks on it, so an idle app sleeps instead of polling.

use super::derived::Part;
use biodyn::Clock;
use ratatui::crossterm::event::{self, Event, KeyEvent, KeyEventKind, MouseEvent, MouseEventKind};
use std::any::Any;
use std::sync::mpsc::{Receiver, Sender, channel};
use std::thread;

/// Everything that can change the app's state.
#[derive(Debug)]
pub enum Msg {
    Key(KeyEvent),
    Resize(u16, u16),
    /// A button press or a wheel step (only while mouse capture is on).
    Mouse(MouseEvent),
    /// Part of the derived data (curves, modes) of model generation `.0`,
    /// computed in the background for a large model.
    Derived(u64, Part),
    /// A message for tab `.0` from its own worker; only that tab knows the
    /// type inside (training progress, a background study, …).
    Tab(usize, Box<dyn Any + Send>),
    /// Text the user pasted (bracketed paste): for the open field, never keys.
    Paste(String),
    /// SIGTERM, SIGHUP, SIGINT or SIGQUIT: leave cleanly, restoring the terminal.
    Signal(i32),
}

/// A tab's way to the main channel: whatever it sends arrives back at it
/// as `Tab::on_msg`. None where there is no channel (some tests). With it
/// the clock its workers read (a test's manual one, or the real one).
#[derive(Debug, Clone)]
pub struct Mailbox {
    pub tab: usize,
    pub tx: Option<Sender<Msg>>,
    pub clock: Clock,
}

impl Mailbox {
    /// The channel and a function that wraps a `T` for this tab.
    pub fn wrap<T: Send + 'static>(
        &self,
    ) -> Option<(Sender<Msg>, impl Fn(T) -> Msg + Send + 'static)> {
        let tab = self.tab;
        let tx = self.tx.clone()?;
        Some((tx, move |t: T| Msg::Tab(tab, Box::new(t))))
    }
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

/// Blocks in `event::read`; only key presses (not repeats' releases),
/// mouse presses and wheel steps (not moves, drags or releases) and
/// resizes go on. Ends when the receiver is gone or the terminal errors.
fn input_loop(tx: &Sender<Msg>) {
    while let Ok(ev) = event::read() {
        let msg = match ev {
            Event::Key(k) if k.kind == KeyEventKind::Press => Msg::Key(k),
            Event::Resize(w, h) => Msg::Resize(w, h),
            Event::Paste(text) => Msg::Paste(text),
            Event::Mouse(m)
                if matches!(
                    m.kind,
                    MouseEventKind::Down(_) | MouseEventKind::ScrollUp | MouseEventKind::ScrollDown
                ) =>
            {
                Msg::Mouse(m)
            }
            _ => continue,
        };
        if tx.send(msg).is_err() {
            break;
        }
    }
}
