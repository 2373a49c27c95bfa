//! `update`: the only way in for messages. A key goes to the open dialog
//! or field, else to the current tab (whose effects `App::apply` carries
//! out), else to the app's own table, else to the tab digits.

use super::app::{App, open_preset};
use super::component::Cx;
use super::dialog::{ConfirmKind, OpenDialog, Overlay};
use super::event::Msg;
use super::field::{Field, Purpose};
use super::keys::{self, Action};
use biodyn::Param;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use std::path::Path;

/// The one place the state changes.
pub fn update(app: &mut App, msg: Msg) {
    match msg {
        Msg::Key(k) => on_key(app, k),
        Msg::Resize(..) => {}
        Msg::Signal(_) => app.quit = true,
        Msg::Derived(g, part) => app.on_derived(g, part),
        Msg::Tab(i, m) => {
            let mailbox = app.mailbox(i);
            if let Some(t) = app.tabs.get_mut(i) {
                let cx = Cx {
                    shared: &app.shared,
                    mailbox,
                };
                let effects = t.on_msg(m, &cx);
                app.apply(effects);
            }
        }
    }
}

fn on_key(app: &mut App, ev: KeyEvent) {
    // Ctrl-C quits from anywhere, whatever is open.
    if ev.modifiers.contains(KeyModifiers::CONTROL)
        && matches!(ev.code, KeyCode::Char('c') | KeyCode::Char('C'))
    {
        app.shutdown();
        app.quit = true;
        return;
    }
    match std::mem::replace(&mut app.overlay, Overlay::None) {
        Overlay::Confirm(kind, dialog) => on_confirm(app, kind, dialog, &ev),
        Overlay::Help { scroll } => {
            app.overlay = match keys::lookup(keys::HELP, &ev) {
                Some(Action::Up) => Overlay::Help {
                    scroll: scroll.saturating_sub(1),
                },
                Some(Action::Down) => Overlay::Help {
                    scroll: scroll.saturating_add(1),
                },
                Some(Action::Cancel) => Overlay::None,
                _ => Overlay::Help { scroll },
            }
        }
        Overlay::Open(mut d) => match keys::lookup(keys::OPEN, &ev) {
            Some(Action::Cancel) => {}
            Some(Action::Up) => {
                d.step(true);
                app.overlay = Overlay::Open(d);
            }
            Some(Action::Down) => {
                d.step(false);
                app.overlay = Overlay::Open(d);
            }
            Some(Action::Commit) => open_from_dialog(app, d, false),
            _ => {
                edit_field(&mut d.field, &ev);
                app.overlay = Overlay::Open(d);
            }
        },
        Overlay::None => {
            if app.field.is_some() {
                on_field_key(app, &ev);
            } else {
                on_tab_key(app, &ev);
            }
        }
    }
}

fn on_confirm(app: &mut App, kind: ConfirmKind, dialog: Option<OpenDialog>, ev: &KeyEvent) {
    match (keys::lookup(keys::CONFIRM, ev), kind) {
        (Some(Action::Yes), ConfirmKind::Quit) => {
            app.shutdown();
            app.quit = true;
        }
        (Some(Action::Yes), ConfirmKind::Discard) => {
            if let Some(d) = dialog {
                open_from_dialog(app, d, true);
            }
        }
        (Some(Action::No), _) => {
            app.overlay = dialog.map_or(Overlay::None, Overlay::Open);
        }
        _ => app.overlay = Overlay::Confirm(kind, dialog),
    }
}

