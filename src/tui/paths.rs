//! Paths the user types: `~` is the home folder, Tab completes.

use std::path::{Path, PathBuf};

/// `~` and `~/x` become the home folder; anything else is unchanged.
pub fn expand(text: &str) -> PathBuf {
    let t = text.trim();
    let home = std::env::var_os("HOME").filter(|h| !h.is_empty());
    match (t.strip_prefix('~'), home) {
        (Some(""), Some(h)) => PathBuf::from(h),
        (Some(rest), Some(h)) if rest.starts_with('/') => {
            PathBuf::from(h).join(rest.trim_start_matches('/'))
        }
        _ => PathBuf::from(t),
    }
}

/// Why `path` (typed as `text`) cannot be saved to, checked before any
/// "exists: Enter again replaces it": a folder (add a file name, like
/// `example`), or something not a regular file (a FIFO, a device, a
/// socket) that a save must not write into nor replace. None when it is a
/// regular file or nothing is there yet. Every save and export of the TUI
/// asks here first.
pub fn save_refusal(
    text: &str,
    path: &Path,
    example: &str,
    guard: &biodyn::io::Guard,
) -> Option<String> {
    let Ok(meta) = std::fs::metadata(path) else {
        // Nothing there yet: the folder must take it.
        return guard
            .check(path)
            .err()
            .map(|e| format!("{text}: {}", e.reason()));
    };
    if meta.is_dir() {
        Some(format!(
            "{text}: Is a directory; add a file name, e.g. {}/{example}",
            text.trim_end_matches('/')
        ))
    } else if !meta.is_file() {
        Some(format!(
            "{text} is not a regular file (a pipe, device or socket): choose another path"
        ))
    } else {
        // One of the app's open files, or read-only.
        guard
            .check(path)
            .err()
            .map(|e| format!("{text}: {}", e.reason()))
    }
}

/// What a save of the document at `own` (None: an export, a new file) may
/// not replace: every other file the app has open.
pub fn guard(shared: &crate::tui::shared::Shared, own: Option<&Path>) -> biodyn::io::Guard {
    biodyn::io::Guard::reading(&shared.inputs, false).without(own)
}

/// Completes the last part of `text` against the folder it names: the
/// longest common prefix of the matches (a folder gets its `/`), and how
/// many matched. None when nothing matches. Hidden files only when the
/// part starts with a dot. Reads one folder, at most 2000 entries.
pub fn complete(text: &str) -> Option<(String, usize)> {
    let (dir_text, part) = match text.rfind('/') {
        Some(i) => (&text[..=i], &text[i + 1..]),
        None => ("", text),
    };
    let dir = if dir_text.is_empty() {
        PathBuf::from(".")
    } else {
        expand(dir_text)
    };
    let mut names: Vec<(String, bool)> = std::fs::read_dir(dir)
        .ok()?
        .take(2000)
        .filter_map(|e| e.ok())
        .filter_map(|e| {
            let name = e.file_name().into_string().ok()?;
            let is_dir = e.path().is_dir();
            (name.starts_with(part) && (part.starts_with('.') || !name.starts_with('.')))
                .then_some((name, is_dir))
        })
        .collect();
    names.sort();
    let (first, first_dir) = names.first()?.clone();
    let mut common = first.clone();
    for (n, _) in &names[1..] {
        let k = common
            .chars()
            .zip(n.chars())
            .take_while(|(a, b)| a == b)
            .count();
        common = common.chars().take(k).collect();
    }
    if names.len() == 1 && first_dir {
        common.push('/');
    }
    Some((format!("{dir_text}{common}"), names.len()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tilde_and_completion() {
        if let Some(h) = std::env::var_os("HOME").filter(|h| !h.is_empty()) {
            assert_eq!(expand("~/a.toml"), PathBuf::from(&h).join("a.toml"));
            assert_eq!(expand("~"), PathBuf::from(&h));
        }
        assert_eq!(expand("a~/b"), PathBuf::from("a~/b"));
        let dir = tempfile::tempdir().expect("tempdir");
        let d = dir.path().display().to_string();
        std::fs::write(dir.path().join("paper-75kg.toml"), "").expect("write");
        std::fs::write(dir.path().join("paper-65kg.toml"), "").expect("write");
        std::fs::create_dir(dir.path().join("sub")).expect("mkdir");
        assert_eq!(
            complete(&format!("{d}/pa")),
            Some((format!("{d}/paper-"), 2))
        );
        assert_eq!(
            complete(&format!("{d}/paper-7")),
            Some((format!("{d}/paper-75kg.toml"), 1))
        );
        assert_eq!(complete(&format!("{d}/s")), Some((format!("{d}/sub/"), 1)));
        assert_eq!(complete(&format!("{d}/zz")), None);
    }
}
