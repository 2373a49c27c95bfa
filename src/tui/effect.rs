//! What a tab asks the app to do. A tab changes only its own state; every
//! change to what tabs share (the model, the status line, the open field)
//! is an `Effect`, applied by `App::apply` in one place.

use super::popups::field::Field;
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
    /// Set several parameters, in order, as ONE undoable edit (a fit's
    /// values); all or nothing. On success the status line says `.1`.
    SetParams(Vec<(Param, f64)>, String),
    /// Open a text field. A `Purpose::Tab` field is committed back to the
    /// tab that opened it (`Tab::commit`).
    OpenField(Field),
    /// Offer to write a file (the Study tab's `x`): the app asks for the
    /// path, pre-filled with `path_hint`, and writes the contents of the
    /// format the path's extension names, atomically, asking before it
    /// replaces a file. Any tab can return it.
    Export(Export),
    /// Replace the model's structure (segments, links, head, shares) and,
    /// if given, the preset's description, after the checks a preset file
    /// gets; undoable as one step named `what` ("add segment 'arm'").
    SetModel {
        body: Box<Body>,
        description: Option<String>,
        what: String,
    },
}

/// Something a tab can write to a file, in one or more formats.
#[derive(Debug, Clone, PartialEq)]
pub struct Export {
    /// What it is, for the field's label and the status ("study of k4").
    pub what: String,
    /// The pre-filled path, e.g. `paper-75kg-study-k4.csv`; its extension
    /// should be the first format's.
    pub path_hint: String,
    /// The contents per file extension (`"csv"`, `"txt"`), the default first.
    pub formats: Vec<Format>,
}

/// One way to write an export: the file extension that picks it, what it
/// holds (for the field's label: "the curves", "the chart as text") and
/// the bytes, already rendered.
#[derive(Debug, Clone, PartialEq)]
pub struct Format {
    pub ext: &'static str,
    pub what: &'static str,
    pub contents: String,
}

impl Export {
    /// The format for `path`'s extension, or why there is none.
    pub fn pick(&self, path: &std::path::Path) -> Result<&Format, String> {
        let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("");
        self.formats
            .iter()
            .find(|f| f.ext.eq_ignore_ascii_case(ext))
            .ok_or_else(|| {
                let list: Vec<String> = self
                    .formats
                    .iter()
                    .map(|f| format!(".{} ({})", f.ext, f.what))
                    .collect();
                format!("end the file name in {}", list.join(" or "))
            })
    }
}
