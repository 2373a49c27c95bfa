//! Driving the real `update` by keys, and the real binary beside it: what
//! the export tests share.

use biodyn::Preset;
use biodyn_app::tui::app::App;
use biodyn_app::tui::event::Msg;
use biodyn_app::tui::theme::Theme;
use biodyn_app::tui::update::update;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use std::process::Command;

/// The app on `p`, sized 80×24.
pub fn app(p: Preset) -> App {
    let mut a = App::new(p, None, Theme::default());
    update(&mut a, Msg::Resize(80, 24));
    a
}

pub fn key(a: &mut App, code: KeyCode) {
    update(a, Msg::Key(KeyEvent::new(code, KeyModifiers::NONE)));
}

pub fn ch(a: &mut App, c: char) {
    key(a, KeyCode::Char(c));
}

pub fn typ(a: &mut App, s: &str) {
    s.chars().for_each(|c| ch(a, c));
}

/// `biodyn args`, which must succeed: its standard output.
pub fn biodyn(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_biodyn"))
        .args(args)
        .output()
        .expect("run biodyn");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("utf-8")
}

/// `x`, the path typed over the pre-filled one, Enter: the file's text.
pub fn export(a: &mut App, path: &std::path::Path) -> String {
    ch(a, 'x');
    assert!(
        a.field.as_ref().is_some_and(|f| f.path),
        "a path field: {:?}",
        a.status
    );
    typ(a, &path.display().to_string());
    key(a, KeyCode::Enter);
    assert!(a.field.is_none(), "{:?}", a.field);
    std::fs::read_to_string(path).expect("written")
}
