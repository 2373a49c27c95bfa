//! The model's files and band: open, save, the band edit, and the
//! export a tab offered (written atomically).

use super::App;
use crate::tui::component::Change;
use crate::view::format::num;
use biodyn::{Band, Body, Param, Preset, body};
use std::path::{Path, PathBuf};

impl App {
    /// Replaces the model by a loaded preset; undo brings the old one back.
    pub fn load(&mut self, p: Preset, path: Option<PathBuf>) {
        let before = self.snapshot();
        self.shared.body = p.body.clone();
        self.shared.saved = p.body.clone();
        self.shared.saved_description = p.description.clone();
        self.shared.preset = p;
        self.shared.path = path;
        self.saved_band = self.shared.preset.band;
        let label = self.shared.file_label();
        self.push_load_undo(before, format!("open {label}"));
        self.refresh(Change::Loaded);
        self.say(format!("opened {label} (u brings the last model back)"));
    }

    /// Saves atomically; on success the file becomes the loaded one.
    pub fn save_to(&mut self, path: &Path) -> Result<(), String> {
        let shown = path.display().to_string();
        let own = self.shared.path.clone();
        let guard = crate::tui::paths::guard(&self.shared, own.as_deref());
        if let Some(why) = crate::tui::paths::save_refusal(&shown, path, "my-body.toml", &guard) {
            return Err(why);
        }
        let s = &mut self.shared;
        let mut p = s.preset.clone();
        p.body = s.body.clone();
        // A description the user wrote is saved as written.
        if p.description == s.saved_description {
            p.description = fresh_description(&p.description, &s.saved, &s.body);
        }
        p.save_guarded(path, &guard).map_err(|e| e.to_string())?;
        s.preset = p;
        s.saved = s.body.clone();
        s.saved_description = s.preset.description.clone();
        s.path = Some(path.to_path_buf());
        self.saved_band = s.preset.band;
        self.say(format!("saved {}", path.display()));
        Ok(())
    }

    pub fn default_save_path(&self) -> String {
        match &self.shared.path {
            Some(p) => p.display().to_string(),
            None => format!("{}.toml", self.shared.preset.name),
        }
    }

    /// Sets the band (checked by the library: `Band::new`, and the sweep's
    /// work for this model); undoable; every tab recomputes.
    pub fn set_band(&mut self, from: f64, to: f64, step: f64) -> Result<(), String> {
        let band = Band::new(from, to, step).map_err(|e| e.to_string())?;
        band.check_work(self.shared.body.n())
            .map_err(|e| e.to_string())?;
        let old = self.shared.preset.band;
        if band == old {
            self.say("band unchanged");
            return Ok(());
        }
        let what = format!("band {} → {}", band_text(&old), band_text(&band));
        let before = self.snapshot();
        self.shared.preset.band = band;
        self.say(format!("{what} ({} points)", band.len()));
        self.push_undo(before, what);
        self.refresh(Change::Edited);
        Ok(())
    }

    /// Writes the pending export to `path` in the format its extension
    /// names, atomically (temp file in the same folder, then rename).
    pub fn write_export(&mut self, path: &Path) -> Result<(), String> {
        let Some(x) = &self.export else {
            return Err("nothing to export".into());
        };
        let f = x.pick(path)?;
        if path.is_dir() {
            return Err(format!("{} is a folder: add a file name", path.display()));
        }
        if path.exists() && !path.is_file() {
            return Err(format!(
                "{} is not a regular file (a device or pipe): choose another path",
                path.display()
            ));
        }
        let guard = crate::tui::paths::guard(&self.shared, None);
        biodyn::io::save_guarded(path, &guard, f.contents.as_bytes()).map_err(|e| e.to_string())?;
        let text = format!("exported {} ({}) to {}", x.what, f.what, path.display());
        self.export = None;
        self.say(text);
        Ok(())
    }
}

/// "0.5–20 Hz step 0.1", as the band field and undo name it.
pub fn band_text(b: &Band) -> String {
    format!("{}–{} Hz step {}", b.from, b.to, b.step)
}

/// The description as it reads for the edited body: a body mass it
/// quotes ("x 75 kg") follows the new one; other edits are noted once.
pub fn fresh_description(desc: &str, saved: &Body, body: &Body) -> String {
    if saved == body || desc.is_empty() {
        return desc.to_string();
    }
    let (old, new) = (saved.get(Param::BodyMass), body.get(Param::BodyMass));
    let mut out = desc.to_string();
    if old != new {
        for sig in (1..=6).rev() {
            let quoted = format!("{} kg", num(old, sig));
            if num(old, sig).parse::<f64>().ok() == Some(old) && out.contains(&quoted) {
                out = out.replace(&quoted, &format!("{} kg", num(new, 6)));
                break;
            }
        }
    }
    // An edit other than the body mass: the description no longer tells all.
    let mut rescaled = saved.clone();
    let only_mass = rescaled.set(Param::BodyMass, new).is_ok() && rescaled == *body;
    const NOTE: &str = " (edited in biodyn)";
    if !only_mass && !out.ends_with(NOTE) {
        out.push_str(NOTE);
    }
    out
}

/// Opens a preset file or built-in name; the path when it is a file.
pub fn open_preset(arg: &str) -> Result<(Preset, Option<PathBuf>), body::PresetError> {
    let expanded = crate::tui::paths::expand(arg);
    let arg = if arg.trim_start().starts_with('~') {
        expanded.to_string_lossy().into_owned()
    } else {
        arg.to_string()
    };
    let p = Preset::open(&arg)?;
    let path = Path::new(&arg).is_file().then(|| PathBuf::from(&arg));
    Ok((p, path))
}
