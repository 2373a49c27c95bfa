//! ISO 2631-1: the weightings against the analog formula of Annex A, the
//! metrics against closed forms, the EU and comfort boundaries.

use biodyn::iso2631::{self, Accumulator, BandBank, Eu, Verdict, Weighting, band_centres, comfort};
use num_complex::Complex64;
use std::f64::consts::PI;

use super::weightings::analog;

fn phase_deg(z: Complex64) -> f64 {
    z.im.atan2(z.re).to_degrees()
}

fn wrap(d: f64) -> f64 {
    (d + 540.0).rem_euclid(360.0) - 180.0
}

#[test]
fn wk_checks_of_spec_7() {
    for (f, want) in [(1.0, 0.4825), (6.31, 1.054), (10.0, 0.9884)] {
        let got = analog(Weighting::Wk, f).norm();
        assert!((got - want).abs() < 5e-4, "|Wk({f})| = {got}, want {want}");
        let lib = Weighting::Wk.analog(f).norm();
        assert!((lib - want).abs() < 5e-4, "library |Wk({f})| = {lib}");
        let dig = Weighting::Wk.digital(1000.0).response(f).norm();
        assert!((dig / want - 1.0).abs() < 0.01, "digital |Wk({f})| = {dig}");
    }
}

#[test]
fn digital_weightings_match_the_analog_formula_at_third_octave_centres() {
    for fs in [1000.0, 2000.0, 5000.0] {
        for w in Weighting::ALL {
            let filt = w.digital(fs);
            let mut worst_mag: f64 = 0.0;
            let mut worst_phase: f64 = 0.0;
            for f in w.centres() {
                let a = analog(w, f);
                let d = filt.response(f);
                worst_mag = worst_mag.max((d.norm() / a.norm() - 1.0).abs());
                worst_phase = worst_phase.max(wrap(phase_deg(d) - phase_deg(a)).abs());
            }
            eprintln!(
                "{} fs {fs}: |W| within {:.4} %, phase within {:.3}°",
                w.name(),
                worst_mag * 100.0,
                worst_phase
            );
            assert!(worst_mag < 0.002, "{} at fs {fs}: {worst_mag}", w.name());
            assert!(worst_phase < 0.1, "{} at fs {fs}: {worst_phase}°", w.name());
            assert!(filt.warning().is_none(), "{:?}", filt.warning());
        }
    }
}

#[test]
fn a_plain_bilinear_wk_would_fail_so_the_test_can_fail() {
    // The textbook bilinear transform of the same sections misses |Wk| at 80 Hz by > 1 %.
    use biodyn::time::{Biquad, Cascade};
    let fs = 1000.0;
    let w = |f: f64| 2.0 * PI * f;
    let q = 1.0 / 2f64.sqrt();
    let g = (w(2.37) / w(3.35)).powi(2);
    let secs = [
        ([0.0, 0.0, 1.0], [w(0.4).powi(2), w(0.4) / q, 1.0]),
        (
            [1.0, 0.0, 0.0],
            [1.0, 1.0 / (q * w(100.0)), 1.0 / w(100.0).powi(2)],
        ),
        (
            [1.0, 1.0 / w(12.5), 0.0],
            [1.0, 1.0 / (0.63 * w(12.5)), 1.0 / w(12.5).powi(2)],
        ),
        (
            [g, g / (0.91 * w(2.37)), g / w(2.37).powi(2)],
            [1.0, 1.0 / (0.91 * w(3.35)), 1.0 / w(3.35).powi(2)],
        ),
    ];
    let c = Cascade::new(
        secs.iter()
            .map(|(n, d)| Biquad::bilinear(*n, *d, 2.0 * fs))
            .collect(),
    );
    let f = 80.0;
    let want = analog(Weighting::Wk, f).norm();
    assert!((c.response(f, fs).norm() / want - 1.0).abs() > 0.01);
    assert!((c.response(1.0, fs).norm() / analog(Weighting::Wk, 1.0).norm() - 1.0).abs() < 1e-3);
    let ours = Weighting::Wk.digital(fs).response(f).norm() / want;
    assert!((ours - 1.0).abs() < 0.01);
}

