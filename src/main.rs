//! The `biodyn` binary: the full-screen TUI (no arguments) and the headless
//! command line. Both are thin front ends over the `biodyn` library.

mod cli;
mod tui;

fn main() -> std::process::ExitCode {
    cli::main()
}
