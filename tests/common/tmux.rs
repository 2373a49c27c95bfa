//! The real binary in a real terminal: a private tmux server driven as a
//! person would (keys, SGR mouse reports), for the `tui_*` tests.

use std::path::Path;
use std::process::Command;
use std::time::{Duration, Instant};

/// A private tmux server (its own socket), so no user session is touched.
pub struct Tmux {
    socket: String,
}

impl Tmux {
    pub fn run(&self, args: &[&str]) -> Option<String> {
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

    pub fn screen(&self) -> String {
        self.run(&["capture-pane", "-t", "s", "-p"])
            .unwrap_or_default()
    }

    pub fn keys(&self, keys: &[&str]) {
        let mut args = vec!["send-keys", "-t", "s"];
        args.extend_from_slice(keys);
        self.run(&args);
    }

    /// Bytes as the terminal would send them (escape sequences too).
    pub fn raw(&self, bytes: &str) {
        self.run(&["send-keys", "-t", "s", "-l", bytes]);
    }

    /// A left press and release at a 0-based cell, `n` times in one
    /// write (2: a double click), as SGR mouse reports (1-based).
    pub fn click(&self, (x, y): (usize, usize), n: usize) {
        let one = format!("\x1b[<0;{};{}M\x1b[<0;{};{}m", x + 1, y + 1, x + 1, y + 1);
        self.raw(&one.repeat(n));
    }

    /// A wheel step down at a 0-based cell.
    pub fn wheel_down(&self, (x, y): (usize, usize)) {
        self.raw(&format!("\x1b[<65;{};{}M", x + 1, y + 1));
    }

    /// Waits up to 10 s for `want` on the screen.
    pub fn wait_for(&self, want: &str) -> String {
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

    /// The 0-based cell where `text` starts on the line that shows `line`,
    /// waiting up to 10 s for it (a frame can be captured half drawn).
    pub fn find(&self, line: &str, text: &str) -> (usize, usize) {
        let end = Instant::now() + Duration::from_secs(10);
        loop {
            let s = self.screen();
            let at = s.lines().enumerate().find_map(|(y, l)| {
                let from = l.find(line)? + line.len();
                let i = l[from..].find(text)? + from;
                Some((l[..i].chars().count(), y))
            });
            match at {
                Some(at) => return at,
                None if Instant::now() > end => panic!("{text} after {line} not on screen:\n{s}"),
                None => std::thread::sleep(Duration::from_millis(50)),
            }
        }
    }
}

impl Drop for Tmux {
    fn drop(&mut self) {
        self.run(&["kill-server"]);
    }
}

/// Starts `biodyn ARGS` at 80×24 in a session named `s`; its exit status
/// goes to `rc_file`. None when tmux is not installed.
pub fn start(name: &str, args: &str, rc_file: &Path) -> Option<Tmux> {
    Command::new("tmux").arg("-V").output().ok()?;
    let t = Tmux {
        socket: format!("biodyn-{name}-{}", std::process::id()),
    };
    let bin = env!("CARGO_BIN_EXE_biodyn");
    let cmd = format!(
        "'{bin}' {args}; echo rc=$? > '{}'; sleep 30",
        rc_file.display()
    );
    t.run(&["new-session", "-d", "-s", "s", "-x", "80", "-y", "24", &cmd])?;
    Some(t)
}

/// The status line the session wrote to `rc_file` (`rc=0`), waiting up to 10 s.
pub fn wait_rc(rc_file: &Path) -> String {
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
