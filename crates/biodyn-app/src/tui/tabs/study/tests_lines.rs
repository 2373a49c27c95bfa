//! What the Study tab says must stay true and whole at 80×24: the status
//! after the cursor moves, the cursor column in the legend with long
//! labels, and the messages for a list with nothing to compare.

use super::StudyTab;
use crate::tui::app::App;
use crate::tui::event::Msg;
use crate::tui::tests::{app, key, screen, typ};
use crate::tui::update::update;
use ratatui::crossterm::event::KeyCode;

fn tab(a: &App) -> &StudyTab {
    a.tab_state().expect("study tab")
}

fn on_tab(w: u16, h: u16) -> App {
    let mut a = app();
    update(&mut a, Msg::Resize(w, h));
    key(&mut a, KeyCode::Char('3'));
    a
}

fn ch(a: &mut App, c: char) {
    key(a, KeyCode::Char(c));
}

fn go_to(a: &mut App, f: &str) {
    ch(a, 'g');
    a.field.as_mut().expect("go-to field").set_text(f);
    key(a, KeyCode::Enter);
    assert!(a.field.is_none(), "go to {f} refused");
}

fn values(a: &mut App, v: &str) {
    key(a, KeyCode::Enter);
    a.field.as_mut().expect("values field").set_text(v);
    key(a, KeyCode::Enter);
}

#[test]
fn moving_the_cursor_replaces_the_go_to_message() {
    let mut a = on_tab(80, 24);
    ch(&mut a, 'k');
    go_to(&mut a, "5.8312");
    assert!(a.status.text.contains("5.8312"), "{}", a.status.text);
    ch(&mut a, '>');
    let f = tab(&a).cursor.f_hz.expect("a cursor");
    assert!((f - 5.9).abs() < 1e-9, "{f}");
    assert!(!a.status.text.contains("5.8312"), "stale: {}", a.status.text);
    assert!(a.status.text.contains("5.9 Hz"), "{}", a.status.text);
    let s = screen(&a, 80, 24);
    assert!(!s.contains("5.8312"), "{s}");
}
