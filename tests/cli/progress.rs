//! The progress line of long commands: on a terminal's stderr it is drawn
//! (once before any work, so a short run shows it) and cleared before the
//! result; in a pipe, with `CI` set or with `--quiet`, nothing. And the
//! closing summary that is not printed once the reader has left.
//!
//! No clock in here: the first draw happens before the work starts, the
//! clear when the work ends, whatever the machine's speed.

use crate::common::{root, skip};
use std::io::{BufRead, BufReader};
use std::process::{Command, Stdio};

/// Erase-line, what indicatif's clear (and our interrupt handler) writes.
const ERASE: &str = "\x1b[2K";

/// Each long command, the start of its progress line and a piece of its
/// result that comes only after the work.
const LONG: &[(&str, &str, &str)] = &[
    (
        "train --case mass-apms --epochs 3",
        "mass-apms [",
        "hold-out (0.5",
    ),
    (
        "fit --data examples/synthetic-stht-apms-3pct-2deg.csv --starts 2 --intervals curvature",
        "fit [",
        "95% high",
    ),
    ("response --step 0.01", "response [", "f Hz"),
    ("study k4 -40%,0%,+40%", "study [", "Study of k4"),
    (
        "plot stht --study mass=65,75,85",
        "study [",
        "seat-to-head transmissibility",
    ),
    (
        "assess --signal sine:freq=5,amp=1 --duration 5",
        "assess [",
        "At the seat",
    ),
    (
        "seat --preset paper-75kg-suspension-seat --class EM6 --vary suspension.c=200..4000 --stroke-rms-max 0.015",
        "seat [",
        "best: suspension.c",
    ),
];

/// `biodyn ARGS` under a pseudo-terminal of 100 x 40 (util-linux `script`;
/// its own terminal has no size), with `env` set and `CI` removed unless
/// set there: everything the terminal got, stdout and stderr interleaved
/// as they were written. None: no `script`.
fn in_pty(args: &str, env: &[(&str, &str)]) -> Option<String> {
    let line = format!(
        "stty cols 100 rows 40; exec {} {args}",
        env!("CARGO_BIN_EXE_biodyn")
    );
    let mut c = Command::new("script");
    c.args(["-qec", &line, "/dev/null"])
        .current_dir(root())
        .env_remove("CI")
        .stdin(Stdio::null());
    for (k, v) in env {
        c.env(k, v);
    }
    let Ok(out) = c.output() else {
        skip("script (util-linux) not available");
        return None;
    };
    assert_eq!(out.status.code(), Some(0), "{args}: {out:?}");
    Some(String::from_utf8_lossy(&out.stdout).into_owned())
}

/// `biodyn ARGS` with stdout and stderr on pipes and no `CI`: (status, stdout, stderr).
fn in_pipes(args: &[&str]) -> (Option<i32>, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_biodyn"))
        .args(args)
        .current_dir(root())
        .env_remove("CI")
        .stdin(Stdio::null())
        .output()
        .expect("biodyn runs");
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn a_terminal_sees_the_line_and_it_is_cleared_before_the_result() {
    for &(args, line, result) in LONG {
        let Some(screen) = in_pty(args, &[]) else {
            return;
        };
        let first = screen.find(line).unwrap_or_else(|| {
            panic!("{args}: no progress line {line:?} on the terminal:\n{screen:?}")
        });
        let at = screen
            .find(result)
            .unwrap_or_else(|| panic!("{args}: no result {result:?}:\n{screen:?}"));
        assert!(first < at, "{args}: the line is drawn after the result");
        let last = screen.rfind(line).unwrap_or(first);
        assert!(
            last < at,
            "{args}: the line is drawn again after the result:\n{screen:?}"
        );
        let between = &screen[last..at];
        assert!(
            between.contains(ERASE),
            "{args}: the line is not erased before the result:\n{between:?}"
        );
    }
}

#[test]
fn simulate_into_a_file_shows_the_line_but_not_beside_rows_on_the_terminal() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("run.csv");
    let args = format!(
        "simulate --signal sine:freq=5,amp=1 --duration 2 --format csv > {}",
        file.display()
    );
    let Some(screen) = in_pty(&args, &[]) else {
        return;
    };
    assert!(screen.contains("simulate ["), "{screen:?}");
    assert!(screen.contains(ERASE), "{screen:?}");
    let csv = std::fs::read_to_string(&file).unwrap();
    assert!(
        !csv.contains('\x1b') && csv.lines().count() == 2001,
        "{csv}"
    );
    // Rows streamed to the terminal are the progress themselves.
    let Some(screen) = in_pty("simulate --signal sine:freq=5,amp=1 --duration 0.1", &[]) else {
        return;
    };
    assert!(!screen.contains("simulate ["), "{screen:?}");
}

#[test]
fn quiet_anywhere_on_the_line_and_ci_draw_nothing() {
    for &(args, line, result) in LONG {
        let (cmd, rest) = args.split_once(' ').unwrap();
        for (how, args, env) in [
            ("--quiet after", format!("{args} --quiet"), &[][..]),
            ("-q before", format!("-q {cmd} {rest}"), &[][..]),
            ("CI=1", args.to_string(), &[("CI", "1")][..]),
        ] {
            let Some(screen) = in_pty(&args, env) else {
                return;
            };
            assert!(screen.contains(result), "{how} {args}: {screen:?}");
            assert!(
                !screen.contains(line) && !screen.contains('\x1b'),
                "{how} {args}: a progress line:\n{screen:?}"
            );
        }
    }
    // An empty CI is no CI.
    let Some(screen) = in_pty("response --step 0.01", &[("CI", "")]) else {
        return;
    };
    assert!(screen.contains("response ["), "{screen:?}");
}

