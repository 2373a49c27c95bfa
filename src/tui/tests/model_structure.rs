//! The Model tab's structure edits, driven by keys through the real
//! `update`: add a segment and a link, rename, head, share, description,
//! delete; each one undo step named for what it did; refusals carry the
//! library's message and leave the model as it was.

use super::*;
use crate::tui::tabs::model::ModelTab;
use biodyn::End;

fn model(a: &App) -> &ModelTab {
    a.tab_state().expect("model tab")
}

fn status(a: &App) -> &str {
    &a.status.text
}

/// Selects row `row` of the Model tab (0 = body mass).
fn select(a: &mut App, row: usize) {
    key(a, KeyCode::Home);
    for _ in 0..row {
        key(a, KeyCode::Down);
    }
    assert_eq!(model(a).row, row);
}

/// Opens a field with `k`, replaces its text with `text`, commits.
fn field(a: &mut App, k: char, text: &str) {
    key(a, KeyCode::Char(k));
    assert!(a.field.is_some(), "{k} opens a field");
    typ(a, text);
    key(a, KeyCode::Enter);
}

#[test]
fn add_a_segment_and_a_link_then_undo_and_redo_each() {
    let mut a = app();
    let before = a.shared.body.clone();
    select(&mut a, 2); // m2 chest
    field(&mut a, 'a', "arm 5 chest 1e5 500");
    assert!(a.field.is_none(), "committed: {:?}", a.field);
    let b = &a.shared.body;
    assert_eq!(b.segments.len(), 5);
    assert_eq!(b.segments[4].name, "arm");
    assert_eq!(b.segments[4].mass, 5.0);
    // The paper's model has shares: the new segment gets its share of 75 kg.
    assert_eq!(b.segments[4].share, Some(5.0 / 75.0));
    let l = b.links.last().expect("link");
    assert_eq!(
        (l.name.as_str(), l.upper, l.lower),
        ("arm-chest", 4, End::Segment(1))
    );
    assert_eq!((l.k, l.c), (1e5, 500.0));
    assert_eq!(model(&a).row, 5, "the new segment is selected");
    let after_seg = a.shared.body.clone();

    field(&mut a, 'A', "arm pelvis 2e4 100 arm-pelvis");
    let l = a.shared.body.links.last().expect("link");
    assert_eq!(
        (l.name.as_str(), l.upper, l.lower),
        ("arm-pelvis", 4, End::Segment(3))
    );
    assert_eq!(a.shared.body.links.len(), 6);

    key(&mut a, KeyCode::Char('u'));
    assert_eq!(status(&a), "undid add link 'arm-pelvis' (^R redoes it)");
    assert_eq!(a.shared.body, after_seg);
    key(&mut a, KeyCode::Char('u'));
    assert_eq!(
        status(&a),
        "undid add segment 'arm' (link 'arm-chest') (^R redoes it)"
    );
    assert_eq!(a.shared.body, before);
    ctrl(&mut a, 'r');
    assert_eq!(status(&a), "redid add segment 'arm' (link 'arm-chest')");
    assert_eq!(a.shared.body, after_seg);
    // The new model is computed like any other: mode shapes have 5 entries.
    let modes = a.shared.modes.clone().expect("modes").expect("ok");
    assert!(modes.damped.iter().all(|m| m.shape_mag.len() == 5));
}

#[test]
fn rename_and_head_are_undoable_and_named() {
    let mut a = app();
    select(&mut a, 2);
    field(&mut a, 'r', "thorax");
    assert_eq!(a.shared.body.segments[1].name, "thorax");
    assert_eq!(
        status(&a),
        "rename segment 'chest' → 'thorax' (u undoes it)"
    );
    key(&mut a, KeyCode::Char('H'));
    assert_eq!(a.shared.body.head, 1);
    assert!(screen(&a, 80, 24).contains("thorax"));
    key(&mut a, KeyCode::Char('u'));
    assert_eq!(status(&a), "undid head → 'thorax' (^R redoes it)");
    assert_eq!(a.shared.body.head, 0);
    key(&mut a, KeyCode::Char('u'));
    assert_eq!(a.shared.body.segments[1].name, "chest");
    // A link renames the same way.
    select(&mut a, 5); // link 1
    field(&mut a, 'r', "neck");
    assert_eq!(a.shared.body.links[0].name, "neck");
}

