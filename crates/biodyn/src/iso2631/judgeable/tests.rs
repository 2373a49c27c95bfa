use super::*;
use crate::iso2631::Accumulator;
use std::f64::consts::PI;

/// E₂ and E₄^¼ of the analog step responses, from an independent
/// integration (scipy.signal.step of the ISO 2631-1 Annex A formula, 0–200 s
/// at 0.5 ms: scripts/reference/step_energies.py): the digital filter at
/// 1 kHz agrees.
#[test]
fn step_energies_match_the_analog_weighting() {
    for (w, e2, e4q) in [
        (Weighting::Wk, 0.045_07, 0.352_87),
        (Weighting::Wd, 0.125_17, 0.427_21),
    ] {
        let (d2, d4q) = step_energies(w, 1000.0, 60.0);
        assert!((d2 / e2 - 1.0).abs() < 0.01, "{w:?}: E2 {d2} vs {e2}");
        assert!((d4q / e4q - 1.0).abs() < 0.01, "{w:?}: E4^¼ {d4q} vs {e4q}");
    }
}

/// ISO 2631-1's band for health is 0.5–80 Hz: a rate must exceed 160 Hz.
#[test]
fn the_rate_must_carry_the_band() {
    assert!(check_rate(Weighting::Wk, 160.001).is_ok());
    let e = check_rate(Weighting::Wk, 160.0).unwrap_err();
    assert!(
        matches!(e, JudgeError::Rate { top_hz, .. } if top_hz == 80.0),
        "{e}"
    );
    let e = check_rate(Weighting::Wd, 0.5).unwrap_err().to_string();
    assert!(e.contains("more than 160 Hz") && e.contains("t_ms"), "{e}");
}

/// Metrics of `a(t)` weighted by Wk at 500 Hz for 10 s, and its mean.
fn weighted(a: impl Fn(f64) -> f64) -> (Metrics, f64) {
    let fs = 500.0;
    let mut f = Weighting::Wk.digital(fs);
    let mut acc = Accumulator::new(fs);
    let mut mean = Mean::new(fs);
    for i in 0..5000 {
        let x = a(i as f64 / fs);
        mean.push(x);
        acc.push(f.process(x));
    }
    (acc.metrics(), mean.offset())
}

/// The record: 1 + 0.05·sin(2π·5t) g on z is refused; the same
/// vibration without the 1 g is judged with nothing said.
#[test]
fn gravity_is_refused_and_vibration_is_not() {
    let vib = |t: f64| 0.05 * G_N * (2.0 * PI * 5.0 * t).sin();
    let (m, mean) = weighted(|t| G_N + vib(t));
    let e = check_offset(Axis::Z, Weighting::Wk, 500.0, mean, &m).unwrap_err();
    let JudgeError::Offset {
        aw_share,
        vdv_share,
        ..
    } = e
    else {
        panic!("{e}")
    };
    assert!(aw_share > 0.5 && vdv_share > 0.5, "{aw_share} {vdv_share}");
    assert!(e.to_string().contains("remove_mean"), "{e}");
    let (m, mean) = weighted(vib);
    assert!(mean.abs() < 1e-12);
    assert_eq!(
        check_offset(Axis::Z, Weighting::Wk, 500.0, mean, &m),
        Ok(None)
    );
}

/// A one-sided shock later in the record has a mean but starts at rest: no
/// step, nothing refused; the same shock on an offset is refused.
#[test]
fn a_shock_is_no_offset() {
    let shock = |t: f64| {
        if (1.0..1.5).contains(&t) {
            30.0 * (2.0 * PI * (t - 1.0)).sin()
        } else {
            0.0
        }
    };
    let (m, offset) = weighted(shock);
    assert_eq!(offset, 0.0);
    assert_eq!(
        check_offset(Axis::Z, Weighting::Wk, 500.0, offset, &m),
        Ok(None)
    );
    let (m, offset) = weighted(|t| shock(t) + G_N);
    assert!((offset - G_N).abs() < 1e-9, "{offset}");
    assert!(check_offset(Axis::Z, Weighting::Wk, 500.0, offset, &m).is_err());
}

/// A small offset is said, a smaller one is not: the bound grows with |m|.
#[test]
fn a_small_mean_is_noted_below_the_refusal() {
    let vib = |t: f64| 0.5 * (2.0 * PI * 5.0 * t).sin();
    let (m, mean) = weighted(|t| 0.03 + vib(t));
    let note = check_offset(Axis::Z, Weighting::Wk, 500.0, mean, &m).unwrap();
    let s = offset_share(Weighting::Wk, 500.0, mean, &m);
    assert!(s.vdv > OFFSET_NOTED && s.vdv < OFFSET_REFUSED, "{s:?}");
    assert!(note.is_some_and(|n| n.contains("remove the mean")));
    let (m, mean) = weighted(|t| 0.001 + vib(t));
    assert_eq!(
        check_offset(Axis::Z, Weighting::Wk, 500.0, mean, &m),
        Ok(None)
    );
}

/// Metrics and offset of `a(t)` weighted by Wk at 500 Hz for 60 s.
fn weighted_60(a: impl Fn(f64) -> f64) -> (Metrics, f64) {
    let fs = 500.0;
    let mut f = Weighting::Wk.digital(fs);
    let mut acc = Accumulator::new(fs);
    let mut mean = Mean::new(fs);
    for i in 0..30_000 {
        let x = a(i as f64 / fs);
        mean.push(x);
        acc.push(f.process(x));
    }
    (acc.metrics(), mean.offset())
}

/// A hostile review's record: 1 g from t = 1 s on (a logger started
/// before its sensor), first second quiet. The start rule alone let it
/// through with VDV "above action value"; the level it holds refuses it.
/// A slow heave below the band (0.25 Hz, 4 m/s²), whose first second has
/// a mean of 2.5 m/s², is judged.
#[test]
fn an_offset_that_starts_late_is_refused() {
    let vib = |t: f64| 0.05 * G_N * (2.0 * PI * 5.0 * t).sin();
    let late = |t: f64| vib(t) + if t >= 1.0 { G_N } else { 0.0 };
    let (m, offset) = weighted_60(late);
    assert!((offset - G_N * 59.0 / 60.0).abs() < 1e-6, "{offset}");
    assert!(check_offset(Axis::Z, Weighting::Wk, 500.0, offset, &m).is_err());
    for v in [vib, |t: f64| 4.0 * (2.0 * PI * 0.25 * t).sin()] {
        let (m, offset) = weighted_60(v);
        assert!(
            check_offset(Axis::Z, Weighting::Wk, 500.0, offset, &m).is_ok(),
            "{offset}"
        );
    }
}

/// A clock in seconds named t_ms reads 1000 times too fast: a 5 Hz
/// vibration at 200 kHz is all but removed by Wk, and refused; the same
/// rate with in-band content is judged.
#[test]
fn content_far_above_the_band_is_refused() {
    let fs = 200_000.0;
    let run = |f_hz: f64| {
        let mut w = Weighting::Wk.digital(fs);
        let mut acc = Accumulator::new(fs);
        let mut mean = Mean::new(fs);
        for i in 0..480_000 {
            let x = (2.0 * PI * f_hz * i as f64 / fs).sin();
            mean.push(x);
            acc.push(w.process(x));
        }
        check_band(Axis::Z, Weighting::Wk, fs, &mean, &acc.metrics())
    };
    let e = run(5000.0).unwrap_err();
    assert!(e.to_string().contains("t_ms"), "{e}");
    assert!(run(5.0).is_ok());
}
