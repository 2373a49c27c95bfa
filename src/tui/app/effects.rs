//! Effects land here: a tab's `Vec<Effect>` and a dialog's `Vec<Act>`,
//! each applied in one place, and the parameter edits they carry
//! (validated by the library, undoable).

use super::{App, open_preset};
use crate::tui::component::Change;
use crate::tui::effect::Effect;
use crate::tui::popups::confirm::{Confirm, ConfirmKind};
use crate::tui::popups::field::{Field, Purpose};
use crate::tui::popups::open::OpenDialog;
use crate::tui::popups::{Act, Overlay};
use crate::view::format::num;
use biodyn::Param;

impl App {
    /// Sets a parameter through the library's validation; on success the
    /// old body goes on the undo stack. On error nothing changes.
    pub fn set_param(&mut self, p: Param, v: f64) -> Result<(), String> {
        let mut next = self.shared.body.clone();
        next.set(p, v).map_err(|e| refusal(&e, p))?;
        if next == self.shared.body {
            return Ok(());
        }
        let what = format!(
            "{} {} → {}",
            next.label(p),
            num(self.shared.body.get(p), 6),
            num(next.get(p), 6)
        );
        let before = self.snapshot();
        self.shared.body = next;
        self.push_undo(before, what);
        self.refresh(Change::Edited);
        Ok(())
    }

    /// Sets several parameters in order as one edit (one undo step, named
    /// by their labels); on the first refusal nothing changes.
    pub fn set_params(&mut self, values: &[(Param, f64)]) -> Result<(), String> {
        let mut next = self.shared.body.clone();
        for &(p, v) in values {
            next.set(p, v).map_err(|e| refusal(&e, p))?;
        }
        if next == self.shared.body {
            return Ok(());
        }
        let labels: Vec<String> = values.iter().map(|&(p, _)| next.label(p)).collect();
        let before = self.snapshot();
        self.shared.body = next;
        self.push_undo(before, format!("the edit of {}", labels.join(", ")));
        self.refresh(Change::Edited);
        Ok(())
    }

    /// Carries out what a tab asked for: the one place effects land.
    pub fn apply(&mut self, effects: Vec<Effect>) {
        for e in effects {
            match e {
                Effect::Status(t) => self.say(t),
                Effect::Error(t) => self.fail(t),
                Effect::SetParam(p, v) => match self.set_param(p, v) {
                    Ok(()) => self.say_param(p),
                    Err(why) => self.fail(why),
                },
                Effect::SetParams(values, done) => match self.set_params(&values) {
                    Ok(()) => self.say(done),
                    Err(why) => self.fail(why),
                },
                Effect::OpenField(f) => self.field = Some(f),
                Effect::SetModel {
                    body,
                    description,
                    what,
                } => match self.set_model(*body, description, what) {
                    Ok(Some(what)) => self.say(format!("{what} (u undoes it)")),
                    Ok(None) => self.say("unchanged"),
                    Err(why) => self.fail(why),
                },
                Effect::Export(x) => {
                    let label = match x.formats.as_slice() {
                        [one] => format!("export {} ({}) to", x.what, one.what),
                        many => {
                            let l: Vec<String> = many
                                .iter()
                                .map(|f| format!(".{} {}", f.ext, f.what))
                                .collect();
                            format!("export {} ({}) to", x.what, l.join(", "))
                        }
                    };
                    let f = Field::new(Purpose::Export, label, x.path_hint.clone());
                    self.field = Some(f.for_path());
                    self.export = Some(x);
                }
            }
        }
    }
}

impl App {
    /// Carries out what a dialog or the field asked for: the one place
    /// their acts land.
    pub fn apply_acts(&mut self, acts: Vec<Act>) {
        for a in acts {
            match a {
                Act::Close => self.overlay = Overlay::None,
                Act::Show(o) => self.overlay = o,
                Act::Quit => {
                    self.shutdown();
                    self.quit = true;
                }
                Act::SaveThenQuit => {
                    let path = self.default_save_path();
                    self.field = Some(Field::new(
                        Purpose::SaveAndQuit,
                        "save preset, then quit, to",
                        path,
                    ));
                }
                Act::Open(d, confirmed) => self.open_from_dialog(d, confirmed),
                Act::CommitField => self.commit_field(),
                Act::CancelField => {
                    self.field = None;
                    self.export = None;
                    self.say("cancelled; nothing changed");
                }
                Act::ToggleMouse => self.toggle_mouse(),
                Act::Fail(t) => self.fail(t),
            }
        }
    }

    /// Opens what the open dialog names; with unsaved edits it asks first
    /// (unless `confirmed`); a refusal goes back to the dialog, said there.
    fn open_from_dialog(&mut self, mut d: OpenDialog, confirmed: bool) {
        let arg = d.field.text.trim().to_string();
        match open_preset(&arg) {
            Ok(_) if self.modified() && !confirmed => {
                self.overlay = Overlay::Confirm(Confirm::new(ConfirmKind::Discard, Some(d)));
            }
            Ok((p, path)) => self.load(p, path),
            Err(e) => {
                d.field.error = Some(e.to_string());
                self.overlay = Overlay::Open(d);
            }
        }
    }

    /// `M`: the mouse on or off, said in one line that fits 80 columns.
    pub fn toggle_mouse(&mut self) {
        self.mouse = !self.mouse;
        self.say(if self.mouse {
            "mouse on: click tabs, values, charts; the wheel scrolls; M turns it off"
        } else {
            "mouse off: the terminal selects text to copy; M turns the mouse on"
        });
    }
}

/// Why a value was refused, about the value the user typed: a link's
/// stiffness or damping is told its own range only.
fn refusal(e: &biodyn::body::ModelError, p: Param) -> String {
    use biodyn::body::{MAX_C, MAX_K, ModelError};
    match (e, p) {
        (ModelError::BadLinkValue { link, value, .. }, Param::Stiffness(i)) => format!(
            "k{} of link '{link}' = {value:?} N/m: stiffness must be in [0, {MAX_K:e}] N/m",
            i + 1
        ),
        (ModelError::BadLinkValue { link, value, .. }, Param::Damping(i)) => format!(
            "c{} of link '{link}' = {value:?} N·s/m: damping must be in [0, {MAX_C:e}] N·s/m",
            i + 1
        ),
        _ => e.to_string(),
    }
}
