//! The whole-body frequency weightings of ISO 8041-1:2017 (Wb, Wc, Wd, We,
//! Wf, Wj, Wk, Wm), as the analog formula and as digital filters.
//!
//! The analog weighting is ISO 8041-1 Formula (5), s = j2πf, ωi = 2πfi:
//! W(s) = Hh·Hl·Ht·Hs with the band limits Hh = 1/(1 + ω1/(Q1 s) + (ω1/s)²),
//! Hl = 1/(1 + s/(Q2 ω2) + (s/ω2)²), the transition
//! Ht = K (1 + s/ω3)/(1 + s/(Q4 ω4) + (s/ω4)²) and the upward step
//! Hs = (1 + s/(Q5 ω5) + (s/ω5)²)/(1 + s/(Q6 ω6) + (s/ω6)²)·(ω5/ω6)²; a stage
//! whose frequencies the table gives as ∞ is 1. The parameters are one table
//! ([`table`]).
//!
//! The digital form is that weighting discretised exactly for an input
//! linear between samples (Van Loan's matrix exponential, as for the body)
//! in parallel form, one biquad per pole pair (`time::foh`, shared with ISO
//! 2631-5's seat-to-spine transfer), plus a 3-tap
//! zero-phase FIR that undoes the hold's sinc² droop ([`filter`]). A plain
//! bilinear Wk is 3 % low at 80 Hz for fs = 1000 Hz; this one is within
//! 0.1 % in magnitude with exact phase (tests/physics/iso2631.rs).

mod filter;
mod formula;
mod table;

pub use filter::WeightingFilter;
pub use formula::Weighting;
pub use table::{Definition, Params, Quantity, Step, TABLE};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_is_in_the_order_of_all_and_fits_the_filter() {
        for (i, w) in Weighting::ALL.into_iter().enumerate() {
            assert_eq!(TABLE[i].name, format!("{w:?}"));
            assert_eq!(Weighting::parse(&w.name().to_lowercase()), Some(w));
            assert!(w.sections().len() <= filter::SECTIONS, "{w:?}");
            let p = w.params();
            // A zero without its pole pair would make the transition improper.
            assert!(p.f3.is_none() || p.f4.is_some(), "{w:?}");
            assert_eq!(p.f4.is_some(), p.q4.is_some(), "{w:?}");
        }
        assert_eq!(Weighting::parse("Wz"), None);
    }

    #[test]
    fn centres_are_the_exact_third_octaves_of_the_band() {
        let c: Vec<f64> = Weighting::Wk.centres().collect();
        assert_eq!(c.len(), 23);
        assert!((c[0] - 10f64.powf(-0.3)).abs() < 1e-15);
        assert!((c[22] - 10f64.powf(1.9)).abs() < 1e-12);
        assert_eq!(Weighting::Wf.centres().count(), 8);
        assert_eq!(Weighting::Wm.centres().count(), 20);
    }
}
