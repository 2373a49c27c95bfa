//! A large model: the app is built and drawn without computing anything on
//! the main thread; curves, modes and the study arrive through the channel
//! and equal what a direct computation gives.

use super::*;
use crate::tui::app::open_preset;
use biodyn::{Band, Body, Param, Segment};
use std::sync::mpsc::Receiver;
use std::time::{Duration, Instant};

/// A chain of `n` one-kilogram segments, saved as a preset in `dir`.
pub fn chain_preset(dir: &std::path::Path, n: usize) -> std::path::PathBuf {
    let segments = (0..n)
        .map(|i| Segment::new(&format!("s{}", i + 1), 1.0))
        .collect();
    let k = vec![2.0e5; n];
    let c = vec![300.0; n];
    let p = Preset {
        name: format!("chain{n}"),
        description: format!("{n} one-kilogram segments in a line"),
        source: "test".into(),
        body: Body::chain(segments, &k, &c),
        band: Band::default(),
    };
    let path = dir.join(format!("chain{n}.toml"));
    p.save(&path).expect("save the chain preset");
    path
}

fn settled(a: &App) -> bool {
    !a.computing() && !a.shared.stale && a.shared.modes.is_some() && study(a).result.is_some()
}

fn pump(a: &mut App, rx: &Receiver<Msg>) {
    let end = Instant::now() + Duration::from_secs(120);
    while !settled(a) && Instant::now() < end {
        if let Ok(m) = rx.recv_timeout(Duration::from_millis(50)) {
            update(a, m);
        }
    }
    assert!(settled(a), "the background computation did not arrive");
}

#[test]
fn a_large_model_is_drawn_at_once_and_computed_in_the_background() {
    let dir = tempfile::tempdir().expect("tempdir");
    let path = chain_preset(dir.path(), 20);
    let (preset, file) = open_preset(&path.display().to_string()).expect("open chain");
    let (tx, rx) = std::sync::mpsc::channel();
    let mut a = App::with_channel(preset, file, Theme::default(), Some(tx));
    // nothing derived was computed on this thread
    assert!(a.shared.derived.is_none() && a.shared.modes.is_none());
    assert!(a.computing());
    let s = screen(&a, 80, 24);
    assert!(s.contains("chain20") && s.contains("m1  s1 "), "{s}");
    assert!(
        s.contains("m10 s10 "),
        "row labels as wide as 20 needs:\n{s}"
    );
    assert!(s.contains("computing"), "{s}");
    for t in ['2', '3'] {
        key(&mut a, KeyCode::Char(t));
        let s = screen(&a, 80, 24);
        assert!(s.contains("computing") && s.contains("q quits"), "{s}");
    }
    key(&mut a, KeyCode::Char('1'));
    pump(&mut a, &rx);
    let direct = Derived::compute(&a.shared.body, a.shared.band());
    assert_eq!(derived(&a).curve, direct.curve);
    assert!(screen(&a, 80, 24).contains("fn Hz"));
    // three quick edits of m1: the stale curves stay up, marked, and the
    // last edit's curves arrive (at most one computation at a time)
    key(&mut a, KeyCode::Down);
    for _ in 0..3 {
        key(&mut a, KeyCode::Char('+'));
    }
    assert!(a.shared.stale && a.shared.derived.is_some());
    assert!(screen(&a, 80, 24).contains("updating"));
    pump(&mut a, &rx);
    let direct = Derived::compute(&a.shared.body, a.shared.band());
    assert_eq!(derived(&a).curve, direct.curve);
    assert!((a.shared.body.get(Param::Mass(0)) - 1.05f64.powi(3)).abs() < 1e-12);
    // q answers at once while a computation runs
    key(&mut a, KeyCode::Char('u'));
    assert!(a.computing());
    key(&mut a, KeyCode::Char('q'));
    assert!(!a.quit, "unsaved edits: asks first");
    key(&mut a, KeyCode::Char('y'));
    assert!(a.quit);
}

#[test]
fn a_large_model_without_a_channel_is_computed_at_once() {
    let dir = tempfile::tempdir().expect("tempdir");
    let path = chain_preset(dir.path(), 20);
    let a = App::open(&path.display().to_string(), Theme::default()).expect("open");
    assert!(a.shared.derived.is_some() && a.shared.modes.is_some());
    assert!(!a.computing());
}
