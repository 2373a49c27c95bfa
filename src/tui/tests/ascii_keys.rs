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

#[test]
fn training_chart_of_another_case_says_left_right() {
    let (tx, rx) = std::sync::mpsc::channel();
    let mut a = App::with_channel(
        Preset::builtin_default(),
        None,
        Theme {
            mono: true,
            ascii: true,
        },
        Some(tx),
    );
    key(&mut a, KeyCode::Char('4'));
    super::training_runs::set(&mut a, "epoch limit", "5");
    key(&mut a, KeyCode::Char('t'));
    super::training_runs::pump(&mut a, &rx, |a| !training(a).running());
    super::training_runs::go_to_named(&mut a, "case");
    key(&mut a, KeyCode::Right); // another case than the shown run's
    let s = screen(&a, 160, 48);
    let flat: String = s.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(flat.contains("Left/Right on the case row goes back"), "{s}");
    assert!(!flat.contains("</> on the case row"), "{s}");
}

/// Eleven variants: the legend scrolls with Up/Down, and the Study tab
/// says so without `^v` (its title), or not at all (a bare heading cell
/// of 9 columns); the readout line's "more" is a Down away.
#[test]
fn study_scroll_position_and_more_name_up_down() {
    let mut a = ascii_app();
    key(&mut a, KeyCode::Char('3'));
    key(&mut a, KeyCode::Enter);
    typ(&mut a, "50,55,60,65,70,75,80,85,90,95,100");
    key(&mut a, KeyCode::Enter);
    let s = screen(&a, 80, 24);
    assert!(s.contains("/11 Up/Down"), "{s}");
    let mut more = false;
    for (w, h) in [(60u16, 16u16), (70, 20), (80, 24), (100, 30)] {
        let s = screen(&a, w, h);
        assert!(!s.contains("^v") && !s.contains("v more"), "{w}x{h}\n{s}");
        more |= s.contains("Down more");
    }
    assert!(more, "no readout line cut with 'Down more'");
}

#[test]
fn fit_dialog_says_up_down_for_more() {
    let mut a = ascii_app();
    key(&mut a, KeyCode::Char('2'));
    key(&mut a, KeyCode::Char('D'));
    if let Some(f) = a.field.as_mut() {
        f.set_text("examples/synthetic-stht-apms-3pct-2deg.csv");
    }
    key(&mut a, KeyCode::Enter);
    key(&mut a, KeyCode::Char('F'));
    let s = screen(&a, 80, 20);
    assert!(s.contains("(Up/Down more)"), "{s}");
    assert!(!s.contains("(^v more)"), "{s}");
}
