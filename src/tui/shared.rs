//! What every tab may read: the model, the preset it came from, what is
//! derived from it, and the theme. Only the app changes it (through
//! effects); tabs get it by shared reference.

use super::derived::Derived;
use super::theme::Theme;
use biodyn::freq::Modes;
use biodyn::{Band, Body, Param, Preset};
use std::path::PathBuf;

pub struct Shared {
    /// Name, description, source and band of the loaded preset.
    pub preset: Preset,
    /// The model being edited.
    pub body: Body,
    /// The model as last loaded or saved: `body != saved` means modified.
    pub saved: Body,
    /// The description as last loaded or saved: an edited one (`D` on the
    /// Model tab) is an unsaved edit too, and is saved as typed.
    pub saved_description: String,
    /// The file the preset came from; None for a built-in.
    pub path: Option<PathBuf>,
    /// Curves and peaks of the body; None while a large model's first
    /// computation runs.
    pub derived: Option<Derived>,
    /// Modes of the body; None while they are computed.
    pub modes: Option<Result<Modes, String>>,
    /// The derived data belong to an earlier edit; newer ones are on the way.
    pub stale: bool,
    pub theme: Theme,
    /// Every file the app has open (the preset, measured data, a record,
    /// the day and its records, a network): a save must not replace one
    /// unless it is the document being saved. Refreshed after each message.
    pub inputs: Vec<PathBuf>,
}

impl Shared {
    pub fn band(&self) -> &Band {
        &self.preset.band
    }

    pub fn modified(&self) -> bool {
        self.body != self.saved || self.preset.description != self.saved_description
    }

    /// "paper-75kg (built-in)" or the file path.
    pub fn file_label(&self) -> String {
        match &self.path {
            Some(p) => p.display().to_string(),
            None => format!("{} (built-in)", self.preset.name),
        }
    }

    /// What the user reads for a parameter: "k4 pelvis-seat (N/m)".
    pub fn describe(&self, p: Param) -> String {
        let b = &self.body;
        let name = match p {
            Param::BodyMass => None,
            Param::Mass(i) => b.segments.get(i).map(|s| s.name.as_str()),
            Param::Stiffness(i) | Param::Damping(i) => b.links.get(i).map(|l| l.name.as_str()),
        };
        let what = name.map(|n| format!(" {n}")).unwrap_or_default();
        format!("{}{what} ({})", b.label(p), p.unit())
    }

    /// Grid index nearest `f_hz`, within the current curve.
    pub fn index_of(&self, f_hz: f64) -> usize {
        let b = self.band();
        let i = ((f_hz - b.from) / b.step).round().max(0.0) as usize;
        i.min(self.curve_len().saturating_sub(1))
    }

    pub fn curve_len(&self) -> usize {
        self.derived.as_ref().map_or(0, |d| d.curve.len())
    }

    /// A line for a tab whose data are not there yet.
    pub fn computing(&self) -> String {
        format!(
            "computing responses, peaks and modes of {} segments in the background… (q quits)",
            self.body.segments.len()
        )
    }
}
