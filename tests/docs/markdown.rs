//! Finding the examples in the Markdown files: fenced blocks, the
//! `<!-- doctest: … -->` comment that may stand before one, the commands in
//! a block and what a `console` block says each prints.

use std::path::{Path, PathBuf};

/// One fenced block that holds commands.
#[derive(Debug)]
pub struct Block {
    /// The file, relative to the repository root.
    pub file: PathBuf,
    /// 1-based line of the opening fence.
    pub line: usize,
    pub commands: Vec<Cmd>,
    pub marks: Marks,
}

/// A command line of a block and, for a `console` block, the output shown
/// under it (`None` in an `sh` block: run, status checked, output not).
#[derive(Debug)]
pub struct Cmd {
    /// 1-based line of the command in its file.
    pub line: usize,
    pub text: String,
    pub expected: Option<Vec<String>>,
    /// What the doc says it ends with: an error line shown means non-zero.
    pub fails: bool,
    /// Not run: opens the terminal app, or is a `cargo` line.
    pub not_run: Option<&'static str>,
}

/// What the `<!-- doctest: … -->` comment before a block asks.
#[derive(Debug, Default)]
pub struct Marks {
    /// Never run, with the reason (listed in the test's output).
    pub skip: Option<String>,
    /// Run only by the ignored test `slow_examples`, with the reason.
    pub slow: Option<String>,
    /// Shell lines run first in the block's folder (hidden from the reader).
    pub setup: Vec<String>,
    /// Run only when the binary knows this subcommand (one another branch adds).
    pub needs_subcommand: Option<String>,
}

/// Every `.md` file under `root`, outside `target/` and hidden folders, sorted.
pub fn markdown_files(root: &Path) -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        let Ok(entries) = std::fs::read_dir(dir) else {
            return;
        };
        for e in entries.flatten() {
            let p = e.path();
            let name = e.file_name().to_string_lossy().into_owned();
            if name.starts_with('.') || name == "target" {
                continue;
            }
            if p.is_dir() {
                walk(&p, out);
            } else if name.ends_with(".md") {
                out.push(p);
            }
        }
    }
    let mut out = Vec::new();
    walk(root, &mut out);
    out.sort();
    out
}

/// A fence: its marker (``` or ~~~, at least three) and the info string.
fn fence(line: &str) -> Option<(String, String)> {
    let t = line.trim_start();
    let c = t.chars().next()?;
    if c != '`' && c != '~' {
        return None;
    }
    let n = t.chars().take_while(|&x| x == c).count();
    (n >= 3).then(|| (c.to_string().repeat(n), t[n..].trim().to_string()))
}

/// The blocks of one file: ```console and ```sh (also bash, shell).
pub fn blocks(root: &Path, path: &Path) -> Vec<Block> {
    let text = std::fs::read_to_string(path).unwrap_or_default();
    let file = path.strip_prefix(root).unwrap_or(path).to_path_buf();
    let lines: Vec<&str> = text.lines().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        let Some((marker, info)) = fence(lines[i]) else {
            i += 1;
            continue;
        };
        let start = i;
        let mut end = i + 1;
        while end < lines.len() && !lines[end].trim_start().starts_with(marker.as_str()) {
            end += 1;
        }
        let body: Vec<(usize, &str)> = (start + 1..end.min(lines.len()))
            .map(|k| (k + 1, lines[k]))
            .collect();
        let lang = info.split_whitespace().next().unwrap_or("");
        let commands = match lang {
            "console" => console(&body),
            "sh" | "bash" | "shell" => script(&body),
            _ => Vec::new(),
        };
        if !commands.is_empty() {
            out.push(Block {
                file: file.clone(),
                line: start + 1,
                commands,
                marks: marks(&lines[..start]),
            });
        }
        i = end + 1;
    }
    out
}

