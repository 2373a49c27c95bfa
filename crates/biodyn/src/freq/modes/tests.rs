//! The modes of the Boileau & Rakheja model against the reference, shapes
//! against the pencil, and the messages.

use super::*;
use crate::body::model::{Body, Segment};
use crate::freq::response::Solver;

#[test]
fn a_mode_message_gives_four_significant_digits_at_any_size() {
    let e = |hz| {
        ModesError::Untrusted {
            hz,
            residual: 1e-3,
            limit: 1e-8,
        }
        .to_string()
    };
    assert!(
        e(1.234e-7).starts_with("mode near 1.234e-7 Hz"),
        "{}",
        e(1.234e-7)
    );
    assert!(e(5.2).starts_with("mode near 5.200 Hz"), "{}", e(5.2));
    assert!(e(1432.0).starts_with("mode near 1432 Hz"), "{}", e(1432.0));
}

fn br1998() -> Body {
    let masses = [5.31, 28.49, 8.62, 12.78];
    let segs = crate::body::model::PAPER_SEGMENTS
        .iter()
        .zip(masses)
        .map(|(n, m)| Segment {
            name: n.to_string(),
            mass: m,
            share: None,
            seat: false,
        })
        .collect();
    Body::chain(
        segs,
        &crate::body::model::PAPER_K,
        &crate::body::model::PAPER_C,
    )
}

#[test]
fn boileau_rakheja_modes_match_reference() {
    let modes = analyse_modes(&br1998()).unwrap();
    let und: Vec<f64> = modes.undamped.iter().map(|u| u.natural_hz).collect();
    // A zip stops at the shorter side: without the count an empty list passes.
    assert_eq!(und.len(), 4, "{und:?}");
    for (got, want) in und.iter().zip([5.11, 18.61, 35.42, 42.52]) {
        assert!((got - want).abs() < 0.006, "{und:?}");
    }
    let osc: Vec<(f64, f64)> = modes
        .damped
        .iter()
        .filter_map(|m| match m.kind {
            // The reference quotes |λ|/2π, the damped mode's natural frequency.
            ModeKind::Oscillatory {
                natural_hz,
                damping_ratio,
                ..
            } => Some((natural_hz, damping_ratio)),
            _ => None,
        })
        .collect();
    assert_eq!(osc.len(), 2, "{osc:?}");
    assert!((osc[0].0 - 5.13).abs() < 0.006 && (osc[0].1 - 0.394).abs() < 6e-4);
    assert!((osc[1].0 - 41.1).abs() < 0.06 && (osc[1].1 - 0.186).abs() < 6e-4);
    let mut rates: Vec<f64> = modes
        .damped
        .iter()
        .filter_map(|m| match m.kind {
            ModeKind::Overdamped { rate_per_s, .. } => Some(rate_per_s),
            _ => None,
        })
        .collect();
    rates.sort_by(f64::total_cmp);
    assert_eq!(rates.len(), 4, "{rates:?}");
    for (got, want) in rates.iter().zip([37.8, 45.5, 311.7, 1342.9]) {
        assert!((got - want).abs() < 0.06, "{rates:?}");
    }
}

#[test]
fn shapes_are_null_vectors_of_the_pencil() {
    let body = br1998();
    let s = Solver::new(&body);
    let modes = analyse_modes(&body).unwrap();
    for mode in &modes.damped {
        let l = mode.eigenvalue;
        let k = s.stiffness_matrix();
        let c = s.damping_matrix();
        for i in 0..4 {
            let mut r = Complex64::new(0.0, 0.0);
            let mut scale = 0.0;
            for j in 0..4 {
                let mut q = k[(i, j)] + l * c[(i, j)];
                if i == j {
                    q += l * l * body.segments[i].mass;
                }
                r += q * mode.shape[j];
                scale += q.norm() * mode.shape[j].norm();
            }
            assert!(r.norm() <= 1e-7 * scale, "residual {r} vs {scale}");
        }
    }
}
