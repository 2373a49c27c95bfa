//! Integration tests of the network side: determinism, metrics against
//! independent computations, divergence, stop reasons, files, bad input
//! (the worker thread: `worker.rs`).

use biodyn::ann::{
    self, AnnError, Case, Flow, Scaling, Settings, StopReason, Trainer, train, train_with,
    worst_holdout,
};
use biodyn::{Band, ManualClock, Solver};
use std::time::Duration;

fn quick_bp(case: Case, epochs: u64) -> Settings {
    let mut s = Settings::paper(case);
    s.epochs = epochs;
    s
}

fn quick_lm(case: Case, epochs: u64, ensemble: usize) -> Settings {
    let mut s = Settings::lm(case);
    s.epochs = epochs;
    s.ensemble = ensemble;
    s
}

fn go(case: Case, s: &Settings) -> biodyn::ann::Outcome {
    train(case, s, &mut |_| Flow::Continue).unwrap()
}

#[test]
fn same_seed_gives_bit_identical_runs_and_another_seed_differs() {
    for (case, s) in [
        (Case::K4Dpmi, quick_bp(Case::K4Dpmi, 40)),
        (Case::MassStht, quick_lm(Case::MassStht, 5, 2)),
    ] {
        let a = go(case, &s);
        let b = go(case, &s);
        assert_eq!(
            a.net, b.net,
            "{case}: weights differ between identical runs"
        );
        assert_eq!(a.rms.map(f64::to_bits), b.rms.map(f64::to_bits));
        assert_eq!(a.mpre_pct.map(f64::to_bits), b.mpre_pct.map(f64::to_bits));
        assert_eq!(a.holdout, b.holdout);
        let mut other = s.clone();
        other.seed += 1;
        let c = go(case, &other);
        assert_ne!(a.net.members[0].params, c.net.members[0].params);
        assert_ne!(a.rms, c.rms);
    }
}

#[test]
fn reported_metrics_match_an_independent_computation() {
    let case = Case::K4Apms;
    let s = quick_bp(case, 30);
    let out = go(case, &s);
    // Recompute training RMS (scaled) and MPRE (physical) by hand from the
    // analytic engine and the net's raw forward pass.
    let (mut se, mut n, mut mpre, mut right) = (0.0, 0.0, 0.0f64, 0.0);
    for &k4 in &s.train_values {
        let body = case.body_at(k4).unwrap();
        let solver = Solver::new(&body);
        for f in s.grid.freqs() {
            let actual = solver.at(f).apms.norm();
            let mut x = [0.0; 2];
            out.net.scaling.scale_inputs(&[k4, f], &mut x);
            let y = out.net.members[0].eval(&x)[0];
            let d = out.net.scaling.scale_output(actual);
            se += (y - d) * (y - d);
            n += 1.0;
            if (y - d).abs() <= s.train_tolerance {
                right += 1.0;
            }
            let phys = out.net.scaling.unscale_output(y);
            mpre = mpre.max(100.0 * (phys - actual).abs() / actual);
        }
    }
    assert_eq!(n, 120.0);
    let rms = (se / n).sqrt();
    assert!(
        (out.rms.unwrap() - rms).abs() < 1e-12,
        "{:?} vs {rms}",
        out.rms
    );
    assert!((out.mpre_pct.unwrap() - mpre).abs() < 1e-9);
    assert!((out.share_right.unwrap() - right / n).abs() < 1e-12);
    // Hold-out: four curves of 196 points, two inside and two outside.
    assert_eq!(out.holdout.len(), 4);
    let ext: Vec<bool> = out.holdout.iter().map(|h| h.extrapolation).collect();
    assert_eq!(ext, [true, false, false, true]);
    let h = &out.holdout[1];
    let body = case.body_at(h.value).unwrap();
    let freqs = Band::default().freqs();
    let pred = out.net.predict_body(&body, &freqs).unwrap();
    let solver = Solver::new(&body);
    let actual: Vec<f64> = freqs.iter().map(|&f| solver.at(f).apms.norm()).collect();
    let (max, mean) = ann::curve_error(&pred, &actual);
    assert!((h.max_err_pct - max).abs() < 1e-12 && (h.mean_err_pct - mean).abs() < 1e-12);
    assert_eq!(
        worst_holdout(&out.holdout, false),
        Some(out.holdout[1].max_err_pct.max(out.holdout[2].max_err_pct))
    );
}

