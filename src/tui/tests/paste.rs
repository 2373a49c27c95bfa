//! A paste is text, never keys (issue 19 item 4): with bracketed paste on,
//! the terminal sends a paste as one event (`Msg::Paste`); it goes into the
//! open field, and is ignored with a note where no field is open.

use super::{app, key};
use crate::tui::event::Msg;
use crate::tui::popups::field::MAX_PASTE;
use crate::tui::update::update;
use ratatui::crossterm::event::KeyCode;

fn paste(a: &mut crate::tui::app::App, text: &str) {
    update(a, Msg::Paste(text.to_string()));
}

#[test]
fn a_paste_with_control_characters_and_newlines_is_text_for_the_field() {
    let mut a = app();
    let segments = a.shared.body.n();
    key(&mut a, KeyCode::Char('+'));
    assert!(a.modified());
    key(&mut a, KeyCode::Enter);
    let f = a.field.as_mut().expect("Enter opens m1's field");
    f.set_text("");
    // ^C inside a paste does not quit; a newline does not commit, and the
    // letters after it (`d` deletes a segment, `q` quits) do not run.
    paste(&mut a, "garbage\u{3}more\nd q\u{1b}[A\tx\n");
    assert!(!a.quit, "a pasted ^C must not quit");
    let f = a.field.as_ref().expect("the field stays open");
    assert_eq!(f.text, "garbagemore d q[A x");
    assert_eq!(a.shared.body.n(), segments, "no segment deleted");
    assert!(a.modified(), "the unsaved edit is kept");
}

#[test]
fn a_paste_with_no_field_open_is_ignored_with_a_note() {
    let mut a = app();
    let segments = a.shared.body.n();
    key(&mut a, KeyCode::Char('+'));
    let body = a.shared.body.clone();
    paste(&mut a, "dddq\n");
    assert!(!a.quit);
    assert!(a.field.is_none());
    assert_eq!(a.shared.body, body, "nothing pasted acted as a key");
    assert_eq!(a.shared.body.n(), segments);
    assert!(a.status.text.contains("paste ignored"), "{}", a.status.text);
}

#[test]
fn an_overlong_paste_is_refused_whole_with_its_reason_in_the_field() {
    let mut a = app();
    key(&mut a, KeyCode::Enter);
    let before = a.field.as_ref().expect("field").text.clone();
    paste(&mut a, &"7".repeat(MAX_PASTE + 1));
    let f = a.field.as_ref().expect("field");
    assert_eq!(f.text, before);
    let e = f.error.clone().unwrap_or_default();
    assert!(e.contains("paste of 4097 characters refused"), "{e}");
    // One that fits goes in.
    paste(&mut a, &"7".repeat(3));
    assert!(a.field.as_ref().expect("field").text.ends_with("777"));
}

/// A refusal under a field whose text is taller than the screen (4086
/// characters pasted, then 4097 more) stays in view, at the popup's foot,
/// and the text scrolls to the cursor's row (issue 19 item 23: the
/// reason was off-screen).
#[test]
fn a_refusal_under_a_long_text_stays_on_screen() {
    let mut a = app();
    key(&mut a, KeyCode::Enter);
    paste(&mut a, &"7".repeat(MAX_PASTE - 10));
    paste(&mut a, &"7".repeat(MAX_PASTE + 1));
    for (w, h) in [(80u16, 24u16), (60, 16)] {
        let s = crate::tui::tests::screen(&a, w, h);
        let flat: String = s.split_whitespace().collect::<Vec<_>>().join(" ");
        assert!(
            flat.contains("refused: paste of 4097 characters refused"),
            "{w}x{h}\n{s}"
        );
        // the cursor's row (the text's last, not a full one) is shown
        let rows: Vec<&str> = s.lines().filter(|l| l.contains("7777")).collect();
        assert!(
            rows.iter()
                .any(|l| !l.contains(&"7".repeat(usize::from(w) - 8))),
            "{s}"
        );
    }
    // at the start of the text its first row is shown, the refusal still
    key(&mut a, KeyCode::Home);
    let s = crate::tui::tests::screen(&a, 80, 24);
    assert!(s.contains("refused: paste of 4097"), "{s}");
}
