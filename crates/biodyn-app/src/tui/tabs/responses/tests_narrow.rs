//! The cursor across band changes, and the lines that must stay readable
//! at narrow widths (the compare peak line, the copied CSV line).

use super::{ResponsesTab, view};
use crate::tui::app::App;
use crate::tui::event::Msg;
use crate::tui::tests::{app, key, screen, typ};
use crate::tui::update::update;
use ratatui::crossterm::event::KeyCode;

fn tab(a: &App) -> &ResponsesTab {
    a.tab_state().expect("responses tab")
}

fn on_tab(w: u16, h: u16) -> App {
    let mut a = app();
    update(&mut a, Msg::Resize(w, h));
    key(&mut a, KeyCode::Char('2'));
    a
}

/// The cursor's frequency as the readout reads it.
fn cursor_hz(a: &App) -> f64 {
    view::at_cursor(tab(a), &a.shared).expect("a cursor").f_hz
}

fn band(a: &mut App, text: &str) {
    key(a, KeyCode::Char('b'));
    typ(a, text);
    key(a, KeyCode::Enter);
    assert!(a.field.is_none(), "band {text} refused");
}

#[test]
fn a_new_band_keeps_the_cursor_frequency_not_its_index() {
    let mut a = on_tab(80, 24);
    let f0 = cursor_hz(&a);
    assert!((f0 - 4.6).abs() < 1e-9, "starts on the STHT peak: {f0}");
    band(&mut a, "2 12 0.05");
    assert!((cursor_hz(&a) - 4.6).abs() < 1e-9, "{}", cursor_hz(&a));
    assert!(screen(&a, 80, 24).contains("f 4.6 Hz"));
    // A grid without 4.6: the nearest point of the new grid.
    band(&mut a, "0.5 20 0.25");
    assert!((cursor_hz(&a) - 4.5).abs() < 1e-9, "{}", cursor_hz(&a));
    // A band that ends below the cursor: clamped to its end.
    band(&mut a, "5 10 0.1");
    assert!((cursor_hz(&a) - 5.0).abs() < 1e-9, "{}", cursor_hz(&a));
    // Undo walks the band back; the cursor stays at 5 Hz.
    key(&mut a, KeyCode::Char('u'));
    assert!((cursor_hz(&a) - 5.0).abs() < 1e-9, "{}", cursor_hz(&a));
}

#[test]
fn an_exact_cursor_inside_the_new_band_stays_exact() {
    let mut a = on_tab(80, 24);
    key(&mut a, KeyCode::Char('g'));
    let f = a.field.as_mut().expect("go-to field");
    f.set_text("6.123");
    key(&mut a, KeyCode::Enter);
    band(&mut a, "2 12 0.05");
    assert!((cursor_hz(&a) - 6.123).abs() < 1e-12, "{}", cursor_hz(&a));
    assert!(screen(&a, 80, 24).contains("f 6.123 Hz"));
    // Outside the new band: the nearest grid point, clamped in.
    band(&mut a, "0.5 5 0.1");
    assert!((cursor_hz(&a) - 5.0).abs() < 1e-9, "{}", cursor_hz(&a));
    // A step moves from there along the grid.
    key(&mut a, KeyCode::Left);
    assert!((cursor_hz(&a) - 4.9).abs() < 1e-9, "{}", cursor_hz(&a));
}
