//! Running a block: one bash session in a fresh folder, a marker line after
//! each command carrying its exit status, the output cut at the markers.

use crate::markdown::{Block, Cmd, matches};
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::Mutex;
use std::time::{Duration, Instant};

const MARK: &str = "@@biodyn-doctest@@";

#[derive(Default)]
pub struct Outcome {
    /// `BIODYN_DOCS_BLESS=1`: outputs to write into the docs, as
    /// (file, first line of the shown output, its length, what was printed).
    pub bless: Vec<(PathBuf, usize, usize, Vec<String>)>,
    pub ran: usize,
    pub compared: usize,
    pub not_run: usize,
    pub skipped: Vec<String>,
    pub failures: Vec<String>,
}

/// Every block, on as many threads as the machine has cores (at most 4).
pub fn run_all(blocks: &[&Block], root: &Path) -> Vec<Outcome> {
    let queue = Mutex::new(blocks.iter().collect::<Vec<_>>());
    let out = Mutex::new(Vec::new());
    let n = std::thread::available_parallelism().map_or(2, |n| n.get().min(4));
    std::thread::scope(|s| {
        for _ in 0..n {
            s.spawn(|| {
                loop {
                    let next = queue.lock().map(|mut q| q.pop()).ok().flatten();
                    let Some(b) = next else { break };
                    let o = run_block(b, root);
                    if let Ok(mut v) = out.lock() {
                        v.push(o);
                    }
                }
            });
        }
    });
    out.into_inner().unwrap_or_default()
}

/// The `biodyn` under test: the one cargo just built, or `BIODYN_DOCS_BIN`
/// (another build named `biodyn`, to hold an older binary to the same docs).
fn bin() -> PathBuf {
    std::env::var_os("BIODYN_DOCS_BIN")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_BIN_EXE_biodyn")))
}

/// Copies `from` into `to`, recursively.
fn copy_dir(from: &Path, to: &Path) -> std::io::Result<()> {
    std::fs::create_dir_all(to)?;
    for e in std::fs::read_dir(from)? {
        let e = e?;
        let dest = to.join(e.file_name());
        if e.file_type()?.is_dir() {
            copy_dir(&e.path(), &dest)?;
        } else {
            std::fs::copy(e.path(), dest)?;
        }
    }
    Ok(())
}

/// bash in `dir` with `biodyn` first on PATH and a fixed locale; stdin empty,
/// stderr joined to stdout as on a terminal. Killed after `limit`.
fn bash(script: &str, dir: &Path, limit: Duration) -> Result<String, String> {
    let bin_dir = bin().parent().map(Path::to_path_buf).unwrap_or_default();
    let path = std::env::var_os("PATH").unwrap_or_default();
    let mut paths = vec![bin_dir];
    paths.extend(std::env::split_paths(&path));
    let path = std::env::join_paths(paths).map_err(|e| e.to_string())?;
    let mut cmd = Command::new("bash");
    cmd.args(["--noprofile", "--norc", "-c", script])
        .current_dir(dir)
        .env("PATH", path)
        .env("HOME", dir)
        .env("LC_ALL", "C.UTF-8")
        .env("TZ", "UTC");
    for v in [
        "COLUMNS",
        "LINES",
        "NO_COLOR",
        "BIODYN_GLYPHS",
        "BIODYN_COLOR",
        "CLICOLOR_FORCE",
    ] {
        cmd.env_remove(v);
    }
    let mut child = cmd
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .map_err(|e| format!("cannot start bash: {e}"))?;
    let mut stdout = child.stdout.take().ok_or("no stdout")?;
    let reader = std::thread::spawn(move || {
        let mut buf = Vec::new();
        let _ = stdout.read_to_end(&mut buf);
        buf
    });
    let start = Instant::now();
    loop {
        match child.try_wait() {
            Ok(Some(_)) => break,
            Ok(None) if start.elapsed() > limit => {
                let _ = child.kill();
                let _ = child.wait();
                return Err(format!("still running after {} s: killed", limit.as_secs()));
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(5)),
            Err(e) => return Err(e.to_string()),
        }
    }
    let buf = reader.join().map_err(|_| "reader thread panicked")?;
    Ok(String::from_utf8_lossy(&buf).into_owned())
}

/// Does the binary know `sub`? (Another branch adds `man` and `completions`.)
fn knows_subcommand(sub: &str, dir: &Path) -> bool {
    bash(
        &format!("biodyn {sub} --help 2>&1"),
        dir,
        Duration::from_secs(30),
    )
    .is_ok_and(|o| !o.contains("unrecognized subcommand"))
}

