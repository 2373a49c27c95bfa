//! `update`: the only way in for messages. A key goes to the open dialog
//! or field (whose acts `App::apply_acts` carries out), else to the
//! current tab (whose effects `App::apply` carries out), else to the app's
//! own table, else to the tab digits.

use super::app::{App, band_text};
use super::component::{Cx, Mouse, MouseKind};
use super::event::Msg;
use super::keys::{self, Action};
use super::popups::Overlay;
use super::popups::confirm::{Confirm, ConfirmKind};
use super::popups::field::{self, Field, Purpose};
use super::popups::help::HelpView;
use super::popups::open::OpenDialog;
use ratatui::crossterm::event::{
    KeyCode, KeyEvent, KeyModifiers, MouseButton, MouseEvent, MouseEventKind,
};
use std::time::{Duration, Instant};

/// The one place the state changes.
pub fn update(app: &mut App, msg: Msg) {
    match msg {
        Msg::Key(k) => on_key(app, k),
        Msg::Resize(w, h) => app.size = Some((w, h)),
        Msg::Mouse(m) => on_mouse(app, m),
        Msg::Signal(sig) => {
            app.quit = true;
            app.signal = Some(sig);
        }
        Msg::Paste(text) => on_paste(app, &text),
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
    app.refresh_inputs();
}

/// A paste is text for the open field; with no field open (a dialog, or
/// the tabs) it is ignored and the status line says so: its characters are
/// never keys (a pasted `d` deleted a segment, `^C` quit).
fn on_paste(app: &mut App, text: &str) {
    if app.too_small() {
        return;
    }
    match (app.overlay.popup(), app.field.as_mut()) {
        (None, Some(f)) => field::paste(f, text),
        _ => {
            app.say("paste ignored: no text field is open (Enter opens the selected value's field)")
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
    // The open dialog, else the open field, else the tab and the app.
    let view = app.popup_view();
    let mut overlay = std::mem::replace(&mut app.overlay, Overlay::None);
    let acts = match (overlay.popup_mut(), app.field.as_mut()) {
        (Some(p), _) => p.on_key(&ev, &view),
        (None, Some(f)) => field::on_key(f, &ev),
        (None, None) => return on_tab_key(app, &ev),
    };
    app.overlay = overlay;
    app.apply_acts(acts);
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
    let global = keys::lookup(keys::GLOBAL, ev);
    if let Some(a) = global
        && let Some(effects) = app.tabs[i].on_global(a, &cx)
    {
        app.apply(effects);
        return;
    }
    match global {
        Some(Action::Quit) if app.quit_reasons().is_empty() => app.quit = true,
        Some(Action::Quit) => app.overlay = Overlay::Confirm(Confirm::new(ConfirmKind::Quit, None)),
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
        Some(Action::Mouse) => app.toggle_mouse(),
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
    let scrolls = app.overlay.popup().is_some_and(|p| p.scrolls());
    match (&app.overlay, kind) {
        (_, MouseKind::WheelUp | MouseKind::WheelDown) if scrolls => return wheel(app),
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
    let body = app.body_area(w, h);
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
