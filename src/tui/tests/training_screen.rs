//! The Training tab after a review at 80×24 and 60×16: numbers never cut
//! inside, the held-out row in the chosen case's unit, one epoch count,
//! the held-out table readable on a small screen, the run panel and the
//! setting's help whole, pause/stop offered only while a run goes.

use super::training_runs::{channel_app, go_to_named, pump, set};
use super::*;
use crate::tui::tabs::training::settings::Row;
use crate::view::format::num;
use biodyn::ann::Case;
use std::sync::mpsc::Receiver;

/// The lines of the run panel (the left column under the settings list).
fn run_panel(s: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut inside = false;
    for l in s.lines() {
        let left: String = l.chars().take(34).collect();
        if left.starts_with("┌ run") {
            inside = true;
            continue;
        }
        if inside {
            if left.starts_with('└') {
                break;
            }
            out.push(left.trim_matches('│').trim().to_string());
        }
    }
    out
}

/// A run of `epochs` with `trainer` on the fresh app's tab 4, to its end.
fn run_to_end(trainer_left: bool, epochs: &str) -> (App, Receiver<Msg>) {
    let (mut a, rx) = channel_app();
    key(&mut a, KeyCode::Char('4'));
    if trainer_left {
        go_to_named(&mut a, "trainer");
        key(&mut a, KeyCode::Left); // lm → backprop
    }
    set(&mut a, "epoch limit", epochs);
    key(&mut a, KeyCode::Char('t'));
    assert!(training(&a).running(), "{}", a.status.text);
    pump(&mut a, &rx, |a| !training(a).running());
    (a, rx)
}

#[test]
fn settings_show_extreme_numbers_short_and_lists_cut_between_numbers() {
    let mut a = app();
    key(&mut a, KeyCode::Char('4'));
    go_to_named(&mut a, "trainer");
    key(&mut a, KeyCode::Left); // backprop: learning rate, momentum
    set(&mut a, "learning rate", "1e30");
    assert_eq!(a.status.text, "learning rate = 1e30");
    set(&mut a, "momentum", "1e-320");
    set(&mut a, "function gain", "1e300");
    let s = screen(&a, 80, 24);
    for (row, want) in [
        ("learning rate", "1e30"),
        ("momentum", "1e-320"),
        ("function gain", "1e300"),
    ] {
        assert!(
            s.lines()
                .any(|l| l.contains(row) && l.contains(&format!(" {want} "))),
            "{row} = {want}:\n{s}"
        );
    }
    assert!(!s.contains("0000000000"), "{s}");
    // k4-apms: the list of training values is cut after a whole number.
    go_to_named(&mut a, "case");
    key(&mut a, KeyCode::Left);
    assert_eq!(training(&a).case, Case::K4Apms);
    go_to_named(&mut a, "training values");
    let s = screen(&a, 80, 24);
    let row = s
        .lines()
        .find(|l| l.contains("training values"))
        .expect("the row");
    let shown: String = row.chars().take(34).collect();
    assert!(shown.contains("54000,9e4,…"), "{shown}");
    // Selected, the status line has the whole list.
    assert!(
        a.status
            .text
            .starts_with("training values = 54000,9e4,126000  ("),
        "{}",
        a.status.text
    );
}

#[test]
fn the_held_out_row_follows_the_chosen_case_not_the_last_runs() {
    let (mut a, _rx) = run_to_end(true, "20");
    assert_eq!(training(&a).holdout_value(), 70.0);
    assert!(training(&a).prediction().is_some());
    go_to_named(&mut a, "case");
    key(&mut a, KeyCode::Left); // mass-stht → k4-apms
    let k4 = Case::K4Apms.holdout_values_on(None)[1];
    assert_eq!(training(&a).holdout_value(), k4);
    let s = screen(&a, 80, 24);
    let want = format!("◀ {} N/m ▶", num(k4, 4));
    assert!(s.contains(&want), "{want}:\n{s}");
    assert!(!s.contains("70 N/m"), "{s}");
    // No chart or table of the mass net under a k4 case: said instead.
    assert!(training(&a).prediction().is_none());
    assert!(s.contains("no k4-apms network yet"), "{s}");
    assert!(!s.contains("held-out errors"), "{s}");
    // Back on its case, the run's net is shown where the row points.
    key(&mut a, KeyCode::Right);
    go_to_named(&mut a, "held-out value");
    key(&mut a, KeyCode::Right);
    let p = training(&a).prediction().expect("prediction");
    assert_eq!((p.value, training(&a).holdout_value()), (80.0, 80.0));
    assert!(screen(&a, 80, 24).contains("held-out errors"));
}

