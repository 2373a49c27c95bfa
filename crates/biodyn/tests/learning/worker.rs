//! The training worker on a manual clock: the test moves time by hand and
//! waits for the worker's own reports (paused, resumed, a progress
//! message, the end), never sleeping and never asserting on wall-clock
//! bounds. The waits' timeout only guards against a hang, loudly.

use biodyn::ann::{
    AnnError, Case, Event, Finished, MIN_INTERVAL, Progress, Settings, StopReason, Worker,
};
use biodyn::{Clock, ManualClock};
use std::sync::mpsc::{self, Receiver};
use std::time::Duration;

/// How long a wait may take before the worker counts as hung.
const HANG: Duration = Duration::from_secs(120);

/// Back-propagation that only a time limit, a cancel or a pause stops.
fn endless(case: Case) -> Settings {
    let mut s = Settings::paper(case);
    s.epochs = u64::MAX / 2;
    s.stop_when_all_right = false;
    s
}

/// The worker's next report (the hang guard fails the test).
fn next<M>(rx: &Receiver<M>, what: &str) -> M {
    rx.recv_timeout(HANG)
        .unwrap_or_else(|e| panic!("no {what} within {HANG:?} ({e}): the worker hangs"))
}

fn progress(e: Event, what: &str) -> Progress {
    match e {
        Event::Progress(p) => p,
        other => panic!("wanted {what}, got {other:?}"),
    }
}

/// The rest of a joined run's reports: the final progress, then the end.
fn the_end(rx: &Receiver<Event>) -> (Progress, Finished) {
    let rest: Vec<Event> = rx.try_iter().collect();
    match &rest[..] {
        [Event::Progress(p), Event::Finished(f)] if !p.paused => (p.clone(), f.clone()),
        other => panic!("wanted the final progress and the end, got {other:?}"),
    }
}

/// The TUI's own message type, to show that `map` lets it wrap worker events.
#[derive(Debug)]
enum TuiMsg {
    Train(Event),
}

/// One report per `MIN_INTERVAL` of the worker's clock, however many
/// epochs run in between: with the clock moved one interval at a time,
/// each move lets exactly one report out, whose rate is the epochs since
/// the last one over that interval; with the clock still, none comes
/// until the end (a throttle that does not throttle sends one per epoch).
#[test]
fn worker_reports_once_per_interval_of_its_clock_and_returns_the_net() {
    let case = Case::K4Stht;
    let hand = ManualClock::new();
    let (tx, rx) = mpsc::channel();
    let w = Worker::start_on(case, endless(case), hand.clock(), tx, TuiMsg::Train).unwrap();
    let mut last_epoch = 0;
    for i in 1..=5u32 {
        hand.advance(MIN_INTERVAL);
        let TuiMsg::Train(e) = next(&rx, "a progress report");
        let p = progress(e, "a progress report");
        assert!(!p.paused && p.epoch > last_epoch, "report {i}: {p:?}");
        let rate = (p.epoch - last_epoch) as f64 / MIN_INTERVAL.as_secs_f64();
        assert_eq!(p.epochs_per_s, rate, "report {i}");
        assert_eq!(p.elapsed_s, (MIN_INTERVAL * i).as_secs_f64(), "report {i}");
        assert!(!p.history.is_empty() && p.rms.is_finite());
        last_epoch = p.epoch;
    }
    w.cancel();
    let out = w.join().unwrap();
    assert_eq!(out.stop, StopReason::Cancelled);
    let rest: Vec<Event> = rx.try_iter().map(|TuiMsg::Train(e)| e).collect();
    // Nothing between the fifth report and the cancel: the clock stood still.
    match &rest[..] {
        [Event::Progress(p), Event::Finished(f)] => {
            assert!(p.epoch >= last_epoch && f.stop == StopReason::Cancelled);
            assert_eq!(p.elapsed_s, (MIN_INTERVAL * 5).as_secs_f64());
        }
        other => panic!("wanted the final progress and the end, got {other:?}"),
    }
    assert!(out.net.members[0].params.iter().all(|p| p.is_finite()));
}

