//! Two values for one model parameter are refused by every command that
//! takes the model flags (`--body-mass`, `--set`), naming both: which one
//! would win is a rule of order the reader cannot see.

use crate::common::{fails, ok};

/// Each command with the model flags, with what else it needs.
fn commands(dir: &std::path::Path) -> Vec<Vec<String>> {
    let save = dir.join("saved.toml").display().to_string();
    let net = dir.join("k4.json").display().to_string();
    ok(&[
        "train", "--case", "k4-stht", "--epochs", "2", "--save", &net, "--quiet",
    ]);
    let seat = "--preset=paper-75kg-suspension-seat";
    [
        vec!["response"],
        vec!["modes"],
        vec!["peaks"],
        vec!["study", "c4", "1500,2500"],
        vec!["plot", "stht"],
        vec![
            "simulate",
            "--signal",
            "sine:freq=5,amp=5",
            "--duration",
            "2",
        ],
        vec!["assess", "--signal", "sine:freq=5,amp=5", "--duration", "2"],
        vec!["seat", seat, "--class", "EM6"],
        vec![
            "fit",
            "--data",
            "examples/synthetic-stht-apms-3pct-2deg.csv",
        ],
        vec!["train", "--case", "k4-stht", "--epochs", "2"],
        vec!["predict", "--net", &net],
        vec!["preset", "save", &save],
    ]
    .into_iter()
    .map(|c| c.into_iter().map(String::from).collect())
    .collect()
}

fn refused(command: &[String], extra: &[&str]) -> String {
    let mut args: Vec<&str> = command.iter().map(String::as_str).collect();
    args.extend_from_slice(extra);
    fails(&args)
}

#[test]
fn a_parameter_set_twice_is_refused_naming_both_values() {
    let dir = tempfile::tempdir().unwrap();
    for c in commands(dir.path()) {
        let e = refused(&c, &["--set", "k4=90000", "--set", "k4=2"]);
        assert!(
            e.contains("k4 is given twice, --set k4=90000 and --set k4=2:"),
            "{c:?}: {e}"
        );
        // The same link by its name and by its number is one parameter.
        if !c.contains(&"--preset=paper-75kg-suspension-seat".to_string()) {
            let e = refused(&c, &["--set", "pelvis-seat.c=2000", "--set", "c4=2100"]);
            assert!(e.contains("c4 is given twice"), "{c:?}: {e}");
        }
    }
    assert!(!dir.path().join("saved.toml").exists());
}

#[test]
fn the_body_mass_by_set_and_by_flag_is_refused_in_either_order() {
    let dir = tempfile::tempdir().unwrap();
    for c in commands(dir.path()) {
        for order in [
            ["--set", "body_mass=90", "--body-mass", "60"],
            ["--body-mass", "60", "--set", "body_mass=90"],
        ] {
            let e = refused(&c, &order);
            assert!(
                e.contains("body mass is given twice, --body-mass 60 and --set body_mass=90:"),
                "{c:?} {order:?}: {e}"
            );
            assert!(e.contains("give each parameter once"), "{e}");
        }
    }
}

/// Different parameters, and one parameter once, are still taken.
#[test]
fn different_parameters_are_taken() {
    ok(&[
        "response",
        "--body-mass",
        "60",
        "--set",
        "k4=54000",
        "--set",
        "m1=5",
        "--format",
        "csv",
    ]);
}

/// A training setting given twice is refused by the parser itself.
#[test]
fn a_training_setting_given_twice_is_refused() {
    let (code, out, err) = crate::common::run(&[
        "train", "--case", "k4-stht", "--epochs", "3", "--epochs", "4",
    ]);
    assert_eq!(code, Some(2), "{err}");
    assert!(out.is_empty());
    assert!(
        err.contains("'--epochs <N>' cannot be used multiple times"),
        "{err}"
    );
}