#[test]
fn a_pipe_gets_no_progress_on_stderr() {
    for &(args, _, result) in LONG {
        let argv: Vec<&str> = args.split(' ').collect();
        let (code, out, err) = in_pipes(&argv);
        assert_eq!(code, Some(0), "{args}: {err}");
        assert!(out.contains(result), "{args}: {out}");
        assert!(err.is_empty(), "{args}: stderr in a pipe: {err:?}");
    }
}

#[test]
fn quiet_silences_saved_notes_but_not_warnings() {
    let dir = tempfile::tempdir().unwrap();
    let net = dir.path().join("net.json");
    let net = net.to_str().unwrap();
    let train = ["train", "--case", "k4-dpmi", "--epochs", "2", "--save", net];
    let (code, _, err) = in_pipes(&train);
    assert_eq!(code, Some(0), "{err}");
    assert!(err.contains("saved k4-dpmi to"), "{err}");
    let (code, _, err) = in_pipes(&[&train[..], &["--force", "--quiet"]].concat());
    assert_eq!(code, Some(0), "{err}");
    assert!(err.is_empty(), "--quiet: {err}");
    // A warning about the result is not progress: it stays.
    let (code, _, err) = in_pipes(&["predict", "--net", net, "--body-mass", "90", "-q"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        err.contains("warning: k4-dpmi was trained at 75 kg"),
        "{err}"
    );
}

/// A network for `predict`, trained in a few epochs.
fn small_net(dir: &std::path::Path) -> String {
    let net = dir.join("apms.json");
    let net = net.to_str().unwrap().to_string();
    let (code, _, err) = in_pipes(&[
        "train",
        "--case",
        "mass-apms",
        "--epochs",
        "2",
        "--save",
        &net,
    ]);
    assert_eq!(code, Some(0), "{err}");
    net
}

#[test]
fn a_reader_that_left_gets_no_summary_and_the_status_is_0() {
    let dir = tempfile::tempdir().unwrap();
    let net = small_net(dir.path());
    // Read to the end: the summary follows the result.
    let args = [
        "predict", "--net", &net, "--format", "csv", "--step", "0.001",
    ];
    let (code, out, err) = in_pipes(&args);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        out.len() > 1 << 19,
        "{} bytes: more than any pipe holds",
        out.len()
    );
    assert!(err.contains("mass-apms: max error"), "{err}");
    // `| head -1`: one line read, then the pipe closed. The output is
    // far larger than a pipe's buffer, so a write fails after the close.
    let mut child = Command::new(env!("CARGO_BIN_EXE_biodyn"))
        .args(args)
        .current_dir(root())
        .env_remove("CI")
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("biodyn runs");
    let mut first = String::new();
    BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut first)
        .unwrap();
    assert_eq!(first, "f_hz,predicted,analytic,err_pct\n");
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{err}");
    assert!(err.is_empty(), "after the reader left: {err:?}");
}

/// Ctrl-C in the middle of a long run: the line is erased, then the
/// process dies of the signal as it did before there was a line (the
/// shell's status 130). The signal is sent once the first draw is seen:
/// no clock.
#[test]
fn ctrl_c_erases_the_line_and_ends_by_the_signal() {
    use std::io::Read;
    let line = format!(
        "stty cols 100 rows 40; echo PID=$$; exec {} train --case mass-apms --epochs 1000000",
        env!("CARGO_BIN_EXE_biodyn")
    );
    let Ok(mut child) = Command::new("script")
        .args(["-qec", &line, "/dev/null"])
        .current_dir(root())
        .env_remove("CI")
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .spawn()
    else {
        skip("script (util-linux) not available");
        return;
    };
    let mut out = child.stdout.take().unwrap();
    let mut seen = Vec::new();
    let mut buf = [0u8; 4096];
    while !String::from_utf8_lossy(&seen).contains("mass-apms [") {
        let n = out.read(&mut buf).unwrap();
        assert!(
            n > 0,
            "ended before drawing: {:?}",
            String::from_utf8_lossy(&seen)
        );
        seen.extend_from_slice(&buf[..n]);
    }
    let text = String::from_utf8_lossy(&seen).into_owned();
    let pid = text
        .split("PID=")
        .nth(1)
        .and_then(|r| r.split_whitespace().next())
        .expect("the shell's pid");
    let kill = Command::new("kill").args(["-INT", pid]).status().unwrap();
    assert!(kill.success());
    out.read_to_end(&mut seen).unwrap();
    let status = child.wait().unwrap();
    let screen = String::from_utf8_lossy(&seen);
    assert_eq!(status.code(), Some(130), "{screen:?}");
    let last = screen.rfind("mass-apms [").unwrap();
    assert!(
        screen[last..].contains(ERASE),
        "the line is left on the screen: {:?}",
        &screen[last..]
    );
    assert!(
        !screen.contains("panicked") && !screen.contains("error"),
        "{screen:?}"
    );
}
