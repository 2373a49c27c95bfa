//! What a tab asks the app to do. A tab changes only its own state; every
//! change to what tabs share (the model, the status line, the open field)
//! is an `Effect`, applied by `App::apply` in one place.

use super::field::Field;
use biodyn::{Body, Param};

#[derive(Debug, Clone, PartialEq)]
pub enum Effect {
    /// A message on the status line.
    Status(String),
    /// An error on the status line ("error: …").
    Error(String),
    /// Set a model parameter through the library's validation (undoable);
    /// the status line says the new value or why it was refused.
    SetParam(Param, f64),
    /// Open a text field. A `Purpose::Tab` field is committed back to the
    /// tab that opened it (`Tab::commit`).
    OpenField(Field),
    /// Replace the model's structure (segments, links, head, shares) and,
    /// if given, the preset's description, after the checks a preset file
    /// gets; undoable as one step named `what` ("add segment 'arm'").
    SetModel {
        body: Box<Body>,
        description: Option<String>,
        what: String,
    },
}
