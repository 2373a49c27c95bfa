//! The progress callbacks beside the long computations (`sweep_with`,
//! `run_study_with`, `design_with`) report counts that rise to the total
//! and change no bit of the result: they cut the work into blocks, and a
//! block boundary must not change which path solves a point.

use biodyn::freq::{self, Step};
use biodyn::seat::{FloorPsd, SeatGrid, Vary, design, design_with};
use biodyn::time::InputClass;
use biodyn::{Band, Body, End, Link, Param, Preset, Segment, Solver};

/// Every call of a `(done, total)` callback.
fn recorder(calls: &mut Vec<(usize, usize)>) -> impl FnMut(usize, usize) + '_ {
    |done, total| calls.push((done, total))
}

/// Starts at 0, never falls, ends at the total; the total never changes.
fn rises_to_the_total(calls: &[(usize, usize)], total: usize) {
    assert_eq!(calls.first(), Some(&(0, total)), "{calls:?}");
    assert_eq!(calls.last(), Some(&(total, total)), "{calls:?}");
    assert!(
        calls
            .windows(2)
            .all(|w| w[0].0 <= w[1].0 && w[1].1 == total)
    );
}

/// A sweep over more points than one progress block, with a ragged end
/// (not a multiple of the chain's lanes), on each solver path.
#[test]
fn a_sweep_with_progress_is_the_sweep_bit_for_bit() {
    let band = Band::new(0.5, 20.0, 0.00197).unwrap();
    assert!(band.len() > freq::SWEEP_BLOCK + 1 && band.len() % 8 != 0);
    let chain = Body::paper(75.0).unwrap();
    let mut tree = Body::paper(75.0).unwrap();
    tree.segments.push(Segment::new("viscera", 6.5));
    tree.links
        .push(Link::new("viscera-chest", 4, End::Segment(1), 4e4, 900.0));
    let seat = Preset::builtin("paper-75kg-suspension-seat")
        .unwrap()
        .unwrap()
        .body;
    for (name, body) in [("chain", chain), ("tree", tree), ("seat", seat)] {
        let solver = Solver::new(&body);
        let mut calls = Vec::new();
        let with = solver.sweep_with(&band, &mut recorder(&mut calls));
        assert!(with == solver.sweep(&band), "{name} ({})", solver.method());
        rises_to_the_total(&calls, band.len());
        assert!(calls.len() >= 3, "{name}: {calls:?}");
    }
}

#[test]
fn a_study_with_progress_is_the_study() {
    let body = Body::paper(75.0).unwrap();
    let band = Band::default();
    let steps = [
        Step::Percent(-40.0),
        Step::Percent(0.0),
        Step::Percent(40.0),
    ];
    let mut calls = Vec::new();
    let with = freq::run_study_with(
        &body,
        Param::Stiffness(3),
        &steps,
        &band,
        &mut recorder(&mut calls),
    )
    .unwrap();
    let without = freq::run_study(&body, Param::Stiffness(3), &steps, &band).unwrap();
    for (a, b) in with.variants.iter().zip(&without.variants) {
        assert!(a.curve == b.curve && a.peaks == b.peaks, "{}", a.label);
    }
    assert_eq!(calls.first(), Some(&(0, 3 * band.len())));
    assert_eq!(calls.last(), Some(&(3 * band.len(), 3 * band.len())));
    assert!(calls.windows(2).all(|w| w[0].0 <= w[1].0));
}

#[test]
fn a_design_with_progress_is_the_design_and_counts_every_evaluation() {
    let p = Preset::builtin("paper-75kg-suspension-seat")
        .unwrap()
        .unwrap();
    let g = SeatGrid::new(&FloorPsd::Class(InputClass::parse("EM6").unwrap())).unwrap();
    let vary = [Vary::new(&p.body, "suspension.c", 200.0, 4000.0).unwrap()];
    let mut calls = Vec::new();
    let with = design_with(&p.body, &g, &vary, 0.015, &mut recorder(&mut calls)).unwrap();
    assert_eq!(with, design(&p.body, &g, &vary, 0.015).unwrap());
    let map = biodyn::seat::MAP_POINTS[0];
    assert_eq!(calls[0], (0, map));
    assert_eq!(calls.len(), with.evaluations + 1, "one call per evaluation");
    assert!(calls.iter().enumerate().all(|(i, &c)| c == (i, map)));
}
