//! The Training tab's runs: the runs table after two runs (and its
//! snapshot), a network loaded back from a file, the "model" row
//! (predictions on the model being edited) and a FIFO refused as a file.

use super::*;
use crate::tui::tabs::training::RunRecord;
use crate::tui::tabs::training::settings::Row;
use biodyn::ann::{Case, Trainer};
use std::sync::mpsc::Receiver;

pub(super) fn pump(a: &mut App, rx: &Receiver<Msg>, done: impl Fn(&App) -> bool) {
    let end = std::time::Instant::now() + std::time::Duration::from_secs(60);
    while !done(a) && std::time::Instant::now() < end {
        if let Ok(m) = rx.recv_timeout(std::time::Duration::from_millis(20)) {
            update(a, m);
        }
    }
    assert!(done(a), "timed out waiting for the worker");
}

pub(super) fn go_to_named(a: &mut App, name: &str) {
    for _ in 0..training(a).rows().len() {
        if training(a).current().name() == name {
            return;
        }
        key(a, KeyCode::Down);
    }
    assert_eq!(training(a).current().name(), name);
}

/// Sets a text setting of the Training tab.
pub(super) fn set(a: &mut App, row: &str, text: &str) {
    go_to_named(a, row);
    key(a, KeyCode::Enter);
    typ(a, text);
    key(a, KeyCode::Enter);
    assert!(a.field.is_none(), "{row} = {text}: {:?}", a.field);
}

/// A backprop run of a few epochs on the training tab, to its end.
pub(super) fn short_run(a: &mut App, rx: &Receiver<Msg>, seed: &str) {
    set(a, "seed", seed);
    key(a, KeyCode::Char('t'));
    assert!(training(a).running(), "{}", a.status.text);
    pump(a, rx, |a| !training(a).running());
}

pub(super) fn channel_app() -> (App, Receiver<Msg>) {
    let (tx, rx) = std::sync::mpsc::channel();
    let a = App::with_channel(Preset::builtin_default(), None, Theme::default(), Some(tx));
    (a, rx)
}

pub(super) fn backprop(a: &mut App) {
    key(a, KeyCode::Char('4'));
    go_to_named(a, "trainer");
    key(a, KeyCode::Left);
    assert_eq!(training(a).settings.trainer, biodyn::ann::Trainer::Backprop);
    set(a, "epoch limit", "30");
}

#[test]
fn the_runs_table_fills_after_two_short_runs() {
    let (mut a, rx) = channel_app();
    backprop(&mut a);
    short_run(&mut a, &rx, "1");
    short_run(&mut a, &rx, "2");
    let runs = &training(&a).history.runs;
    assert_eq!(runs.len(), 2);
    assert_eq!((runs[0].seed, runs[1].seed), (1, 2));
    assert!(
        runs.iter()
            .all(|r| r.member_epochs == [30] && r.rms.is_some())
    );
    // Different seeds, different networks.
    assert_ne!(runs[0].rms, runs[1].rms);
    // The held-out columns are the run's own held-out results.
    let out = training(&a)
        .run
        .as_ref()
        .and_then(|r| r.outcome.as_ref())
        .expect("outcome");
    let worst = out
        .holdout
        .iter()
        .map(|h| h.max_err_pct)
        .fold(0.0, f64::max);
    assert_eq!(runs[1].holdout_max_pct, Some(worst));
    let s = screen(&a, 160, 48);
    assert!(s.contains("last 2 runs"), "{s}");
    assert!(s.contains("seed"), "{s}");
    let s = screen(&a, 80, 24);
    assert!(s.contains("last 2 runs"), "{s}");
}

#[test]
fn a_network_saved_by_the_library_loads_back_and_predicts() {
    let (mut a, rx) = channel_app();
    backprop(&mut a);
    short_run(&mut a, &rx, "7");
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("net.json");
    let out = training(&a)
        .run
        .as_ref()
        .and_then(|r| r.outcome.as_ref())
        .expect("outcome");
    biodyn::ann::save_network(&path, &out.net).expect("library saves");
    let expected = out
        .net
        .compare(70.0, &biodyn::Band::default())
        .expect("compare");

    // A fresh app (no run) loads it.
    let mut b = app();
    key(&mut b, KeyCode::Char('4'));
    key(&mut b, KeyCode::Char('o'));
    assert!(
        b.field.as_ref().is_some_and(|f| f.path),
        "a path field (~, Tab)"
    );
    typ(&mut b, &path.display().to_string());
    key(&mut b, KeyCode::Enter);
    assert!(b.field.is_none(), "{:?}", b.field);
    assert!(b.status.text.starts_with("loaded"), "{}", b.status.text);
    let p = training(&b).prediction().expect("prediction");
    // At the selected held-out value (70 kg), by the library's compare.
    assert_eq!(p.value, 70.0);
    assert_eq!(p.max_err_pct, expected.max_err_pct);
    let s = screen(&b, 160, 48);
    assert!(s.contains("net.json: STHT at 70 kg"), "{s}");
    // A file that is not a network is refused with the library's reason.
    std::fs::write(dir.path().join("bad.json"), "{}").expect("write");
    key(&mut b, KeyCode::Char('o'));
    typ(&mut b, &dir.path().join("bad.json").display().to_string());
    key(&mut b, KeyCode::Enter);
    let why = b
        .field
        .as_ref()
        .and_then(|f| f.error.clone())
        .expect("refused");
    assert!(why.contains("bad.json"), "{why}");
}