#[test]
fn a_refused_structure_keeps_the_model_and_says_the_librarys_reason() {
    let mut a = app();
    let before = a.shared.body.clone();
    // A duplicate name: the library's message, in the open field.
    select(&mut a, 2);
    field(&mut a, 'r', "pelvis");
    let f = a.field.as_ref().expect("field stays open");
    assert_eq!(
        f.error.as_deref(),
        Some("segment name 'pelvis' is used twice: segment names must be unique")
    );
    key(&mut a, KeyCode::Esc);
    // "seat" is a preset rule, not a Body one: refused too.
    field(&mut a, 'r', "seat");
    let why = a
        .field
        .as_ref()
        .and_then(|f| f.error.clone())
        .expect("refused");
    assert!(why.contains("\"seat\" is reserved"), "{why}");
    key(&mut a, KeyCode::Esc);
    // Deleting link 4 (pelvis-seat) leaves no link to the seat.
    select(&mut a, 8);
    key(&mut a, KeyCode::Char('d'));
    assert!(screen(&a, 80, 24).contains("delete link 'pelvis-seat'?"));
    key(&mut a, KeyCode::Char('y'));
    assert!(a.status.error);
    // The library's reason, whole, in the question, which stays open.
    assert_eq!(
        model(&a).refusal.as_deref(),
        Some("no link reaches the seat: add a link with lower = \"seat\"")
    );
    assert!(screen(&a, 80, 24).contains("refused: no link reaches the seat: add a link with"));
    key(&mut a, KeyCode::Esc);
    assert_eq!(model(&a).pending, None);
    // Deleting the pelvis with its links leaves the rest floating.
    select(&mut a, 4);
    key(&mut a, KeyCode::Char('d'));
    key(&mut a, KeyCode::Char('x'));
    assert!(a.status.error);
    let why = model(&a).refusal.clone().expect("refused");
    assert!(why.contains("no link reaches the seat"), "{why}");
    key(&mut a, KeyCode::Esc);
    // Link 3 (lower-torso-pelvis) holds the upper body: the library's
    // long reason is wrapped in the question, not cut.
    select(&mut a, 7);
    key(&mut a, KeyCode::Char('d'));
    key(&mut a, KeyCode::Char('y'));
    let why = model(&a).refusal.clone().expect("refused");
    assert!(
        why.starts_with("segment 'head-neck' is not tied to the seat"),
        "{why}"
    );
    assert!(screen(&a, 80, 24).contains("undetermined"));
    key(&mut a, KeyCode::Esc);
    assert_eq!(a.shared.body, before);
    assert!(a.undo.is_empty(), "a refusal is not an undo step");
    // The refusal wraps in the popup instead of being cut.
    select(&mut a, 1);
    field(&mut a, 'a', "arm 5 nowhere");
    let s = screen(&a, 80, 24);
    assert!(
        s.contains("'nowhere' is neither a segment name nor \"seat\""),
        "{s}"
    );
}

#[test]
fn deleting_a_middle_segment_rejoins_the_chain() {
    let mut a = app();
    select(&mut a, 2); // chest
    key(&mut a, KeyCode::Char('d'));
    assert!(screen(&a, 160, 48).contains("to 'lower-torso'"));
    key(&mut a, KeyCode::Char('y'));
    let b = &a.shared.body;
    let names: Vec<&str> = b.segments.iter().map(|s| s.name.as_str()).collect();
    assert_eq!(names, ["head-neck", "lower-torso", "pelvis"]);
    // head-neck now hangs on lower-torso (index 1), with its own k and c.
    let l = &b.links[0];
    assert_eq!((l.upper, l.lower, l.k), (0, End::Segment(1), 310_000.0));
    assert_eq!(b.links.len(), 3);
    assert!(status(&a).starts_with("remove segment 'chest' (1 link moved to 'lower-torso')"));
    key(&mut a, KeyCode::Char('u'));
    assert_eq!(a.shared.body.segments.len(), 4);
    // n keeps it.
    key(&mut a, KeyCode::Char('d'));
    key(&mut a, KeyCode::Char('n'));
    assert_eq!(a.shared.body.segments.len(), 4);
    assert_eq!(model(&a).pending, None);
}

