//! The Training tab obeys the library's size limits (`ann::bounds`): a
//! setting past what fits is refused with the reason, and the settings are
//! left as they were.

use super::training_runs::go_to_named;
use super::*;

/// Opens a setting, replaces its text and commits; returns the refusal.
fn refuse(a: &mut App, row: &str, text: &str) -> String {
    go_to_named(a, row);
    key(a, KeyCode::Enter);
    if let Some(f) = a.field.as_mut() {
        f.set_text(text);
    }
    key(a, KeyCode::Enter);
    let e = field_error(a);
    assert!(!e.is_empty(), "{row} = {text} was taken");
    let s = screen(a, 160, 48).replace('\n', " ");
    let shown: Vec<&str> = s.split_whitespace().collect();
    let all = e
        .split_whitespace()
        .all(|w| shown.iter().any(|x| x.contains(w)));
    assert!(all, "the reason is not on screen whole: {e}\n{s}");
    key(a, KeyCode::Esc);
    e
}

#[test]
fn sizes_past_what_fits_are_refused_with_the_reason() {
    let mut a = app();
    key(&mut a, KeyCode::Char('4'));
    let before = training(&a).settings.clone();
    let e = refuse(&mut a, "ensemble size", "1000000");
    assert!(
        e.contains("ensemble = 1000000: at most 1000 networks"),
        "{e}"
    );
    // The default case (mass-stht) has five inputs.
    let e = refuse(&mut a, "layers", "5-10000-1");
    assert!(
        e.contains("70001 weights") && e.contains("at most 2000"),
        "{e}"
    );
    assert_eq!(training(&a).settings, before);
    // Zero keeps its range words.
    let e = refuse(&mut a, "ensemble size", "0");
    assert!(e.contains("a whole number from 1 to 1000"), "{e}");
}
