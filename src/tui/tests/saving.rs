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
    assert!(made.success());
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
