//! The Training tab driven through `update`, with the real worker on a
//! manual clock: the test moves time itself and waits for the worker's
//! reports, never sleeping.

use super::*;
use crate::tui::tabs::training::settings::Row;
use biodyn::ManualClock;
use biodyn::ann::MIN_INTERVAL;
use std::sync::mpsc::Receiver;
use std::time::Duration;

/// Feeds worker messages into `update` until `done` holds. With `tick`,
/// the clock moves one report interval before each wait (the throttle
/// then lets one progress report out); without, it stands still. The
/// wait's timeout only guards against a hang.
fn pump(a: &mut App, rx: &Receiver<Msg>, tick: Option<&ManualClock>, done: impl Fn(&App) -> bool) {
    const HANG: Duration = Duration::from_secs(120);
    while !done(a) {
        if let Some(hand) = tick {
            hand.advance(MIN_INTERVAL);
        }
        match rx.recv_timeout(HANG) {
            Ok(m) => update(a, m),
            Err(e) => panic!("no report from the worker within {HANG:?} ({e}): it hangs"),
        }
    }
}

fn epoch(a: &App) -> u64 {
    training(a)
        .run
        .as_ref()
        .and_then(|r| r.last.as_ref())
        .map_or(0, |p| p.epoch)
}

fn rms(a: &App) -> Option<f64> {
    training(a)
        .run
        .as_ref()
        .and_then(|r| r.last.as_ref())
        .map(|p| p.rms)
}

/// Selects `row` with ↓ (at most one round).
fn go_to(a: &mut App, row: Row) {
    for _ in 0..training(a).rows().len() {
        if training(a).current() == row {
            return;
        }
        key(a, KeyCode::Down);
    }
    assert_eq!(training(a).current(), row);
}

fn go_to_named(a: &mut App, name: &str) {
    let row = training(a)
        .rows()
        .into_iter()
        .find(|r| r.name() == name)
        .expect("a row of that name");
    go_to(a, row);
}

