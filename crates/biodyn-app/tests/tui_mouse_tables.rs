//! The mouse on the Model tab in a real terminal (tmux): the real binary
//! reads SGR mouse reports (what xterm, tmux and most terminals send with
//! capture on) for a click, a double click and the wheel, and edits a
//! value as Enter would. Skipped when tmux is not installed.

use std::path::Path;
use std::process::Command;
use std::time::{Duration, Instant};

/// A private tmux server (its own socket), so no user session is touched.
struct Tmux {
    socket: String,
}

impl Tmux {
    fn run(&self, args: &[&str]) -> Option<String> {
        let out = Command::new("tmux")
            .arg("-L")
            .arg(&self.socket)
            .args(args)
            .output()
            .ok()?;
        out.status
            .success()
            .then(|| String::from_utf8_lossy(&out.stdout).into_owned())
    }

    fn screen(&self) -> String {
        self.run(&["capture-pane", "-t", "s", "-p"])
            .unwrap_or_default()
    }

    fn keys(&self, keys: &[&str]) {
        let mut args = vec!["send-keys", "-t", "s"];
        args.extend_from_slice(keys);
        self.run(&args);
    }

    /// Bytes as the terminal would send them (escape sequences too).
    fn raw(&self, bytes: &str) {
        self.run(&["send-keys", "-t", "s", "-l", bytes]);
    }

    /// A left press and release at a 0-based cell, `n` times in one
    /// write (2: a double click), as SGR mouse reports (1-based).
    fn click(&self, (x, y): (usize, usize), n: usize) {
        let one = format!("\x1b[<0;{};{}M\x1b[<0;{};{}m", x + 1, y + 1, x + 1, y + 1);
        self.raw(&one.repeat(n));
    }

    /// A wheel step down at a 0-based cell.
    fn wheel_down(&self, (x, y): (usize, usize)) {
        self.raw(&format!("\x1b[<65;{};{}M", x + 1, y + 1));
    }

    /// Waits up to 10 s for `want` on the screen.
    fn wait_for(&self, want: &str) -> String {
        let end = Instant::now() + Duration::from_secs(10);
        loop {
            let s = self.screen();
            if s.contains(want) || Instant::now() > end {
                assert!(s.contains(want), "waited for {want:?}:\n{s}");
                return s;
            }
            std::thread::sleep(Duration::from_millis(50));
        }
    }

    /// The 0-based cell where `text` starts on the line that shows `line`.
    fn find(&self, line: &str, text: &str) -> (usize, usize) {
        let s = self.screen();
        s.lines()
            .enumerate()
            .find_map(|(y, l)| {
                let from = l.find(line)? + line.len();
                let i = l[from..].find(text)? + from;
                Some((l[..i].chars().count(), y))
            })
            .unwrap_or_else(|| panic!("{text} after {line} not on screen:\n{s}"))
    }
}

impl Drop for Tmux {
    fn drop(&mut self) {
        self.run(&["kill-server"]);
    }
}

fn start(rc_file: &Path) -> Option<Tmux> {
    Command::new("tmux").arg("-V").output().ok()?;
    let t = Tmux {
        socket: format!("biodyn-mouse-tables-{}", std::process::id()),
    };
    let bin = env!("CARGO_BIN_EXE_biodyn");
    let cmd = format!("'{bin}'; echo rc=$? > '{}'; sleep 30", rc_file.display());
    t.run(&["new-session", "-d", "-s", "s", "-x", "80", "-y", "24", &cmd])?;
    Some(t)
}

fn wait_rc(rc_file: &Path) -> String {
    let end = Instant::now() + Duration::from_secs(10);
    while Instant::now() < end {
        if let Ok(s) = std::fs::read_to_string(rc_file)
            && s.ends_with('\n')
        {
            return s.trim().to_string();
        }
        std::thread::sleep(Duration::from_millis(50));
    }
    panic!("the app did not exit");
}

#[test]
fn a_double_click_on_a_model_cell_edits_it_in_a_real_terminal() {
    let dir = tempfile::tempdir().expect("tempdir");
    let rc = dir.path().join("rc");
    let Some(t) = start(&rc) else {
        eprintln!("tmux not available: skipped");
        return;
    };
    t.wait_for("head-neck");
    // Capture off: a click is the terminal's, the app does nothing.
    let k4 = t.find("pelvis-seat", "90000");
    t.click((k4.0 + 2, k4.1), 2);
    std::thread::sleep(Duration::from_millis(300));
    assert!(!t.screen().contains("(type to replace"), "{}", t.screen());
    t.keys(&["M"]);
    t.wait_for("M mouse on");

    // A click on m2's mass selects it: Enter then edits m2.
    let m2 = t.find("m2 chest", "30.15");
    t.click((m2.0 + 1, m2.1), 1);
    t.keys(&["Enter"]);
    t.wait_for("30.15 (type to replace");
    t.keys(&["Escape"]);
    t.wait_for("cancelled");

    // The wheel over the table moves the selection a row: m3.
    t.wheel_down(m2);
    t.keys(&["Enter"]);
    t.wait_for("9.15 (type to replace");
    t.keys(&["Escape"]);
    t.wait_for("cancelled");

    // A double click on k4 opens its field, as Enter; typing replaces it.
    t.click((k4.0 + 2, k4.1), 2);
    t.wait_for("90000 (type to replace");
    t.raw("95000");
    t.keys(&["Enter"]);
    let s = t.wait_for("*modified");
    assert!(t.find("pelvis-seat", "95000") == k4, "{s}");
    // The change is one undo step.
    t.keys(&["u"]);
    t.wait_for("undid");
    assert_eq!(t.find("pelvis-seat", "90000"), k4);

    t.keys(&["q"]);
    assert_eq!(wait_rc(&rc), "rc=0");
}
