//! The Training tab on "this model": `t` trains on a snapshot of the model
//! being edited (its inputs, layers and held-out values follow it), a model
//! the case cannot use is refused with the library's reason, and the mouse
//! selects and edits settings rows.

use super::*;
use biodyn::ann::{Case, Trainer};
use biodyn::{Band, Body, Function, Param, Solver};
use ratatui::crossterm::event::{MouseButton, MouseEventKind};
use std::sync::mpsc::Receiver;

fn pump(a: &mut App, rx: &Receiver<Msg>, done: impl Fn(&App) -> bool) {
    let end = std::time::Instant::now() + std::time::Duration::from_secs(60);
    while !done(a) && std::time::Instant::now() < end {
        if let Ok(m) = rx.recv_timeout(std::time::Duration::from_millis(20)) {
            update(a, m);
        }
    }
    assert!(done(a), "timed out waiting for the worker");
}

fn go_to_named(a: &mut App, name: &str) {
    for _ in 0..training(a).rows().len() {
        if training(a).current().name() == name {
            return;
        }
        key(a, KeyCode::Down);
    }
    assert_eq!(training(a).current().name(), name);
}

fn set(a: &mut App, row: &str, text: &str) {
    go_to_named(a, row);
    key(a, KeyCode::Enter);
    typ(a, text);
    key(a, KeyCode::Enter);
    assert!(a.field.is_none(), "{row} = {text}: {:?}", a.field);
}

fn channel_app() -> (App, Receiver<Msg>) {
    let (tx, rx) = std::sync::mpsc::channel();
    let a = App::with_channel(Preset::builtin_default(), None, Theme::default(), Some(tx));
    (a, rx)
}

/// The "model" row on "this model".
fn this_model(a: &mut App) {
    go_to_named(a, "model");
    if !training(a).this_model {
        key(a, KeyCode::Right);
    }
    assert!(training(a).this_model);
}

/// Tab 1: a fifth segment "arm" (5 kg) hanging off the chest.
fn add_arm(a: &mut App) {
    key(a, KeyCode::Char('1'));
    key(a, KeyCode::Down);
    key(a, KeyCode::Down);
    key(a, KeyCode::Char('a'));
    typ(a, "arm 5 chest 1e5 500");
    key(a, KeyCode::Enter);
    assert_eq!(a.shared.body.n(), 5, "{}", a.status.text);
}

#[test]
fn t_trains_on_a_snapshot_of_the_edited_five_segment_model() {
    let (mut a, rx) = channel_app();
    add_arm(&mut a);
    let edited = a.shared.body.clone();
    key(&mut a, KeyCode::Char('4'));
    set(&mut a, "ensemble size", "1");
    set(&mut a, "epoch limit", "5");
    assert_eq!(training(&a).settings.layers[0], 5, "paper: m1..m4 and f");
    this_model(&mut a);
    // The inputs follow the model: m1..m5 and f.
    assert_eq!(training(&a).settings.layers[0], 6);
    assert!(screen(&a, 120, 40).contains("6-6-4-2-1"));
    key(&mut a, KeyCode::Char('t'));
    assert!(training(&a).running(), "{}", a.status.text);
    assert!(
        a.status.text.contains("snapshot of this model"),
        "{}",
        a.status.text
    );
    // An edit while it runs changes the next run, not this one.
    a.set_param(Param::Mass(4), 7.0).expect("m5 = 7");
    pump(&mut a, &rx, |a| !training(a).running());
    let run = training(&a).run.as_ref().expect("run");
    assert_eq!(run.settings.base.as_ref(), Some(&edited));
    let out = run.outcome.as_ref().expect("outcome");
    assert_eq!(out.net.base(), Some(&edited));
    assert_eq!(out.net.input_names().len(), 6);
    assert_eq!(training(&a).settings.base.as_ref(), Some(&a.shared.body));
    assert_eq!(a.shared.body.segments[4].mass, 7.0);
    // Hold-outs on the model: its body mass × 60/75 … 90/75. Check one
    // curve against the engine on a body built here: by the shares when
    // every segment has one, else every segment in proportion.
    let bm = edited.get(Param::BodyMass);
    let values: Vec<f64> = out.holdout.iter().map(|h| h.value).collect();
    let want: Vec<f64> = [60.0, 70.0, 80.0, 90.0]
        .iter()
        .map(|x| (bm * x) / 75.0)
        .collect();
    assert_eq!(values, want);
    let v = want[3];
    let mut by_hand = edited.clone();
    let shares = by_hand.segments.iter().all(|s| s.share.is_some());
    for s in &mut by_hand.segments {
        s.mass = match s.share {
            Some(sh) if shares => sh * v,
            _ => s.mass * v / bm,
        };
    }
    let c = out.net.compare(v, &Band::default()).expect("compare");
    let f = c.freqs[30];
    let want = Solver::new(&by_hand).at(f).mag(Function::Stht);
    assert!((c.analytic[30] - want).abs() <= 1e-12 * want, "{f} Hz");
    // The panel says what it trained on, and the runs table too.
    let s = screen(&a, 160, 48);
    let on = format!(
        "on this model: 5 seg, {} kg",
        crate::view::format::num(bm, 4)
    );
    assert!(s.contains(&on), "{on}\n{s}");
    assert!(s.contains("5 seg"), "{s}");
    assert_eq!(
        training(&a).history.runs.back().map(|r| r.body.as_str()),
        Some("5 seg")
    );
}