#[test]
fn training_starts_pauses_resumes_stops_and_keeps_the_result() {
    let (tx, rx) = std::sync::mpsc::channel();
    let mut a = App::with_channel(Preset::builtin_default(), None, Theme::default(), Some(tx));
    let hand = ManualClock::new();
    a.clock = hand.clock();
    key(&mut a, KeyCode::Char('4'));
    for _ in 0..3 {
        key(&mut a, KeyCode::Right); // mass-stht → k4-stht
    }
    assert_eq!(training(&a).case, biodyn::ann::Case::K4Stht);
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Left); // lm → backprop
    assert_eq!(
        training(&a).settings.trainer,
        biodyn::ann::Trainer::Backprop
    );
    go_to_named(&mut a, "epoch limit");
    key(&mut a, KeyCode::Enter);
    for _ in 0..10 {
        key(&mut a, KeyCode::Backspace);
    }
    typ(&mut a, "50000000");
    key(&mut a, KeyCode::Enter);
    assert_eq!(training(&a).settings.epochs, 50_000_000);
    key(&mut a, KeyCode::Char('t'));
    assert!(training(&a).running());
    pump(&mut a, &rx, Some(&hand), |a| epoch(a) > 0);
    let rms0 = rms(&a);
    assert!(screen(&a, 80, 24).contains("running"));
    key(&mut a, KeyCode::Char(' '));
    pump(&mut a, &rx, None, |a| {
        training(a)
            .run
            .as_ref()
            .and_then(|r| r.last.as_ref())
            .is_some_and(|p| p.paused)
    });
    let e_paused = epoch(&a);
    assert!(screen(&a, 80, 24).contains("paused"));
    // paused time does not count as training time: the clock has stood
    // still since the pause key, so the pause is the 1.2 s it moves now
    hand.advance(Duration::from_millis(1200));
    let paused_s = training(&a).run.as_ref().map(|r| r.paused_s());
    assert_eq!(paused_s, Some(1.2));
    assert!(screen(&a, 80, 24).contains("whole run"));
    key(&mut a, KeyCode::Char('v'));
    assert!(screen(&a, 80, 24).contains("recent window"));
    key(&mut a, KeyCode::Char('v'));
    // other tabs keep working and show the run on the status line, but do
    // not offer the Training tab's keys
    key(&mut a, KeyCode::Char('2'));
    let s = screen(&a, 120, 30);
    assert!(s.contains("paused k4-stht"), "{s}");
    assert!(!s.contains("space pauses"), "{s}");
    // quitting asks while a training runs
    key(&mut a, KeyCode::Char('q'));
    assert!(screen(&a, 80, 24).contains("A training is running"));
    key(&mut a, KeyCode::Char('n'));
    key(&mut a, KeyCode::Char('4'));
    key(&mut a, KeyCode::Char(' '));
    pump(&mut a, &rx, Some(&hand), |a| epoch(a) > e_paused);
    assert_ne!(rms0, rms(&a), "the RMS moved");
    key(&mut a, KeyCode::Char('s'));
    pump(&mut a, &rx, None, |a| !training(a).running());
    let run = training(&a).run.as_ref().expect("run kept");
    let out = run.outcome.as_ref().expect("outcome kept");
    assert_eq!(out.stop, biodyn::ann::StopReason::Cancelled);
    let f = run.finished.as_ref().expect("finished");
    // the worker's clock counts the pause, the panel's time leaves it out
    let ticks = hand.elapsed() - Duration::from_millis(1200);
    assert_eq!(f.train_seconds, hand.elapsed().as_secs_f64());
    assert!((run.working_s(f.train_seconds) - ticks.as_secs_f64()).abs() < 1e-9);
    for (w, h) in [(80, 24), (60, 16)] {
        let s = screen(&a, w, h);
        assert!(s.contains("RMS") && s.contains("MPRE"), "{w}x{h}:\n{s}");
        assert!(s.contains("of the final net"), "{w}x{h}:\n{s}");
        if w == 80 {
            // the prediction keeps its frame: the loss curve steps aside
            assert!(s.lines().any(|l| l.contains("┌STHT at")), "{s}");
        }
        assert!(!s.contains('…'), "nothing cut at {w}x{h}:\n{s}");
    }
    assert_eq!(out.holdout.len(), 4);
    assert!(run.prediction.is_some());
    for (w, h) in [(80, 24), (160, 48)] {
        let s = screen(&a, w, h);
        assert!(s.contains("ended: cancelled"), "{s}");
        assert!(s.contains("interp") && s.contains("extrap"), "{s}");
    }
    // the prediction's errors are the library's, for the same curve
    let p = run.prediction.as_ref().expect("prediction");
    let h = out
        .holdout
        .iter()
        .find(|h| (h.value - p.value).abs() < 1e-9 * h.value)
        .expect("the shown value is a hold-out value");
    assert!((h.max_err_pct - p.max_err_pct).abs() < 1e-9 * h.max_err_pct.max(1.0));
    assert_eq!(h.extrapolation, p.extrapolation);
    // the held-out value picks another prediction
    let before = p.value;
    go_to(&mut a, Row::Holdout);
    key(&mut a, KeyCode::Right);
    let after = training(&a)
        .run
        .as_ref()
        .and_then(|r| r.prediction.as_ref())
        .map(|p| p.value);
    assert_ne!(Some(before), after);
    // save the network
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("net.json");
    key(&mut a, KeyCode::Char('w'));
    if let Some(f) = a.field.as_mut() {
        f.set_text(path.display().to_string());
    }
    key(&mut a, KeyCode::Enter);
    assert!(a.field.is_none(), "{:?}", a.field);
    assert!(biodyn::ann::load_network(&path).is_ok());
    // saving again over it asks first, as the preset save does
    key(&mut a, KeyCode::Char('w'));
    if let Some(f) = a.field.as_mut() {
        f.set_text(path.display().to_string());
    }
    key(&mut a, KeyCode::Enter);
    let e = field_error(&a);
    assert!(e.contains("Enter again replaces it"), "{e}");
    key(&mut a, KeyCode::Enter);
    assert!(a.field.is_none(), "{:?}", a.field);
    // a folder is refused at once
    key(&mut a, KeyCode::Char('w'));
    if let Some(f) = a.field.as_mut() {
        f.set_text(dir.path().display().to_string());
    }
    key(&mut a, KeyCode::Enter);
    let e = field_error(&a);
    assert!(e.contains("Is a directory"), "{e}");
    // a pipe is refused at once too, not after "exists: Enter again"
    let fifo = dir.path().join("pipe.json");
    let made = std::process::Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .expect("mkfifo runs");
    assert!(made.success());
    if let Some(f) = a.field.as_mut() {
        f.set_text(fifo.display().to_string());
    }
    key(&mut a, KeyCode::Enter);
    let e = field_error(&a);
    assert!(
        e.contains("not a regular file") && !e.contains("exists"),
        "{e}"
    );
}