/// The `<!-- doctest: … -->` comment that ends right above the fence (blank
/// lines between are allowed). `skip: why`, `slow: why`,
/// `needs-subcommand: man` and `setup:` (the lines after it, to `-->`).
fn marks(above: &[&str]) -> Marks {
    let mut m = Marks::default();
    let mut k = above.len();
    while k > 0 && above[k - 1].trim().is_empty() {
        k -= 1;
    }
    if k == 0 || !above[k - 1].trim_end().ends_with("-->") {
        return m;
    }
    let close = k - 1;
    let mut open = close;
    while !above[open].trim_start().starts_with("<!--") {
        if open == 0 {
            return m;
        }
        open -= 1;
    }
    let comment: Vec<&str> = above[open..=close].to_vec();
    let first = comment[0].trim_start().trim_start_matches("<!--").trim();
    let Some(rest) = first.strip_prefix("doctest:") else {
        return m;
    };
    let mut body: Vec<String> = vec![rest.trim().to_string()];
    body.extend(comment[1..].iter().map(|l| l.to_string()));
    if let Some(last) = body.last_mut() {
        *last = last.trim_end().trim_end_matches("-->").to_string();
    }
    let mut in_setup = false;
    for l in body {
        let t = l.trim();
        if in_setup {
            if !t.is_empty() {
                m.setup.push(l.clone());
            }
        } else if let Some(r) = t.strip_prefix("skip:") {
            m.skip = Some(r.trim().to_string());
        } else if let Some(r) = t.strip_prefix("slow:") {
            m.slow = Some(r.trim().to_string());
        } else if let Some(r) = t.strip_prefix("needs-subcommand:") {
            m.needs_subcommand = Some(r.trim().to_string());
        } else if let Some(r) = t.strip_prefix("setup:") {
            in_setup = true;
            if !r.trim().is_empty() {
                m.setup.push(r.trim().to_string());
            }
        } else if !t.is_empty() {
            m.skip = Some(format!("unknown doctest mark '{t}'"));
        }
    }
    m
}

/// Why a command line is not run, if it is not: `cargo …` lines, and any
/// that opens the terminal app (no subcommand, or `tui`).
fn not_run(cmd: &str) -> Option<&'static str> {
    let mut words = cmd.split_whitespace().skip_while(|w| {
        w.contains('=') && !w.starts_with('-') && w.split('=').next().is_some_and(|k| !k.is_empty())
    });
    match words.next() {
        Some("cargo") => return Some("a cargo command"),
        Some("biodyn") => {}
        _ => return None,
    }
    let mut rest = words.take_while(|w| !w.starts_with('#'));
    loop {
        match rest.next() {
            None | Some("tui") => return Some("opens the terminal app"),
            Some("--preset") => {
                rest.next();
            }
            Some("--ascii") => {}
            Some(w) if w.starts_with("--preset=") => {}
            Some(_) => return None,
        }
    }
}

/// Lines joined where one ends in a backslash.
fn joined(body: &[(usize, &str)]) -> Vec<(usize, String)> {
    let mut out: Vec<(usize, String)> = Vec::new();
    let mut open = false;
    for &(n, l) in body {
        if open {
            if let Some(last) = out.last_mut() {
                last.1.push('\n');
                last.1.push_str(l);
            }
        } else {
            out.push((n, l.to_string()));
        }
        open = l.trim_end().ends_with('\\');
    }
    out
}

/// An `sh` block: every line whose command is `biodyn` is run.
fn script(body: &[(usize, &str)]) -> Vec<Cmd> {
    joined(body)
        .into_iter()
        .filter(|(_, l)| {
            let first = l
                .split_whitespace()
                .find(|w| !w.contains('=') || w.starts_with('-'));
            first == Some("biodyn")
        })
        .map(|(line, text)| Cmd {
            line,
            not_run: not_run(&text),
            text,
            expected: None,
            fails: false,
        })
        .collect()
}

