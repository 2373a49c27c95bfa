//! The full-screen terminal app (ratatui + crossterm).

pub mod chart;

/// Options the command line passes to the TUI.
#[derive(Debug, Clone, Default)]
pub struct TuiOptions {
    /// Preset file or built-in name to open; None for the built-in default.
    pub preset: Option<String>,
    /// Plain ASCII chart markers and borders.
    pub ascii: bool,
}

/// Runs the TUI until the user quits. The terminal is restored on every exit path.
pub fn run(opts: TuiOptions) -> anyhow::Result<()> {
    anyhow::bail!(
        "the terminal app is not built yet (asked for preset {:?}, ascii {}); use the headless commands (biodyn --help)",
        opts.preset,
        opts.ascii
    )
}
