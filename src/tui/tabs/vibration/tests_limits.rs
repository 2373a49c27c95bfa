//! The Vibration tab obeys the time domain's model-size limit: a model past
//! it is refused at once with the library's reason, in the background run
//! too (a message, not a hang or an out-of-memory abort).

use super::tests::{key, screen, tab};
use crate::tui::app::App;
use crate::tui::theme::Theme;
use crate::tui::update::update;
use biodyn::time::MAX_SEGMENTS;
use biodyn::{Body, Preset, Segment};
use ratatui::crossterm::event::KeyCode;
use std::time::{Duration, Instant};

/// A uniform chain of `n` one-kilogram segments.
fn chain(n: usize) -> Preset {
    let segments = (0..n)
        .map(|i| Segment {
            name: format!("s{i}"),
            mass: 1.0,
            share: None,
            seat: false,
        })
        .collect();
    let mut p = Preset::builtin_default();
    p.name = format!("chain{n}");
    p.body = Body::chain(segments, &vec![1e6; n], &vec![50.0; n]);
    p
}

#[test]
fn a_model_past_the_limit_is_refused_in_the_background_run_with_the_reason() {
    let (tx, rx) = std::sync::mpsc::channel();
    let mut a = App::with_channel(chain(MAX_SEGMENTS + 1), None, Theme::default(), Some(tx));
    let start = Instant::now();
    key(&mut a, KeyCode::Char('5'));
    let end = start + Duration::from_secs(60);
    while tab(&a).running && Instant::now() < end {
        if let Ok(m) = rx.recv_timeout(Duration::from_millis(20)) {
            update(&mut a, m);
        }
    }
    assert!(!tab(&a).running, "the run never ended");
    // Refused before the dense step is built: well under a second of work.
    assert!(start.elapsed() < Duration::from_secs(10), "{:?}", start.elapsed());
    let err = match &tab(&a).result {
        Some(Err(e)) => e.clone(),
        other => panic!("{:?}", other.as_ref().map(|r| r.is_ok())),
    };
    assert!(err.contains("501 segments") && err.contains("at most 500"), "{err}");
    let s = screen(&a, 160, 48).replace('\n', " ");
    assert!(s.contains("501 segments") && s.contains("at most 500"), "{s}");
}

#[test]
fn a_model_under_the_limit_runs() {
    // Without a channel the run is in this thread (a debug build: 60 segments).
    let mut a = App::new(chain(60), None, Theme::default());
    key(&mut a, KeyCode::Char('5'));
    assert!(tab(&a).outcome().is_some(), "{:?}", tab(&a).result.as_ref().map(|r| r.is_ok()));
}
