//! Terminal set-up and the guarantee that it is undone: on a normal exit, on
//! an error or a signal (the guard's `Drop`) and on a panic (our hook turns
//! mouse capture off, then ratatui's restores the terminal before the panic
//! message is printed).

use ratatui::DefaultTerminal;
use ratatui::crossterm::event::{
    DisableBracketedPaste, DisableMouseCapture, EnableBracketedPaste, EnableMouseCapture,
};
use ratatui::crossterm::execute;
use std::sync::atomic::{AtomicBool, Ordering};

/// Smallest terminal the layout is drawn for; below it, one line says so.
pub const MIN_WIDTH: u16 = 60;
pub const MIN_HEIGHT: u16 = 16;

/// Mouse capture is on; the panic hook reads it (it has no guard).
static MOUSE_ON: AtomicBool = AtomicBool::new(false);

/// Restores the terminal when dropped.
pub struct Guard {
    pub terminal: DefaultTerminal,
}

impl Guard {
    /// Raw mode + alternate screen + bracketed paste; installs the
    /// restoring panic hook. Mouse capture starts off, so the terminal's own
    /// text selection works. Bracketed paste makes a paste one event of text
    /// (`Msg::Paste`), so a pasted newline or `q` is never a key.
    pub fn init() -> std::io::Result<Guard> {
        let terminal = ratatui::try_init()?;
        let next = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            mouse_off();
            paste_off();
            next(info);
        }));
        // A terminal without it ignores the sequence: pastes then arrive
        // as keys, as before.
        if execute!(std::io::stdout(), EnableBracketedPaste).is_ok() {
            PASTE_ON.store(true, Ordering::SeqCst);
        }
        Ok(Guard { terminal })
    }

    /// Turns mouse capture on or off (the app's `M`).
    pub fn set_mouse(&mut self, on: bool) -> std::io::Result<()> {
        if on == MOUSE_ON.load(Ordering::SeqCst) {
            return Ok(());
        }
        if on {
            execute!(std::io::stdout(), EnableMouseCapture)?;
        } else {
            execute!(std::io::stdout(), DisableMouseCapture)?;
        }
        MOUSE_ON.store(on, Ordering::SeqCst);
        Ok(())
    }
}

/// Bracketed paste is on; the panic hook reads it.
static PASTE_ON: AtomicBool = AtomicBool::new(false);

/// Disables bracketed paste if it is on (idempotent: Drop and the panic hook).
fn paste_off() {
    if PASTE_ON.swap(false, Ordering::SeqCst) {
        let _ = execute!(std::io::stdout(), DisableBracketedPaste);
    }
}

/// Disables mouse capture if it is on (idempotent: Drop and the panic hook).
fn mouse_off() {
    if MOUSE_ON.swap(false, Ordering::SeqCst) {
        let _ = execute!(std::io::stdout(), DisableMouseCapture);
    }
}

impl Drop for Guard {
    fn drop(&mut self) {
        // Undo what we enabled beyond ratatui's defaults (mouse capture),
        // then ratatui's restore (raw mode, alternate screen).
        mouse_off();
        paste_off();
        let _ = self.terminal.show_cursor();
        ratatui::restore();
    }
}