/// Weighted r.m.s. of a sampled sine of amplitude `amp`, after the transient.
fn weighted_rms(w: Weighting, f: f64, fs: f64, amp: f64) -> f64 {
    let mut filt = w.digital(fs);
    // Settle for 30 periods of the lowest pole (0.4 Hz: 75 s), then measure whole periods.
    let settle = (75.0 * fs) as usize;
    let periods = (20.0 * f).ceil().max(20.0);
    let n = (periods / f * fs).round() as usize;
    let mut acc = Accumulator::new(fs);
    for k in 0..settle + n {
        let y = filt.process(amp * (2.0 * PI * f * k as f64 / fs).sin());
        if k >= settle {
            acc.push(y);
        }
    }
    acc.metrics().aw
}

#[test]
fn weighted_rms_of_sampled_sines_within_one_percent() {
    let fs = 1000.0;
    for (_, f) in band_centres() {
        let got = weighted_rms(Weighting::Wk, f, fs, 2.0);
        let want = 2.0 / 2f64.sqrt() * analog(Weighting::Wk, f).norm();
        assert!((got / want - 1.0).abs() < 0.01, "{f} Hz: {got} vs {want}");
    }
}

#[test]
fn vdv_of_a_steady_sine_is_a_w_three_t_over_eight_to_the_quarter() {
    // Unweighted: VDV = a (3T/8)^¼ exactly for whole periods (mean of sin⁴ is 3/8).
    let (fs, f, a, t) = (1000.0, 5.0, 1.3, 20.0);
    let mut acc = Accumulator::new(fs);
    for k in 0..(t * fs) as usize {
        acc.push(a * (2.0 * PI * f * k as f64 / fs).sin());
    }
    let m = acc.metrics();
    let want = a * (3.0 * t / 8.0).powf(0.25);
    assert!((m.vdv / want - 1.0).abs() < 1e-9, "{} vs {want}", m.vdv);
    assert!((m.aw - a / 2f64.sqrt()).abs() < 1e-9);
    assert!((m.mtvv - a / 2f64.sqrt()).abs() < 1e-6);
    assert!((m.crest - 2f64.sqrt()).abs() < 1e-3);
    // Weighted: VDV = a |W(f)| (3T/8)^¼ after the filter has settled.
    let w = Weighting::Wk;
    let mut filt = w.digital(fs);
    let mut acc = Accumulator::new(fs);
    let settle = (75.0 * fs) as usize;
    for k in 0..settle + (t * fs) as usize {
        let y = filt.process(a * (2.0 * PI * f * k as f64 / fs).sin());
        if k >= settle {
            acc.push(y);
        }
    }
    let want = a * analog(w, f).norm() * (3.0 * t / 8.0).powf(0.25);
    assert!(
        (acc.metrics().vdv / want - 1.0).abs() < 0.01,
        "{} vs {want}",
        acc.metrics().vdv
    );
}

#[test]
fn a8_and_vdv_scale_with_exposure() {
    let mut acc = Accumulator::new(100.0);
    for k in 0..6000 {
        acc.push(((k * 7919) % 113) as f64 / 50.0 - 1.0);
    }
    let m = acc.metrics();
    assert!((m.duration_s - 60.0).abs() < 1e-12);
    let e8 = m.exposure(8.0);
    assert!((e8.a8 - m.aw).abs() < 1e-15);
    let e2 = m.exposure(2.0);
    assert!((e2.a8 - m.aw * 0.5).abs() < 1e-12);
    // VDV over T_exp = VDV (T_exp / T)^¼: 8 h of a 60 s record is 480^¼ times it.
    assert!((e8.vdv / m.vdv - 480f64.powf(0.25)).abs() < 1e-9);
    assert!((e8.vdv / e2.vdv - 4f64.powf(0.25)).abs() < 1e-12);
}

