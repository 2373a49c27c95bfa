//! The Seat tab: with and without a seat, at both sizes, in colour and
//! ASCII; its keys; its numbers against the library's.

use super::SeatTab;
use crate::tui::app::App;
use crate::tui::tests::{app, key, screen, typ};
use crate::tui::theme::Theme;
use biodyn::Preset;
use ratatui::crossterm::event::KeyCode;

pub fn seat_app(theme: Theme) -> App {
    let p = Preset::builtin("paper-75kg-suspension-seat")
        .and_then(Result::ok)
        .expect("the shipped seat preset");
    App::new(p, None, theme)
}

fn seat_tab(a: &App) -> &SeatTab {
    a.tab_state().expect("seat tab")
}

/// Opens the Seat tab (the last one).
fn open(a: &mut App) {
    let n = a.tabs.len();
    key(a, KeyCode::Char(char::from(b'0' + n as u8)));
    assert_eq!(a.tab().title(), "Seat");
}

#[test]
fn look() {
    let mut a = seat_app(Theme::default());
    open(&mut a);
    println!("{}", screen(&a, 80, 24));
    println!("{}", screen(&a, 160, 48));
    let mut a = seat_app(Theme { ascii: true, mono: false });
    open(&mut a);
    println!("{}", screen(&a, 80, 24));
    let mut a = app();
    open(&mut a);
    println!("{}", screen(&a, 80, 24));
    let _ = typ;
}

#[test]
fn look_model() {
    let mut a = seat_app(Theme::default());
    key(&mut a, KeyCode::Char('1'));
    println!("{}", screen(&a, 80, 24));
    println!("{}", screen(&a, 160, 48));
}