#[test]
fn absurd_learning_rate_diverges_and_reports_no_numbers() {
    let case = Case::MassDpmi;
    let mut s = quick_bp(case, 200);
    s.learning_rate = 1e300;
    let out = go(case, &s);
    assert!(out.stop.is_diverged(), "stop = {}", out.stop);
    assert_eq!(out.rms, None);
    assert_eq!(out.mpre_pct, None);
    assert!(out.holdout.is_empty());
    let json = serde_json::to_string(&out.report()).unwrap();
    assert!(!json.contains("NaN") && !json.contains("inf"), "{json}");
    assert!(json.contains("\"stop_reason\":\"diverged\""));
}

#[test]
fn stop_reasons_are_reported() {
    let case = Case::K4Stht;
    let mut s = quick_bp(case, 1000);
    s.rms_target = Some(10.0);
    let out = go(case, &s);
    assert_eq!((out.stop.clone(), out.epochs()), (StopReason::RmsTarget, 1));

    let mut s = quick_bp(case, 1000);
    s.mpre_target_pct = Some(1e9);
    assert_eq!(go(case, &s).stop, StopReason::MpreTarget);

    let mut s = quick_bp(case, 1000);
    s.train_tolerance = 10.0;
    assert_eq!(go(case, &s).stop, StopReason::AllRight);

    let s = quick_bp(case, 7);
    let out = go(case, &s);
    assert_eq!(
        (out.stop.clone(), out.epochs()),
        (StopReason::EpochLimit, 7)
    );

    // The time limit, on a clock the observer moves: one second passes
    // in epoch 5, so the run stops there, with a second of training time.
    let mut s = quick_bp(case, 1000);
    s.time_limit_s = Some(1.0);
    let hand = ManualClock::new();
    let out = train_with(
        case,
        &s,
        &hand.clock(),
        &mut |st| {
            if st.epoch == 5 {
                hand.advance(Duration::from_secs(1));
            }
            Flow::Continue
        },
        None,
    )
    .unwrap();
    assert_eq!(
        (out.stop.clone(), out.epochs(), out.train_seconds),
        (StopReason::TimeLimit, 5, 1.0)
    );

    let s = quick_bp(case, 1000);
    let mut count = 0;
    let out = train(case, &s, &mut |_| {
        count += 1;
        if count == 3 {
            Flow::Cancel
        } else {
            Flow::Continue
        }
    })
    .unwrap();
    assert_eq!((out.stop.clone(), out.epochs()), (StopReason::Cancelled, 3));
}

#[test]
fn lm_lowers_the_error_and_ensemble_has_five_members() {
    let case = Case::K4Apms;
    let s = quick_lm(case, 15, 5);
    let mut first = None;
    let mut last = 0.0;
    let out = train(case, &s, &mut |st| {
        if st.member == 0 {
            first.get_or_insert(st.rms);
            last = st.rms;
        }
        Flow::Continue
    })
    .unwrap();
    assert_eq!(out.net.members.len(), 5);
    assert!(
        last < first.unwrap() * 0.5,
        "LM did not converge: {first:?} -> {last}"
    );
    assert!(out.mpre_pct.unwrap() < 50.0);
}

#[test]
fn scaling_round_trips_inside_and_outside_the_trained_range() {
    let rows = vec![vec![54_000.0, 0.5], vec![126_000.0, 20.0]];
    let s = Scaling::fit(&rows, &[0.9, 80.0], &[false, true], true, 0.1, (0.0, 1.0)).unwrap();
    for v in [0.5, 0.9, 12.0, 80.0, 95.0] {
        assert!((s.unscale_output(s.scale_output(v)) - v).abs() / v < 1e-13);
    }
    let mut x = [0.0; 2];
    s.scale_inputs(&[54_000.0, 20.0], &mut x);
    assert!((x[0] - 1.0 / 12.0).abs() < 1e-14);
    assert!((x[1] - 11.0 / 12.0).abs() < 1e-14);
    assert!((s.unscale_input(1, x[1]) - 20.0).abs() < 1e-12);
}