#[test]
fn the_run_panel_and_the_runs_table_count_epochs_per_member() {
    let (mut a, rx) = channel_app();
    key(&mut a, KeyCode::Char('4'));
    set(&mut a, "ensemble size", "2");
    set(&mut a, "epoch limit", "4");
    key(&mut a, KeyCode::Char('t'));
    pump(&mut a, &rx, |a| !training(a).running());
    let out = training(&a)
        .run
        .as_ref()
        .and_then(|r| r.outcome.as_ref())
        .expect("outcome");
    assert_eq!(out.member_epochs, [4, 4]);
    let s = screen(&a, 160, 48);
    assert!(
        run_panel(&s)
            .iter()
            .any(|l| l.starts_with("epochs 2×4 in ")),
        "{s}"
    );
    let table = s
        .lines()
        .skip_while(|l| !l.contains("last 1 runs"))
        .nth(2)
        .unwrap_or_default();
    assert!(table.contains(" 2×4 "), "{table}\n{s}");
    assert!(!table.contains(" 8 "), "{table}");
}

#[test]
fn a_small_screen_reads_the_held_out_errors_whole() {
    let (a, _rx) = run_to_end(true, "20");
    let out = training(&a)
        .run
        .as_ref()
        .and_then(|r| r.outcome.as_ref())
        .expect("outcome");
    let s = screen(&a, 60, 16);
    assert!(s.contains("max error (◀ charted)"), "{s}");
    assert!(s.contains("STHT at 70 kg (interp.)"), "{s}");
    for h in &out.holdout {
        let v = num(h.value, 4);
        let e = num(h.max_err_pct, 3);
        let row = s
            .lines()
            .find(|l| l.contains(&format!("│{v} kg ")))
            .unwrap_or_else(|| panic!("{v} kg:\n{s}"));
        assert!(row.contains(&format!(" {e} %")), "{row}\n{s}");
        assert_eq!(row.contains("extrap"), h.extrapolation, "{row}");
        assert_eq!(row.contains('◀'), h.value == 70.0, "{row}");
    }
    assert!(!s.contains('…'), "{s}");
    // On "this model" the chart's title drops words, not numbers.
    let mut a = a;
    go_to_named(&mut a, "model");
    key(&mut a, KeyCode::Right);
    assert!(training(&a).this_model);
    let s = screen(&a, 60, 16);
    assert!(
        s.contains("STHT this model 70 kg (interp.)") || s.contains("STHT this model 70 kg─"),
        "{s}"
    );
    assert!(screen(&a, 80, 24).contains("STHT this model at 70 kg (interp.)"));
}

#[test]
fn the_run_panel_and_the_help_of_a_setting_are_never_cut() {
    // Idle: the selected setting's help, whole, in the run panel; its
    // value and range on the status line, within 80 columns.
    let mut a = app();
    key(&mut a, KeyCode::Char('4'));
    go_to_named(&mut a, "epoch limit");
    assert_eq!(a.status.text, "epoch limit = 300  (a whole number >= 1)");
    let s = screen(&a, 80, 24);
    let help = run_panel(&s).join(" ");
    let want = biodyn::ann::Setting::find("epochs").expect("epochs").help;
    assert!(help.contains(want), "{want}\n{s}");
    for r in training(&a).rows() {
        let text = training(&a).describe(r, false);
        assert!(text.chars().count() <= 78, "{text}");
        if let Row::Setting(_) = r {
            assert!(text.contains(" = "), "{text}");
        }
    }
    // After a backprop run: every line of the panel whole.
    let (a, _rx) = run_to_end(true, "25");
    let run = training(&a).run.as_ref().expect("run");
    let secs = run.working_s(run.finished.as_ref().expect("finished").train_seconds);
    for (w, h) in [(80, 24), (60, 16)] {
        let s = screen(&a, w, h);
        let panel = run_panel(&s);
        assert!(panel.iter().any(|l| l.starts_with("epochs 25 in ")), "{s}");
        assert!(panel.iter().any(|l| l.contains("right ")), "{s}");
        assert!(panel.iter().any(|l| l.contains("of the final net")), "{s}");
        assert!(panel.iter().any(|l| l.contains("ended: ")), "{s}");
        assert!(panel.iter().any(|l| l.contains("paper's body")), "{s}");
        assert!(panel.iter().all(|l| !l.contains('…')), "{s}");
        // The time the panel states is the run's own working time.
        assert!(secs.is_finite() && secs > 0.0, "{secs}");
    }
}