#[test]
fn share_and_description() {
    let mut a = app();
    select(&mut a, 1);
    key(&mut a, KeyCode::Right);
    key(&mut a, KeyCode::Enter);
    typ(&mut a, "10");
    key(&mut a, KeyCode::Enter);
    let s = &a.shared.body.segments[0];
    assert_eq!(s.share, Some(0.1));
    assert_eq!(s.mass, 0.1 * 75.0);
    assert_eq!(
        status(&a),
        "share of 'head-neck' 7.5 % → 10 % (u undoes it)"
    );
    field(&mut a, 'D', "my body");
    assert_eq!(a.shared.preset.description, "my body");
    assert!(screen(&a, 80, 24).contains("about: my body"));
    key(&mut a, KeyCode::Char('u'));
    assert_eq!(status(&a), "undid edit the description (^R redoes it)");
    assert_ne!(a.shared.preset.description, "my body");
}

#[test]
fn a_long_model_scrolls_to_the_selection() {
    use biodyn::{Body, Preset, Segment};
    let n = 30;
    let segs = (0..n)
        .map(|i| Segment::new(&format!("s{i}"), 1.0))
        .collect();
    let mut p = Preset::builtin_default();
    p.body = Body::chain(segs, &vec![1e5; n], &vec![500.0; n]);
    let mut a = App::new(p, None, crate::tui::theme::Theme::default());
    key(&mut a, KeyCode::End);
    field(&mut a, 'A', "s0 seat 1e4 10 extra");
    assert!(a.field.is_none(), "{:?}", a.field);
    assert_eq!(model(&a).row, 1 + n + n, "the new link is selected");
    let s = screen(&a, 80, 24);
    assert!(s.contains("extra"), "the new link is in view:\n{s}");
    key(&mut a, KeyCode::PageUp);
    assert_eq!(model(&a).row, 1 + n + n - 20);
    assert!(screen(&a, 80, 24).contains("s9-s10"));
}

#[test]
fn other_tabs_follow_a_structure_change_and_its_undo() {
    let mut a = app();
    // The study on k4 (the fourth link), then the chest goes: 3 links left.
    key(&mut a, KeyCode::Char('3'));
    key(&mut a, KeyCode::Char('k'));
    key(&mut a, KeyCode::Char('1'));
    select(&mut a, 2);
    key(&mut a, KeyCode::Char('d'));
    key(&mut a, KeyCode::Char('y'));
    assert_eq!(a.shared.body.links.len(), 3);
    for t in ['2', '3', '4', '1'] {
        key(&mut a, KeyCode::Char(t));
        let _ = screen(&a, 80, 24);
    }
    key(&mut a, KeyCode::Char('u'));
    ctrl(&mut a, 'r');
    key(&mut a, KeyCode::Char('u'));
    key(&mut a, KeyCode::Char('3'));
    assert!(screen(&a, 160, 48).contains("Study"));
    assert_eq!(a.shared.body.links.len(), 4);
}

#[test]
fn an_edited_description_is_an_unsaved_edit_and_is_saved_as_typed() {
    let mut a = app();
    // A structure edit and a description the user wrote.
    select(&mut a, 2);
    field(&mut a, 'r', "thorax");
    field(&mut a, 'D', "my backrest model");
    assert!(a.modified());
    key(&mut a, KeyCode::Char('u')); // the description goes back…
    assert!(a.modified(), "…the rename is still unsaved");
    ctrl(&mut a, 'r');
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("mine.toml");
    a.save_to(&path).expect("saved");
    assert!(!a.modified());
    let back = biodyn::Preset::load(&path).expect("reads back");
    assert_eq!(back.description, "my backrest model");
    assert_eq!(back.body, a.shared.body);
    // Only the description edited: still a reason to ask before quitting.
    field(&mut a, 'D', "changed again");
    assert!(a.modified());
    assert_eq!(a.quit_reasons(), ["the model has unsaved edits"]);
}

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
