//! Snapshots of the export and band fields and of the hint bar with the
//! mouse on, at 80×24 and 160×48 (behaviour: tests/tui_export_band_mouse.rs).

use super::*;

fn snap(name: &str, a: &mut App) {
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
    snap("field_export_study", &mut a);
    typ(&mut a, "k4.xlsx");
    key(&mut a, KeyCode::Enter);
    snap("field_export_refused", &mut a);
    key(&mut a, KeyCode::Esc);
    key(&mut a, KeyCode::Char('b'));
    snap("field_band", &mut a);
    typ(&mut a, "1 20000 0.001");
    key(&mut a, KeyCode::Enter);
    snap("field_band_refused", &mut a);
    key(&mut a, KeyCode::Esc);
    key(&mut a, KeyCode::Char('b'));
    typ(&mut a, "2 12 0.25");
    key(&mut a, KeyCode::Enter);
    key(&mut a, KeyCode::Char('M'));
    snap("study_band_mouse_on", &mut a);
}