fn run_block(b: &Block, root: &Path) -> Outcome {
    let mut o = Outcome::default();
    let at = format!("{}:{}", b.file.display(), b.line);
    let fail = |o: &mut Outcome, why: String| o.failures.push(format!("{at}: {why}"));
    let dir = match tempfile::tempdir() {
        Ok(d) => d,
        Err(e) => {
            fail(&mut o, format!("no temporary folder: {e}"));
            return o;
        }
    };
    for sub in ["presets", "examples"] {
        if let Err(e) = copy_dir(&root.join(sub), &dir.path().join(sub)) {
            fail(&mut o, format!("cannot copy {sub}/: {e}"));
            return o;
        }
    }
    if let Some(sub) = &b.marks.needs_subcommand
        && !knows_subcommand(sub, dir.path())
    {
        o.skipped.push(format!(
            "{at}: skipped: this biodyn has no `{sub}` subcommand yet (runs once it has)"
        ));
        return o;
    }
    let runnable: Vec<&Cmd> = b.commands.iter().filter(|c| c.not_run.is_none()).collect();
    o.not_run = b.commands.len() - runnable.len();
    if runnable.is_empty() {
        return o;
    }
    let mut script = String::from("set -o pipefail\nexec 2>&1\n");
    if !b.marks.setup.is_empty() {
        script.push_str("(\nset -e\n");
        for l in &b.marks.setup {
            script.push_str(l);
            script.push('\n');
        }
        script.push_str(")\n");
    }
    script.push_str(&format!("printf '\\n{MARK} %d\\n' $?\n"));
    for c in &runnable {
        script.push_str("( exit ${__st:-0} )\n");
        script.push_str(&c.text);
        script.push_str(&format!("\n__st=$?; printf '\\n{MARK} %d\\n' $__st\n"));
    }
    let limit = Duration::from_secs(if b.marks.slow.is_some() { 1800 } else { 120 });
    let out = match bash(&script, dir.path(), limit) {
        Ok(out) => out,
        Err(e) => {
            fail(&mut o, e);
            return o;
        }
    };
    let mut parts: Vec<(String, Option<i32>)> = Vec::new();
    let mut cur = String::new();
    for line in out.split_inclusive('\n') {
        if let Some(st) = line.strip_prefix(MARK) {
            parts.push((std::mem::take(&mut cur), st.trim().parse().ok()));
        } else {
            cur.push_str(line);
        }
    }
    let mut parts = parts.into_iter();
    match parts.next() {
        Some((_, Some(0))) => {}
        Some((text, st)) if !b.marks.setup.is_empty() => {
            fail(&mut o, format!("the hidden setup failed ({st:?}):\n{text}"));
            return o;
        }
        _ => {
            fail(&mut o, format!("bash did not start the session:\n{out}"));
            return o;
        }
    }
    for c in runnable {
        let Some((text, st)) = parts.next() else {
            fail(
                &mut o,
                format!(
                    "the session ended before line {}: `{}`\n{cur}",
                    c.line, c.text
                ),
            );
            return o;
        };
        o.ran += 1;
        let here = format!("{}:{}: `{}`", b.file.display(), c.line, c.text);
        let status_ok = match st {
            Some(0) => !c.fails,
            // 101 is a panic, 128+ a signal: never what a doc shows.
            Some(s) => c.fails && s != 101 && s < 128,
            None => false,
        };
        if !status_ok {
            let want = if c.fails {
                "a non-zero status"
            } else {
                "status 0"
            };
            o.failures.push(format!(
                "{here}\n  exited {st:?}, the doc says {want}; it printed:\n{text}"
            ));
            continue;
        }
        if let Some(expected) = &c.expected {
            o.compared += 1;
            let actual: Vec<String> = text.lines().map(str::to_string).collect();
            // The marker starts on a line of its own: drop the newline added before it.
            if !matches(expected, &actual) {
                let wild = expected
                    .iter()
                    .any(|l| l.trim() == "..." || l.contains("[..]"));
                if std::env::var_os("BIODYN_DOCS_BLESS").is_some() && !wild {
                    let shown = expected.iter().rposition(|l| !l.trim().is_empty());
                    let n = shown.map_or(0, |k| k + 1);
                    let mut printed = actual.clone();
                    while printed.last().is_some_and(|l| l.trim().is_empty()) {
                        printed.pop();
                    }
                    let first = c.line - 1 + c.text.lines().count();
                    o.bless.push((b.file.clone(), first, n, printed));
                    continue;
                }
                o.failures.push(format!(
                    "{here}\n--- the doc shows\n{}\n--- it printed\n{}",
                    expected.join("\n"),
                    text.trim_end()
                ));
            }
        }
    }
    o
}
