//! The undo history: what a step restores, and undo / redo.

use super::App;
use crate::tui::component::Change;
use biodyn::{Band, Body, Preset};
use std::path::PathBuf;

/// Undo depth: plenty for a session, bounded memory.
const UNDO_LIMIT: usize = 200;

/// What undo restores: the model and, for a load, the preset and file.
#[derive(Debug, Clone)]
pub struct Snapshot {
    pub body: Body,
    pub preset: Preset,
    pub path: Option<PathBuf>,
    pub saved: Body,
    /// The band as last loaded or saved.
    pub saved_band: Band,
    pub saved_description: String,
}

/// One undoable change: the state before it and what it was
/// ("k4 54000 → 90000", "open paper-65kg (built-in)").
#[derive(Debug, Clone)]
pub struct Step {
    pub before: Snapshot,
    pub what: String,
    /// Another file was opened: undo brings the old document back (its
    /// file and saved state). Any other step is an edit of the document
    /// open now: undo changes the model, never which file it is saved in
    /// nor what was last saved (a save is not undone), so an undo after
    /// Ctrl-S shows `*modified` and `q` asks.
    pub load: bool,
}

impl App {
    pub(super) fn snapshot(&self) -> Snapshot {
        let s = &self.shared;
        Snapshot {
            body: s.body.clone(),
            preset: s.preset.clone(),
            path: s.path.clone(),
            saved: s.saved.clone(),
            saved_band: self.saved_band,
            saved_description: s.saved_description.clone(),
        }
    }

    /// Records the state before an edit named `what`.
    pub(super) fn push_undo(&mut self, before: Snapshot, what: String) {
        self.push_step(Step {
            before,
            what,
            load: false,
        });
    }

    /// Records the state before another file was opened.
    pub(super) fn push_load_undo(&mut self, before: Snapshot, what: String) {
        self.push_step(Step {
            before,
            what,
            load: true,
        });
    }

    fn push_step(&mut self, step: Step) {
        self.undo.push(step);
        if self.undo.len() > UNDO_LIMIT {
            self.undo.remove(0);
        }
        self.redo.clear();
    }

    /// Puts `snap` in place; returns the state it replaced. An edit's
    /// snapshot (`load` false) brings back the model, its band and its
    /// description, and keeps the document: its file, its name and source,
    /// and what was last saved.
    pub(super) fn restore(&mut self, mut snap: Snapshot, load: bool) -> Snapshot {
        let now = self.snapshot();
        if !load {
            let mut preset = now.preset.clone();
            preset.band = snap.preset.band;
            preset.description = std::mem::take(&mut snap.preset.description);
            snap.preset = preset;
            snap.path.clone_from(&now.path);
            snap.saved.clone_from(&now.saved);
            snap.saved_band = now.saved_band;
            snap.saved_description.clone_from(&now.saved_description);
        }
        // A band edit or a description edit is an edit, not another model:
        // the tabs keep their state. A change of shape is a load.
        let mut same = snap.preset.clone();
        same.band = now.preset.band;
        same.description.clone_from(&now.preset.description);
        let loaded = now.path != snap.path
            || now.preset != same
            || !super::structure::same_shape(&now.body, &snap.body);
        self.saved_band = snap.saved_band;
        let s = &mut self.shared;
        s.body = snap.body;
        s.preset = snap.preset;
        s.path = snap.path;
        s.saved = snap.saved;
        s.saved_description = snap.saved_description;
        self.refresh(if loaded {
            Change::Loaded
        } else {
            Change::Edited
        });
        now
    }

    /// Undoes the last change and says which ("undid k4 54000 → 90000").
    pub fn undo(&mut self) {
        match self.undo.pop() {
            Some(step) => {
                let now = self.restore(step.before, step.load);
                self.say(format!("undid {} (^R redoes it)", step.what));
                self.redo.push(Step {
                    before: now,
                    what: step.what,
                    load: step.load,
                });
            }
            None => self.fail("nothing to undo"),
        }
    }

    pub fn redo(&mut self) {
        match self.redo.pop() {
            Some(step) => {
                let now = self.restore(step.before, step.load);
                self.say(format!("redid {}", step.what));
                self.undo.push(Step {
                    before: now,
                    what: step.what,
                    load: step.load,
                });
            }
            None => self.fail("nothing to redo"),
        }
    }
}