#[test]
fn pause_and_stop_are_offered_only_while_a_run_goes() {
    let (mut a, rx) = channel_app();
    key(&mut a, KeyCode::Char('4'));
    let hints = |a: &App| {
        screen(a, 120, 30)
            .lines()
            .last()
            .unwrap_or_default()
            .to_string()
    };
    let idle = hints(&a);
    assert!(idle.contains("t start"), "{idle}");
    assert!(
        !idle.contains("space pause") && !idle.contains("s stop"),
        "{idle}"
    );
    set(&mut a, "epoch limit", "100000");
    key(&mut a, KeyCode::Char('t'));
    let live = hints(&a);
    assert!(
        live.contains("space pause") && live.contains("s stop"),
        "{live}"
    );
    key(&mut a, KeyCode::Char('s'));
    pump(&mut a, &rx, |a| !training(a).running());
    let after = hints(&a);
    assert!(!after.contains("space pause"), "{after}");
    // The ? page still lists them.
    let help: Vec<String> = crate::tui::frame::help_lines(&a)
        .iter()
        .map(|l| format!("{l:?}"))
        .collect();
    assert!(
        help.iter().any(|l| l.contains("pause / resume")),
        "{help:?}"
    );
}

#[test]
fn loading_a_network_of_another_case_moves_the_case_row_to_it() {
    let (a, _rx) = run_to_end(true, "10");
    let net = &training(&a)
        .run
        .as_ref()
        .and_then(|r| r.outcome.as_ref())
        .expect("outcome")
        .net;
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("mass.json");
    biodyn::ann::save_network(&path, net).expect("save");
    let mut b = app();
    key(&mut b, KeyCode::Char('4'));
    key(&mut b, KeyCode::Left); // case: mass-stht → k4-apms
    assert_eq!(training(&b).case, Case::K4Apms);
    key(&mut b, KeyCode::Char('o'));
    if let Some(f) = b.field.as_mut() {
        f.set_text(path.display().to_string());
    }
    key(&mut b, KeyCode::Enter);
    assert!(b.field.is_none(), "{:?}", b.field);
    assert!(
        b.status.text.ends_with("the case row follows it"),
        "{}",
        b.status.text
    );
    assert_eq!(training(&b).case, Case::MassStht);
    assert_eq!(training(&b).holdout_value(), 70.0);
    let p = training(&b).prediction().expect("prediction");
    assert_eq!(p.value, 70.0);
    assert!(screen(&b, 80, 24).contains("mass.json: STHT at 70 kg"));
}

/// Needs the change in `tui/frame.rs` `render_status` (not this branch's
/// file): put "  │ " before a tab's summary only after other text, so an
/// empty status line does not start with a stray separator.
#[test]
fn the_run_summary_on_other_tabs_starts_without_a_separator() {
    let (mut a, rx) = channel_app();
    key(&mut a, KeyCode::Char('4'));
    set(&mut a, "epoch limit", "100000");
    key(&mut a, KeyCode::Char('t'));
    pump(&mut a, &rx, |a| {
        training(a).run.as_ref().is_some_and(|r| r.last.is_some())
    });
    key(&mut a, KeyCode::Char('2'));
    let s = screen(&a, 80, 24);
    let status = s.lines().nth(22).unwrap_or_default().to_string();
    key(&mut a, KeyCode::Char('4'));
    key(&mut a, KeyCode::Char('s'));
    pump(&mut a, &rx, |a| !training(a).running());
    assert!(status.contains("training mass-stht: epoch"), "{s}");
    assert!(!status.contains('│'), "{status}");
}
