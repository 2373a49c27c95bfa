//! `update`: the only way in for messages. A key goes to the open dialog
//! or field, else to the current tab (whose effects `App::apply` carries
//! out), else to the app's own table, else to the tab digits.

use super::app::{App, band_text, open_preset};
use super::component::{Cx, Mouse, MouseKind};
use super::dialog::{ConfirmKind, HelpView, OpenDialog, Overlay};
use super::event::Msg;
use super::field::{Field, Purpose};
use super::keys::{self, Action};
use super::paths;
use biodyn::Param;
use ratatui::crossterm::event::{
    KeyCode, KeyEvent, KeyModifiers, MouseButton, MouseEvent, MouseEventKind,
};
use ratatui::layout::Rect;
use std::time::{Duration, Instant};

/// The one place the state changes.
pub fn update(app: &mut App, msg: Msg) {
    match msg {
        Msg::Key(k) => on_key(app, k),
        Msg::Resize(w, h) => app.size = Some((w, h)),
        Msg::Mouse(m) => on_mouse(app, m),
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
    // Nothing the user cannot see acts: while "terminal too small" shows,
    // only q (when nothing would be lost) leaves.
    if app.too_small() {
        if keys::lookup(keys::GLOBAL, &ev) == Some(Action::Quit) && app.quit_reasons().is_empty() {
            app.quit = true;
        }
        return;
    }
    match std::mem::replace(&mut app.overlay, Overlay::None) {
        Overlay::Confirm(kind, dialog) => on_confirm(app, kind, dialog, &ev),
        Overlay::Help(h) => on_help(app, h, &ev),
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
    match (keys::lookup(app.confirm_keys(kind), ev), kind) {
        (Some(Action::Yes), ConfirmKind::Quit) => {
            app.shutdown();
            app.quit = true;
        }
        (Some(Action::SaveAndQuit), ConfirmKind::Quit) if app.modified() => {
            let path = app.default_save_path();
            app.field = Some(Field::new(
                Purpose::SaveAndQuit,
                "save preset, then quit, to",
                path,
            ));
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
        // The page starts with the current tab's own section.
        Some(Action::Help) => app.overlay = Overlay::Help(HelpView::default()),
        Some(Action::NextTab) => app.go_to_tab((i + 1) % n),
        Some(Action::PrevTab) => app.go_to_tab((i + n - 1) % n),
        Some(Action::Zoom) if app.zoom => app.zoom = false,
        Some(Action::Zoom) if app.tabs[i].has_chart(&app.shared) => {
            app.zoom = true;
            app.say("zoomed: z or Esc goes back");
        }
        Some(Action::Zoom) => app.fail("this tab has no chart to zoom"),
        Some(Action::Open) => {
            app.overlay = Overlay::Open(OpenDialog::new(app.shared.path.as_ref()))
        }
        Some(Action::Save) => {
            let path = app.default_save_path();
            app.field = Some(Field::new(Purpose::SavePath, "save preset to", path));
        }
        Some(Action::Band) => {
            let b = app.shared.preset.band;
            let text = format!("{} {} {}", b.from, b.to, b.step);
            app.field = Some(Field::new(
                Purpose::Band,
                format!("band: from to step, Hz (now {})", band_text(&b)),
                text,
            ));
        }
        Some(Action::Mouse) => toggle_mouse(app),
        Some(Action::Undo) => app.undo(),
        Some(Action::Redo) => app.redo(),
        Some(_) => {}
        None => {
            if let Some(t) = keys::tab_of(ev, n) {
                app.go_to_tab(t);
            } else if app.zoom && ev.code == KeyCode::Esc {
                app.zoom = false;
            }
        }
    }
}

fn on_field_key(app: &mut App, ev: &KeyEvent) {
    match keys::lookup(keys::FIELD, ev) {
        Some(Action::Commit) => commit_field(app),
        Some(Action::Cancel) => {
            app.field = None;
            app.export = None;
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
    } else if let Some(why) = paths::save_refusal(t, path, "my-body.toml") {
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
    if let Some(why) = paths::save_refusal(t, path, "export.csv") {
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

/// "from to step" in Hz; spaces, commas, colons or semicolons between.
pub fn parse_band(text: &str) -> Result<(f64, f64, f64), String> {
    let parts: Vec<&str> = text
        .split(|c: char| c.is_whitespace() || matches!(c, ',' | ':' | ';'))
        .filter(|p| !p.is_empty())
        .collect();
    let [from, to, step] = parts.as_slice() else {
        return Err(format!(
            "give three numbers, from to step in Hz, e.g. 0.5 20 0.1 (got {})",
            parts.len()
        ));
    };
    let num = |name: &str, t: &str| -> Result<f64, String> {
        t.parse::<f64>()
            .map_err(|_| format!("{name} '{t}' is not a number (write e.g. 0.5 20 0.1)"))
    };
    Ok((num("from", from)?, num("to", to)?, num("step", step)?))
}

fn band_from_field(app: &mut App, text: &str) -> Result<(), String> {
    let (from, to, step) = parse_band(text)?;
    app.set_band(from, to, step)
}

/// A press or wheel step with mouse capture on: the tab bar opens a tab,
/// the wheel scrolls the help page, the rest goes to the current tab.
fn on_mouse(app: &mut App, m: MouseEvent) {
    let Some((w, h)) = app.size else {
        return;
    };
    // With capture off (M) the mouse belongs to the terminal's selection.
    if app.too_small() || !app.mouse {
        return;
    }
    let kind = match m.kind {
        MouseEventKind::Down(MouseButton::Left) => {
            let now = Instant::now();
            let double = app.last_click.is_some_and(|(t, c, r)| {
                (c, r) == (m.column, m.row)
                    && now.saturating_duration_since(t) < Duration::from_millis(500)
            });
            app.last_click = (!double).then_some((now, m.column, m.row));
            if double {
                MouseKind::DoubleClick
            } else {
                MouseKind::Click
            }
        }
        MouseEventKind::ScrollUp => MouseKind::WheelUp,
        MouseEventKind::ScrollDown => MouseKind::WheelDown,
        _ => return,
    };
    // A wheel step is three arrow presses in the help page or open dialog.
    let wheel = |app: &mut App| {
        let code = if kind == MouseKind::WheelUp {
            KeyCode::Up
        } else {
            KeyCode::Down
        };
        for _ in 0..3 {
            on_key(app, KeyEvent::new(code, KeyModifiers::NONE));
        }
    };
    match (&app.overlay, kind) {
        (Overlay::Help(_) | Overlay::Open(_), MouseKind::WheelUp | MouseKind::WheelDown) => {
            return wheel(app);
        }
        (Overlay::None, _) if app.field.is_none() => {}
        _ => return,
    }
    if m.row == 0 {
        if matches!(kind, MouseKind::Click | MouseKind::DoubleClick)
            && let Some(i) = app.tab_at(w, m.column)
        {
            app.go_to_tab(i);
        }
        return;
    }
    let body = Rect::new(0, 1, w, h.saturating_sub(3));
    if m.row >= body.bottom() {
        return;
    }
    let i = app.current.min(app.tabs.len() - 1);
    let cx = Cx {
        shared: &app.shared,
        mailbox: app.mailbox(i),
    };
    let ev = Mouse {
        kind,
        column: m.column,
        row: m.row,
        zoomed: app.zoom,
    };
    let effects = app.tabs[i].on_mouse(ev, body, &cx);
    app.apply(effects);
}

/// `M`: the mouse on or off, said in one line that fits 80 columns.
fn toggle_mouse(app: &mut App) {
    app.mouse = !app.mouse;
    app.say(if app.mouse {
        "mouse on: click tabs, values, charts; the wheel scrolls; M turns it off"
    } else {
        "mouse off: the terminal selects text to copy; M turns the mouse on"
    });
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

/// The `?` page: scrolling, paging and `/` search. Its length and page
/// come from the lines and the terminal's height.
fn on_help(app: &mut App, mut h: HelpView, ev: &KeyEvent) {
    // The rows as `render_help` lays them out (long entries wrap): a
    // search finds an entry's first row.
    let (cols, rows) = app.size.unwrap_or((80, 24));
    let help = super::frame::help_lines(app);
    let inner_w = usize::from(cols.min(super::frame::HELP_W).saturating_sub(2));
    let lines: Vec<String> = keys::help_rows(&help, inner_w)
        .iter()
        .map(|r| match (&r.keys, r.heading) {
            (Some(_), _) | (_, true) => help.get(r.entry).map(|l| l.text()).unwrap_or_default(),
            _ => String::new(),
        })
        .collect();
    // The page's inner height: the body less the popup's frame.
    let inner_h = usize::from(rows.saturating_sub(5)).max(1);
    let page = inner_h.saturating_sub(1).max(1);
    let last = lines.len().saturating_sub(inner_h);
    if h.typing {
        match ev.code {
            KeyCode::Esc => {
                h.typing = false;
                h.query.clear();
            }
            KeyCode::Enter => h.typing = false,
            KeyCode::Backspace => {
                h.query.pop();
            }
            KeyCode::Char(c)
                if !ev
                    .modifiers
                    .intersects(KeyModifiers::CONTROL | KeyModifiers::ALT) =>
            {
                h.query.push(c);
                if let Some(i) = h.find(&lines, h.scroll) {
                    h.scroll = i;
                }
            }
            _ => {}
        }
        app.overlay = Overlay::Help(h);
        return;
    }
    match keys::lookup(keys::HELP, ev) {
        Some(Action::Up) => h.scroll = h.scroll.saturating_sub(1),
        Some(Action::Down) => h.scroll += 1,
        Some(Action::PageUp) => h.scroll = h.scroll.saturating_sub(page),
        Some(Action::PageDown) => h.scroll += page,
        Some(Action::Home) => h.scroll = 0,
        Some(Action::End) => h.scroll = last,
        Some(Action::Search) => {
            h.typing = true;
            h.query.clear();
        }
        Some(Action::NextMatch) => match h.find(&lines, h.scroll + 1) {
            Some(i) => h.scroll = i,
            None if h.query.is_empty() => app.fail("/ starts a search"),
            None => app.fail(format!("'{}' not found in the key help", h.query)),
        },
        Some(Action::Mouse) => toggle_mouse(app),
        Some(Action::Cancel) if !h.query.is_empty() => h.query.clear(),
        Some(Action::Cancel) => return,
        _ => {}
    }
    h.scroll = h.scroll.min(last);
    app.overlay = Overlay::Help(h);
}