#[test]
fn network_file_round_trips_bit_for_bit_and_leaves_no_temp_file() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("net.json");
    let case = Case::MassApms;
    let out = go(case, &quick_lm(case, 3, 2));
    ann::save_network(&path, &out.net).unwrap();
    let back = ann::load_network(&path).unwrap();
    assert_eq!(back, out.net);
    let x = [5.0, 28.0, 8.5, 12.7, 3.3];
    assert_eq!(back.predict(&x).to_bits(), out.net.predict(&x).to_bits());
    let names: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names, vec![std::ffi::OsString::from("net.json")]);
    assert!(ann::load_network_expect(&path, case, Some(&[5, 6, 4, 1])).is_ok());
}

#[test]
fn bad_network_files_are_clear_errors() {
    let dir = tempfile::tempdir().unwrap();
    let case = Case::K4Stht;
    let out = go(case, &quick_bp(case, 2));
    let good = dir.path().join("good.json");
    ann::save_network(&good, &out.net).unwrap();
    let text = std::fs::read_to_string(&good).unwrap();

    let missing = ann::load_network(&dir.path().join("nope.json")).unwrap_err();
    assert!(matches!(missing, AnnError::Io { .. }), "{missing}");

    let write = |name: &str, body: &str| {
        let p = dir.path().join(name);
        std::fs::write(&p, body).unwrap();
        p
    };
    for (name, body) in [
        ("garbage.json", "this is not json"),
        ("truncated.json", &text[..text.len() / 2]),
        (
            "other-format.json",
            &text.replace("biodyn-network", "something-else"),
        ),
        (
            "unknown-case.json",
            &text.replace("\"k4-stht\"", "\"k4-zzz\""),
        ),
        ("empty.json", ""),
    ] {
        let e = ann::load_network(&write(name, body)).unwrap_err();
        assert!(matches!(e, AnnError::Corrupted { .. }), "{name}: {e}");
        assert!(
            e.to_string().contains(name),
            "error must name the file: {e}"
        );
    }
    let e = ann::load_network(&write(
        "v9.json",
        &text.replace("\"version\": 1", "\"version\": 9"),
    ))
    .unwrap_err();
    assert!(matches!(e, AnnError::WrongVersion { found: 9, .. }), "{e}");

    // Architecture that does not match the stored weights.
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    v["network"]["members"][0]["layers"] = serde_json::json!([2, 6, 3, 1]);
    v["network"]["settings"]["layers"] = serde_json::json!([2, 6, 3, 1]);
    let e = ann::load_network(&write("arch.json", &v.to_string())).unwrap_err();
    assert!(
        matches!(e, AnnError::Corrupted { .. }) && e.to_string().contains("weights"),
        "{e}"
    );
    v["network"]["members"][0]["layers"] = serde_json::json!([5, 5, 3, 1]);
    v["network"]["settings"]["layers"] = serde_json::json!([5, 5, 3, 1]);
    let e = ann::load_network(&write("inputs.json", &v.to_string())).unwrap_err();
    assert!(e.to_string().contains("first layer must have 2"), "{e}");

    let e = ann::load_network_expect(&good, Case::MassStht, None).unwrap_err();
    assert!(
        matches!(
            e,
            AnnError::WrongCase {
                expected: "mass-stht",
                found: "k4-stht",
                ..
            }
        ),
        "{e}"
    );
    let e = ann::load_network_expect(&good, case, Some(&[2, 8, 1])).unwrap_err();
    assert!(matches!(e, AnnError::WrongArchitecture { .. }), "{e}");
}

#[test]
fn bad_settings_are_refused_with_the_field_named() {
    let case = Case::MassStht;
    let check = |f: &dyn Fn(&mut Settings), want: &str| {
        let mut s = Settings::paper(case);
        f(&mut s);
        let e = train(case, &s, &mut |_| Flow::Continue)
            .unwrap_err()
            .to_string();
        assert!(e.contains(want), "expected '{want}' in: {e}");
    };
    check(&|s| s.layers = vec![5, 0, 1], "layer 2 has 0 neurons");
    check(&|s| s.layers = vec![2, 5, 1], "first layer must have 5");
    check(&|s| s.layers = vec![5, 3, 2], "one output");
    check(&|s| s.layers = vec![5], "at least an input and an output");
    check(&|s| s.epochs = 0, "epochs = 0");
    check(&|s| s.learning_rate = 0.0, "learning rate = 0");
    check(&|s| s.learning_rate = -1.0, "learning rate = -1");
    check(&|s| s.learning_rate = f64::NAN, "learning rate = NaN");
    check(&|s| s.momentum = 1.0, "momentum = 1");
    check(&|s| s.momentum = -0.1, "momentum = -0.1");
    check(&|s| s.momentum = f64::NAN, "momentum = NaN");
    check(&|s| s.ensemble = 0, "ensemble = 0");
    check(&|s| s.train_values = vec![], "no training values");
    check(&|s| s.train_values = vec![65.0, -1.0], "body_mass = -1");
    check(&|s| s.scaling_margin = -0.5, "scaling margin = -0.5");
    check(
        &|s| s.train_tolerance = f64::INFINITY,
        "train_tolerance = inf",
    );
    assert!(matches!(
        Case::parse("mass-xyz"),
        Err(AnnError::UnknownCase(_))
    ));
    assert!(matches!(
        Trainer::parse("adam"),
        Err(AnnError::UnknownTrainer(_))
    ));
}

