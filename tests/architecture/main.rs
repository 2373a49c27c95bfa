//! The architecture of ARCHITECTURE.md as a test, read from the source tree
//! of both crates: no import circles (a child's use of an item its
//! parent's own file defines counts, the components below aside); `cli/`
//! and `tui/` never import each
//! other; no tab imports another tab; the library uses no terminal crate,
//! prints nothing and names no command-line flag in its strings; no
//! non-test source file over 500 lines (pure tables aside). Every broken
//! rule is reported at once, one line each.
//!
//! The checker (`check.rs`) takes paths and texts, so the tests below plant
//! each kind of violation in a tiny tree in memory and see it reported.

mod check;

use check::{Crate, check};
use std::collections::BTreeMap;
use std::path::Path;

/// The crates of the workspace: the app's library (cli, tui, view), the
/// binary (the one file that knows both fronts) and the library crate.
const CRATES: [Crate; 3] = [
    Crate {
        name: "biodyn_app",
        root: "src/lib.rs",
        library: false,
        components: COMPONENTS,
    },
    Crate {
        name: "biodyn(bin)",
        root: "src/main.rs",
        library: false,
        components: &[],
    },
    Crate {
        name: "biodyn",
        root: "crates/biodyn/src/lib.rs",
        library: true,
        components: &[],
    },
];

/// The app's components: a type defined in a `mod.rs` whose children hold
/// its impl blocks, views and key handling and so must name it, while the
/// `mod.rs` calls into them. Splitting a large impl over files is what the
/// module tree is for; anything else a child takes from its parent's own
/// file is a circle, and is moved to a sibling instead (the dialogs' frame
/// to `popups/layout.rs`, the chart's options to `chart/opts.rs`, the clap
/// definition to `cli/command.rs`).
///
/// The dialogs' contract is the one other kind kept: `Act` names the
/// registry's `Overlay` and `OpenDialog`, `View` names `HelpLine`, and each
/// dialog returns `Act`s and implements `Popup` over a `View`: a circle of
/// types, which no split over files removes (in a sibling it would circle
/// with each dialog's file instead). It stays beside `Overlay`, which the
/// `register!` macro that declares the dialogs' modules generates in
/// `mod.rs` (the checker sees no item a macro call defines, so `Overlay`
/// needs no line).
const COMPONENTS: &[(&str, &str)] = &[
    ("tui::app::App", "its impl is split over app/*.rs"),
    (
        "tui::popups::Popup",
        "the dialogs' trait: each dialog's file holds its impl",
    ),
    (
        "tui::popups::Act",
        "the dialogs' contract: names Overlay and OpenDialog, which return it",
    ),
    (
        "tui::popups::View",
        "the dialogs' contract: names HelpLine; every Popup impl reads it",
    ),
    (
        "tui::tabs::model::ModelTab",
        "the tab; its impl is split over confirm.rs and mouse.rs",
    ),
    (
        "tui::tabs::responses::ResponsesTab",
        "the tab; its impl is split over extras.rs, fit_keys.rs and view.rs work on it",
    ),
    (
        "tui::tabs::study::StudyTab",
        "the tab; its impl is split over cursor.rs, export.rs and mouse.rs",
    ),
    (
        "tui::tabs::vibration::VibrationTab",
        "the tab; its impl is split over mouse.rs and window.rs",
    ),
    (
        "tui::tabs::day::DayTab",
        "the tab; its impl is split over files.rs (open and save), view.rs draws it",
    ),
    (
        "tui::tabs::seat::SeatTab",
        "the tab; view.rs draws it and export.rs writes it",
    ),
];

/// Every `.rs` file under `dir` (relative to the root), and the library's
/// manifest.
fn read_tree(root: &Path) -> BTreeMap<String, String> {
    fn walk(root: &Path, dir: &Path, out: &mut BTreeMap<String, String>) {
        let mut entries: Vec<_> = std::fs::read_dir(dir)
            .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
            .map(|e| e.expect("a directory entry").path())
            .collect();
        entries.sort();
        for p in entries {
            if p.is_dir() {
                walk(root, &p, out);
            } else if p.extension().is_some_and(|x| x == "rs") {
                let rel = p.strip_prefix(root).expect("under the root");
                let text =
                    std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
                out.insert(rel.to_string_lossy().replace('\\', "/"), text);
            }
        }
    }
    let mut files = BTreeMap::new();
    walk(root, &root.join("src"), &mut files);
    walk(root, &root.join("crates/biodyn/src"), &mut files);
    let manifest = "crates/biodyn/Cargo.toml";
    let text = std::fs::read_to_string(root.join(manifest)).expect("the library's manifest");
    files.insert(manifest.to_string(), text);
    files
}

