//! A committed text field: what it was for decides what happens (a model
//! value, a save path, an export, the band, or back to the tab that
//! opened it). A refusal keeps the field open with the reason.

use super::App;
use crate::tui::component::Cx;
use crate::tui::input::parse_band;
use crate::tui::paths;
use crate::tui::popups::field::{Field, Purpose};
use biodyn::Param;

impl App {
    /// Enter in the open field.
    pub fn commit_field(&mut self) {
        commit_field(self);
    }
}

fn commit_field(app: &mut App) {
    let Some(mut f) = app.field.take() else {
        return;
    };
    let result = match f.purpose {
        Purpose::Param(_) if f.text.trim() == f.initial.trim() => {
            app.say("unchanged");
            Ok(())
        }
        Purpose::Param(p) => commit_param(app, p, &f.text),
        Purpose::SavePath => save_from_field(app, &f),
        Purpose::SaveAndQuit => save_from_field(app, &f).map(|()| {
            app.shutdown();
            app.quit = true;
        }),
        Purpose::OpenPath => Ok(()),
        Purpose::Export => export_from_field(app, &f),
        Purpose::Band => band_from_field(app, &f.text),
        Purpose::Tab(tag) => {
            let i = app.current.min(app.tabs.len() - 1);
            let cx = Cx {
                shared: &app.shared,
                mailbox: app.mailbox(i),
            };
            app.tabs[i]
                .commit(tag, &f.text, &cx)
                .map(|effects| app.apply(effects))
        }
    };
    if let Err(why) = result {
        f.error = Some(why);
        app.field = Some(f);
    }
}

/// Another file of that name is only replaced on a second Enter; any edit
/// of the path clears the error and asks again.
fn save_from_field(app: &mut App, f: &Field) -> Result<(), String> {
    let t = f.text.trim();
    let expanded = paths::expand(t);
    let path = expanded.as_path();
    let exists = format!("{t} exists: Enter again replaces it, or change the path");
    if t.is_empty() {
        Err("give a file path, e.g. presets/my-body.toml".into())
    } else if let Some(why) = paths::save_refusal(
        t,
        path,
        "my-body.toml",
        &paths::guard(&app.shared, app.shared.path.as_deref()),
    ) {
        Err(why)
    } else if path.exists()
        && app.shared.path.as_deref() != Some(path)
        && f.error.as_deref() != Some(exists.as_str())
    {
        Err(exists)
    } else {
        app.save_to(path)
    }
}

/// Writes the pending export; like preset save, an existing file is only
/// replaced on a second Enter.
fn export_from_field(app: &mut App, f: &Field) -> Result<(), String> {
    let t = f.text.trim();
    if t.is_empty() {
        return Err("give a file path, e.g. study.csv".into());
    }
    let expanded = paths::expand(t);
    let path = expanded.as_path();
    let exists = format!("{t} exists: Enter again replaces it, or change the path");
    if let Some(why) = paths::save_refusal(t, path, "export.csv", &paths::guard(&app.shared, None))
    {
        return Err(why);
    }
    if path.is_file() && f.error.as_deref() != Some(exists.as_str()) {
        // A wrong extension is said first, before asking to replace.
        if let Some(x) = &app.export {
            x.pick(path)?;
        }
        return Err(exists);
    }
    app.write_export(path)
}

fn band_from_field(app: &mut App, text: &str) -> Result<(), String> {
    let (from, to, step) = parse_band(text)?;
    app.set_band(from, to, step)
}

/// Parses and sets a model value; the reason on refusal.
fn commit_param(app: &mut App, p: Param, text: &str) -> Result<(), String> {
    let t = text.trim();
    let v: f64 = t
        .parse()
        .map_err(|_| format!("'{t}' is not a number (write e.g. 75 or 1.5e5)"))?;
    app.set_param(p, v)?;
    app.say_param(p);
    Ok(())
}
