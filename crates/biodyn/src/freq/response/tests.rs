//! The solver's paths agree with each other, and which one it takes.

use super::*;
use crate::body::model::Param;

#[test]
fn tri_and_general_agree_on_the_paper_model() {
    let s = Solver::new(&Body::paper(75.0).unwrap());
    for f in [0.5, 1.0, 4.7, 5.46, 12.0, 20.0] {
        let a = s.transfer(f);
        let b = s.transfer_general(f);
        for (x, y) in a.iter().zip(&b) {
            assert!((x - y).norm() <= 1e-12 * y.norm(), "{f}: {x} vs {y}");
        }
    }
}

/// The chain's fast path takes any link that carries something: a spring,
/// a damper, or both; the solver keeps the segments' masses as given.
#[test]
fn a_spring_or_a_damper_alone_keeps_the_chain_path_and_the_masses_are_the_bodys() {
    let body = Body::paper(75.0).unwrap();
    let s = Solver::new(&body);
    assert_eq!(s.method(), "chain");
    let want: Vec<f64> = body.segments.iter().map(|g| g.mass).collect();
    assert_eq!(s.masses(), want.as_slice());
    for p in [Param::Stiffness(1), Param::Damping(1)] {
        let mut half = body.clone();
        half.set(p, 0.0).unwrap();
        let s = Solver::new(&half);
        assert_eq!(s.method(), "chain", "{p:?} = 0");
        // And it agrees with the general solve there too.
        for f in [0.7, 3.0, 9.0] {
            for (x, y) in s.transfer(f).iter().zip(&s.transfer_general(f)) {
                assert!(
                    (x - y).norm() <= 1e-12 * y.norm(),
                    "{p:?} = 0, {f}: {x} vs {y}"
                );
            }
        }
    }
}