#[test]
fn the_source_tree_keeps_the_architecture() {
    let files = read_tree(Path::new(env!("CARGO_MANIFEST_DIR")));
    assert!(files.len() > 50, "only {} files read", files.len());
    let problems = check(&files, &CRATES);
    assert!(
        problems.is_empty(),
        "{} architecture rule(s) broken:\n{}",
        problems.len(),
        problems.join("\n")
    );
}

/// A tree in memory: (path, text) pairs.
fn tree(files: &[(&str, &str)]) -> BTreeMap<String, String> {
    files
        .iter()
        .map(|(p, t)| (p.to_string(), t.to_string()))
        .collect()
}

const APP: [Crate; 1] = [Crate {
    name: "app",
    root: "src/lib.rs",
    library: false,
    components: &[],
}];

const LIB: [Crate; 1] = [Crate {
    name: "lib",
    root: "crates/biodyn/src/lib.rs",
    library: true,
    components: &[],
}];

/// Exactly one problem, containing every one of `words`.
fn one(problems: &[String], words: &[&str]) {
    assert_eq!(problems.len(), 1, "{problems:#?}");
    for w in words {
        assert!(problems[0].contains(w), "{w:?} not in {:?}", problems[0]);
    }
}

#[test]
fn a_clean_tree_has_no_problem_and_a_parent_may_use_its_children() {
    let files = tree(&[
        ("src/lib.rs", "pub mod a;\npub use a::b::Thing;\n"),
        (
            "src/a/mod.rs",
            "pub mod b;\npub mod c;\npub mod d;\npub use c::Shared;\npub struct Own;\npub fn f() { b::g() }\n#[cfg(test)]\nmod tests { use crate::x::Y; }\n",
        ),
        // A child uses what its parent re-exports: the path leads to the
        // sibling that defines it, not back to the parent.
        (
            "src/a/b.rs",
            "use super::Shared;\npub struct Thing;\npub fn g() { let _ = Shared; }\n",
        ),
        ("src/a/c.rs", "pub struct Shared;\n"),
        // A child uses its parent's own item, and the parent does not use
        // that child: the module tree, not a circle.
        ("src/a/d.rs", "pub fn h() { let _ = super::Own; }\n"),
    ]);
    let problems = check(&files, &APP);
    assert!(problems.is_empty(), "{problems:#?}");
}

/// A parent that uses its child while the child uses an item the parent's
/// own file defines (through `super::`), however deep.
#[test]
fn a_circle_through_a_child_using_its_parents_own_item_is_found() {
    let files = tree(&[
        ("src/lib.rs", "mod a;\n"),
        (
            "src/a/mod.rs",
            "mod b;\nmod c;\npub struct Shared;\npub fn f() { c::h() }\n",
        ),
        ("src/a/b.rs", "pub fn g() {}\n"),
        // Through a grandchild's `super::super` and a sibling.
        ("src/a/c/mod.rs", "mod e;\npub fn h() { e::k() }\n"),
        (
            "src/a/c/e.rs",
            "pub fn k() { let _ = super::super::Shared; super::super::b::g(); }\n",
        ),
    ]);
    one(
        &check(&files, &APP),
        &[
            "import circle",
            "app::a ",
            "app::a::c ",
            "app::a::c::e ",
            "src/a/c/e.rs:1 `super::super::Shared`",
        ],
    );

    // The same with the item listed as a component's: no problem.
    const LISTED: [Crate; 1] = [Crate {
        name: "app",
        root: "src/lib.rs",
        library: false,
        components: &[("a::Shared", "the component's type")],
    }];
    let problems = check(&files, &LISTED);
    assert!(problems.is_empty(), "{problems:#?}");

    // A listed item no child uses any more is reported.
    const STALE: [Crate; 1] = [Crate {
        name: "app",
        root: "src/lib.rs",
        library: false,
        components: &[("a::Shared", "the component's type"), ("a::f", "gone")],
    }];
    one(&check(&files, &STALE), &["app::a::f is listed", "drop it"]);
}

