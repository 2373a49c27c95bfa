//! Snapshots of the Model tab's structure views (add field, delete
//! question, refusal) and the Training tab's runs table and loaded
//! network, at 80×24 and 160×48.

use super::*;
use crate::tui::tabs::training::RunRecord;
use biodyn::ann::{Case, Trainer};

fn snap(name: &str, a: &App) {
    for (w, h) in [(80, 24), (160, 48)] {
        insta::assert_snapshot!(format!("{name}_{w}x{h}"), screen(a, w, h));
    }
}

#[test]
fn model_structure_views() {
    let mut a = app();
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Down); // chest
    key(&mut a, KeyCode::Char('a'));
    snap("model_add_segment_field", &a);
    typ(&mut a, "arm 5 chest 1e5 500");
    key(&mut a, KeyCode::Enter);
    snap("model_added_arm", &a);
    key(&mut a, KeyCode::Char('u'));
    key(&mut a, KeyCode::Home);
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Char('d'));
    snap("model_delete_question", &a);
    key(&mut a, KeyCode::Esc);
    key(&mut a, KeyCode::Char('r'));
    typ(&mut a, "pelvis");
    key(&mut a, KeyCode::Enter);
    snap("model_rename_refused", &a);
    key(&mut a, KeyCode::Esc);
    // Deleting the pelvis with its links would leave the rest floating.
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Char('d'));
    key(&mut a, KeyCode::Char('x'));
    snap("model_delete_refused", &a);
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
