//! Structure edits from the Model tab: a whole new body (segments, links,
//! head, shares) and description, checked as a preset file is, one undo
//! step each.

use super::App;
use crate::tui::component::Change;
use crate::tui::model_check::check_model;
use biodyn::Body;

impl App {
    /// Replaces the model's structure (and description) once it passes
    /// `check_model`; one undo step named `what`. Ok(None): nothing changed.
    pub fn set_model(
        &mut self,
        body: Body,
        description: Option<String>,
        what: String,
    ) -> Result<Option<String>, String> {
        check_model(&self.shared.preset, &body)?;
        let desc_changed = description
            .as_ref()
            .is_some_and(|d| *d != self.shared.preset.description);
        if body == self.shared.body && !desc_changed {
            return Ok(None);
        }
        let before = self.snapshot();
        self.shared.body = body;
        if let Some(d) = description {
            self.shared.preset.description = d;
        }
        let change = if same_shape(&before.body, &self.shared.body) {
            Change::Edited
        } else {
            // Parameters the tabs hold (a study's k4) may be gone.
            Change::Loaded
        };
        self.push_undo(before, what.clone());
        self.refresh(change);
        Ok(Some(what))
    }
}

/// Same segments and links by count: every `Param` a tab holds still
/// exists. A structure edit that changes them is told to tabs as a load.
pub fn same_shape(a: &Body, b: &Body) -> bool {
    a.segments.len() == b.segments.len() && a.links.len() == b.links.len()
}
