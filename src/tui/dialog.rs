//! The app's own dialogs over the tabs: the `?` page, the open-preset
//! dialog and the quit / discard confirmation. State only; `frame.rs`
//! draws them.

use super::field::{Field, Purpose};
use biodyn::body::preset;
use std::path::PathBuf;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ConfirmKind {
    Quit,
    /// Open the preset named in the open dialog's field (kept beside the
    /// confirmation), discarding unsaved edits.
    Discard,
}

/// A TOML file in the working folder is listed only if its start reads
/// like a preset (so `Cargo.toml` is not offered).
fn looks_like_preset(p: &std::path::Path) -> bool {
    use std::io::Read;
    let mut head = [0u8; 4096];
    let n = std::fs::File::open(p)
        .and_then(|f| f.take(4096).read(&mut head))
        .unwrap_or(0);
    let text = String::from_utf8_lossy(&head[..n]);
    text.contains("schema") && text.contains("[[segment]]")
}

#[derive(Debug, Clone, PartialEq)]
pub struct OpenDialog {
    /// (what the list shows, what `Preset::open` gets)
    pub entries: Vec<(String, String)>,
    pub sel: Option<usize>,
    pub field: Field,
}

impl OpenDialog {
    /// `presets/*.toml` and `*.toml` in the working folder, then the
    /// built-ins; the field starts at the current file.
    pub fn new(current: Option<&PathBuf>) -> OpenDialog {
        let mut entries = Vec::new();
        for folder in ["presets", "."] {
            let Ok(dir) = std::fs::read_dir(folder) else {
                continue;
            };
            let mut files: Vec<String> = dir
                .take(2000)
                .filter_map(|e| e.ok())
                .map(|e| e.path())
                .filter(|p| p.is_file() && p.extension().is_some_and(|x| x == "toml"))
                .filter(|p| folder == "presets" || looks_like_preset(p))
                .map(|p| {
                    let s = p.display().to_string();
                    s.strip_prefix("./").map(str::to_string).unwrap_or(s)
                })
                .collect();
            files.sort();
            entries.extend(files.into_iter().map(|f| (f.clone(), f)));
        }
        for (name, _) in preset::SHIPPED {
            entries.push((format!("{name} (built-in)"), name.to_string()));
        }
        let text = current.map(|p| p.display().to_string()).unwrap_or_default();
        OpenDialog {
            entries,
            sel: None,
            field: Field::new(Purpose::OpenPath, "path or built-in name", text),
        }
    }

    /// Moves the selection (wrapping) and fills the field with it.
    pub fn step(&mut self, up: bool) {
        let n = self.entries.len();
        if n == 0 {
            return;
        }
        let i = match (self.sel, up) {
            (None, true) => n - 1,
            (None, false) => 0,
            (Some(i), true) => (i + n - 1) % n,
            (Some(i), false) => (i + 1) % n,
        };
        self.sel = Some(i);
        if let Some((_, arg)) = self.entries.get(i) {
            let arg = arg.clone();
            self.field.set_text(arg);
            self.field.selected = true;
        }
    }
}

/// The `?` page: where it is scrolled to and what is searched for.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct HelpView {
    /// First line shown.
    pub scroll: usize,
    /// The search text (`/`); lines that hold it are marked.
    pub query: String,
    /// The search text is being typed.
    pub typing: bool,
}

impl HelpView {
    /// The first line at or after `from` (wrapping) whose text holds the
    /// query, ignoring case.
    pub fn find(&self, lines: &[String], from: usize) -> Option<usize> {
        let q = self.query.to_lowercase();
        if q.is_empty() {
            return None;
        }
        let n = lines.len();
        (0..n)
            .map(|i| (from + i) % n)
            .find(|&i| lines.get(i).is_some_and(|l| l.to_lowercase().contains(&q)))
    }
}

#[derive(Debug, Clone, PartialEq)]
pub enum Overlay {
    None,
    Help(HelpView),
    Open(OpenDialog),
    Confirm(ConfirmKind, Option<OpenDialog>),
}
