//! The real binary in a real terminal (tmux), driven as a person would:
//! start, switch tabs, edit, quit with the confirmation, and check the
//! process ended cleanly. Skipped when tmux is not installed.

use crate::common::tmux::{start, wait_rc};
use std::process::Command;

#[test]
fn tui_edits_and_quits_cleanly_in_a_real_terminal() {
    let dir = tempfile::tempdir().expect("tempdir");
    let rc = dir.path().join("rc");
    let Some(t) = start("edit", "tui", &rc) else {
        crate::common::skip("tmux not available");
        return;
    };
    t.wait_for("head-neck");
    t.keys(&["2"]);
    t.wait_for("f 4.6 Hz");
    t.keys(&["1", "+"]);
    // 80 columns keep the full tab names: the mark is "*" there.
    t.wait_for("paper-75kg *");
    t.keys(&["?"]);
    // The help page (the Model tab's section first; its keys fill page 1).
    t.wait_for("/ search, Esc close");
    // Esc and q sent together would read as Alt-q, as in any terminal app.
    t.keys(&["Escape"]);
    t.wait_for("modes (seat fixed)");
    t.keys(&["q"]);
    t.wait_for("Quit anyway?");
    t.keys(&["y"]);
    assert_eq!(wait_rc(&rc), "rc=0");
    // back on the shell's screen: the alternate screen is gone
    let s = t.screen();
    assert!(!s.contains("1 Model"), "{s}");
}

#[test]
fn tui_ascii_mode_draws_only_ascii() {
    let dir = tempfile::tempdir().expect("tempdir");
    let rc = dir.path().join("rc");
    let Some(t) = start("ascii", "tui --ascii", &rc) else {
        crate::common::skip("tmux not available");
        return;
    };
    t.wait_for("head-neck");
    t.keys(&["2"]);
    let s = t.wait_for("STHT magnitude");
    assert!(s.is_ascii(), "{s}");
    t.keys(&["C-c"]);
    assert_eq!(wait_rc(&rc), "rc=0");
}

/// A signal ends the app through its normal path (the terminal restored)
/// with the status a shell gives a command the signal killed: 128 + its
/// number (SIGTERM 143, not 0).
#[test]
fn tui_restores_the_terminal_on_a_signal_and_exits_128_plus_it() {
    for (sig, want) in [("TERM", 143), ("HUP", 129), ("INT", 130), ("QUIT", 131)] {
        let dir = tempfile::tempdir().expect("tempdir");
        let rc = dir.path().join("rc");
        let Some(t) = start(&format!("sig{sig}"), "tui", &rc) else {
            crate::common::skip("tmux not available");
            return;
        };
        t.wait_for("head-neck");
        // The pane runs `sh -c "biodyn …; echo rc=…"`: biodyn is its child.
        let pane = t
            .run(&["display", "-p", "-t", "s", "#{pane_pid}"])
            .expect("pane pid");
        let Ok(child) = Command::new("pgrep").args(["-P", pane.trim()]).output() else {
            crate::common::skip("pgrep not available");
            return;
        };
        let pid = String::from_utf8_lossy(&child.stdout).trim().to_string();
        assert!(!pid.is_empty(), "no child of pane {pane}");
        let killed = Command::new("kill")
            .args([&format!("-{sig}"), &pid])
            .status()
            .expect("kill");
        assert!(killed.success());
        assert_eq!(wait_rc(&rc), format!("rc={want}"), "SIG{sig}");
        let s = t.screen();
        assert!(
            !s.contains("1 Model"),
            "SIG{sig}: still on the app's screen:
{s}"
        );
    }
}

/// A chain of `n` one-kilogram segments as preset text.
fn chain_toml(n: usize) -> String {
    let mut t = format!("schema = 1\nname = \"chain{n}\"\n");
    for i in 1..=n {
        t += &format!("\n[[segment]]\nname = \"s{i}\"\nmass_kg = 1.0\n");
    }
    for i in 1..=n {
        let lower = if i < n {
            format!("s{}", i + 1)
        } else {
            "seat".into()
        };
        t += &format!(
            "\n[[link]]\nname = \"s{i}-{lower}\"\nupper = \"s{i}\"\nlower = \"{lower}\"\nk_n_per_m = 200000.0\nc_ns_per_m = 300.0\n"
        );
    }
    t
}

#[test]
fn tui_draws_a_large_model_at_once_and_quits_while_it_computes() {
    let dir = tempfile::tempdir().expect("tempdir");
    let rc = dir.path().join("rc");
    let preset = dir.path().join("chain400.toml");
    std::fs::write(&preset, chain_toml(400)).expect("write the chain preset");
    let args = format!("tui --preset '{}'", preset.display());
    let Some(t) = start("chain", &args, &rc) else {
        crate::common::skip("tmux not available");
        return;
    };
    // The first frame shows the model while its responses are computed.
    t.wait_for("model: chain400");
    t.wait_for("computing");
    t.keys(&["2"]);
    t.wait_for("in the background");
    t.keys(&["q"]);
    assert_eq!(wait_rc(&rc), "rc=0");
}

#[test]
fn tui_refuses_a_bad_preset_without_a_terminal_too() {
    let out = Command::new(env!("CARGO_BIN_EXE_biodyn"))
        .args(["tui", "--preset", "/nonexistent/x.toml"])
        .output()
        .expect("run biodyn");
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("/nonexistent/x.toml"), "{err}");
    assert!(out.stdout.is_empty());
}

#[test]
fn tui_refuses_a_bad_preset_before_touching_the_terminal() {
    // In a real terminal: one line naming the file, left on the shell's
    // screen (the app's screen never appeared), status 1.
    let dir = tempfile::tempdir().expect("tempdir");
    let rc = dir.path().join("rc");
    let Some(t) = start("badpreset", "tui --preset /nonexistent/x.toml", &rc) else {
        crate::common::skip("tmux not available");
        return;
    };
    assert_eq!(wait_rc(&rc), "rc=1");
    let s = t.screen();
    assert!(s.contains("/nonexistent/x.toml"), "{s}");
    assert!(!s.contains("1 Model"), "the app's screen was drawn:\n{s}");
}