#[test]
fn k4_follows_the_models_k4_and_three_links_are_refused_with_the_reason() {
    let (mut a, rx) = channel_app();
    a.set_param(Param::Stiffness(3), 60_000.0).expect("k4");
    key(&mut a, KeyCode::Char('4'));
    for _ in 0..3 {
        key(&mut a, KeyCode::Right); // mass-stht → k4-stht
    }
    assert_eq!(training(&a).case, Case::K4Stht);
    go_to_named(&mut a, "trainer");
    key(&mut a, KeyCode::Left);
    assert_eq!(training(&a).settings.trainer, Trainer::Backprop);
    set(&mut a, "epoch limit", "20");
    assert_eq!(training(&a).holdout_values()[0], 0.4 * 90_000.0);
    this_model(&mut a);
    // k4 × 0.6, 1, 1.4 for training; × 0.4 … 1.6 held out.
    assert_eq!(
        training(&a).settings.train_values,
        [36_000.0, 60_000.0, 84_000.0]
    );
    assert_eq!(
        training(&a).holdout_values(),
        [
            0.4 * 60_000.0,
            0.8 * 60_000.0,
            1.2 * 60_000.0,
            1.6 * 60_000.0
        ]
    );
    key(&mut a, KeyCode::Char('t'));
    pump(&mut a, &rx, |a| !training(a).running());
    let out = training(&a)
        .run
        .as_ref()
        .and_then(|r| r.outcome.as_ref())
        .expect("outcome");
    assert_eq!(out.holdout[1].value, 48_000.0);
    let mut by_hand = Body::paper(75.0).expect("paper");
    by_hand.links[3].k = 48_000.0;
    let c = out
        .net
        .compare(48_000.0, &Band::default())
        .expect("compare");
    let want = Solver::new(&by_hand).at(c.freqs[20]).mag(Function::Stht);
    assert!((c.analytic[20] - want).abs() <= 1e-12 * want);
    assert!(screen(&a, 120, 40).contains("on this model: 4 seg, 75 kg"));

    // Three segments: no 4th link, so no k4 case on it.
    key(&mut a, KeyCode::Char('1'));
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Char('d'));
    key(&mut a, KeyCode::Char('y'));
    assert_eq!(a.shared.body.n(), 3);
    assert!(a.shared.body.links.len() < 4);
    key(&mut a, KeyCode::Char('4'));
    key(&mut a, KeyCode::Char('t'));
    assert!(!training(&a).running());
    assert!(a.status.error, "{}", a.status.text);
    assert!(
        a.status.text.contains("k4 cases vary k4, the 4th link"),
        "{}",
        a.status.text
    );
    // A mass case takes it: m1..m3 and f.
    go_to_named(&mut a, "case");
    key(&mut a, KeyCode::Left);
    key(&mut a, KeyCode::Left);
    key(&mut a, KeyCode::Left);
    assert_eq!(training(&a).case, Case::MassStht);
    assert_eq!(training(&a).settings.layers[0], 4);
    assert!(training(&a).base_err.is_none());
}