#[test]
fn ensemble_median_and_mean_combine_the_members() {
    let case = Case::K4Stht;
    let mut s = quick_lm(case, 2, 3);
    s.combine = biodyn::ann::Combine::Median;
    let out = go(case, &s);
    let net = &out.net;
    let raw = [80_000.0, 4.5];
    let mut x = [0.0; 2];
    net.scaling.scale_inputs(&raw, &mut x);
    let mut ys: Vec<f64> = net
        .members
        .iter()
        .map(|m| net.scaling.unscale_output(m.eval(&x)[0]))
        .collect();
    assert!(ys[0] != ys[1] && ys[1] != ys[2], "members should differ");
    let mean = ys.iter().sum::<f64>() / 3.0;
    ys.sort_by(f64::total_cmp);
    assert_eq!(net.predict(&raw), ys[1]);
    let mut as_mean = net.clone();
    as_mean.settings.combine = biodyn::ann::Combine::Mean;
    assert_eq!(as_mean.predict(&raw), mean);
}

/// `compare` against an independent computation: the analytic engine on the
/// case's body and the net's own point predictions; the hold-out report is
/// the same comparison.
#[test]
fn compare_matches_the_engine_and_the_holdout_report() {
    let case = Case::K4Apms;
    let out = go(case, &quick_lm(case, 3, 2));
    let band = Band::new(0.5, 20.0, 0.5).unwrap();
    for &v in &case.holdout_values() {
        let c = out.net.compare(v, &band).unwrap();
        let body = case.body_at(v).unwrap();
        let solver = Solver::new(&body);
        assert_eq!(c.freqs, band.freqs());
        let mut max = 0.0f64;
        let mut sum = 0.0;
        for (i, &f) in c.freqs.iter().enumerate() {
            let an = solver.at(f).mag(case.function());
            let pr = out.net.predict(&case.inputs_of(&body, f).unwrap());
            assert_eq!(c.analytic[i], an);
            assert_eq!(c.predicted[i], pr);
            let e = 100.0 * (pr - an).abs() / an.abs();
            assert!((c.err_pct[i] - e).abs() <= 1e-12 * e.max(1.0));
            max = max.max(e);
            sum += e;
        }
        assert!((c.max_err_pct - max).abs() <= 1e-12 * max.max(1.0));
        assert!((c.mean_err_pct - sum / c.freqs.len() as f64).abs() <= 1e-9);
        assert_eq!(c.extrapolation, !(54_000.0..=126_000.0).contains(&v));
        assert!(!c.beyond_grid);
    }
    let h = biodyn::ann::evaluate_holdouts(&out.net, &[72_000.0], &band).unwrap();
    let c = out.net.compare(72_000.0, &band).unwrap();
    assert_eq!(h[0].max_err_pct, c.max_err_pct);
    assert_eq!(h[0].mean_err_pct, c.mean_err_pct);
    let wide = Band::new(0.5, 1e5, 1e3).unwrap();
    assert!(out.net.compare(72_000.0, &wide).unwrap().beyond_grid);
    assert!(out.net.compare(-1.0, &band).is_err());
}

/// Both trainers sit behind the one trait, and each names its own kind.
#[test]
fn every_trainer_kind_has_its_algorithm() {
    for k in Trainer::ALL {
        assert_eq!(biodyn::ann::algorithm_for(k).trainer(), k);
    }
}
