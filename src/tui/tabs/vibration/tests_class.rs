//! The `class` signal kind (an input spectral class, issue 18): ←→ on the
//! kind reaches it from either side, its rows are the grammar's (name,
//! seed), an edit of either goes through the library's parser, and the run
//! is the library's record of that class.

use super::settings::{Kind, Row};
use super::tests::{app, edit, key, screen, tab};
use ratatui::crossterm::event::KeyCode;

#[test]
fn the_class_kind_shows_its_name_and_seed_and_runs() {
    let mut a = app();
    // sine ← file ← class: stepping back from the file kind lands on the
    // class's own signal (its slot once missed: the file's rows showed).
    key(&mut a, KeyCode::Left);
    key(&mut a, KeyCode::Left);
    let s = &tab(&a).settings;
    assert_eq!(s.kind, Kind::Class);
    let sig = s.signal().expect("a generated signal").to_string();
    assert!(sig.starts_with("class:"), "{sig}");
    let rows = s.rows();
    assert!(rows.contains(&Row::Param(0, "name")), "{rows:?}");
    assert!(rows.contains(&Row::Param(0, "seed")), "{rows:?}");
    assert!(!rows.contains(&Row::Path), "{rows:?}");
    let text = screen(&a, 80, 24);
    assert!(text.contains("◀ class ▶") && text.contains("EM6"), "{text}");
    edit(&mut a, Row::Param(0, "name"), "ag2");
    edit(&mut a, Row::Param(0, "seed"), "7");
    let sig = tab(&a).settings.signal().expect("signal").to_string();
    assert!(sig.contains("AG2") && sig.contains("seed=7"), "{sig}");
    // Right from class is the file kind, Left twice more the shock.
    key(&mut a, KeyCode::Up);
    while tab(&a).sel != 0 {
        key(&mut a, KeyCode::Up);
    }
    key(&mut a, KeyCode::Right);
    assert_eq!(tab(&a).settings.kind, Kind::File);
    key(&mut a, KeyCode::Left);
    key(&mut a, KeyCode::Left);
    assert_eq!(tab(&a).settings.kind, Kind::Shock);
    key(&mut a, KeyCode::Right);
    // The class's edits are kept under its kind.
    let sig = tab(&a).settings.signal().expect("signal").to_string();
    assert!(sig.contains("AG2") && sig.contains("seed=7"), "{sig}");
}

#[test]
fn under_a_seat_model_the_tab_judges_and_draws_the_pan() {
    use biodyn::iso2631::assess;
    use biodyn::time::{Generator, Signal, Simulator};
    let p = biodyn::Preset::builtin("paper-75kg-suspension-seat").unwrap().unwrap();
    let mut a = crate::tui::app::App::new(p, None, crate::tui::theme::Theme::default());
    key(&mut a, KeyCode::Char('5'));
    edit(&mut a, super::settings::Row::Spec, "class:EM6,seed=2");
    let o = tab(&a).outcome().expect("a result");
    let body = &a.shared.body;
    let sig = Signal::parse("class:EM6,seed=2").unwrap();
    let x: Vec<f64> = Generator::new(&sig, 1000.0, 10.0).unwrap().collect();
    let r = assess(body, 1000.0, x.iter().map(|&v| Ok(v)), 8.0).unwrap();
    assert_eq!(o.assessment.seat, r.seat);
    assert_eq!(o.assessment.floor, r.floor);
    assert!(r.floor.is_some());
    // The seat trace is the pan's acceleration, not the floor record.
    let mut sim = Simulator::new(body, 1000.0).unwrap();
    let pan = body.pan().expect("pan");
    let mut y = vec![0.0; sim.layout().len()];
    let mut peak: f64 = 0.0;
    for &v in &x {
        sim.step(v, &mut y);
        peak = peak.max(y[pan].abs());
    }
    assert_eq!(o.traces.seat.abs_max, peak);
    assert!(screen(&a, 160, 48).contains("seat pan"));
}
