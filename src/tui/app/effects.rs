//! Effects land here: a tab's `Vec<Effect>` applied in one place, and
//! the parameter edits they carry (validated by the library, undoable).

use super::App;
use crate::tui::component::Change;
use crate::tui::effect::Effect;
use crate::tui::field::{Field, Purpose};
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

/// Why a value was refused, about the value the user typed: a link's
/// stiffness or damping is told its own range only.
fn refusal(e: &biodyn::body::model::ModelError, p: Param) -> String {
    use biodyn::body::model::{MAX_C, MAX_K, ModelError};
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
