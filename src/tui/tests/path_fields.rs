//! Every field that takes a file path completes it on Tab (issue 19 item
//! 15): the Responses tab's measured data (`D`) and the Vibration tab's
//! record, as the other path fields do; Tab no longer types a space there.

use super::{app, key, typ};
use crate::tui::app::App;
use ratatui::crossterm::event::KeyCode;

/// A folder with one file whose name `rec` starts uniquely.
fn folder() -> (tempfile::TempDir, String, String) {
    let d = tempfile::tempdir().expect("tempdir");
    let file = d.path().join("record-abc.csv");
    std::fs::write(&file, "t_s,az\n0,1\n").expect("write");
    let typed = format!("{}/rec", d.path().display());
    (d, typed, file.display().to_string())
}

fn tab_completes(a: &mut App, typed: &str, want: &str) {
    let f = a.field.as_mut().expect("a field is open");
    f.set_text("");
    typ(a, typed);
    key(a, KeyCode::Tab);
    let text = a.field.as_ref().map(|f| f.text.clone()).unwrap_or_default();
    assert_eq!(text, want, "Tab completes the path, it types no space");
}

#[test]
fn the_data_and_record_fields_complete_paths() {
    let (_d, typed, full) = folder();
    let mut a = app();
    key(&mut a, KeyCode::Char('2'));
    key(&mut a, KeyCode::Char('D'));
    tab_completes(&mut a, &typed, &full);
    key(&mut a, KeyCode::Esc);
    key(&mut a, KeyCode::Char('5'));
    // sine ← file (the last kind), then its path row.
    key(&mut a, KeyCode::Left); // from sine back to the last kind: file
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Enter);
    tab_completes(&mut a, &typed, &full);
}
