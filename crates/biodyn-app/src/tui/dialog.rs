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

#[derive(Debug, Clone, PartialEq)]
pub struct OpenDialog {
    /// (what the list shows, what `Preset::open` gets)
    pub entries: Vec<(String, String)>,
    pub sel: Option<usize>,
    pub field: Field,
}

impl OpenDialog {
    /// `presets/*.toml` in the working folder, then the built-ins; the
    /// field starts at the current file.
    pub fn new(current: Option<&PathBuf>) -> OpenDialog {
        let mut entries = Vec::new();
        if let Ok(dir) = std::fs::read_dir("presets") {
            let mut files: Vec<String> = dir
                .filter_map(|e| e.ok())
                .map(|e| e.path())
                .filter(|p| p.extension().is_some_and(|x| x == "toml"))
                .map(|p| p.display().to_string())
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
        }
    }
}

#[derive(Debug, Clone, PartialEq)]
pub enum Overlay {
    None,
    Help { scroll: u16 },
    Open(OpenDialog),
    Confirm(ConfirmKind, Option<OpenDialog>),
}
