//! Runs that cannot fit or finish are refused before the work, with the
//! reason and the limit (issue 19 items 6 and 7); a time limit holds inside
//! one epoch; a rate out of range blames the rate (item 23).

use crate::big_models::chain_preset;
use crate::common::{fails, run};
use std::time::{Duration, Instant};

/// Refused at once (before any large allocation), one error and one hint.
fn refused_fast(args: &[&str]) -> String {
    let t0 = Instant::now();
    let err = fails(args);
    assert!(
        t0.elapsed() < Duration::from_secs(20),
        "{args:?} took {:?}",
        t0.elapsed()
    );
    err
}

#[test]
fn oversized_networks_and_ensembles_are_refused_with_the_rule() {
    // LM on 2-10000-1 grew past 8 GB: the normal matrix is weights².
    let e = refused_fast(&[
        "train",
        "--case",
        "k4-stht",
        "--layers",
        "2-10000-1",
        "--epochs",
        "1",
    ]);
    assert!(e.contains("--layers 2-10000-1: 40001 weights"), "{e}");
    assert!(e.contains("at most 2000 weights"), "{e}");
    // Back-propagation on 2-10000-10000-1 aborted on an allocation failure.
    let e = refused_fast(&[
        "train",
        "--case",
        "k4-stht",
        "--trainer",
        "backprop",
        "--layers",
        "2-10000-10000-1",
    ]);
    assert!(
        e.contains("--layers 2-10000-10000-1: 100050001 weights"),
        "{e}"
    );
    assert!(e.contains("2.4 GB") && e.contains("1 GiB budget"), "{e}");
    let e = refused_fast(&["train", "--case", "k4-apms", "--ensemble", "1000000"]);
    assert!(
        e.contains("--ensemble 1000000: at most 1000 networks"),
        "{e}"
    );
    let e = refused_fast(&[
        "train", "--case", "k4-apms", "--from", "0.001", "--to", "1000", "--step", "0.001",
    ]);
    assert!(
        e.contains("--from/--to/--step") && e.contains("cap of 1000000"),
        "{e}"
    );
}

fn json_run(args: &[&str]) -> (serde_json::Value, Duration) {
    let t0 = Instant::now();
    let (code, out, err) = run(args);
    assert_eq!(code, Some(0), "{args:?}: {err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("JSON");
    (v[0].clone(), t0.elapsed())
}

#[test]
fn the_time_limit_holds_inside_one_epoch_and_one_lm_iteration() {
    // One epoch of this net takes far longer than the limit: before the
    // check inside the epoch, the first epoch ran to its end (epochs 1).
    let (r, _) = json_run(&[
        "train",
        "--case",
        "k4-stht",
        "--trainer",
        "backprop",
        "--layers",
        "2-600-600-1",
        "--epochs",
        "3",
        "--time-limit",
        "0.01",
        "--format",
        "json",
    ]);
    assert_eq!(r["stop_reason"], "time-limit", "{r}");
    assert_eq!(r["epochs"], 0, "{r}");
    // LM: the limit is seen in the Jacobian, JᵀJ and before each solve.
    let (r, took) = json_run(&[
        "train",
        "--case",
        "k4-stht",
        "--layers",
        "2-499-1",
        "--ensemble",
        "1",
        "--epochs",
        "3",
        "--time-limit",
        "0.01",
        "--format",
        "json",
    ]);
    assert_eq!(r["stop_reason"], "time-limit", "{r}");
    assert_eq!(r["epochs"], 0, "{r}");
    assert!(took < Duration::from_secs(30), "{took:?}");
}

#[test]
fn simulate_and_assess_refuse_a_model_past_the_time_domain_limit() {
    let dir = tempfile::tempdir().expect("tempdir");
    let big = chain_preset(dir.path(), 501);
    let big = big.to_str().expect("UTF-8 path");
    for cmd in ["simulate", "assess"] {
        let e = refused_fast(&[
            cmd,
            "--preset",
            big,
            "--signal",
            "sine:freq=5,amp=1",
            "--duration",
            "1",
        ]);
        assert!(
            e.contains("501 segments") && e.contains("at most 500"),
            "{cmd}: {e}"
        );
        assert!(
            e.contains("responses and peaks work at any size"),
            "{cmd}: {e}"
        );
    }
    // The frequency engine still takes it.
    let (code, _, err) = run(&[
        "response", "--preset", big, "--from", "1", "--to", "2", "--step", "1",
    ]);
    assert_eq!(code, Some(0), "{err}");
}

#[test]
fn a_sampling_rate_out_of_range_blames_the_rate_not_a_mass() {
    let dir = tempfile::tempdir().expect("tempdir");
    let rec = dir.path().join("one.csv");
    std::fs::write(&rec, "z_m_s2\n0\n1\n0\n1\n").expect("write");
    let rec = rec.to_str().expect("UTF-8 path");
    let e = fails(&[
        "simulate", "--input", rec, "--fs", "1e-300", "--format", "csv",
    ]);
    assert!(e.contains("a step of 1e300 s"), "{e}");
    assert!(
        e.contains("from 1e-3 to 1e6 Hz") && e.contains("--fs"),
        "{e}"
    );
    assert!(!e.contains("mass"), "{e}");
}

#[test]
fn a_network_scaling_that_overflows_says_what_overflows() {
    let dir = tempfile::tempdir().expect("tempdir");
    let net = dir.path().join("n.json");
    let net_s = net.to_str().expect("UTF-8 path");
    let args = [
        "train",
        "--case",
        "k4-stht",
        "--epochs",
        "2",
        "--ensemble",
        "1",
        "--save",
        net_s,
    ];
    let (code, _, err) = run(&args);
    assert_eq!(code, Some(0), "{err}");
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&net).expect("read")).expect("JSON");
    fn find_inputs(v: &mut serde_json::Value) -> Option<&mut serde_json::Value> {
        match v {
            serde_json::Value::Object(m) => {
                if m.contains_key("inputs") && m.contains_key("margin") {
                    return m.get_mut("inputs");
                }
                m.values_mut().find_map(find_inputs)
            }
            _ => None,
        }
    }
    let inputs = find_inputs(&mut v).expect("a scaling with inputs");
    // k4 is the first input, a log column (ln 54000 = 10.9).
    assert_eq!(inputs[0]["log"], true, "{inputs}");
    inputs[0]["min"] = 10.89.into();
    inputs[0]["max"] = 1e308.into();
    std::fs::write(&net, v.to_string()).expect("write");
    let e = fails(&["predict", "--net", net_s]);
    assert!(e.contains("min = 10.89, max = 1e308 are logarithms"), "{e}");
    assert!(e.contains("overflows f64") && e.contains("retrain"), "{e}");
    assert!(!e.contains("must be finite with min"), "{e}");
}