#[test]
fn epoch_limits_and_layer_lists_are_refused_in_one_voice() {
    let mut a = app();
    key(&mut a, KeyCode::Char('4'));
    let refusal = |a: &mut App, row: &str, text: &str| {
        go_to_named(a, row);
        key(a, KeyCode::Enter);
        typ(a, text);
        key(a, KeyCode::Enter);
        let e = a.field.as_ref().and_then(|f| f.error.clone());
        key(a, KeyCode::Esc);
        e.unwrap_or_default()
    };
    let minus = refusal(&mut a, "epoch limit", "-5");
    let zero = refusal(&mut a, "epoch limit", "0");
    assert!(
        minus.contains(">= 1") && zero.contains(">= 1"),
        "{minus} / {zero}"
    );
    let double = refusal(&mut a, "layers", "5--1");
    let nought = refusal(&mut a, "layers", "5-0-1");
    assert!(
        !double.is_empty() && !nought.is_empty(),
        "{double} / {nought}"
    );
}

#[test]
fn bad_training_settings_are_refused() {
    let mut a = app();
    key(&mut a, KeyCode::Char('4'));
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Left); // lm → backprop: momentum is listed
    go_to_named(&mut a, "momentum");
    key(&mut a, KeyCode::Enter);
    for _ in 0..10 {
        key(&mut a, KeyCode::Backspace);
    }
    typ(&mut a, "1.5");
    key(&mut a, KeyCode::Enter);
    assert!(a.field.as_ref().is_some_and(|f| f.error.is_some()));
    assert_eq!(training(&a).settings.momentum, 0.9);
    key(&mut a, KeyCode::Esc);
    go_to_named(&mut a, "layers");
    key(&mut a, KeyCode::Enter);
    for _ in 0..20 {
        key(&mut a, KeyCode::Backspace);
    }
    typ(&mut a, "3-4-1");
    key(&mut a, KeyCode::Enter);
    let e = field_error(&a);
    assert!(e.contains('5') || e.contains("input"), "{e}");
}

#[test]
fn lm_lists_its_own_settings_and_they_are_settable() {
    let mut a = app();
    key(&mut a, KeyCode::Char('4'));
    assert_eq!(training(&a).settings.trainer, biodyn::ann::Trainer::Lm);
    let s = screen(&a, 160, 48);
    assert!(
        !s.contains("momentum") && !s.contains("learning rate"),
        "{s}"
    );
    for want in ["ensemble size", "log target", "weight decay"] {
        assert!(s.contains(want), "{want}:\n{s}");
    }
    let set = |a: &mut App, row: &str, text: &str| {
        go_to_named(a, row);
        key(a, KeyCode::Enter);
        if let Some(f) = a.field.as_mut() {
            f.set_text(text);
        }
        key(a, KeyCode::Enter);
    };
    set(&mut a, "weight decay", "-1");
    assert!(a.field.as_ref().is_some_and(|f| f.error.is_some()));
    key(&mut a, KeyCode::Esc);
    set(&mut a, "weight decay", "1e-4");
    assert_eq!(training(&a).settings.weight_decay, 1e-4);
    set(&mut a, "ensemble size", "0");
    assert!(a.field.as_ref().is_some_and(|f| f.error.is_some()));
    key(&mut a, KeyCode::Esc);
    set(&mut a, "ensemble size", "2");
    assert_eq!(training(&a).settings.ensemble, 2);
    set(&mut a, "log target", "false");
    assert!(!training(&a).settings.log_target);
    assert_eq!(a.status.text, "log target = false");
    // ←→ toggles a flag in place
    key(&mut a, KeyCode::Right);
    assert!(training(&a).settings.log_target);
    assert_eq!(a.status.text, "log target = true");
}
