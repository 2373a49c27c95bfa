//! Saving the trained network (`w`) and loading one back (`o`), through
//! the library's `netfile` as `biodyn train --save` and `biodyn predict
//! --net` do.

use super::{TrainingTab, err, say, state};
use crate::tui::effect::Effect;
use biodyn::ann::{Settings, self};

impl TrainingTab {
    /// Saves the network; another file of that name is replaced only on a
    /// second Enter (as the preset save asks).
    pub(super) fn save_net(
        &mut self,
        text: &str,
        shared: &crate::tui::shared::Shared,
    ) -> Result<Vec<Effect>, String> {
        if text.is_empty() {
            return Err("give a file path, e.g. mass-stht.json".into());
        }
        let expanded = crate::tui::paths::expand(text);
        let path = expanded.as_path();
        // A folder, pipe or device is refused before any "exists" question.
        let guard = crate::tui::paths::guard(shared, None);
        if let Some(why) = crate::tui::paths::save_refusal(text, path, "mass-stht.json", &guard) {
            return Err(why);
        }
        if path.exists() && self.overwrite_ok.as_deref() != Some(text) {
            self.overwrite_ok = Some(text.to_string());
            return Err(format!(
                "{text} exists: Enter again replaces it, or change the path"
            ));
        }
        self.overwrite_ok = None;
        let out = self
            .run
            .as_ref()
            .and_then(|r| r.outcome.as_ref())
            .ok_or("no trained network to save")?;
        ann::save_network_guarded(path, &out.net, &guard).map_err(|e| e.to_string())?;
        self.last_net_path = Some(text.to_string());
        Ok(say(format!("saved network to {text}")))
    }

    /// Reads a network file through the library (`ann::load_network`, as
    /// `biodyn predict --net`) and shows its prediction.
    pub(super) fn load_net(&mut self, text: &str, body: &biodyn::Body) -> Result<Vec<Effect>, String> {
        if text.is_empty() {
            return Err("give the path of a network file, e.g. mass-stht-lm.json".into());
        }
        let path = crate::tui::paths::expand(text);
        if path.is_dir() {
            return Err(format!("{text}: Is a directory; give a network file (.json)"));
        }
        // ann::load_network reads with read_to_string: a FIFO would block the
        // UI, so only a regular file goes to it.
        if path.exists() && !path.is_file() {
            return Err(format!("{text}: not a regular file; give a network file (.json)"));
        }
        let net = ann::load_network(&path).map_err(|e| e.to_string())?;
        let mut what = format!(
            "loaded {text}: {} network, {} trainer, {} member(s)",
            net.case,
            net.settings.trainer,
            net.members.len()
        );
        // The tab shows one case at a time: the case row follows the file
        // (as ←/→ on it would: the next run's settings are that case's).
        if net.case != self.case {
            self.case = net.case;
            self.settings = Settings::for_trainer(self.case, self.settings.trainer);
            self.sync_base(body);
            what.push_str("; the case row follows it");
        }
        self.loaded = Some(state::Loaded {
            path: text.to_string(),
            net,
            prediction: None,
        });
        self.show_loaded = true;
        self.last_net_path = Some(text.to_string());
        self.repredict(body);
        Ok(match &self.prediction_err {
            Some(e) => err(format!("{what}; no prediction: {e}")),
            None => say(what),
        })
    }
}