/// `use super::*` in a non-test child brings in every item the parent's
/// own file defines: with the parent using the child, a circle.
#[test]
fn a_glob_of_the_parents_own_items_is_a_circle() {
    let files = tree(&[
        ("src/lib.rs", "mod a;\n"),
        (
            "src/a/mod.rs",
            "mod b;\npub struct Shared;\npub fn f() { b::g() }\n",
        ),
        (
            "src/a/b.rs",
            "use super::*;\npub fn g() { let _ = Shared; }\n#[cfg(test)]\nmod tests { use super::*; }\n",
        ),
    ]);
    one(
        &check(&files, &APP),
        &[
            "import circle",
            "app::a (",
            "app::a::b (src/a/b.rs:1 `super`)",
        ],
    );

    // A glob of a parent whose file defines no item (`mod` and `pub use`
    // lines only) is the module tree, not a circle.
    let files = tree(&[
        ("src/lib.rs", "mod a;\n"),
        (
            "src/a/mod.rs",
            "mod b;\nmod c;\npub use b::g;\npub use c::Shared;\n",
        ),
        (
            "src/a/b.rs",
            "use super::*;\npub fn g() { let _ = Shared; }\n",
        ),
        ("src/a/c.rs", "pub struct Shared;\n"),
    ]);
    let problems = check(&files, &APP);
    assert!(problems.is_empty(), "{problems:#?}");
}

#[test]
fn a_circle_between_siblings_is_reported_with_its_path() {
    let files = tree(&[
        ("src/lib.rs", "mod fit;\n"),
        ("src/fit/mod.rs", "mod data;\nmod error;\nmod run;\n"),
        (
            "src/fit/data.rs",
            "use super::error::FitError;\npub const KNOWN: [&str; 1] = [\"x\"];\n",
        ),
        // Through a name `use` brought in, and inside a macro's tokens.
        (
            "src/fit/error.rs",
            "use super::data;\npub enum FitError {}\nfn f() { let _ = format!(\"{:?}\", data::KNOWN); }\n",
        ),
        ("src/fit/run.rs", "pub const MAX_STARTS: usize = 1;\n"),
    ]);
    one(
        &check(&files, &APP),
        &[
            "import circle",
            "app::fit::data",
            "app::fit::error",
            "src/fit/data.rs:1",
            "src/fit/error.rs",
        ],
    );
}

#[test]
fn a_circle_through_a_re_export_and_three_modules_is_found() {
    let files = tree(&[
        ("src/lib.rs", "mod a;\nmod b;\nmod c;\npub use c::C;\n"),
        ("src/a.rs", "use crate::b::B;\npub struct A;\n"),
        ("src/b.rs", "pub struct B(crate::C);\n"),
        ("src/c.rs", "pub struct C(crate::a::A);\n"),
    ]);
    one(
        &check(&files, &APP),
        &["app::a", "app::b", "app::c", "crate::C"],
    );
}

#[test]
fn the_fronts_importing_each_other_are_reported_both_ways() {
    let files = tree(&[
        ("src/lib.rs", "pub mod cli;\npub mod tui;\npub mod view;\n"),
        (
            "src/cli/mod.rs",
            "use crate::view::Chart;\npub fn run() { crate::tui::draw(); }\n",
        ),
        ("src/tui/mod.rs", "pub fn draw() {}\n"),
        ("src/view.rs", "pub struct Chart;\n"),
    ]);
    let problems = check(&files, &APP);
    one(
        &problems,
        &["cli imports tui", "src/cli/mod.rs:2", "crate::tui::draw"],
    );

    let files = tree(&[
        ("src/lib.rs", "pub mod cli;\npub mod tui;\n"),
        ("src/cli/mod.rs", "pub mod out;\n"),
        ("src/cli/out.rs", "pub fn emit() {}\n"),
        ("src/tui/mod.rs", "use crate::cli::out::emit;\n"),
    ]);
    one(
        &check(&files, &APP),
        &["tui imports cli", "src/tui/mod.rs:1"],
    );
}

