//! ASCII mode names the keys a prompt means: an arrow there would become
//! `<` `>` `^` `v` (keys of their own, e.g. `<` `>` scroll the Vibration
//! traces), so every text that names arrow keys spells them out, one
//! function (`keys::arrows`) for all. Decorations that are no key (a
//! selector's `< value >`) stay.

use super::*;
use crate::tui::theme::Theme;

fn ascii_app() -> App {
    App::new(
        Preset::builtin_default(),
        None,
        Theme {
            mono: true,
            ascii: true,
        },
    )
}

#[test]
fn open_dialog_asks_to_pick_with_up_down() {
    let mut a = ascii_app();
    ctrl(&mut a, 'o');
    if let Some(f) = a.field.as_mut() {
        f.set_text(String::new());
    }
    key(&mut a, KeyCode::Enter);
    let s = screen(&a, 100, 30);
    assert!(s.contains("pick a preset with Up/Down"), "{s}");
    assert!(!s.contains("with ^v"), "{s}");
}

#[test]
fn training_rows_say_left_right_picks() {
    let mut a = ascii_app();
    key(&mut a, KeyCode::Char('4'));
    key(&mut a, KeyCode::Right); // case row: the next case
    assert!(
        a.status
            .text
            .contains("(Left/Right: the network the next run trains)"),
        "{}",
        a.status.text
    );
    key(&mut a, KeyCode::Down); // trainer row
    assert!(
        a.status.text.contains("(Left/Right: backprop"),
        "{}",
        a.status.text
    );
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.status.text, "Left/Right picks this one");
    let s = screen(&a, 100, 30);
    assert!(s.contains("Left/Right picks this one"), "{s}");
    assert!(!s.contains("</>"), "{s}");
}

#[test]
fn vibration_kind_is_left_right_not_the_scroll_keys() {
    let mut a = ascii_app();
    key(&mut a, KeyCode::Char('5'));
    let s = screen(&a, 100, 30);
    // Too long for the panel with its name: the keys stay, whole.
    assert!(s.contains(" Left/Right kind, Enter edit "), "{s}");
    assert!(!s.contains("<> kind"), "{s}");
    let s = screen(&a, 160, 48);
    assert!(s.contains(" signal (Left/Right kind, Enter edit) "), "{s}");
    // The selector's brackets are no key name: they stay.
    assert!(s.contains("< sine >"), "{s}");
    key(&mut a, KeyCode::Enter); // on the kind row
    assert_eq!(
        a.status.text,
        "Left/Right pick the signal kind; Enter on a row below edits it"
    );
    key(&mut a, KeyCode::Left); // sine → file, no path yet
    let s = screen(&a, 100, 30);
    let flat: String = s.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(flat.contains("no file yet: Down to 'file'"), "{s}");
    assert!(
        flat.contains("Up/Down pick a setting and Enter edits it; Left/Right picks"),
        "{s}"
    );
    assert!(!flat.contains("v to 'file'"), "{s}");
}