#[test]
fn the_model_row_predicts_on_the_edited_model() {
    let (mut a, rx) = channel_app();
    backprop(&mut a);
    short_run(&mut a, &rx, "3");
    let paper = training(&a).prediction().expect("prediction").clone();
    // Make the model heavier (m2 = 40 kg), then choose "this model".
    key(&mut a, KeyCode::Char('1'));
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Enter);
    typ(&mut a, "40");
    key(&mut a, KeyCode::Enter);
    key(&mut a, KeyCode::Char('4'));
    go_to_named(&mut a, "model");
    assert_eq!(training(&a).current(), Row::Model);
    key(&mut a, KeyCode::Right);
    assert!(training(&a).this_model);
    let net = &training(&a)
        .run
        .as_ref()
        .and_then(|r| r.outcome.as_ref())
        .expect("out")
        .net;
    // On this model brought to the held-out value the row shows (70 kg),
    // where the table's ◀ points, not at the model's own body mass.
    let (net, model) = (net.clone(), a.shared.body.clone());
    let on = |v: f64| {
        let body = net.case.body_on(Some(&model), v).expect("body");
        net.compare_body(&body, &biodyn::Band::default())
            .expect("compare")
    };
    let want = on(70.0);
    assert_eq!(training(&a).holdout_value(), 70.0);
    let p = training(&a).prediction().expect("prediction on this model");
    assert_eq!((p.value, p.max_err_pct), (70.0, want.max_err_pct));
    assert_ne!(p.max_err_pct, paper.max_err_pct);
    let s = screen(&a, 80, 24);
    assert!(s.contains("STHT this model at 70 kg"), "{s}");
    assert!(
        s.lines().any(|l| l.contains(" 70 kg") && l.contains('◀')),
        "{s}"
    );
    // Another held-out value moves the chart with it.
    go_to_named(&mut a, "held-out value");
    key(&mut a, KeyCode::Right);
    let p = training(&a).prediction().expect("prediction on this model");
    assert_eq!((p.value, p.max_err_pct), (80.0, on(80.0).max_err_pct));
    assert!(screen(&a, 80, 24).contains("STHT this model at 80 kg"));
    go_to_named(&mut a, "model");
    // t now trains on this model (training_model.rs tests it in full).
    key(&mut a, KeyCode::Char('t'));
    assert!(
        !a.status.error && a.status.text.contains("snapshot of this model"),
        "{}",
        a.status.text
    );
    pump(&mut a, &rx, |a| !training(a).running());
    // A model the network cannot read (3 segments): said, not drawn.
    key(&mut a, KeyCode::Char('1'));
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Char('d'));
    key(&mut a, KeyCode::Char('y'));
    assert_eq!(a.shared.body.segments.len(), 3);
    assert!(training(&a).prediction().is_none());
    key(&mut a, KeyCode::Char('4'));
    assert!(screen(&a, 160, 48).contains("no prediction on this model"));
}

#[cfg(unix)]
#[test]
fn loading_a_fifo_is_refused_without_blocking() {
    let dir = tempfile::tempdir().expect("tempdir");
    let fifo = dir.path().join("pipe.json");
    let made = std::process::Command::new("mkfifo").arg(&fifo).status();
    if !made.is_ok_and(|s| s.success()) {
        // As tests/common's skip: .ci/run forbids skipping.
        assert_ne!(
            std::env::var("BIODYN_REQUIRE_TOOLS").as_deref(),
            Ok("1"),
            "mkfifo not available, and BIODYN_REQUIRE_TOOLS=1 forbids skipping"
        );
        eprintln!("mkfifo not available: skipped");
        return;
    }
    let mut a = app();
    key(&mut a, KeyCode::Char('4'));
    key(&mut a, KeyCode::Char('o'));
    typ(&mut a, &fifo.display().to_string());
    key(&mut a, KeyCode::Enter);
    let why = a
        .field
        .as_ref()
        .and_then(|f| f.error.clone())
        .expect("refused");
    assert!(
        why.ends_with("not a regular file; give a network file (.json)"),
        "{why}"
    );
}

fn snap(name: &str, a: &App) {
    for (w, h) in [(80, 24), (160, 48)] {
        insta::assert_snapshot!(format!("{name}_{w}x{h}"), screen(a, w, h));
    }
}

/// Fixed records (the drawing is under test, not the training).
fn record(i: u64) -> RunRecord {
    RunRecord {
        case: if i % 2 == 0 {
            Case::MassStht
        } else {
            Case::K4Stht
        },
        trainer: if i % 2 == 0 {
            Trainer::Lm
        } else {
            Trainer::Backprop
        },
        seed: i,
        member_epochs: if i % 2 == 0 {
            vec![100 * i; 5]
        } else {
            vec![100 * i]
        },
        seconds: 0.25 * i as f64,
        rms: Some(0.01 * i as f64),
        mpre_pct: Some(3.5 * i as f64),
        holdout_max_pct: Some(12.0 + i as f64),
        holdout_mean_pct: Some(4.0 + i as f64 / 10.0),
        stop: "epoch limit".into(),
        body: if i % 3 == 0 { "5 seg" } else { "paper" }.into(),
    }
}

#[test]
fn training_runs_table() {
    let mut a = app();
    key(&mut a, KeyCode::Char('4'));
    let t = a
        .tabs
        .iter_mut()
        .find_map(|t| (t.as_mut() as &mut dyn std::any::Any).downcast_mut::<TrainingTab>())
        .expect("training tab");
    for i in 1..=10 {
        t.history.push(record(i));
    }
    assert_eq!(t.history.runs.len(), crate::tui::tabs::training::RUNS_KEPT);
    assert_eq!(
        t.history.runs.front().map(|r| r.seed),
        Some(3),
        "the oldest went"
    );
    snap("training_runs_table", &a);
}
