//! Which preset files a folder offers: every `presets/*.toml`, and the
//! `*.toml` files beside it whose start reads like a preset (so
//! `Cargo.toml` or a day file is not offered). `biodyn preset list` and the
//! terminal app's open dialog list the same files.

use std::io::Read;
use std::path::{Path, PathBuf};

/// Entries read from one folder at most (a huge folder stays quick).
const MAX_ENTRIES: usize = 2000;

/// The preset files under `base`, named relative to it (`presets/a.toml`,
/// `mine.toml`), `presets/` first, each group sorted.
pub fn listed_presets(base: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for folder in ["presets", "."] {
        let Ok(dir) = std::fs::read_dir(base.join(folder)) else {
            continue;
        };
        let mut files: Vec<PathBuf> = dir
            .take(MAX_ENTRIES)
            .filter_map(|e| e.ok())
            .map(|e| e.path())
            .filter(|p| p.extension().is_some_and(|x| x == "toml"))
            // Everything in presets/ is listed (a broken or special file
            // too, for the list to say so); beside it only what reads like
            // a preset, and is_file (links followed) keeps a FIFO unopened.
            .filter(|p| folder == "presets" || (p.is_file() && looks_like_preset(p)))
            .map(|p| {
                let p = p.strip_prefix(base).unwrap_or(&p);
                p.strip_prefix(".").unwrap_or(p).to_path_buf()
            })
            .collect();
        files.sort();
        out.extend(files);
    }
    out
}

/// Whether the file's first 4 KiB read like a preset: a schema line and a
/// `[[segment]]` table.
fn looks_like_preset(p: &Path) -> bool {
    let mut head = [0u8; 4096];
    let n = std::fs::File::open(p)
        .and_then(|f| f.take(4096).read(&mut head))
        .unwrap_or(0);
    let text = String::from_utf8_lossy(&head[..n]);
    text.contains("schema") && text.contains("[[segment]]")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn presets_and_preset_looking_files_beside_them_are_listed() {
        let d = tempfile::tempdir().unwrap();
        std::fs::create_dir(d.path().join("presets")).unwrap();
        std::fs::write(d.path().join("presets/b.toml"), "anything").unwrap();
        std::fs::write(d.path().join("presets/a.toml"), "anything").unwrap();
        std::fs::write(d.path().join("presets/notes.txt"), "x").unwrap();
        crate::Preset::builtin_default()
            .save(&d.path().join("mine.toml"))
            .unwrap();
        std::fs::write(d.path().join("Cargo.toml"), "[package]\nname = \"x\"\n").unwrap();
        std::fs::write(d.path().join("day.toml"), "format = \"biodyn-day\"\n").unwrap();
        let got = listed_presets(d.path());
        let want: Vec<PathBuf> = ["presets/a.toml", "presets/b.toml", "mine.toml"]
            .iter()
            .map(PathBuf::from)
            .collect();
        assert_eq!(got, want);
    }
}
