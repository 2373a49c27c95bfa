//! The `biodyn` binary: the full-screen TUI (no arguments) and the headless
//! command line. Both are thin front ends over the `biodyn` library.

fn main() -> std::process::ExitCode {
    biodyn_app::cli::main()
}
