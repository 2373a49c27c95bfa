//! Saving the preset where no file can be replaced (a FIFO, a device) is
//! refused at once, without blocking.

use super::*;

/// Ctrl-S, the path typed, Enter: the field's refusal, if any.
fn save_as(a: &mut App, path: &std::path::Path) -> Option<String> {
    ctrl(a, 's');
    if let Some(f) = a.field.as_mut() {
        f.set_text(path.display().to_string());
    }
    key(a, KeyCode::Enter);
    a.field.as_ref().and_then(|f| f.error.clone())
}

#[cfg(unix)]
#[test]
fn saving_over_a_fifo_or_a_device_is_refused_at_once() {
    use std::os::unix::fs::FileTypeExt;
    let dir = tempfile::tempdir().expect("tempdir");
    let fifo = dir.path().join("pipe.toml");
    let made = std::process::Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .expect("mkfifo runs");
    assert!(made.success(), "mkfifo failed");
    for target in [fifo.clone(), std::path::PathBuf::from("/dev/null")] {
        let mut a = app();
        key(&mut a, KeyCode::Char('+'));
        let e = save_as(&mut a, &target).unwrap_or_default();
        assert!(
            e.contains("not a regular file"),
            "{}: {e}",
            target.display()
        );
        assert!(!e.contains("exists"), "{e}");
        // A second Enter refuses again; nothing was written or replaced.
        key(&mut a, KeyCode::Enter);
        let e = field_error(&a);
        assert!(e.contains("not a regular file"), "{e}");
        assert!(a.modified());
    }
    let meta = std::fs::symlink_metadata(&fifo).expect("fifo stays");
    assert!(meta.file_type().is_fifo());
    // A regular file still asks first, then replaces.
    let file = dir.path().join("body.toml");
    std::fs::write(&file, "x").expect("write");
    let mut a = app();
    key(&mut a, KeyCode::Char('+'));
    let e = save_as(&mut a, &file).unwrap_or_default();
    assert!(e.contains("exists: Enter again replaces it"), "{e}");
    key(&mut a, KeyCode::Enter);
    assert!(a.field.is_none() && !a.modified());
}

/// A folder with the model saved as `p.toml` and the example data as
/// `my.csv`, and an app opened on `p.toml` with `my.csv` over its charts.
fn opened() -> (tempfile::TempDir, App) {
    let dir = tempfile::tempdir().expect("tempdir");
    let p = dir.path().join("p.toml");
    Preset::builtin_default().save(&p).expect("save");
    let data = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("examples/synthetic-stht-apms-3pct-2deg.csv");
    std::fs::copy(data, dir.path().join("my.csv")).expect("copy");
    let preset = Preset::load(&p).expect("load");
    let mut a = App::new(preset, Some(p), crate::tui::theme::Theme::default());
    key(&mut a, KeyCode::Char('2'));
    key(&mut a, KeyCode::Char('D'));
    if let Some(f) = a.field.as_mut() {
        f.set_text(dir.path().join("my.csv").display().to_string());
    }
    key(&mut a, KeyCode::Enter);
    assert!(responses(&a).data.is_some(), "{}", field_error(&a));
    // An unsaved edit on the Model tab.
    key(&mut a, KeyCode::Char('1'));
    key(&mut a, KeyCode::Char('+'));
    assert!(a.modified());
    (dir, a)
}

/// Issue 19 item 1 in the app: no save replaces a file the app has open
/// (the measured data, the preset under an export), by whatever path.
#[test]
fn a_save_onto_a_file_the_app_has_open_is_refused() {
    let (dir, mut a) = opened();
    let data = std::fs::read(dir.path().join("my.csv")).expect("read");
    for target in ["my.csv", "./my.csv"] {
        let e = save_as(&mut a, &dir.path().join(target)).unwrap_or_default();
        assert!(e.contains("is the input"), "{target}: {e}");
        key(&mut a, KeyCode::Esc);
    }
    assert_eq!(
        std::fs::read(dir.path().join("my.csv")).expect("read"),
        data
    );
    // The study's export onto the preset the app edits is refused too.
    let preset = std::fs::read(dir.path().join("p.toml")).expect("read");
    key(&mut a, KeyCode::Char('3'));
    key(&mut a, KeyCode::Char('x'));
    assert!(a.field.is_some(), "x offers the export");
    if let Some(f) = a.field.as_mut() {
        f.set_text(dir.path().join("p.toml").display().to_string());
    }
    key(&mut a, KeyCode::Enter);
    assert!(
        field_error(&a).contains("is the input"),
        "{}",
        field_error(&a)
    );
    key(&mut a, KeyCode::Esc);
    assert_eq!(
        std::fs::read(dir.path().join("p.toml")).expect("read"),
        preset
    );
    // The model's own file is its save, not an input.
    assert_eq!(save_as(&mut a, &dir.path().join("p.toml")), None);
    assert!(!a.modified());
}

/// Issue 19 item 3 in the app: a read-only file is not replaced, not even
/// the model's own.
#[cfg(unix)]
#[test]
fn a_read_only_file_is_not_replaced() {
    use std::os::unix::fs::PermissionsExt;
    let (dir, mut a) = opened();
    let p = dir.path().join("p.toml");
    std::fs::set_permissions(&p, std::fs::Permissions::from_mode(0o444)).expect("chmod");
    let before = std::fs::read(&p).expect("read");
    let e = save_as(&mut a, &p).unwrap_or_default();
    assert!(e.contains("is read-only (mode 0444)"), "{e}");
    key(&mut a, KeyCode::Enter);
    assert!(field_error(&a).contains("read-only"), "{}", field_error(&a));
    assert_eq!(std::fs::read(&p).expect("read"), before);
    assert!(a.modified());
}

/// Issue 19 item 5: a save is not undone. After Ctrl-S to t1.toml and `u`
/// the title still names t1.toml, says `*modified`, and `q` asks; redo
/// brings back the saved state, unmodified.
#[test]
fn undo_after_a_save_keeps_the_file_and_says_modified() {
    let dir = tempfile::tempdir().expect("tempdir");
    let t1 = dir.path().join("t1.toml");
    let mut a = app();
    key(&mut a, KeyCode::Char('+'));
    assert_eq!(save_as(&mut a, &t1), None);
    assert!(!a.modified());
    let title = |a: &App| {
        screen(a, 120, 30)
            .lines()
            .next()
            .unwrap_or_default()
            .to_string()
    };
    assert!(title(&a).contains("t1.toml"), "{}", title(&a));
    key(&mut a, KeyCode::Char('u'));
    assert_eq!(a.shared.path.as_deref(), Some(t1.as_path()));
    assert!(a.modified());
    let t = title(&a);
    assert!(t.contains("t1.toml") && t.contains("*modified"), "{t}");
    assert!(!a.quit_reasons().is_empty(), "q must ask");
    key(&mut a, KeyCode::Char('q'));
    assert!(!a.quit, "q asks first");
    key(&mut a, KeyCode::Esc);
    ctrl(&mut a, 'r');
    assert!(!a.modified(), "redo brings back what t1.toml holds");
    assert_eq!(a.shared.path.as_deref(), Some(t1.as_path()));
}