/// Pause: the worker says "paused" and stops training (a minute paused
/// does not use up its one-second time limit); resume: it says so at the
/// same epoch and goes on; a cancel while paused ends the run right there.
#[test]
fn worker_pauses_resumes_and_cancels() {
    let case = Case::K4Dpmi;
    let mut s = endless(case);
    s.time_limit_s = Some(1.0);
    let hand = ManualClock::new();
    let (tx, rx) = mpsc::channel();
    let w = Worker::start_on(case, s, hand.clock(), tx, |e| e).unwrap();
    w.pause();
    assert!(w.is_paused());
    // The clock has not moved, so the throttle let nothing out before it.
    let paused = progress(next(&rx, "the paused report"), "the paused report");
    assert!(paused.paused, "{paused:?}");
    hand.advance(Duration::from_secs(60));
    w.resume();
    assert!(!w.is_paused());
    let resumed = progress(next(&rx, "the resumed report"), "the resumed report");
    assert!(!resumed.paused, "{resumed:?}");
    assert_eq!(resumed.epoch, paused.epoch, "no epoch ran while paused");
    assert_eq!(resumed.elapsed_s, 60.0);
    hand.advance(MIN_INTERVAL);
    let on = progress(
        next(&rx, "a report after the resume"),
        "a report after the resume",
    );
    assert!(!on.paused && on.epoch > paused.epoch, "{on:?}");
    w.pause();
    let again = progress(next(&rx, "the second paused report"), "the paused report");
    assert!(again.paused && again.epoch >= on.epoch, "{again:?}");
    w.cancel();
    let out = w.join().unwrap();
    assert_eq!(out.stop, StopReason::Cancelled);
    assert_eq!(out.epochs(), again.epoch, "an epoch ran after the cancel");
    let (last, end) = the_end(&rx);
    assert_eq!((last.epoch, end.stop), (again.epoch, StopReason::Cancelled));
}

/// The time limit counts working time only: 0.14 s of training, 10 s
/// paused, then the clock moved 0.07 s at a time: the run stops on its
/// time limit once 0.3 s of work have passed (at 0.35 s, or one step
/// later if the worker read the clock after the test's next move), never
/// at the resume (where a limit that counted the pause would stop it).
#[test]
fn worker_time_limit_leaves_paused_time_out() {
    const STEP: Duration = Duration::from_millis(70);
    let case = Case::K4Stht;
    let mut s = endless(case);
    s.time_limit_s = Some(0.3);
    let hand = ManualClock::new();
    let (tx, rx) = mpsc::channel();
    let w = Worker::start_on(case, s, hand.clock(), tx, |e| e).unwrap();
    for _ in 0..2 {
        hand.advance(STEP);
        let p = progress(next(&rx, "a progress report"), "a progress report");
        assert!(!p.paused);
    }
    w.pause();
    assert!(progress(next(&rx, "the paused report"), "the paused report").paused);
    let pause = Duration::from_secs(10);
    hand.advance(pause);
    w.resume();
    let resumed = progress(next(&rx, "the resumed report"), "the resumed report");
    assert!(!resumed.paused, "the run ended at the resume: {resumed:?}");
    // Move on until the end comes; the last progress says when it stopped.
    let mut last = resumed;
    let end = loop {
        hand.advance(STEP);
        match next(&rx, "a report or the end") {
            Event::Progress(p) => last = p,
            Event::Finished(f) => break f,
            Event::Failed(why) => panic!("{why}"),
        }
    };
    assert_eq!(end.stop, StopReason::TimeLimit);
    let worked = Duration::from_secs_f64(last.elapsed_s) - pause;
    assert!(
        // (1 µs for the f64 seconds' rounding)
        worked >= Duration::from_millis(300) && worked <= STEP * 6 + Duration::from_micros(1),
        "stopped after {worked:?} of work"
    );
    let out = w.join().unwrap();
    assert_eq!(out.stop, StopReason::TimeLimit);
    assert_eq!(out.net.settings.time_limit_s, Some(0.3));
}

#[test]
fn worker_refuses_bad_settings_before_starting() {
    let case = Case::K4Stht;
    let mut s = endless(case);
    s.learning_rate = -2.0;
    let (tx, _rx) = mpsc::channel::<Event>();
    assert!(matches!(
        Worker::start_on(case, s, Clock::Real, tx, |e| e),
        Err(AnnError::BadLearningRate(_))
    ));
}
