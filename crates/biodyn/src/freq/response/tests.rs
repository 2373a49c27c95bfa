//! The solver's paths agree with each other.

use super::*;

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
