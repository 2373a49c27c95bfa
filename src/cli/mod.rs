//! The headless command line (clap). Data go to stdout, diagnostics to stderr;
//! every error is one line plus a hint, with a non-zero exit.

use clap::{Parser, Subcommand};
use std::process::ExitCode;

#[derive(Debug, Parser)]
#[command(
    name = "biodyn",
    version,
    about = "Biodynamics of the seated human body under vertical whole-body vibration"
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// Open the full-screen terminal app (also the default with no command).
    Tui(TuiArgs),
}

#[derive(Debug, clap::Args)]
pub struct TuiArgs {
    /// Preset file (or built-in name) to open.
    #[arg(long)]
    pub preset: Option<String>,
    /// ASCII chart markers, for fonts without braille.
    #[arg(long)]
    pub ascii: bool,
}

pub fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        None => crate::tui::run(crate::tui::TuiOptions::default()),
        Some(Command::Tui(a)) => crate::tui::run(crate::tui::TuiOptions {
            preset: a.preset,
            ascii: a.ascii,
        }),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("biodyn: error: {e:#}");
            ExitCode::from(2)
        }
    }
}
