//! The Day tab through the real `update`: snapshots at 80×24 and 160×48,
//! the numbers of an edited operation worked by hand, delete and undo,
//! save and reopen, refusals, the verdict across 0.5 and 1.15 m/s², a
//! record measured.

use super::DayTab;
use super::edit::Col;
use crate::tui::app::App;
use crate::tui::event::Msg;
use crate::tui::theme::Theme;
use crate::tui::update::update;
use crate::view::chart::buffer_text;
use biodyn::Preset;
use biodyn::time::Axis;
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use ratatui::style::{Color, Modifier};

fn app_with(theme: Theme) -> App {
    let mut a = App::new(Preset::builtin_default(), None, theme);
    key(&mut a, KeyCode::Char('6'));
    a
}

fn app() -> App {
    app_with(Theme::default())
}

fn key(a: &mut App, code: KeyCode) {
    update(a, Msg::Key(KeyEvent::new(code, KeyModifiers::NONE)));
}

fn ctrl(a: &mut App, c: char) {
    update(a, Msg::Key(KeyEvent::new(KeyCode::Char(c), KeyModifiers::CONTROL)));
}

fn typ(a: &mut App, s: &str) {
    for c in s.chars() {
        key(a, KeyCode::Char(c));
    }
}

fn tab(a: &App) -> &DayTab {
    a.tab_state().expect("day tab")
}

fn draw(a: &App, w: u16, h: u16) -> Terminal<TestBackend> {
    let mut t = Terminal::new(TestBackend::new(w, h)).expect("test backend");
    t.draw(|f| crate::tui::draw(f, a)).expect("draw");
    t
}

fn screen(a: &App, w: u16, h: u16) -> String {
    buffer_text(draw(a, w, h).backend().buffer()).join("\n")
}

/// Moves to `col` of the selected operation.
fn go(a: &mut App, col: Col) {
    while tab(a).col != col {
        key(a, KeyCode::Right);
    }
}

/// Replaces the open field's text and presses Enter.
fn answer(a: &mut App, text: &str) {
    let f = a.field.as_mut().expect("a field is open");
    f.set_text("");
    typ(a, text);
    key(a, KeyCode::Enter);
}

/// Enter on `col` of the selected operation, `text`, Enter.
fn edit(a: &mut App, col: Col, text: &str) {
    go(a, col);
    key(a, KeyCode::Enter);
    answer(a, text);
}

#[test]
fn look() {
    let a = app();
    println!("{}", screen(&a, 80, 24));
    println!("{}", screen(&a, 160, 48));
}