/// The current tab first, then the app's own keys, then the tab digits.
fn on_tab_key(app: &mut App, ev: &KeyEvent) {
    let i = app.current.min(app.tabs.len() - 1);
    let cx = Cx {
        shared: &app.shared,
        mailbox: app.mailbox(i),
    };
    if let Some(effects) = app.tabs[i].on_key(ev, &cx) {
        app.apply(effects);
        return;
    }
    let n = app.tabs.len();
    match keys::lookup(keys::GLOBAL, ev) {
        Some(Action::Quit) if app.quit_reasons().is_empty() => app.quit = true,
        Some(Action::Quit) => app.overlay = Overlay::Confirm(ConfirmKind::Quit, None),
        Some(Action::ForceQuit) => {
            app.shutdown();
            app.quit = true;
        }
        Some(Action::Help) => app.overlay = Overlay::Help { scroll: 0 },
        Some(Action::NextTab) => app.current = (i + 1) % n,
        Some(Action::PrevTab) => app.current = (i + n - 1) % n,
        Some(Action::Open) => {
            app.overlay = Overlay::Open(OpenDialog::new(app.shared.path.as_ref()))
        }
        Some(Action::Save) => {
            let path = app.default_save_path();
            app.field = Some(Field::new(Purpose::SavePath, "save preset to", path));
        }
        Some(Action::Undo) => app.undo(),
        Some(Action::Redo) => app.redo(),
        Some(_) => {}
        None => {
            if let Some(t) = keys::tab_of(ev, n) {
                app.current = t;
            }
        }
    }
}

fn on_field_key(app: &mut App, ev: &KeyEvent) {
    match keys::lookup(keys::FIELD, ev) {
        Some(Action::Commit) => commit_field(app),
        Some(Action::Cancel) => {
            app.field = None;
            app.say("cancelled; nothing changed");
        }
        _ => {
            if let Some(f) = app.field.as_mut() {
                edit_field(f, ev);
            }
        }
    }
}

/// Cursor moves and deletions from the field table; other characters type.
fn edit_field(f: &mut Field, ev: &KeyEvent) {
    match keys::lookup(keys::FIELD, ev) {
        Some(Action::Left) => f.left(),
        Some(Action::Right) => f.right(),
        Some(Action::Home) => f.home(),
        Some(Action::End) => f.end(),
        Some(Action::DeleteBack) => f.backspace(),
        Some(Action::DeleteFwd) => f.delete(),
        Some(Action::KillToStart) => f.kill_to_start(),
        Some(Action::KillToEnd) => f.kill_to_end(),
        Some(Action::KillWord) => f.kill_word(),
        Some(Action::KillWordPart) => f.kill_word_part(),
        Some(Action::Complete) if f.path => f.complete(),
        // A tab in another field is pasted text: a separator (a space,
        // which a terminal can draw).
        Some(Action::Complete) => f.insert(' '),
        Some(_) => {}
        None => {
            if let KeyCode::Char(c) = ev.code
                && !ev
                    .modifiers
                    .intersects(KeyModifiers::CONTROL | KeyModifiers::ALT)
            {
                f.insert(c);
            }
        }
    }
}

fn open_from_dialog(app: &mut App, mut d: OpenDialog, confirmed: bool) {
    let arg = d.field.text.trim().to_string();
    if arg.is_empty() {
        d.field.error = Some("give a path or pick a preset with ↑↓".into());
        app.overlay = Overlay::Open(d);
        return;
    }
    match open_preset(&arg) {
        Ok(_) if app.modified() && !confirmed => {
            app.overlay = Overlay::Confirm(ConfirmKind::Discard, Some(d));
        }
        Ok((p, path)) => app.load(p, path),
        Err(e) => {
            d.field.error = Some(e.to_string());
            app.overlay = Overlay::Open(d);
        }
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
        Purpose::OpenPath => Ok(()),
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
    let path = Path::new(t);
    let exists = format!("{t} exists: Enter again replaces it, or change the path");
    if t.is_empty() {
        Err("give a file path, e.g. presets/my-body.toml".into())
    } else if path.exists()
        && app.shared.path.as_deref() != Some(path)
        && f.error.as_deref() != Some(exists.as_str())
    {
        Err(exists)
    } else {
        app.save_to(path)
    }
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
