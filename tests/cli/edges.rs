//! The command line's edges as real processes: closed pipes, a full disk,
//! help that lists every closed set of values, settings flags built from the
//! library's table, refused combinations, hostile `./presets` entries and
//! the terminal app started where it cannot draw.

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).to_path_buf()
}

fn cmd(args: &[&str]) -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_biodyn"));
    c.args(args).current_dir(root()).stdin(Stdio::null());
    c
}

/// Runs to the end, but never longer than 60 s: a hang is a failure, not a stuck test.
fn finish(mut c: Command, what: &str) -> Output {
    let mut child = c
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("biodyn runs");
    let start = Instant::now();
    while child.try_wait().expect("wait").is_none() {
        if start.elapsed() > Duration::from_secs(60) {
            let _ = child.kill();
            panic!("{what}: still running after 60 s");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    child.wait_with_output().expect("output")
}

fn run(args: &[&str]) -> Output {
    finish(cmd(args), &format!("{args:?}"))
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

/// A small trained k4 network in `dir`.
fn k4_net(dir: &Path) -> String {
    let net = dir.join("k4.json");
    let n = net.to_str().unwrap().to_string();
    let out = run(&[
        "train",
        "--case",
        "k4-apms",
        "--epochs",
        "3",
        "--ensemble",
        "1",
        "--save",
        &n,
    ]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    n
}

/// Runs with stdout on a pipe whose reading end is already closed: every
/// write meets a closed pipe, with no race against a reader.
#[cfg(unix)]
fn into_closed_pipe(args: &[&str]) -> Output {
    // A socket pair behaves as a pipe here: with the reading end gone, a
    // write fails with EPIPE (BrokenPipe), exactly like `| head -1` after head quits.
    let (reader, writer) = std::os::unix::net::UnixStream::pair().expect("socket pair");
    drop(reader);
    let writer = std::os::fd::OwnedFd::from(writer);
    let mut c = cmd(args);
    c.stdout(Stdio::from(writer)).stderr(Stdio::piped());
    let child = c.spawn().expect("biodyn runs");
    child.wait_with_output().expect("output")
}

#[cfg(unix)]
#[test]
fn a_closed_pipe_ends_train_and_predict_quietly() {
    let dir = tempfile::tempdir().unwrap();
    let net = k4_net(dir.path());
    for args in [
        &[
            "train",
            "--case",
            "k4-stht",
            "--epochs",
            "2",
            "--ensemble",
            "1",
        ][..],
        &[
            "train", "--case", "k4-stht", "--epochs", "2", "--format", "json",
        ],
        &["predict", "--net", &net],
        &["predict", "--net", &net, "--format", "csv"],
        &["response"],
        &["modes"],
        &["--help"],
        &["--version"],
    ] {
        let out = into_closed_pipe(args);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{args:?}: {}",
            text(&out.stderr)
        );
        let e = text(&out.stderr);
        assert!(
            !e.contains("Broken pipe") && !e.contains("biodyn: error"),
            "{args:?}: {e}"
        );
    }
}

#[test]
fn a_full_disk_on_stdout_is_an_error_that_says_so() {
    let Ok(full) = std::fs::OpenOptions::new().write(true).open("/dev/full") else {
        crate::common::skip("no /dev/full on this system");
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let net = k4_net(dir.path());
    for args in [
        &["--help"][..],
        &["--version"],
        &["help", "response"],
        &["response", "--help"],
        &["response"],
        &["modes", "--format", "json"],
        &[
            "train",
            "--case",
            "k4-stht",
            "--epochs",
            "2",
            "--ensemble",
            "1",
        ],
        &["predict", "--net", &net],
    ] {
        let mut c = cmd(args);
        c.stdout(full.try_clone().unwrap()).stderr(Stdio::piped());
        let out = c.spawn().unwrap().wait_with_output().unwrap();
        assert_eq!(out.status.code(), Some(1), "{args:?}");
        let e = text(&out.stderr);
        assert!(e.contains("standard output"), "{args:?}: {e}");
        assert!(e.contains("No space left"), "{args:?}: {e}");
        assert!(!e.contains("hint"), "{args:?}: an unrelated hint: {e}");
        assert_eq!(e.lines().count(), 1, "{args:?}: {e}");
    }
}

#[test]
fn train_help_lists_cases_trainers_and_every_setting_flag() {
    let out = run(&["train", "--help"]);
    assert!(out.status.success());
    let h = text(&out.stdout);
    for c in biodyn::ann::Case::ALL {
        assert!(h.contains(c.key()), "case {c} missing:\n{h}");
    }
    for w in [
        "all", "backprop", "lm", "--from", "--to", "--step", "Example",
    ] {
        assert!(h.contains(w), "{w} missing:\n{h}");
    }
    assert!(!h.contains("--grid"), "--grid is gone:\n{h}");
    for s in biodyn::ann::SETTINGS
        .iter()
        .filter(|s| s.kind != biodyn::ann::SettingKind::Band)
    {
        assert!(
            h.contains(&format!("--{} ", s.flag)),
            "--{} missing",
            s.flag
        );
    }
    let p = text(&run(&["predict", "--help"]).stdout);
    for w in ["--preset", "--body-mass", "--set", "--from", "Example"] {
        assert!(p.contains(w), "predict --help lacks {w}:\n{p}");
    }
    let plot = text(&run(&["plot", "--help"]).stdout);
    assert!(plot.contains("stht") && plot.contains("apms") && plot.contains("20..1000"));
}

#[test]
fn setting_flags_reach_the_saved_network_and_ignored_ones_are_named() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("n.json");
    let p = path.to_str().unwrap();
    let out = run(&[
        "train",
        "--case",
        "k4-stht",
        "--trainer",
        "backprop",
        "--epochs",
        "3",
        "--activation",
        "tanh",
        "--gain",
        "0.5",
        "--from",
        "1",
        "--to",
        "10",
        "--step",
        "0.25",
        "--train-values",
        "60000,120000",
        "--weight-decay",
        "0.1",
        "--save",
        p,
    ]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let e = text(&out.stderr);
    assert!(
        e.contains("note: --weight-decay applies to --trainer lm only; backprop ignores it"),
        "{e}"
    );
    let net = biodyn::ann::load_network(&path).unwrap();
    let s = &net.settings;
    assert_eq!(s.activation, biodyn::ann::Activation::Tanh);
    assert_eq!(s.gain, 0.5);
    assert_eq!((s.grid.from, s.grid.to, s.grid.step), (1.0, 10.0, 0.25));
    assert_eq!(s.train_values, vec![60_000.0, 120_000.0]);
    assert_eq!(s.epochs, 3);
}

#[test]
fn predict_warns_far_outside_the_trained_frequencies() {
    let dir = tempfile::tempdir().unwrap();
    let net = k4_net(dir.path());
    let out = run(&[
        "predict", "--net", &net, "--from", "1", "--to", "100000", "--step", "1000",
    ]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let e = text(&out.stderr);
    assert!(
        e.contains("outside the trained frequencies 0.5–20 Hz"),
        "{e}"
    );
    let inside = run(&["predict", "--net", &net]);
    assert!(text(&inside.stderr).is_empty(), "{}", text(&inside.stderr));
    // The model group: the default preset equals --preset paper-75kg, and
    // --set takes only finite numbers.
    let a = run(&["predict", "--net", &net, "--format", "csv"]);
    let b = run(&[
        "predict",
        "--net",
        &net,
        "--preset",
        "paper-75kg",
        "--format",
        "csv",
    ]);
    assert_eq!(a.stdout, b.stdout);
    let bad = run(&["predict", "--net", &net, "--set", "k4=inf"]);
    assert_eq!(bad.status.code(), Some(1));
    assert!(
        text(&bad.stderr).contains("finite"),
        "{}",
        text(&bad.stderr)
    );
}

#[test]
fn plot_refuses_phase_on_a_log_axis_and_names_the_real_size_range() {
    let out = run(&["plot", "stht", "--phase", "--log-y"]);
    assert_eq!(out.status.code(), Some(2));
    let e = text(&out.stderr);
    assert!(e.contains("--phase") && e.contains("--log-y"), "{e}");
    assert!(out.stdout.is_empty());
    for w in ["100000", "5", "70000"] {
        let out = run(&["plot", "stht", "--width", w]);
        assert_eq!(out.status.code(), Some(1), "--width {w}");
        let e = text(&out.stderr);
        assert!(e.contains("20..1000"), "--width {w}: {e}");
        assert!(!e.contains("65535"), "--width {w}: {e}");
    }
}

/// `biodyn preset list` run in `dir` (which must succeed): its stdout, and
/// the one row that names `presets/<name>` (it must stand exactly once).
fn preset_list_in(dir: &Path) -> (String, impl Fn(&str) -> String) {
    let mut c = Command::new(env!("CARGO_BIN_EXE_biodyn"));
    c.args(["preset", "list"])
        .current_dir(dir)
        .stdin(Stdio::null());
    let out = finish(c, "preset list");
    assert!(out.status.success(), "{}", text(&out.stderr));
    let t = text(&out.stdout);
    let rows = t.clone();
    let row = move |name: &str| -> String {
        let p = format!("presets/{name}");
        assert_eq!(rows.matches(&p).count(), 1, "{p} not exactly once:\n{rows}");
        rows.lines()
            .find(|l| l.contains(&p))
            .unwrap_or_default()
            .to_string()
    };
    (t, row)
}

#[test]
fn preset_list_reports_hostile_entries_without_opening_them() {
    let dir = tempfile::tempdir().unwrap();
    let presets = dir.path().join("presets");
    std::fs::create_dir(&presets).unwrap();
    let good = std::fs::read_to_string(root().join("presets/paper-85kg.toml")).unwrap();
    std::fs::write(presets.join("good.toml"), good).unwrap();
    std::fs::write(presets.join("broken.toml"), "segments = [ nonsense").unwrap();
    let big = std::fs::File::create(presets.join("big.toml")).unwrap();
    big.set_len(64 << 20).unwrap();
    #[cfg(unix)]
    let fifo = {
        std::os::unix::fs::symlink("/dev/zero", presets.join("zero.toml")).unwrap();
        Command::new("mkfifo")
            .arg(presets.join("fifo.toml"))
            .status()
            .is_ok_and(|s| s.success())
    };
    #[cfg(not(unix))]
    let fifo = false;
    let (t, row) = preset_list_in(dir.path());
    assert!(row("good.toml").contains("66.38"), "{t}");
    assert!(row("broken.toml").contains("BROKEN"), "{t}");
    assert!(row("big.toml").contains("cap"), "{t}");
    #[cfg(unix)]
    assert!(row("zero.toml").contains("character device"), "{t}");
    if fifo {
        assert!(row("fifo.toml").contains("FIFO"), "{t}");
    }
}

/// A broken preset in `preset list` reads in the command line's words, as
/// the same error does anywhere else on the command line: the flag a name
/// clashes with, the command that prints a valid preset.
#[test]
fn preset_list_words_its_broken_rows_as_the_command_line_does() {
    let dir = tempfile::tempdir().unwrap();
    let presets = dir.path().join("presets");
    std::fs::create_dir(&presets).unwrap();
    let good = std::fs::read_to_string(root().join("presets/paper-75kg.toml")).unwrap();
    let clash = good.replacen("name = \"head-neck\"", "name = \"m1\"", 1);
    assert_ne!(clash, good, "the preset names its head segment head-neck");
    std::fs::write(presets.join("clash.toml"), clash).unwrap();
    std::fs::write(presets.join("empty.toml"), "").unwrap();
    let (t, row) = preset_list_in(dir.path());
    assert!(
        row("clash.toml").contains("--set would be ambiguous"),
        "{t}"
    );
    assert!(
        row("empty.toml").contains("(see `biodyn preset show`)"),
        "{t}"
    );
    let check = run(&[
        "preset",
        "check",
        &presets.join("empty.toml").display().to_string(),
    ]);
    assert!(text(&check.stderr).contains("(see `biodyn preset show`)"));
}

/// The library names no flag; the command line puts them back into the
/// phrases the library composes (a name a `--set` cannot reach, the
/// sampling rate of a signal above fs/2): each message as it always read.
#[test]
fn library_phrases_come_back_with_their_flags() {
    let dir = tempfile::tempdir().unwrap();
    let good = std::fs::read_to_string(root().join("presets/paper-75kg.toml")).unwrap();
    for (name, want) in [
        (
            "a=b",
            "contains '=': --set NAME=VALUE could not reach it; remove the '='",
        ),
        (
            " x",
            "starts or ends with a space: --set could not reach it; remove the space",
        ),
        ("m1", "--set would be ambiguous; rename it"),
    ] {
        let bad = good.replacen("name = \"head-neck\"", &format!("name = \"{name}\""), 1);
        let path = dir.path().join("named.toml");
        std::fs::write(&path, bad).unwrap();
        let out = run(&["preset", "check", &path.display().to_string()]);
        assert!(!out.status.success(), "{name:?} accepted");
        assert!(
            text(&out.stderr).contains(want),
            "{name:?}: {}",
            text(&out.stderr)
        );
    }
    let out = run(&[
        "simulate",
        "--signal",
        "sine:freq=600,amp=1",
        "--fs",
        "1000",
        "--duration",
        "1",
    ]);
    assert!(
        text(&out.stderr).contains("raise --fs (now 1e3) or lower the frequency"),
        "{}",
        text(&out.stderr)
    );
}

/// The message bare `biodyn` gives without a terminal.
fn no_terminal_message() -> String {
    let out = run(&[]);
    assert_eq!(out.status.code(), Some(2));
    let e = text(&out.stderr);
    assert!(e.contains("no terminal for the full-screen app"), "{e}");
    e
}

#[test]
fn the_app_without_a_terminal_says_so_the_same_way_everywhere() {
    let want = no_terminal_message();
    for args in [
        &["tui"][..],
        &["--ascii"],
        &["--preset", "presets/paper-85kg.toml"],
        &["tui", "--ascii"],
    ] {
        let out = run(args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert_eq!(text(&out.stderr), want, "{args:?}");
        assert!(out.stdout.is_empty(), "{args:?}");
    }
    // Options of the app after a command are refused, not silently taken.
    assert_eq!(run(&["--ascii", "response"]).status.code(), Some(2));
}

/// `script` gives biodyn a pseudo-terminal; skipped where it is missing.
fn in_pty(shell: &str) -> Option<String> {
    let bin = env!("CARGO_BIN_EXE_biodyn");
    let line = shell.replace("BIODYN", bin);
    let mut c = Command::new("timeout");
    c.args(["20", "script", "-qec", &line, "/dev/null"])
        .stdin(Stdio::null());
    let Ok(out) = c.output() else {
        crate::common::skip("timeout not available");
        return None;
    };
    if out.status.code() == Some(127) {
        crate::common::skip("script not available");
        return None;
    }
    Some(text(&out.stdout) + &text(&out.stderr))
}

#[test]
fn the_app_refuses_a_file_on_stdout_and_a_dumb_terminal() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("screen.txt");
    let Some(out) = in_pty(&format!("BIODYN tui > {}; echo status=$?", file.display())) else {
        return;
    };
    assert!(out.contains("no terminal for the full-screen app"), "{out}");
    assert!(out.contains("status=2"), "{out}");
    let written = std::fs::read(&file).unwrap_or_default();
    assert!(
        !written.contains(&0x1b),
        "escape sequences written into the file"
    );
    let Some(out) = in_pty("TERM=dumb BIODYN tui; echo status=$?") else {
        return;
    };
    assert!(out.contains("TERM=dumb"), "{out}");
    assert!(
        out.contains("response"),
        "points to the headless commands: {out}"
    );
    assert!(out.contains("status=2"), "{out}");
}

/// A note on stderr ("saved …") with stderr full must not turn a finished
/// save into a panic (exit 101): the file is written and the status is 0.
#[test]
fn a_save_with_stderr_full_still_succeeds() {
    let dir = tempfile::tempdir().expect("tempdir");
    let target = dir.path().join("saved.toml");
    let full = std::fs::File::create("/dev/full").expect("/dev/full");
    let mut c = cmd(&["preset", "save", target.to_str().expect("utf-8 path")]);
    c.stdout(Stdio::null()).stderr(Stdio::from(full));
    let status = c.status().expect("biodyn runs");
    assert_eq!(status.code(), Some(0), "{status:?}");
    assert!(target.is_file());
}
