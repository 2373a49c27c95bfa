//! `biodyn train` on a model other than the paper's (--preset, --body-mass,
//! --set) and `biodyn predict` on the network's own model, as real processes.

use crate::common::{fails, run};
use biodyn::{Function, Preset, Solver};
use std::path::Path;

/// A five-segment chain with masses set directly (52 kg seated).
const FIVE: &str = r#"schema = 1
name = "five"
head = "head"

[[segment]]
name = "head"
mass_kg = 5.0
[[segment]]
name = "chest"
mass_kg = 22.0
[[segment]]
name = "belly"
mass_kg = 9.0
[[segment]]
name = "pelvis"
mass_kg = 10.0
[[segment]]
name = "thighs"
mass_kg = 6.0

[[link]]
upper = "head"
lower = "chest"
k_n_per_m = 310000.0
c_ns_per_m = 400.0
[[link]]
upper = "chest"
lower = "belly"
k_n_per_m = 183000.0
c_ns_per_m = 4750.0
[[link]]
upper = "belly"
lower = "pelvis"
k_n_per_m = 162800.0
c_ns_per_m = 4585.0
[[link]]
upper = "pelvis"
lower = "thighs"
k_n_per_m = 90000.0
c_ns_per_m = 2064.0
[[link]]
upper = "thighs"
lower = "seat"
k_n_per_m = 60000.0
c_ns_per_m = 1500.0
"#;

/// Three segments, three links: no k4.
const THREE: &str = r#"schema = 1
name = "three"
[[segment]]
name = "a"
mass_kg = 5.0
[[segment]]
name = "b"
mass_kg = 35.0
[[segment]]
name = "c"
mass_kg = 15.0
[[link]]
upper = "a"
lower = "b"
k_n_per_m = 300000.0
c_ns_per_m = 400.0
[[link]]
upper = "b"
lower = "c"
k_n_per_m = 180000.0
c_ns_per_m = 4000.0
[[link]]
upper = "c"
lower = "seat"
k_n_per_m = 90000.0
c_ns_per_m = 2000.0
"#;

fn write(dir: &Path, name: &str, text: &str) -> String {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.to_str().unwrap().to_string()
}

fn json(text: &str) -> serde_json::Value {
    serde_json::from_str(text).unwrap_or_else(|e| panic!("{e}: {text}"))
}

