//! The Vibration tab's `x` export, driven by keys through the real
//! `update`, is byte for byte what the real binary's `biodyn simulate
//! --format csv` prints for the same model and signal: a generated sine, a
//! random record plus a shock, and a CSV record read from a file.

use biodyn::Preset;
use biodyn_app::tui::app::App;
use biodyn_app::tui::event::Msg;
use biodyn_app::tui::tabs::vibration::VibrationTab;
use biodyn_app::tui::tabs::vibration::settings::Row;
use biodyn_app::tui::theme::Theme;
use biodyn_app::tui::update::update;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use std::path::Path;
use std::process::Command;

fn key(a: &mut App, code: KeyCode) {
    update(a, Msg::Key(KeyEvent::new(code, KeyModifiers::NONE)));
}

fn typ(a: &mut App, s: &str) {
    for c in s.chars() {
        key(a, KeyCode::Char(c));
    }
}

fn tab(a: &App) -> &VibrationTab {
    a.tab_state().expect("vibration tab")
}

fn edit(a: &mut App, row: Row, text: &str) {
    let i = tab(a).rows().iter().position(|&r| r == row).expect("row");
    while tab(a).sel != i {
        key(a, KeyCode::Down);
    }
    key(a, KeyCode::Enter);
    a.field.as_mut().expect("field").set_text("");
    typ(a, text);
    key(a, KeyCode::Enter);
    assert!(a.field.is_none(), "{:?}", a.field);
}

fn export(a: &mut App, path: &Path) -> Vec<u8> {
    key(a, KeyCode::Char('x'));
    a.field.as_mut().expect("export field").set_text("");
    typ(a, &path.display().to_string());
    key(a, KeyCode::Enter);
    assert!(a.status.text.starts_with("exported"), "{:?}", a.status);
    std::fs::read(path).expect("exported file")
}

fn cli(args: &[&str]) -> Vec<u8> {
    let out = Command::new(env!("CARGO_BIN_EXE_biodyn"))
        .args(args)
        .output()
        .expect("run biodyn");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    out.stdout
}

#[test]
fn the_export_equals_biodyn_simulate_byte_for_byte() {
    let dir = tempfile::tempdir().expect("tempdir");
    let mut a = App::new(Preset::builtin_default(), None, Theme::default());
    key(&mut a, KeyCode::Char('5'));

    let mine = export(&mut a, &dir.path().join("sine.csv"));
    let theirs = cli(&[
        "simulate",
        "--signal",
        "sine:freq=5,amp=5",
        "--format",
        "csv",
    ]);
    assert_eq!(mine.len(), theirs.len());
    assert!(mine == theirs, "sine: the files differ");

    let spec = "random:rms=0.8,band=1-20,seed=1+shock:peak=15,width=0.1,at=2";
    edit(&mut a, Row::Spec, spec);
    edit(&mut a, Row::Duration, "4");
    edit(&mut a, Row::Fs, "500");
    let mine = export(&mut a, &dir.path().join("rs.csv"));
    let theirs = cli(&[
        "simulate",
        "--signal",
        spec,
        "--duration",
        "4",
        "--fs",
        "500",
        "--format",
        "csv",
    ]);
    assert!(mine == theirs, "random+shock: the files differ");

    // a record from a file, with a time column that does not start at 0
    let rec = dir.path().join("seat.csv");
    let mut text = String::from("t_s,z_m_s2\n");
    for i in 0..3000 {
        let t = 1.5 + i as f64 / 400.0;
        text.push_str(&format!(
            "{t},{}\n",
            2.0 * (7.0 * t).sin() + (31.0 * t).cos()
        ));
    }
    std::fs::write(&rec, text).expect("write record");
    for _ in 0..4 {
        key(&mut a, KeyCode::Left);
        if tab(&a).settings.signal().is_none() {
            break;
        }
    }
    assert!(tab(&a).settings.signal().is_none(), "file kind");
    edit(&mut a, Row::Path, &rec.display().to_string());
    let mine = export(&mut a, &dir.path().join("rec.csv"));
    let theirs = cli(&[
        "simulate",
        "--input",
        &rec.display().to_string(),
        "--format",
        "csv",
    ]);
    assert!(mine == theirs, "record: the files differ");
    assert_eq!(
        tab(&a).outcome().map(|o| o.traces.seat.len),
        Some(3000),
        "the tab ran the record too"
    );
}
