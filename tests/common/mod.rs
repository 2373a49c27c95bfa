//! Helpers shared by the tests of the real binary: run `biodyn`
//! from the workspace root and check the shape of its success or error.

// Each test file uses its own subset of these.
#![allow(dead_code)]

use std::path::Path;
use std::process::{Command, Stdio};

/// A test that cannot run here because a tool is missing (tmux, pgrep,
/// mkfifo, script, /dev/full, groff/man, bash) says so on stderr; with
/// `BIODYN_REQUIRE_TOOLS=1`, which `.ci/run` sets after installing them,
/// the skip is a failure instead, so CI never passes a test it did not run.
pub fn skip(what: &str) {
    if std::env::var("BIODYN_REQUIRE_TOOLS").is_ok_and(|v| v == "1") {
        panic!("{what}: this test cannot run, and BIODYN_REQUIRE_TOOLS=1 forbids skipping it");
    }
    eprintln!("{what}: skipped");
}

/// The workspace root, where `presets/`, `data/` and `examples/` live.
pub fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// Runs biodyn with `args` from the workspace root: (exit code, stdout, stderr).
pub fn run(args: &[&str]) -> (Option<i32>, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_biodyn"))
        .args(args)
        .current_dir(root())
        .stdin(Stdio::null())
        .output()
        .expect("biodyn runs");
    (
        out.status.code(),
        String::from_utf8(out.stdout).expect("stdout is UTF-8"),
        String::from_utf8(out.stderr).expect("stderr is UTF-8"),
    )
}

/// Runs and expects success with nothing on stderr; returns stdout.
pub fn ok(args: &[&str]) -> String {
    let (code, out, err) = run(args);
    assert_eq!(code, Some(0), "{args:?} failed: {err}");
    assert!(err.is_empty(), "{args:?}: stderr: {err}");
    out
}

/// Runs and expects a biodyn error: status 1, empty stdout, one error line
/// and one hint line on stderr. Returns stderr.
pub fn fails(args: &[&str]) -> String {
    let (code, out, err) = run(args);
    assert_eq!(code, Some(1), "{args:?}: status {code:?}, stderr: {err}");
    assert!(out.is_empty(), "{args:?}: stdout not empty: {out}");
    assert!(!err.contains("panicked"), "{args:?}: {err}");
    let lines: Vec<&str> = err.lines().collect();
    assert_eq!(lines.len(), 2, "{args:?}: not error + hint: {err}");
    assert!(lines[0].starts_with("biodyn: error: "), "{args:?}: {err}");
    assert!(lines[1].starts_with("  hint: "), "{args:?}: {err}");
    assert!(lines[1].len() > "  hint: ".len() + 10, "{args:?}: {err}");
    err
}
pub mod tmux;