#[test]
fn a_tab_importing_another_tab_is_reported() {
    let files = tree(&[
        ("src/lib.rs", "pub mod tui;\n"),
        ("src/tui/mod.rs", "pub mod tabs;\n"),
        // Tabs declared by a registry macro, as src/tui/tabs/mod.rs does.
        (
            "src/tui/tabs/mod.rs",
            "macro_rules! register { ($($m:ident),+) => { $(pub mod $m;)+ }; }\nregister! { responses, study }\npub trait Tab {}\n",
        ),
        ("src/tui/tabs/responses/mod.rs", "pub fn wrap_words() {}\n"),
        ("src/tui/tabs/study/mod.rs", "mod table;\nuse super::Tab;\n"),
        (
            "src/tui/tabs/study/table.rs",
            "use super::super::responses::wrap_words;\n",
        ),
    ]);
    one(
        &check(&files, &APP),
        &[
            "the study tab imports the responses tab",
            "src/tui/tabs/study/table.rs:1",
        ],
    );
}

#[test]
fn the_library_using_the_terminal_or_printing_is_reported() {
    let files = tree(&[
        (
            "crates/biodyn/Cargo.toml",
            "[dependencies]\nratatui = \"0.30\"\n",
        ),
        (
            "crates/biodyn/src/lib.rs",
            "use crossterm::event;\npub fn f() {\n    println!(\"hi\");\n    let _ = std::io::stderr();\n}\n#[cfg(test)]\nmod tests { fn t() { eprintln!(\"fine in a test\"); } }\n#[test]\nfn t() { println!(\"fine too\"); }\n",
        ),
    ]);
    let problems = check(&files, &LIB);
    assert_eq!(problems.len(), 4, "{problems:#?}");
    let all = problems.join("\n");
    for w in [
        "depends on ratatui: crates/biodyn/Cargo.toml:2",
        "uses crossterm: crates/biodyn/src/lib.rs:1",
        "prints: crates/biodyn/src/lib.rs:3 `println!`",
        "writes to stderr: crates/biodyn/src/lib.rs:4",
    ] {
        assert!(all.contains(w), "{w:?} not in {all}");
    }
}

#[test]
fn a_library_string_naming_a_flag_is_reported_not_a_comment_or_a_test() {
    let files = tree(&[(
        "crates/biodyn/src/lib.rs",
        concat!(
            "//! Use `--free` on the command line (a comment: fine).\n",
            "/// `--bound` in a doc comment: fine.\n",
            "#[derive(Debug)]\n",
            "pub enum E {\n",
            "    #[error(\"bad --set {0}\")]\n",
            "    Set(String),\n",
            "}\n",
            "pub fn f(x: f64) -> String { format!(\"{x} is not a --starts count\") }\n",
            "pub const RULE: &str = \"-----\";\n",
            "pub const ARROW: &str = \"a --> b\";\n",
            "pub const WORD: &str = \"x--y\";\n",
            "pub const RAW: &str = r#\"--raw\"#;\n",
            "#[cfg(test)]\n",
            "mod tests { const T: &str = \"--free k4\"; }\n",
        ),
    )]);
    let problems = check(&files, &LIB);
    assert_eq!(problems.len(), 3, "{problems:#?}");
    assert!(
        problems[0].contains("--set") && problems[0].contains("lib.rs:5"),
        "{problems:#?}"
    );
    assert!(
        problems[1].contains("--starts") && problems[1].contains("lib.rs:8"),
        "{problems:#?}"
    );
    assert!(
        problems[2].contains("--raw") && problems[2].contains("lib.rs:12"),
        "{problems:#?}"
    );
}

#[test]
fn a_long_file_is_reported_and_a_long_test_file_is_not() {
    let long = "fn f() {}\n".repeat(check::MAX_LINES + 1);
    let short = "fn f() {}\n".repeat(check::MAX_LINES);
    let files = tree(&[
        (
            "src/lib.rs",
            "mod big;\nmod fine;\n#[cfg(test)]\nmod tests;\n",
        ),
        ("src/big.rs", &long),
        ("src/fine.rs", &short),
        ("src/tests.rs", &long),
    ]);
    one(&check(&files, &APP), &["src/big.rs: 501 lines"]);
}

#[test]
fn a_missing_module_file_is_reported() {
    let files = tree(&[("src/lib.rs", "mod gone;\n")]);
    one(&check(&files, &APP), &["`mod gone;` has no file"]);
}
