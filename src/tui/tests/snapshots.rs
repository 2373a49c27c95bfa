//! Every tab and every dialog at 80×24 and 160×48, rendered through
//! TestBackend and compared with the committed snapshots in
//! `tests/snapshots/` (insta). A layout change shows up as a readable diff;
//! review it with `cargo insta review`, or run with INSTA_UPDATE=always and
//! read the `.snap` diff in git. CI (CI=true) never writes new snapshots.

use super::*;
use crate::tui::popups::Overlay;
use crate::tui::popups::open::OpenDialog;

const SIZES: [(u16, u16); 2] = [(80, 24), (160, 48)];

/// Snapshots `a` at both sizes as `<name>_<w>x<h>`.
fn snap(name: &str, a: &App) {
    for (w, h) in SIZES {
        insta::assert_snapshot!(format!("{name}_{w}x{h}"), screen(a, w, h));
    }
}

#[test]
fn every_tab() {
    let mut a = app();
    for i in 0..a.tabs.len() {
        key(&mut a, KeyCode::Char(char::from(b'1' + i as u8)));
        let name = a.tab().title().to_lowercase();
        snap(&format!("tab_{name}"), &a);
    }
}

#[test]
fn tabs_in_their_other_modes() {
    let mut a = app();
    key(&mut a, KeyCode::Char('2'));
    key(&mut a, KeyCode::Char('p'));
    key(&mut a, KeyCode::Char('a'));
    snap("responses_phase_log", &a);
    key(&mut a, KeyCode::Char('3'));
    key(&mut a, KeyCode::Char('k'));
    key(&mut a, KeyCode::Char('f'));
    snap("study_k4_dpmi", &a);
    key(&mut a, KeyCode::Char('4'));
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Left); // backprop: its own settings
    snap("training_backprop", &a);
}

#[test]
fn the_help_page() {
    let mut a = app();
    key(&mut a, KeyCode::Char('?'));
    snap("dialog_help", &a);
    for _ in 0..30 {
        key(&mut a, KeyCode::Down);
    }
    snap("dialog_help_scrolled", &a);
}

/// The open dialog lists a folder made here (four presets under presets/,
/// one preset and one other TOML file beside them), not whatever the
/// working folder holds when the tests run.
#[test]
fn the_open_dialog() {
    let dir = tempfile::tempdir().expect("temp dir");
    std::fs::create_dir(dir.path().join("presets")).expect("presets/");
    for name in [
        "boileau-rakheja-1998",
        "paper-65kg",
        "paper-75kg",
        "paper-85kg",
    ] {
        let text = Preset::builtin(name)
            .and_then(Result::ok)
            .expect("built-in")
            .to_toml();
        std::fs::write(dir.path().join(format!("presets/{name}.toml")), text).expect("write");
    }
    std::fs::write(dir.path().join("notes.toml"), "title = 'not a preset'\n").expect("write");
    let mut a = app();
    ctrl(&mut a, 'o');
    assert!(
        matches!(a.overlay, Overlay::Open(_)),
        "Ctrl-O opens the dialog"
    );
    a.overlay = Overlay::Open(OpenDialog::in_folder(dir.path(), None));
    key(&mut a, KeyCode::Down);
    snap("dialog_open", &a);
    if let Overlay::Open(d) = &mut a.overlay {
        d.field.set_text("/nonexistent/preset.toml");
    }
    key(&mut a, KeyCode::Enter);
    snap("dialog_open_refused", &a);
}

#[test]
fn the_confirmations() {
    let mut a = app();
    key(&mut a, KeyCode::Char('+'));
    key(&mut a, KeyCode::Char('q'));
    snap("dialog_confirm_quit", &a);
    key(&mut a, KeyCode::Char('n'));
    ctrl(&mut a, 'o');
    if let Overlay::Open(d) = &mut a.overlay {
        d.field.set_text("paper-65kg");
    }
    key(&mut a, KeyCode::Enter);
    snap("dialog_confirm_discard", &a);
}

#[test]
fn the_text_fields() {
    let mut a = app();
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Enter);
    snap("field_param", &a);
    for _ in 0..10 {
        key(&mut a, KeyCode::Backspace);
    }
    typ(&mut a, "-3");
    key(&mut a, KeyCode::Enter);
    snap("field_param_refused", &a);
    key(&mut a, KeyCode::Esc);
    ctrl(&mut a, 's');
    snap("field_save_preset", &a);
    key(&mut a, KeyCode::Esc);
    key(&mut a, KeyCode::Char('3'));
    key(&mut a, KeyCode::Enter);
    snap("field_study_values", &a);
    key(&mut a, KeyCode::Esc);
    key(&mut a, KeyCode::Char('4'));
    for _ in 0..3 {
        key(&mut a, KeyCode::Down); // layers
    }
    key(&mut a, KeyCode::Enter);
    snap("field_training_setting", &a);
}

#[test]
fn the_small_terminal_and_no_colour_ascii() {
    let a = app();
    insta::assert_snapshot!("too_small_40x10", screen(&a, 40, 10));
    let mut b = App::new(
        Preset::builtin_default(),
        None,
        Theme {
            mono: true,
            ascii: true,
        },
    );
    key(&mut b, KeyCode::Char('2'));
    snap("ascii_responses", &b);
}

/// Snapshots `a` at both sizes, told each size first (`Msg::Resize`).
fn snap_resized(name: &str, a: &mut App) {
    for (w, h) in [(80, 24), (160, 48)] {
        update(a, Msg::Resize(w, h));
        insta::assert_snapshot!(format!("{name}_{w}x{h}"), screen(a, w, h));
    }
}

#[test]
fn export_band_and_mouse_screens() {
    let mut a = app();
    key(&mut a, KeyCode::Char('3'));
    key(&mut a, KeyCode::Char('k'));
    key(&mut a, KeyCode::Char('x'));
    snap_resized("field_export_study", &mut a);
    typ(&mut a, "k4.xlsx");
    key(&mut a, KeyCode::Enter);
    snap_resized("field_export_refused", &mut a);
    key(&mut a, KeyCode::Esc);
    key(&mut a, KeyCode::Char('b'));
    snap_resized("field_band", &mut a);
    typ(&mut a, "1 20000 0.001");
    key(&mut a, KeyCode::Enter);
    snap_resized("field_band_refused", &mut a);
    key(&mut a, KeyCode::Esc);
    key(&mut a, KeyCode::Char('b'));
    typ(&mut a, "2 12 0.25");
    key(&mut a, KeyCode::Enter);
    key(&mut a, KeyCode::Char('M'));
    snap_resized("study_band_mouse_on", &mut a);
}
