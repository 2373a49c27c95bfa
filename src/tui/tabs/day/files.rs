//! The day's file: open (Ctrl-O on this tab) and save (Ctrl-S), through
//! the library's `DayFile::load` and `DayFile::save` (checked, atomic: a
//! day that would not load back is not written). Another file of the
//! name is only replaced on a second Enter, as the preset's save asks.
//! A record path is written relative to the day file's folder, so a day
//! saved to another folder has its record paths rewritten to still name
//! the same files.

use super::DayTab;
use super::edit::resolve;
use biodyn::iso2631::spine::Person;
use biodyn::exposure::{DayFile, OperationSpec, Source};
use std::path::{Path, PathBuf};

/// The folder record paths are taken from: the day file's, else the
/// working folder.
pub fn folder_of(path: Option<&Path>) -> PathBuf {
    path.and_then(Path::parent)
        .map_or_else(|| PathBuf::from(""), Path::to_path_buf)
}

/// Record paths for a day moving from `from` to `to`: each record's file
/// named from the new folder (relative when it lies under it, else
/// absolute). True when a path changed.
fn rebase(ops: &mut [OperationSpec], from: &Path, to: &Path) -> bool {
    let abs = |p: &Path| std::path::absolute(p).unwrap_or_else(|_| p.to_path_buf());
    if abs(from) == abs(to) {
        return false;
    }
    let to_abs = abs(to);
    let mut changed = false;
    for o in ops.iter_mut() {
        if let Source::Record(r) = &mut o.source {
            let file = abs(&r.resolved);
            let new = file
                .strip_prefix(&to_abs)
                .map_or_else(|_| file.clone(), Path::to_path_buf)
                .display()
                .to_string();
            if new != r.path {
                r.path = new;
                changed = true;
            }
        }
    }
    resolve(ops, to);
    changed
}

impl DayTab {
    /// Saves the day to `text`'s path; the status, or why not (the field
    /// stays open with it).
    pub(super) fn save_to(
        &mut self,
        text: &str,
        shared: &crate::tui::shared::Shared,
    ) -> Result<String, String> {
        let t = text.trim();
        if t.is_empty() {
            return Err("give a file path, e.g. my-day.toml".into());
        }
        let path = crate::tui::paths::expand(t);
        let guard = crate::tui::paths::guard(shared, self.path.as_deref());
        if let Some(why) = crate::tui::paths::save_refusal(t, &path, "my-day.toml", &guard) {
            return Err(why);
        }
        let ours = self.path.as_deref() == Some(path.as_path());
        if path.exists() && !ours && self.replace.as_deref() != Some(path.as_path()) {
            self.replace = Some(path);
            return Err(format!("{t} exists: Enter again replaces it, or change the path"));
        }
        let mut ops = self.ops.clone();
        let moved = rebase(&mut ops, &folder_of(self.path.as_deref()), &folder_of(Some(&path)));
        let file = DayFile {
            origin: t.to_string(),
            operations: ops.clone(),
            spine: self.spine,
            report: self.report.clone(),
        };
        file.save_guarded(&path, &guard).map_err(|e| e.to_string())?;
        self.replace = None;
        let before = self.snapshot();
        self.ops = ops;
        self.saved = self.ops.clone();
        self.path = Some(path.clone());
        // A save is not undone; only a save-as that rebased the record
        // paths on the new folder is a step (its undo is the old file with
        // its own paths back).
        if before.ops != self.ops {
            self.history.push_document(before, format!("save as {t}"));
        }
        let note = if moved { " (record paths now from its folder)" } else { "" };
        Ok(format!("saved the day to {}{note}", path.display()))
    }

    /// Opens the day file `text` names; the status, or why not.
    pub(super) fn open(&mut self, text: &str) -> Result<String, String> {
        let t = text.trim();
        if t.is_empty() {
            return Err("give a day file's path, e.g. examples/day.toml".into());
        }
        let path = crate::tui::paths::expand(t);
        let file = DayFile::load(&path).map_err(|e| e.to_string())?;
        let before = self.snapshot();
        self.load(file.operations, file.spine, Some(path));
        self.report = file.report;
        self.history.push_document(before, format!("open {t}"));
        let n = self.ops.len();
        Ok(format!(
            "opened {t}: {n} operation{} (u brings the last day back)",
            if n == 1 { "" } else { "s" }
        ))
    }

    /// Puts a loaded day in place, unmodified, the first cell selected.
    pub(super) fn load(&mut self, ops: Vec<OperationSpec>, spine: Option<Person>, path: Option<PathBuf>) {
        self.ops = ops;
        self.spine = spine;
        self.saved = self.ops.clone();
        self.path = path;
        self.row = 0;
        self.col = super::edit::Col::Name;
    }
}