#[test]
fn each_eu_boundary() {
    let j = |v| Verdict::judge(v, iso2631::A8_ACTION, iso2631::A8_LIMIT);
    assert_eq!(j(0.49), Verdict::BelowAction);
    assert_eq!(j(0.5), Verdict::BelowAction);
    assert_eq!(j(0.5000001), Verdict::AboveAction);
    assert_eq!(j(1.15), Verdict::AboveAction);
    assert_eq!(j(1.1500001), Verdict::AboveLimit);
    let v = |x| Verdict::judge(x, iso2631::VDV_ACTION, iso2631::VDV_LIMIT);
    assert_eq!(v(9.1), Verdict::BelowAction);
    assert_eq!(v(9.11), Verdict::AboveAction);
    assert_eq!(v(21.0), Verdict::AboveAction);
    assert_eq!(v(21.01), Verdict::AboveLimit);
    let e = Eu::of(&biodyn::iso2631::Exposure { a8: 0.6, vdv: 25.0 });
    assert_eq!(
        (e.a8.words(), e.vdv.words()),
        ("above action value", "above limit value")
    );
}

#[test]
fn comfort_words_overlap_where_annex_c_does() {
    assert_eq!(comfort(0.2), vec!["not uncomfortable"]);
    assert_eq!(comfort(0.315), vec!["a little uncomfortable"]);
    assert_eq!(
        comfort(0.55),
        vec!["a little uncomfortable", "fairly uncomfortable"]
    );
    assert_eq!(comfort(0.9), vec!["fairly uncomfortable", "uncomfortable"]);
    assert_eq!(comfort(1.4), vec!["uncomfortable", "very uncomfortable"]);
    assert_eq!(
        comfort(2.2),
        vec!["very uncomfortable", "extremely uncomfortable"]
    );
    assert_eq!(comfort(3.0), vec!["extremely uncomfortable"]);
}

#[test]
fn additional_method_checks_fire_on_a_shock() {
    let fs = 100.0;
    let mut acc = Accumulator::new(fs);
    for k in 0..6000 {
        let t = k as f64 / fs;
        let shock = if (30.0..30.1).contains(&t) { 20.0 } else { 0.0 };
        acc.push(0.1 * (2.0 * PI * 3.0 * t).sin() + shock);
    }
    let w = iso2631::additional_methods(&acc.metrics());
    assert_eq!(w.len(), 3, "{w:?}");
    let mut calm = Accumulator::new(fs);
    for k in 0..6000 {
        calm.push((2.0 * PI * 3.0 * k as f64 / fs).sin());
    }
    assert!(iso2631::additional_methods(&calm.metrics()).is_empty());
}

#[test]
fn a_sine_lands_in_its_third_octave_band() {
    let fs = 1000.0;
    for f in [0.63, 5.0, 40.0, 80.0] {
        let mut bank = BandBank::<1>::new(fs);
        let n = (fs * (60.0f64).max(200.0 / f)) as usize;
        for k in 0..n {
            bank.push([(2.0 * PI * f * k as f64 / fs).sin()]);
        }
        let levels = bank.levels();
        let (best, lvl) = levels
            .iter()
            .map(|(f, l)| (*f, l.map(|l| l[0])))
            .max_by(|a, b| a.1.unwrap_or(0.0).total_cmp(&b.1.unwrap_or(0.0)))
            .unwrap();
        assert!((best / f - 1.0).abs() < 0.03, "{f} Hz went to {best}");
        let want = 1.0 / 2f64.sqrt();
        assert!((lvl.unwrap() / want - 1.0).abs() < 0.05, "{f} Hz: {lvl:?}");
        // Two bands away there is almost nothing.
        let i = levels.iter().position(|l| l.0 == best).unwrap();
        for j in [i.checked_sub(2), Some(i + 2)].into_iter().flatten() {
            if j < levels.len() {
                assert!(
                    levels[j].1.unwrap()[0] < 0.1 * want,
                    "{f} Hz leaks into {}: {:?}",
                    levels[j].0,
                    levels[j].1
                );
            }
        }
    }
}

#[test]
fn too_low_a_rate_is_warned_about() {
    // Nyquist below the band's top.
    let w = Weighting::Wk.digital(150.0).warning().unwrap();
    assert!(w.contains("too low") && w.contains("80"), "{w}");
    // Nyquist above 80 Hz but the hold's droop near it is more than 1 %.
    let w = Weighting::Wk.digital(200.0).warning().unwrap();
    assert!(w.contains("misses"), "{w}");
    assert!(Weighting::Wk.digital(1000.0).warning().is_none());
    assert!(Weighting::Wf.digital(20.0).warning().is_none());
}
