use super::*;
use crate::io::{save_atomic, save_guarded};

fn dir() -> tempfile::TempDir {
    tempfile::tempdir().expect("temp dir")
}

#[test]
fn an_input_is_refused_by_any_path_to_it() {
    let d = dir();
    let data = d.path().join("my.csv");
    fs::write(&data, b"f_hz,apms_mag\n1,2\n").unwrap();
    let guard = Guard::reading([&data], false);
    // The same file by its own name, through ./, a symlink and a hard link.
    let dotted = d.path().join(".").join("my.csv");
    #[cfg(unix)]
    std::os::unix::fs::symlink(&data, d.path().join("link.csv")).unwrap();
    fs::hard_link(&data, d.path().join("hard.csv")).unwrap();
    for p in [
        data.clone(),
        dotted,
        d.path().join("link.csv"),
        d.path().join("hard.csv"),
    ] {
        let e = guard.check(&p).unwrap_err();
        assert!(matches!(e, SaveError::OwnInput { .. }), "{p:?}: {e}");
        assert!(e.to_string().contains("is the input"), "{e}");
        let e = save_guarded(&p, &guard, b"preset").unwrap_err();
        assert!(matches!(e, SaveError::OwnInput { .. }), "{e}");
    }
    assert_eq!(fs::read(&data).unwrap(), b"f_hz,apms_mag\n1,2\n");
    // Another file is fine, and so is a new one.
    fs::write(d.path().join("other.toml"), b"x").unwrap();
    guard.check(&d.path().join("other.toml")).unwrap();
    guard.check(&d.path().join("new.toml")).unwrap();
}

#[cfg(unix)]
#[test]
fn a_read_only_file_is_refused_unless_forced() {
    use std::os::unix::fs::PermissionsExt;
    let d = dir();
    let p = d.path().join("p.toml");
    fs::write(&p, b"old").unwrap();
    fs::set_permissions(&p, fs::Permissions::from_mode(0o444)).unwrap();
    let e = Guard::default().check(&p).unwrap_err();
    assert!(matches!(e, SaveError::ReadOnly { mode: 0o444, .. }), "{e}");
    assert!(e.to_string().contains("read-only (mode 0444)"), "{e}");
    let e = save_atomic(&p, b"new").unwrap_err();
    assert!(matches!(e, SaveError::ReadOnly { .. }), "{e}");
    assert_eq!(fs::read(&p).unwrap(), b"old");
    let forced = Guard::reading::<&Path>([], true);
    forced.check(&p).unwrap();
    save_guarded(&p, &forced, b"new").unwrap();
    assert_eq!(fs::read(&p).unwrap(), b"new");
    let mode = fs::metadata(&p).unwrap().permissions().mode() & 0o777;
    assert_eq!(mode, 0o444, "the forced save keeps the mode");
    // Writable by its owner: not read-only.
    fs::set_permissions(&p, fs::Permissions::from_mode(0o644)).unwrap();
    Guard::default().check(&p).unwrap();
}

#[test]
fn a_save_that_cannot_happen_is_found_before_it() {
    let d = dir();
    let g = Guard::default();
    // A missing folder.
    let e = g.check(&d.path().join("no/such/dir/x.json")).unwrap_err();
    assert!(e.to_string().contains("cannot write in its folder"), "{e}");
    // A folder where the file should be.
    fs::create_dir(d.path().join("sub")).unwrap();
    let e = g.check(&d.path().join("sub")).unwrap_err();
    assert!(matches!(e, SaveError::NotRegular { .. }), "{e}");
    // A path that names no file.
    let e = g.check(&d.path().join("nosuch/..")).unwrap_err();
    assert!(e.to_string().contains("names no file"), "{e}");
    // A file's name used as a folder.
    fs::write(d.path().join("f"), b"x").unwrap();
    let e = g.check(&d.path().join("f/x.json")).unwrap_err();
    assert!(e.to_string().contains("Not a directory"), "{e}");
    // The probe leaves nothing behind.
    let mut names: Vec<_> = fs::read_dir(d.path())
        .unwrap()
        .flatten()
        .map(|e| e.file_name())
        .collect();
    names.sort();
    assert_eq!(names, ["f", "sub"]);
}

/// A folder the user may not write in (not testable as root, who may).
#[cfg(unix)]
#[test]
fn a_folder_without_write_permission_is_found_before_the_save() {
    use std::os::unix::fs::PermissionsExt;
    let d = dir();
    let ro = d.path().join("ro");
    fs::create_dir(&ro).unwrap();
    fs::set_permissions(&ro, fs::Permissions::from_mode(0o555)).unwrap();
    // SAFETY: geteuid only reads the process's id.
    let root = unsafe { libc::geteuid() } == 0;
    let r = Guard::default().check(&ro.join("x.json"));
    fs::set_permissions(&ro, fs::Permissions::from_mode(0o755)).unwrap();
    if root {
        assert!(r.is_ok(), "root may write anywhere: {r:?}");
    } else {
        let e = r.unwrap_err();
        assert!(e.to_string().contains("cannot write in its folder"), "{e}");
    }
}

#[test]
fn two_save_targets_are_one_file_by_any_path_to_it() {
    let d = dir();
    let svg = d.path().join("s2.svg");
    let dotted = d.path().join(".").join("s2.svg");
    // Not there yet: the resolved path decides.
    assert!(same_target(&svg, &dotted));
    assert!(!same_target(&svg, &d.path().join("s3.svg")));
    #[cfg(unix)]
    std::os::unix::fs::symlink(&svg, d.path().join("dangling.svg")).unwrap();
    #[cfg(unix)]
    assert!(same_target(&svg, &d.path().join("dangling.svg")));
    // There: the device and inode decide, links followed.
    fs::write(&svg, b"<svg/>").unwrap();
    fs::hard_link(&svg, d.path().join("hard.svg")).unwrap();
    assert!(same_target(&svg, &dotted));
    assert!(same_target(&d.path().join("hard.svg"), &svg));
    #[cfg(unix)]
    assert!(same_target(&d.path().join("dangling.svg"), &svg));
    fs::write(d.path().join("other.svg"), b"<svg/>").unwrap();
    assert!(!same_target(&svg, &d.path().join("other.svg")));
}

#[test]
fn a_path_ending_in_a_slash_is_refused_before_the_work() {
    let d = dir();
    let e = Guard::default()
        .check(&d.path().join("x.svg/"))
        .unwrap_err();
    assert!(e.to_string().contains("ends in '/'"), "{e}");
    Guard::default().check(&d.path().join("x.svg")).unwrap();
}