#[test]
fn train_on_a_five_segment_preset_then_predict_on_it_without_model_flags() {
    let dir = tempfile::tempdir().unwrap();
    let preset = write(dir.path(), "five.toml", FIVE);
    let net = dir.path().join("five-dpmi.json");
    let net_s = net.to_str().unwrap();
    let (code, out, err) = run(&[
        "train",
        "--case",
        "mass-dpmi",
        "--preset",
        &preset,
        "--epochs",
        "8",
        "--ensemble",
        "1",
        "--save",
        net_s,
        "--format",
        "json",
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert!(err.contains("training on five (5 segments"), "{err}");
    let r = &json(&out)[0];
    assert_eq!(r["layers"][0], 6, "m1..m5 and f: {r}");
    assert_eq!(r["base_segments"], 5);
    assert_eq!(r["base_body_mass_kg"], 52.0);
    // Hold-outs at 52 kg × 60/75, 70/75, 80/75, 90/75.
    let values: Vec<f64> = r["holdout"]
        .as_array()
        .unwrap()
        .iter()
        .map(|h| h["value"].as_f64().unwrap())
        .collect();
    let want: Vec<f64> = [60.0, 70.0, 80.0, 90.0]
        .iter()
        .map(|x| (52.0 * x) / 75.0)
        .collect();
    assert_eq!(values, want);
    let file = json(&std::fs::read_to_string(&net).unwrap());
    assert_eq!(file["version"], 2);

    // No model flags: predict on the network's own model, not the paper's.
    let (code, out, err) = run(&[
        "predict", "--net", net_s, "--from", "1", "--to", "8", "--step", "0.5", "--format", "json",
    ]);
    assert_eq!(code, Some(0), "{err}");
    let v = json(&out);
    let inputs = v["inputs"].as_object().unwrap();
    let names: Vec<&str> = inputs.keys().map(String::as_str).collect();
    assert_eq!(names.len(), 5, "{names:?}");
    assert_eq!(v["inputs"]["m5"], 6.0);
    // The analytic curve is the preset's, computed here by the library.
    let body = Preset::load(Path::new(&preset)).unwrap().body;
    let solver = Solver::new(&body);
    let pts = v["points"].as_array().unwrap();
    assert_eq!(pts.len(), 15);
    for p in pts {
        let f = p["f_hz"].as_f64().unwrap();
        let want = solver.at(f).mag(Function::Dpmi);
        let got = p["analytic"].as_f64().unwrap();
        assert!(
            (got - want).abs() <= 1e-12 * want,
            "{f} Hz: {got} vs {want}"
        );
    }
    // --set changes the network's own model (no --preset: not the paper's).
    let (code, out, err) = run(&[
        "predict", "--net", net_s, "--set", "m5=7", "--from", "2", "--to", "3", "--format", "json",
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(json(&out)["inputs"]["m5"], 7.0);

    // The paper's four segments do not fit a five-mass network.
    let e = fails(&["predict", "--net", net_s, "--preset", "paper-75kg"]);
    assert!(
        e.contains("4 segments") && e.contains("5 segment masses"),
        "{e}"
    );
    assert!(
        e.contains("hint: leave out --preset to predict on the network's own model"),
        "{e}"
    );
}

#[test]
fn a_model_the_case_cannot_use_is_refused_before_training() {
    let dir = tempfile::tempdir().unwrap();
    let three = write(dir.path(), "three.toml", THREE);
    let e = fails(&[
        "train", "--case", "k4-stht", "--preset", &three, "--epochs", "2",
    ]);
    assert!(
        e.contains(
            "k4 cases vary k4, the 4th link; this model has 3 links: pick a mass case or add a link"
        ),
        "{e}"
    );
    assert!(
        e.contains("hint: pick a mass case, or a model with at least 4 links"),
        "{e}"
    );
    // A mass case on more segments than it takes inputs for: refused with a way out.
    let mut chain = String::from("schema = 1\nname = \"chain70\"\nhead = \"s0\"\n");
    for i in 0..70 {
        chain.push_str(&format!("[[segment]]\nname = \"s{i}\"\nmass_kg = 1\n"));
    }
    for i in 0..70 {
        let lower = if i + 1 < 70 {
            format!("s{}", i + 1)
        } else {
            "seat".into()
        };
        chain.push_str(&format!(
            "[[link]]\nupper = \"s{i}\"\nlower = \"{lower}\"\nk_n_per_m = 1e5\nc_ns_per_m = 100\n"
        ));
    }
    let chain = write(dir.path(), "chain70.toml", &chain);
    let e = fails(&[
        "train",
        "--case",
        "mass-apms",
        "--preset",
        &chain,
        "--epochs",
        "2",
    ]);
    assert!(e.contains("70 segments") && e.contains("at most 64"), "{e}");
    assert!(e.contains("hint: pick a k4 case"), "{e}");
    // --case all checks every case first: nothing trains.
    let e = fails(&[
        "train", "--case", "all", "--preset", &three, "--epochs", "2",
    ]);
    assert!(e.contains("k4-stht") && e.contains("3 links"), "{e}");
    // Layers that do not fit the model's inputs name them.
    let five = write(dir.path(), "five.toml", FIVE);
    let e = fails(&[
        "train",
        "--case",
        "mass-stht",
        "--preset",
        &five,
        "--layers",
        "5-4-1",
        "--epochs",
        "2",
    ]);
    assert!(
        e.contains("m1, m2, m3, m4, m5, f") && e.contains("6 neurons"),
        "{e}"
    );
    let e = fails(&[
        "train",
        "--case",
        "mass-stht",
        "--set",
        "k9=1",
        "--epochs",
        "2",
    ]);
    assert!(e.contains("k9"), "{e}");
}

#[test]
fn no_model_flags_train_on_the_paper_as_before_and_body_mass_moves_k4_cases() {
    let (code, out, err) = run(&[
        "train",
        "--case",
        "k4-stht",
        "--epochs",
        "3",
        "--ensemble",
        "1",
        "--format",
        "json",
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert!(err.is_empty(), "{err}");
    let r = &json(&out)[0];
    assert!(r.get("base_segments").is_none(), "{r}");
    assert_eq!(r["holdout"][1]["value"], 72000.0);

    let dir = tempfile::tempdir().unwrap();
    let net = dir.path().join("k4-85.json");
    let net_s = net.to_str().unwrap();
    let (code, out, err) = run(&[
        "train",
        "--case",
        "k4-stht",
        "--body-mass",
        "85",
        "--epochs",
        "3",
        "--ensemble",
        "1",
        "--save",
        net_s,
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert!(out.contains("body mass 85 kg"), "{out}");
    // Trained at 85 kg: predicting there needs no warning, 70 kg does.
    let (code, _, err) = run(&["predict", "--net", net_s, "--body-mass", "85"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(!err.contains("warning"), "{err}");
    let (code, _, err) = run(&["predict", "--net", net_s, "--body-mass", "70"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(err.contains("trained at 85 kg"), "{err}");
    // Without model flags: the analytic curve is on the net's own 85 kg
    // body, as the library computes it, not on the paper's 75 kg.
    let (code, out, err) = run(&["predict", "--net", net_s, "--format", "csv"]);
    assert_eq!(code, Some(0), "{err}");
    let first: Vec<f64> = out
        .lines()
        .nth(1)
        .unwrap()
        .split(',')
        .map(|x| x.parse().unwrap())
        .collect();
    let body = biodyn::Body::paper(85.0).unwrap();
    let want = Solver::new(&body).at(first[0]).mag(Function::Stht);
    assert!(
        (first[2] - want).abs() <= 1e-12 * want,
        "{first:?} vs {want}"
    );
}
