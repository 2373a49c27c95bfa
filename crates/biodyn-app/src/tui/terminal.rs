//! Terminal set-up and the guarantee that it is undone: on a normal exit, on
//! an error (the guard's `Drop`) and on a panic (ratatui's hook restores the
//! terminal before the panic message is printed).

use ratatui::DefaultTerminal;

/// Smallest terminal the layout is drawn for; below it, one line says so.
pub const MIN_WIDTH: u16 = 60;
pub const MIN_HEIGHT: u16 = 16;

/// Restores the terminal when dropped.
pub struct Guard {
    pub terminal: DefaultTerminal,
}

impl Guard {
    /// Raw mode + alternate screen; installs the restoring panic hook.
    pub fn init() -> std::io::Result<Guard> {
        let terminal = ratatui::try_init()?;
        Ok(Guard { terminal })
    }
}

impl Drop for Guard {
    fn drop(&mut self) {
        // We enable nothing beyond ratatui's defaults (no mouse capture, no
        // bracketed paste), so its restore undoes everything.
        let _ = self.terminal.show_cursor();
        ratatui::restore();
    }
}
