//! `docs/keys.md` is generated from the key tables: the test builds the
//! page from the `?` page's lines (the same tables the hint bar and the
//! key lookup read) and compares it with the file, so the docs cannot
//! drift from what the keys do. `BIODYN_UPDATE_DOCS=1` writes it instead.

use super::app;
use crate::tui::popups::help::HelpLine;

/// The page, from the `?` page as it opens on the first tab.
fn keys_page() -> String {
    let mut out = String::from(
        "# Keys\n\n\
         Every key of the terminal app, table by table, as the `?` page lists them \
         (the current tab's keys first there). This page is generated from the key \
         tables in `src/tui/` and checked by `cargo test`; do not edit it by hand: \
         after changing a binding, regenerate it with \
         `BIODYN_UPDATE_DOCS=1 cargo test -p biodyn-app --lib docs_keys_md`.\n",
    );
    for l in app().help_lines() {
        match l {
            HelpLine::Heading(h) => {
                out.push_str(&format!("\n## {h}\n\n| keys | what |\n|---|---|\n"))
            }
            HelpLine::Row { keys, help } => out.push_str(&format!(
                "| {} | {} |\n",
                keys.replace('|', "\\|"),
                help.replace('|', "\\|")
            )),
        }
    }
    out
}

#[test]
fn docs_keys_md_is_the_key_tables() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/docs/keys.md");
    let want = keys_page();
    if std::env::var_os("BIODYN_UPDATE_DOCS").is_some_and(|v| v == "1") {
        let dir = std::path::Path::new(path).parent().expect("docs/");
        std::fs::create_dir_all(dir).expect("create docs/");
        std::fs::write(path, &want).expect("write docs/keys.md");
        return;
    }
    let have = std::fs::read_to_string(path).unwrap_or_default();
    assert!(
        have == want,
        "docs/keys.md is not the key tables; regenerate it with \
         BIODYN_UPDATE_DOCS=1 cargo test -p biodyn-app --lib docs_keys_md\n\
         first difference at line {}",
        have.lines()
            .zip(want.lines())
            .position(|(a, b)| a != b)
            .unwrap_or_else(|| have.lines().count().min(want.lines().count()))
            + 1
    );
}
