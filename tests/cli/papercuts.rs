//! What the new user tripped on at the command line (issue 19 items 20 and
//! 23), against the real binary.

use crate::common::{fails, ok, run};

#[test]
fn a_preset_before_the_command_is_the_commands() {
    let before = ok(&["--preset", "paper-85kg", "response", "--at", "4.6"]);
    let after = ok(&["response", "--preset", "paper-85kg", "--at", "4.6"]);
    assert_eq!(before, after);
    assert_ne!(
        before,
        ok(&["response", "--at", "4.6"]),
        "the preset was used"
    );
    for args in [
        &[
            "--preset",
            "paper-85kg",
            "response",
            "--preset",
            "paper-65kg",
        ][..],
        &["--preset", "paper-85kg", "weighting", "wk"],
        &["--ascii", "response"],
    ] {
        let (code, out, err) = run(args);
        assert_eq!(code, Some(2), "{args:?}: {err}");
        assert!(out.is_empty());
        assert!(err.contains("--preset") || err.contains("--ascii"), "{err}");
    }
}

#[test]
fn assess_and_simulate_without_input_name_both_inputs() {
    for cmd in ["assess", "simulate"] {
        let (code, _, err) = run(&[cmd]);
        assert_eq!(code, Some(2));
        assert!(err.contains("--signal") && err.contains("--input"), "{err}");
    }
}

#[test]
fn a_study_without_values_takes_the_papers_list() {
    assert_eq!(ok(&["study", "k4"]), ok(&["study", "k4", "-40%,0%,+40%"]));
    assert_eq!(ok(&["study", "mass"]), ok(&["study", "mass", "65,75,85"]));
    assert_eq!(
        ok(&["plot", "stht", "--study", "c4"]),
        ok(&["plot", "stht", "--study", "c4=-40%,0%,+40%"])
    );
}

#[test]
fn response_at_one_frequency_is_the_bands_value_there() {
    let at = ok(&["response", "--at", "4.6", "--format", "csv"]);
    let band = ok(&[
        "response", "--from", "4.6", "--to", "4.7", "--step", "0.1", "--format", "csv",
    ]);
    let row = |t: &str| t.lines().nth(1).unwrap_or_default().to_string();
    assert_eq!(at.lines().count(), 2, "{at}");
    assert_eq!(row(&at), row(&band));
    let two = ok(&["response", "--at", "3.1,4.56123", "--format", "csv"]);
    assert!(
        two.lines()
            .nth(2)
            .unwrap_or_default()
            .starts_with("4.56123,"),
        "{two}"
    );
    let err = fails(&["response", "--at", "1e9"]);
    assert!(err.contains("at = 1e9 Hz is outside"), "{err}");
    let (code, _, err) = run(&["response", "--at", "4.6", "--from", "2"]);
    assert_eq!(code, Some(2), "{err}");
}

#[test]
fn preset_list_shows_the_preset_files_beside_presets() {
    let dir = tempfile::tempdir().expect("tempdir");
    let bin = env!("CARGO_BIN_EXE_biodyn");
    let sh = |args: &[&str]| {
        let out = std::process::Command::new(bin)
            .args(args)
            .current_dir(dir.path())
            .output()
            .expect("runs");
        String::from_utf8_lossy(&out.stdout).into_owned()
    };
    sh(&["preset", "save", "mine.toml", "--body-mass", "90"]);
    std::fs::write(dir.path().join("Cargo.toml"), "[package]\n").expect("write");
    let list = sh(&["preset", "list"]);
    assert!(
        list.contains("mine.toml") && list.contains("file"),
        "{list}"
    );
    assert!(!list.contains("Cargo.toml"), "{list}");
}

#[test]
fn whole_numbers_say_their_range() {
    for args in [
        &["fit", "--data", "x.csv", "--seed", "-1"][..],
        &["train", "--case", "k4-dpmi", "--seed", "-1"],
    ] {
        let (code, _, err) = run(args);
        assert_eq!(code, Some(2));
        assert!(
            err.contains("is not a whole number from 0 to 18446744073709551615"),
            "{err}"
        );
    }
}

#[test]
fn numbers_print_short_and_without_a_minus_on_zero() {
    let out = ok(&[
        "assess",
        "--signal",
        "sine:freq=5,amp=1",
        "--exposure",
        "0.0000000001",
    ]);
    assert!(out.contains("exposure 1e-10 h a day"), "{out}");
    let widest = out.lines().map(|l| l.chars().count()).max().unwrap_or(0);
    assert!(widest < 200, "a line of {widest} characters");
    let err = fails(&[
        "fit",
        "--data",
        "examples/synthetic-stht-apms-3pct-2deg.csv",
        "--bound",
        "k4=..1e300",
    ]);
    assert!(
        err.contains("1e300 is above the model's limit 1e12 N/m"),
        "{err}"
    );
    // No table of the shipped commands prints a negative zero.
    for args in [
        &["response"][..],
        &["modes"],
        &["peaks"],
        &["study", "k4"],
        &["assess", "--signal", "sine:freq=5,amp=1"],
    ] {
        let t = ok(args);
        for w in t.split(|c: char| c.is_whitespace() || c == '(' || c == ',') {
            let zero = w.strip_prefix('-').is_some_and(|r| {
                !r.is_empty() && r.bytes().all(|b| b == b'0' || b == b'.') && r.contains('0')
            });
            assert!(!zero, "{args:?} prints {w}");
        }
    }
}
