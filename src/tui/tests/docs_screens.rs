//! Every whole screen the manual shows (a fenced block that starts with
//! the title line, ` 1 Model …`) is one the app draws: it equals a
//! committed snapshot, which a test renders from the app. A doc screen
//! that drifts from the app (an axis the docs label 19.9 where the app
//! draws 20, an old title or hint bar) fails here (issue 19 item 22).

fn snapshots() -> Vec<(String, String)> {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    super::files_under(&root.join("src"), "snap")
        .iter()
        .filter_map(|p| {
            let text = std::fs::read_to_string(p).ok()?;
            // insta's header is `---`, its fields, `---`; the screen follows.
            let body = text.splitn(3, "---\n").nth(2)?;
            Some((
                p.display().to_string(),
                body.trim_end_matches('\n').to_string(),
            ))
        })
        .collect()
}

/// The fenced blocks of `text` that are whole screens.
fn screens(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut block: Option<Vec<&str>> = None;
    for line in text.lines() {
        let fence = line.trim_start().starts_with("```");
        match (&mut block, fence) {
            (None, true) => block = Some(Vec::new()),
            (Some(b), true) => {
                if b.first().is_some_and(|l| l.starts_with(" 1 Model")) {
                    out.push(b.join("\n"));
                }
                block = None;
            }
            (Some(b), false) => b.push(line),
            (None, false) => {}
        }
    }
    out
}

#[test]
fn every_screen_in_the_docs_is_one_the_app_draws() {
    let snaps = snapshots();
    assert!(snaps.len() > 50, "{} snapshots found", snaps.len());
    let shown = screens(&super::docs_text());
    assert!(shown.len() >= 4, "{} screens in the docs", shown.len());
    for s in &shown {
        assert!(
            snaps.iter().any(|(_, body)| body == s),
            "this screen of the docs is no snapshot of the app (re-take it from the \
             snapshot its test writes):\n{s}"
        );
    }
}
