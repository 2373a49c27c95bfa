//! Saves that lose nothing (issue 19, items 1–3), against the real binary:
//! never onto the command's own input (by device and inode: another path,
//! a symlink or a hard link to it is it), checked before the work, a
//! read-only file only with `--force`, and results printed when the save
//! fails after the work.

#![cfg(unix)]

use std::fs;
use std::os::unix::fs::{PermissionsExt, symlink};
use std::path::Path;
use std::process::{Command, Stdio};

const DATA: &str = "examples/synthetic-stht-apms-3pct-2deg.csv";

/// Runs `biodyn` in `dir` through `sh -c PREFIX "$@"`: (status, stdout, stderr).
fn sh(dir: &Path, prefix: &str, args: &[&str]) -> (Option<i32>, String, String) {
    let out = Command::new("sh")
        .arg("-c")
        .arg(format!("{prefix} exec \"$0\" \"$@\""))
        .arg(env!("CARGO_BIN_EXE_biodyn"))
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .output()
        .expect("sh runs");
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn run(dir: &Path, args: &[&str]) -> (Option<i32>, String, String) {
    sh(dir, "", args)
}

/// A temp folder holding the synthetic measured data as `my.csv` and the
/// built-in model as `p.toml`.
fn folder() -> tempfile::TempDir {
    let d = tempfile::tempdir().expect("temp dir");
    fs::copy(
        Path::new(env!("CARGO_MANIFEST_DIR")).join(DATA),
        d.path().join("my.csv"),
    )
    .unwrap();
    let (code, _, err) = run(d.path(), &["preset", "save", "p.toml"]);
    assert_eq!(code, Some(0), "{err}");
    d
}

fn refused(r: &(Option<i32>, String, String), what: &str) {
    assert_eq!(r.0, Some(1), "status: {}", r.2);
    assert!(r.1.is_empty(), "no results before a refused save: {}", r.1);
    assert!(r.2.contains(what), "{what:?} not in: {}", r.2);
    assert!(!r.2.contains("saved"), "{}", r.2);
}

#[test]
fn a_save_onto_an_input_is_refused_by_any_path_to_it() {
    let d = folder();
    let p = d.path();
    symlink("my.csv", p.join("link.csv")).unwrap();
    fs::hard_link(p.join("p.toml"), p.join("hard.toml")).unwrap();
    let data = fs::read(p.join("my.csv")).unwrap();
    let preset = fs::read(p.join("p.toml")).unwrap();
    let own = "is the input";
    for save in ["my.csv", "./my.csv", "link.csv"] {
        let r = run(
            p,
            &["fit", "--data", "my.csv", "--starts", "1", "--save", save],
        );
        refused(&r, own);
        assert!(
            r.2.contains("hint: save under another file name"),
            "{}",
            r.2
        );
    }
    for save in ["p.toml", "hard.toml"] {
        let r = run(
            p,
            &[
                "fit", "--data", "my.csv", "--preset", "p.toml", "--starts", "1", "--save", save,
            ],
        );
        refused(&r, own);
        refused(
            &run(
                p,
                &[
                    "train", "--case", "k4-dpmi", "--preset", "p.toml", "--save", save,
                ],
            ),
            own,
        );
        refused(
            &run(
                p,
                &[
                    "preset", "save", save, "--preset", "p.toml", "--set", "k4=1e5",
                ],
            ),
            own,
        );
    }
    // `--force` is for read-only files, not for inputs.
    refused(
        &run(
            p,
            &[
                "preset", "save", "p.toml", "--preset", "./p.toml", "--force",
            ],
        ),
        own,
    );
    assert_eq!(fs::read(p.join("my.csv")).unwrap(), data);
    assert_eq!(fs::read(p.join("p.toml")).unwrap(), preset);
}

#[test]
fn a_save_that_cannot_happen_is_refused_before_the_work() {
    let d = folder();
    let p = d.path();
    fs::create_dir(p.join("sub")).unwrap();
    // `--case all` checks all six targets before the first trains: nothing
    // is trained, nothing printed.
    let r = run(p, &["train", "--case", "all", "--save", "nodir/x.json"]);
    refused(&r, "the folder nodir does not exist");
    assert!(r.2.contains("nodir/x-mass-stht.json"), "{}", r.2);
    refused(
        &run(p, &["train", "--case", "k4-dpmi", "--save", "sub"]),
        "is a directory",
    );
    refused(
        &run(
            p,
            &["fit", "--data", "my.csv", "--starts", "1", "--save", "sub"],
        ),
        "is a directory",
    );
    refused(
        &run(
            p,
            &[
                "fit",
                "--data",
                "my.csv",
                "--starts",
                "1",
                "--save",
                "my.csv/x.toml",
            ],
        ),
        "Not a directory",
    );
    assert_eq!(fs::read_dir(p.join("sub")).unwrap().count(), 0);
}

#[test]
fn a_read_only_file_is_replaced_only_with_force() {
    let d = folder();
    let p = d.path();
    fs::set_permissions(p.join("p.toml"), fs::Permissions::from_mode(0o444)).unwrap();
    let before = fs::read(p.join("p.toml")).unwrap();
    for args in [
        &["preset", "save", "p.toml", "--set", "k4=1e5"][..],
        &[
            "fit", "--data", "my.csv", "--starts", "1", "--save", "p.toml",
        ],
        &[
            "train", "--case", "k4-dpmi", "--epochs", "1", "--save", "p.toml",
        ],
    ] {
        let r = run(p, args);
        refused(&r, "is read-only (mode 0444)");
        assert!(r.2.contains("add --force"), "{}", r.2);
        assert_eq!(fs::read(p.join("p.toml")).unwrap(), before, "{args:?}");
    }
    let r = run(
        p,
        &["preset", "save", "p.toml", "--set", "k4=1e5", "--force"],
    );
    assert_eq!(r.0, Some(0), "{}", r.2);
    let text = fs::read_to_string(p.join("p.toml")).unwrap();
    assert!(text.contains("100000"), "{text}");
    let mode = fs::metadata(p.join("p.toml")).unwrap().permissions().mode() & 0o777;
    assert_eq!(mode, 0o444, "the forced save keeps the mode");
}

/// A save that passes the check and still fails (here: the file-size limit
/// of `ulimit -f 1`, 1 KiB, with SIGXFSZ ignored so the write gets EFBIG)
/// prints the results and says the file was not written.
#[test]
fn a_save_that_fails_after_the_work_prints_the_results() {
    let d = folder();
    let p = d.path();
    let limit = "trap '' XFSZ; ulimit -f 1;";
    let r = sh(
        p,
        limit,
        &[
            "fit",
            "--data",
            "my.csv",
            "--starts",
            "1",
            "--save",
            "fitted.toml",
        ],
    );
    assert_eq!(r.0, Some(1), "{}", r.2);
    assert!(r.1.contains("k4"), "the fit's table is printed: {}", r.1);
    assert!(
        r.2.contains("the fit is printed above; fitted.toml was not written"),
        "{}",
        r.2
    );
    assert!(!p.join("fitted.toml").exists());
    let r = sh(
        p,
        limit,
        &[
            "train", "--case", "k4-dpmi", "--epochs", "2", "--save", "net.json",
        ],
    );
    assert_eq!(r.0, Some(1), "{}", r.2);
    assert!(r.1.contains("k4-dpmi"), "the table is printed: {}", r.1);
    assert!(r.2.contains("k4-dpmi not saved"), "{}", r.2);
    assert!(r.2.contains("not written: net.json"), "{}", r.2);
    assert!(!p.join("net.json").exists());
    let left: Vec<_> = fs::read_dir(p)
        .unwrap()
        .flatten()
        .map(|e| e.file_name())
        .collect();
    assert_eq!(left.len(), 2, "no temp file left behind: {left:?}");
}
