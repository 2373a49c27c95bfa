//! The `biodyn` binary: the full-screen TUI (no arguments) and the headless
//! command line. Both are thin front ends over the `biodyn` library; this
//! file is the only place that knows both.

use biodyn_app::cli::{self, Cli, Command};
use biodyn_app::tui;
use clap::Parser;

fn main() -> std::process::ExitCode {
    let parsed = Cli::parse();
    let result = match &parsed.command {
        None if !cli::have_terminal() => return cli::no_terminal(),
        None => tui::run(tui::TuiOptions::default()),
        Some(Command::Tui(a)) => tui::run(tui::TuiOptions {
            preset: a.preset.clone(),
            ascii: a.ascii,
        }),
        Some(command) => cli::run(command),
    };
    cli::exit(result)
}
