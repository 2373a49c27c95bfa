//! Every command the README and `docs/` show runs as shown.
//!
//! The examples are taken from the Markdown itself: a ```console block is a
//! terminal session (`$ ` lines are commands, the lines under one are what
//! it prints, stdout and stderr together), a ```sh block a list of commands
//! whose `biodyn` lines must succeed. Each block runs in bash (pipes,
//! redirections and `$?` as a reader would type them) in its own temporary
//! folder holding copies of `presets/` and `examples/`, with the `biodyn`
//! just built first on `PATH`. A `...` line in the output stands for any
//! lines, `[..]` for any text within a line (run times). A command whose
//! output shows `biodyn: error:` must exit non-zero; any other, zero.
//! `cargo` lines and commands that open the terminal app are not run.
//! A `<!-- doctest: … -->` comment right above a block can add hidden
//! `setup:` lines, mark it `slow:` (run by `--ignored`) or `skip:` (with a
//! reason, listed in the output), or `needs-subcommand: NAME`.
//!
//! Why not `trycmd`: it runs one program per command, with no shell, and
//! half the examples are pipes (`| head -4`, `| cmp -`, `$(seq …)`).

mod figures;
mod links;
mod markdown;
mod session;

use markdown::Block;
use std::io::Write;
use std::path::Path;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn all_blocks() -> Vec<Block> {
    markdown::markdown_files(root())
        .iter()
        .flat_map(|f| markdown::blocks(root(), f))
        .collect()
}

/// Runs the chosen blocks on a few threads; prints what was skipped and why
/// (straight to stderr, so it shows even when the test passes) and fails
/// with every mismatch at once.
fn run(slow: bool) {
    // The examples are Linux sessions (`/dev/full`, `stat -c`, `mkfifo`, O_TMPFILE).
    if !cfg!(target_os = "linux") {
        let _ = writeln!(
            std::io::stderr(),
            "docs: the examples run on Linux only; not run here"
        );
        return;
    }
    let blocks = all_blocks();
    assert!(
        !blocks.is_empty(),
        "no example blocks found under {}",
        root().display()
    );
    let mut skipped = Vec::new();
    let mut todo = Vec::new();
    for b in &blocks {
        let at = format!("{}:{}", b.file.display(), b.line);
        match (&b.marks.skip, &b.marks.slow) {
            (Some(why), _) => skipped.push(format!("{at}: skipped: {why}")),
            (None, Some(why)) if !slow => {
                skipped.push(format!("{at}: slow, run by `-- --ignored`: {why}"))
            }
            (None, None) if slow => {}
            _ => todo.push(b),
        }
    }
    let results = session::run_all(&todo, root());
    let mut failures = Vec::new();
    let mut bless = Vec::new();
    let (mut ran, mut compared, mut not_run) = (0, 0, 0);
    for r in results {
        ran += r.ran;
        compared += r.compared;
        not_run += r.not_run;
        skipped.extend(r.skipped);
        failures.extend(r.failures);
        bless.extend(r.bless);
    }
    write_blessed(bless);
    let mut err = std::io::stderr().lock();
    let _ = writeln!(
        err,
        "docs: {} blocks run, {ran} commands run, {compared} outputs compared, \
         {not_run} not run (the terminal app, cargo)",
        todo.len()
    );
    for s in &skipped {
        let _ = writeln!(err, "docs: {s}");
    }
    drop(err);
    assert!(
        failures.is_empty(),
        "{} doc example(s) do not run as shown:\n\n{}",
        failures.len(),
        failures.join("\n\n")
    );
}

/// Writes what the commands printed into the docs in place of what they
/// showed (`BIODYN_DOCS_BLESS=1`; outputs with `...` or `[..]` are left to
/// a person), bottom up so the line numbers hold.
fn write_blessed(mut bless: Vec<(std::path::PathBuf, usize, usize, Vec<String>)>) {
    bless.sort_by(|a, b| (&a.0, b.1).cmp(&(&b.0, a.1)));
    for (file, first, n, printed) in bless {
        let path = root().join(&file);
        let Ok(text) = std::fs::read_to_string(&path) else {
            continue;
        };
        let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
        let start = first.min(lines.len());
        let end = (start + n).min(lines.len());
        lines.splice(start..end, printed);
        let _ = std::fs::write(&path, lines.join("\n") + "\n");
        eprintln!("docs: blessed {}:{first}", file.display());
    }
}

#[test]
fn every_command_in_the_docs_runs_as_shown() {
    run(false);
}

/// The examples marked `slow:` (training runs that take a minute in a debug
/// build): `cargo test --release --test docs -- --ignored`.
#[test]
#[ignore = "slow examples; run with --release -- --ignored"]
fn slow_examples() {
    run(true);
}

#[test]
fn every_relative_link_in_the_docs_resolves() {
    let bad = links::broken(root(), &markdown::markdown_files(root()));
    assert!(bad.is_empty(), "broken links:\n{}", bad.join("\n"));
}

/// The README's and docs/tui.md's list of tabs is every tab page: one
/// `docs/tui-*.md` per tab, each linked from docs/tui.md and counted in
/// the README's words ("opens seven tabs").
#[test]
fn every_tab_page_is_named_where_the_tabs_are_listed() {
    let pages: Vec<String> = std::fs::read_dir(root().join("docs"))
        .expect("docs/")
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter(|n| n.starts_with("tui-") && n.ends_with(".md"))
        .collect();
    let tui = std::fs::read_to_string(root().join("docs/tui.md")).expect("docs/tui.md");
    for p in &pages {
        assert!(
            tui.contains(&format!("]({p})")),
            "docs/tui.md does not link {p}"
        );
    }
    let words = [
        "", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine",
    ];
    let n = words.get(pages.len()).expect("fewer than ten tabs");
    let readme = std::fs::read_to_string(root().join("README.md")).expect("README.md");
    let readme = readme.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(
        readme.contains(&format!("opens {n} tabs")),
        "README.md: not 'opens {n} tabs'"
    );
}
