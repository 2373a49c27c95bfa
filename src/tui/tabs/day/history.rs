//! The day's undo and redo, as the app keeps the model's
//! (`tui/app/history.rs`): a step is the day before an edit and what the
//! edit was; a new edit clears the redo list; the depth is bounded.

use biodyn::exposure::OperationSpec;
use biodyn::iso2631::spine::Person;
use std::path::PathBuf;

/// Undo depth: plenty for a session, bounded memory.
const LIMIT: usize = 200;

/// What undo restores: the operations and, for an open or save, the file.
#[derive(Debug, Clone, PartialEq)]
pub struct Snapshot {
    pub ops: Vec<OperationSpec>,
    pub saved: Vec<OperationSpec>,
    pub path: Option<PathBuf>,
    pub spine: Option<Person>,
    pub report: biodyn::exposure::Meta,
}

#[derive(Debug, Clone, PartialEq)]
pub struct Step {
    pub before: Snapshot,
    pub what: String,
    /// An open or a save-as: undo brings the other document back. Any
    /// other step edits the day open now and its undo keeps the file and
    /// what was last saved (a save is not undone).
    pub document: bool,
}

#[derive(Debug, Clone, Default, PartialEq)]
pub struct History {
    undo: Vec<Step>,
    redo: Vec<Step>,
}

impl History {
    /// Records the day before an edit named `what`.
    pub fn push(&mut self, before: Snapshot, what: String) {
        self.push_step(Step {
            before,
            what,
            document: false,
        });
    }

    /// Records the day before another file was opened or saved as.
    pub fn push_document(&mut self, before: Snapshot, what: String) {
        self.push_step(Step {
            before,
            what,
            document: true,
        });
    }

    fn push_step(&mut self, step: Step) {
        self.undo.push(step);
        if self.undo.len() > LIMIT {
            self.undo.remove(0);
        }
        self.redo.clear();
    }

    /// The step to undo, given the day now (kept for redo).
    pub fn undo(&mut self, now: Snapshot) -> Option<Step> {
        let step = self.undo.pop()?;
        self.redo.push(Step {
            before: now,
            what: step.what.clone(),
            document: step.document,
        });
        Some(step)
    }

    /// The step to redo, given the day now (kept for undo).
    pub fn redo(&mut self, now: Snapshot) -> Option<Step> {
        let step = self.redo.pop()?;
        self.undo.push(Step {
            before: now,
            what: step.what.clone(),
            document: step.document,
        });
        Some(step)
    }
}