#[test]
fn the_mouse_selects_edits_and_scrolls_the_settings() {
    let mut a = app();
    update(&mut a, Msg::Resize(80, 24));
    a.mouse = true;
    key(&mut a, KeyCode::Char('4'));
    let click = MouseEventKind::Down(MouseButton::Left);
    // Row i of the list is on screen row 2 + i (tab bar, frame).
    let names: Vec<&str> = training(&a).rows().iter().map(|r| r.name()).collect();
    let epochs = names.iter().position(|n| *n == "epoch limit").expect("row");
    mouse(&mut a, click, 5, 2 + epochs as u16);
    assert_eq!(training(&a).row, epochs);
    assert!(a.field.is_none());
    assert!(a.status.text.contains("epoch limit"), "{}", a.status.text);
    // The same cell again at once: a double click edits, as Enter does.
    mouse(&mut a, click, 5, 2 + epochs as u16);
    let f = a.field.as_ref().expect("the edit field");
    assert_eq!(f.label, "epoch limit");
    key(&mut a, KeyCode::Esc);
    // The wheel moves the selection.
    mouse(&mut a, MouseEventKind::ScrollDown, 40, 10);
    assert_eq!(training(&a).row, epochs + 1);
    mouse(&mut a, MouseEventKind::ScrollUp, 40, 10);
    mouse(&mut a, MouseEventKind::ScrollUp, 40, 10);
    assert_eq!(training(&a).row, epochs - 1);
    // The frame and the run panel select nothing.
    mouse(&mut a, click, 5, 1);
    mouse(&mut a, click, 60, 5);
    assert_eq!(training(&a).row, epochs - 1);
    // At 80×16 the list scrolls: with the last row selected, the row drawn
    // first is the one a click there selects.
    update(&mut a, Msg::Resize(80, 16));
    let n = training(&a).rows().len();
    while training(&a).row != n - 1 {
        key(&mut a, KeyCode::Down);
    }
    let s = screen(&a, 80, 16);
    let first = s.lines().nth(2).expect("a list row").to_string();
    let top = training(&a)
        .rows()
        .iter()
        // Names are cut to the column: their first ten characters.
        .position(|r| {
            first.starts_with(&format!(
                "│{}",
                r.name().chars().take(10).collect::<String>()
            ))
        })
        .unwrap_or_else(|| panic!("a row name on the first list line:\n{s}"));
    assert!(top > 0, "the list is scrolled:\n{s}");
    mouse(&mut a, click, 3, 2);
    assert_eq!(training(&a).row, top, "{s}");
}

#[test]
fn snapshot_of_the_tab_set_to_train_on_this_model() {
    let mut a = app();
    add_arm(&mut a);
    key(&mut a, KeyCode::Char('4'));
    this_model(&mut a);
    for (w, h) in [(80, 24), (160, 48)] {
        insta::assert_snapshot!(format!("training_this_model_{w}x{h}"), screen(&a, w, h));
    }
    // A k4 case on a three-link model: the panel says why not.
    let mut a = app();
    key(&mut a, KeyCode::Char('1'));
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Char('d'));
    key(&mut a, KeyCode::Char('y'));
    key(&mut a, KeyCode::Char('4'));
    this_model(&mut a);
    go_to_named(&mut a, "case");
    key(&mut a, KeyCode::Left);
    assert!(a.status.error, "{}", a.status.text);
    insta::assert_snapshot!("training_this_model_refused_80x24", screen(&a, 80, 24));
}

#[test]
fn a_loaded_version_2_network_predicts_on_its_own_model() {
    // A net trained by the library on 52 kg × (65, 75, 85)/75 of a
    // five-segment chain with masses set directly.
    let segs = ["a", "b", "c", "d", "e"]
        .iter()
        .zip([5.0, 22.0, 9.0, 10.0, 6.0])
        .map(|(n, m)| biodyn::Segment::new(n, m))
        .collect();
    let base = Body::chain(
        segs,
        &[3.1e5, 1.83e5, 1.6e5, 9.0e4, 6.0e4],
        &[400.0, 4750.0, 4585.0, 2064.0, 1500.0],
    );
    let case = Case::MassApms;
    let mut s = biodyn::ann::Settings::for_trainer_on(case, Trainer::Lm, Some(base.clone()))
        .expect("settings");
    s.epochs = 3;
    s.ensemble = 1;
    let out = biodyn::ann::train(case, &s, &mut |_| biodyn::ann::Flow::Continue).expect("train");
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("five.json");
    biodyn::ann::save_network(&path, &out.net).expect("save");
    let mut a = app();
    key(&mut a, KeyCode::Char('4'));
    key(&mut a, KeyCode::Char('o'));
    typ(&mut a, &path.display().to_string());
    key(&mut a, KeyCode::Enter);
    assert!(a.status.text.starts_with("loaded"), "{}", a.status.text);
    // Model row on paper: the net's own body at its second held-out value,
    // 52 × 70/75 kg, every segment scaled in proportion.
    let v = (52.0 * 70.0) / 75.0;
    assert_eq!(training(&a).holdout_value(), v);
    let p = training(&a)
        .prediction()
        .expect("prediction on the net's model");
    assert_eq!(p.value, v);
    let mut by_hand = base.clone();
    for seg in &mut by_hand.segments {
        seg.mass *= v / 52.0;
    }
    let (f, y) = p.curves[0].points[25];
    let want = Solver::new(&by_hand).at(f).mag(Function::Apms);
    assert!((y - want).abs() <= 1e-12 * want, "{f} Hz: {y} vs {want}");
    // This model (the paper's four segments) cannot feed it: said, not drawn.
    this_model(&mut a);
    assert!(training(&a).prediction().is_none());
    assert!(
        a.status.text.contains("4 segments") && a.status.text.contains("5 segment masses"),
        "{}",
        a.status.text
    );
}
