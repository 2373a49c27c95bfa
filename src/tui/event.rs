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