/// A `console` block: `$ ` lines are commands, the lines under one (to the
/// next `$ `) what it prints, stdout and stderr as a terminal shows them.
fn console(body: &[(usize, &str)]) -> Vec<Cmd> {
    let mut out: Vec<Cmd> = Vec::new();
    let mut k = 0;
    while k < body.len() {
        let (n, l) = body[k];
        if let Some(c) = l.strip_prefix("$ ") {
            let mut text = c.to_string();
            while text.trim_end().ends_with('\\') && k + 1 < body.len() {
                k += 1;
                text.push('\n');
                text.push_str(body[k].1);
            }
            out.push(Cmd {
                line: n,
                not_run: not_run(&text),
                text,
                expected: Some(Vec::new()),
                fails: false,
            });
        } else if let Some(cmd) = out.last_mut() {
            if l.starts_with("biodyn: error:") || l.starts_with("error:") {
                cmd.fails = true;
            }
            if let Some(e) = cmd.expected.as_mut() {
                e.push(l.to_string());
            }
        }
        k += 1;
    }
    out
}

/// Does `actual` read as `expected`? A line `...` stands for any number of
/// lines (none too), `[..]` inside a line for any text; trailing spaces and
/// trailing blank lines do not count.
pub fn matches(expected: &[String], actual: &[String]) -> bool {
    let e = trimmed(expected);
    let a = trimmed(actual);
    fn go(e: &[&str], a: &[&str]) -> bool {
        match e.split_first() {
            None => a.is_empty(),
            Some((&"...", rest)) => (0..=a.len()).any(|k| go(rest, &a[k..])),
            Some((first, rest)) => a
                .split_first()
                .is_some_and(|(x, ar)| line_matches(first, x) && go(rest, ar)),
        }
    }
    go(&e, &a)
}

fn trimmed(lines: &[String]) -> Vec<&str> {
    let mut v: Vec<&str> = lines.iter().map(|l| l.trim_end()).collect();
    while v.last().is_some_and(|l| l.is_empty()) {
        v.pop();
    }
    v
}

/// One line against a pattern with `[..]` wildcards.
pub fn line_matches(pattern: &str, line: &str) -> bool {
    let parts: Vec<&str> = pattern.split("[..]").collect();
    if parts.len() == 1 {
        return pattern == line;
    }
    let (first, last) = (parts[0], parts[parts.len() - 1]);
    if !line.starts_with(first) || line.len() < first.len() + last.len() || !line.ends_with(last) {
        return false;
    }
    let mut rest = &line[first.len()..line.len() - last.len()];
    for p in &parts[1..parts.len() - 1] {
        match rest.find(p) {
            Some(i) => rest = &rest[i + p.len()..],
            None => return false,
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(s: &[&str]) -> Vec<String> {
        s.iter().map(|x| x.to_string()).collect()
    }

    #[test]
    fn ellipsis_lines_and_inline_wildcards() {
        assert!(matches(
            &v(&["a", "...", "d"]),
            &v(&["a", "b", "c", "d", ""])
        ));
        assert!(matches(&v(&["a", "...", "b"]), &v(&["a", "b"])));
        assert!(!matches(&v(&["a", "d"]), &v(&["a", "b", "d"])));
        assert!(line_matches("in [..] s", "in 0.057 s"));
        assert!(!line_matches("in [..] s", "in 0.057 ms!"));
        assert!(line_matches("[..]x[..]", "axb"));
    }

    #[test]
    fn the_terminal_app_and_cargo_are_not_run() {
        assert!(not_run("biodyn").is_some());
        assert!(not_run("biodyn                      # 2, x, Enter").is_some());
        assert!(not_run("NO_COLOR=1 biodyn").is_some());
        assert!(not_run("biodyn --preset presets/paper-85kg.toml").is_some());
        assert!(not_run("biodyn tui --ascii").is_some());
        assert!(not_run("cargo run --release").is_some());
        assert!(not_run("biodyn --help > /dev/full").is_none());
        assert!(not_run("biodyn response --format csv").is_none());
    }
}
