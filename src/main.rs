//! The `biodyn` binary: the full-screen TUI (no arguments) and the headless
//! command line. Both are thin front ends over the `biodyn` library; this
//! file is the only place that knows both.

use biodyn_app::cli::{self, Command, TuiArgs};
use biodyn_app::tui;

fn main() -> std::process::ExitCode {
    let parsed = match cli::parse() {
        Ok(p) => p,
        Err(code) => return code,
    };
    let result = match &parsed.command {
        None => return app(&parsed.tui),
        Some(Command::Tui(a)) => return app(a),
        Some(command) => cli::run(command),
    };
    cli::exit(result)
}

/// The full-screen app, when there is a terminal to draw on. A preset that
/// cannot load is named first, wherever the app was started.
fn app(a: &TuiArgs) -> std::process::ExitCode {
    if let Some(p) = &a.preset
        && let Err(e) = biodyn::Preset::open(p)
    {
        return cli::exit(Err(e.into()));
    }
    if let Some(d) = &a.day
        && let Err(e) = biodyn::exposure::DayFile::load(d)
    {
        return cli::exit(Err(e.into()));
    }
    if let Err(why) = cli::terminal_check() {
        return cli::no_terminal(why);
    }
    match tui::run(tui::TuiOptions {
        preset: a.preset.clone(),
        day: a.day.clone(),
        ascii: a.ascii,
    }) {
        // A signal: 128 + its number, as for a command it killed (143 SIGTERM).
        Ok(end) => std::process::ExitCode::from(end.status()),
        Err(e) => cli::exit(Err(e)),
    }
}
