//! ISO 2631-5:2018 against its other form and by hand: the streaming
//! seat-to-spine filter against Formula 2 (the response computed in the
//! frequency domain, a DFT of the whole record, H applied, transformed
//! back), the dose of a record against the peaks of that response, and the
//! Annex C example through a whole assessment.

use biodyn::Body;
use biodyn::iso2631::spine::{Person, Sex, SpineAccumulator, SpineError, SpineFilter};
use biodyn::iso2631::{Weighting, assess_with};
use biodyn::time::{Axis, PerAxis};
use num_complex::Complex64;
use std::f64::consts::PI;

/// Formula 1 written out from ISO 2631-5:2018 §5.2, independent of the
/// library: the zero (34 rad/s, ζ 0.35) over six pole pairs.
fn transfer(f: f64) -> Complex64 {
    let s = Complex64::new(0.0, 2.0 * PI * f);
    let q = |w: f64, z: f64| 1.0 + 2.0 * z * s / w + (s / w) * (s / w);
    q(34.0, 0.35)
        / (q(31.0, 0.21)
            * q(230.0, 0.88)
            * q(260.0, 0.80)
            * q(320.0, 0.40)
            * q(380.0, 0.75)
            * q(420.0, 0.65))
}

/// Formula 2 written out: A(t) = F⁻¹[H(ω)·F[a(t)]], a plain DFT (the record
/// is padded with silence, so the circular response is the linear one).
fn formula_2(a: &[f64], fs: f64) -> Vec<f64> {
    let n = a.len();
    let w = |k: usize, t: usize| {
        Complex64::from_polar(1.0, -2.0 * PI * ((k * t) % n) as f64 / n as f64)
    };
    let spectrum: Vec<Complex64> = (0..=n / 2)
        .map(|k| {
            let x: Complex64 = a.iter().enumerate().map(|(t, &v)| w(k, t) * v).sum();
            x * transfer(k as f64 * fs / n as f64)
        })
        .collect();
    (0..n)
        .map(|t| {
            let mut y = spectrum[0].re;
            for (k, x) in spectrum.iter().enumerate().skip(1) {
                let c = x * w(k, t).conj();
                y += if 2 * k == n { c.re } else { 2.0 * c.re };
            }
            y / n as f64
        })
        .collect()
}

/// Three shocks of different heights and widths (with a rebound, so no
/// mean), surrounded by silence.
fn shocks(fs: f64, n: usize) -> Vec<f64> {
    let mut a = vec![0.0; n];
    for (at, peak, width) in [(0.8, 30.0, 0.06), (2.0, 55.0, 0.1), (3.1, 18.0, 0.03)] {
        let (k0, m) = ((at * fs) as usize, (width * fs) as usize);
        for j in 0..2 * m {
            let u = j as f64 / m as f64;
            a[k0 + j] = peak * (PI * u).sin() * if u < 1.0 { 1.0 } else { 0.4 };
        }
    }
    a
}

/// The streaming filter's response, aligned: the output of call k + 1 is
/// the response at sample k; the last with the input held.
fn streamed(a: &[f64], fs: f64) -> Vec<f64> {
    let mut f = SpineFilter::new(fs);
    let mut out: Vec<f64> = a.iter().map(|&v| f.process(v)).skip(1).collect();
    out.push(f.process(*a.last().unwrap()));
    out
}

#[test]
fn the_streaming_filter_is_formula_2() {
    let fs = 500.0;
    let a = shocks(fs, 2500);
    let (ours, theirs) = (streamed(&a, fs), formula_2(&a, fs));
    let top = theirs.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let worst = ours
        .iter()
        .zip(&theirs)
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
    assert!(top > 30.0, "{top}");
    // The hold (linear between samples) against the DFT's band-limited
    // interpolation: 1.2e-5 of the peak measured, 1e-4 allowed.
    assert!(worst < 1e-4 * top, "worst {worst} of {top}");
}

/// The dose of a record equals 1.07·(Σ A_i⁶)^⅙ over the positive peaks of
/// Formula 2's response, to the peaks' own difference.
#[test]
fn the_dose_is_the_peaks_of_formula_2() {
    let fs = 500.0;
    let a = shocks(fs, 2500);
    let reference = formula_2(&a, fs);
    let (mut peaks, mut run) = (Vec::new(), 0.0f64);
    for &y in &reference {
        if y > 0.0 {
            run = run.max(y);
        } else if run > 0.0 {
            peaks.push(run);
            run = 0.0;
        }
    }
    let dz_ref = 1.07
        * peaks
            .iter()
            .map(|p: &f64| p.powi(6))
            .sum::<f64>()
            .powf(1.0 / 6.0);
    let mut acc = SpineAccumulator::new(fs);
    for &v in &a {
        acc.push(v);
    }
    let who = Person::new(25.0, 10, 240, Sex::Male).unwrap();
    let s = acc.finish(&who, 5.0 / 3600.0).unwrap();
    assert!(s.dose.count >= 3, "{}", s.dose.count);
    assert!(
        (s.dose.dz / dz_ref - 1.0).abs() < 2e-3,
        "{} vs {dz_ref}",
        s.dose.dz
    );
    // t_d = t_m: the daily dose is the dose.
    assert!((s.dzd - s.dose.dz).abs() < 1e-9 * s.dzd);
    // The largest peak is the 55 m/s² shock's response, near 2.0–2.2 s.
    let (t, v) = s.largest(1)[0];
    assert!((2.0..2.3).contains(&t) && v > 40.0, "{t} {v}");
}

/// A sine at 2 Hz: the response is |H(2)|·A, the peaks all equal it, one a
/// cycle, so Dz = 1.07·|H|·A·n^⅙, by hand.
#[test]
fn a_sine_dose_by_hand() {
    let fs = 1000.0;
    let (amp, f, secs) = (3.0, 2.0, 50.0);
    let mut acc = SpineAccumulator::new(fs);
    for k in 0..(secs * fs) as usize {
        acc.push(amp * (2.0 * PI * f * k as f64 / fs).sin());
    }
    let who = Person::new(30.0, 1, 100, Sex::Female).unwrap();
    let s = acc.finish(&who, 1.0).unwrap();
    assert_eq!(s.dose.count, 100);
    let g = transfer(f).norm();
    let hand = 1.07 * g * amp * 100f64.powf(1.0 / 6.0);
    // The first peak is in the start-up transient; the 99 others are steady.
    assert!(
        (s.dose.dz / hand - 1.0).abs() < 5e-3,
        "{} vs {hand}",
        s.dose.dz
    );
    let dzd = s.dose.dz * (3600.0 / secs).powf(1.0 / 6.0);
    assert!((s.dzd - dzd).abs() < 1e-9 * dzd);
}

/// Too short for one shock, and a gravity offset, are refused; a silent
/// record has no peak and says so.
#[test]
fn what_the_method_cannot_judge_is_refused() {
    let who = Person::new(30.0, 5, 200, Sex::Male).unwrap();
    let run = |a: &[f64]| {
        let mut acc = SpineAccumulator::new(200.0);
        for &v in a {
            acc.push(v);
        }
        acc.finish(&who, 8.0)
    };
    assert!(matches!(run(&[1.0; 100]), Err(SpineError::TooShort(d)) if d == 0.5));
    let mut g: Vec<f64> = shocks(200.0, 1000);
    g.iter_mut().for_each(|v| *v += 9.81);
    assert!(
        matches!(run(&g), Err(SpineError::Mean { .. })),
        "{:?}",
        run(&g)
    );
    let quiet = run(&[0.0; 1000]).unwrap();
    // Too slow a rate for the transfer's 67 Hz pole and the 80 Hz band.
    let mut slow = SpineAccumulator::new(100.0);
    (0..500).for_each(|_| slow.push(0.0));
    assert!(matches!(slow.measure(), Err(SpineError::LowRate(f)) if f == 100.0));
    // The bound itself is judged: 160 Hz is fs/2 = 80 Hz, the band's top;
    // a hair below it is not.
    let at = |fs: f64| {
        let mut acc = SpineAccumulator::new(fs);
        (0..(2.0 * fs) as usize).for_each(|_| acc.push(0.0));
        acc.measure()
    };
    assert!(
        at(biodyn::iso2631::spine::MIN_FS).is_ok(),
        "{:?}",
        at(160.0)
    );
    assert!(matches!(at(159.99), Err(SpineError::LowRate(_))));
    assert_eq!((quiet.dose.count, quiet.dose.dz), (0, 0.0));
    assert!(quiet.notes.iter().any(|n| n.contains("no positive")));
}

/// Through a whole assessment: five isolated shocks whose spinal response
/// peaks near 40 m/s², the Annex C example's person; the block equals the
/// accumulator's, MSDV is there for seat and head, and no spine without a
/// person.
#[test]
fn an_assessment_carries_the_spine_and_sickness() {
    let fs = 500.0;
    let n = (12.0 * fs) as usize;
    let mut z = vec![0.0; n];
    for i in 0..5 {
        let k0 = ((1.0 + 2.0 * i as f64) * fs) as usize;
        let m = (0.08 * fs) as usize;
        for j in 0..2 * m {
            let u = j as f64 / m as f64;
            z[k0 + j] = 40.0 * (PI * u).sin() * if u < 1.0 { 1.0 } else { 0.5 };
        }
    }
    let body = Body::paper(75.0).unwrap();
    let mut present = PerAxis::default();
    present.set(Axis::Z, ());
    let rows = || z.iter().map(|&a| Ok([0.0, 0.0, a]));
    let who = Person::new(25.0, 10, 240, Sex::Male).unwrap();
    let r = assess_with(&body, fs, rows(), &present, 8.0, Some(&who)).unwrap();
    let s = r.spine.clone().unwrap().unwrap();
    let mut acc = SpineAccumulator::new(fs);
    z.iter().for_each(|&a| acc.push(a));
    assert_eq!(s, acc.finish(&who, 8.0).unwrap());
    assert!(s.dose.count >= 5);
    let top5: Vec<f64> = s.largest(5).iter().map(|p| p.1).collect();
    assert!(top5.iter().all(|&v| (35.0..50.0).contains(&v)), "{top5:?}");
    assert!((s.dzd / s.dose.dz - (8.0 * 3600.0 / 12.0f64).powf(1.0 / 6.0)).abs() < 1e-9);
    assert!(r.sickness_seat.msdv > 0.0 && r.sickness_head.msdv > 0.0);
    let wf = Weighting::Wf.digital(fs);
    let mut sum2 = 0.0;
    let mut f = wf.clone();
    z.iter().for_each(|&a| {
        let w = f.process(a);
        sum2 += w * w;
    });
    assert!((r.sickness_seat.msdv - (sum2 / fs).sqrt()).abs() < 1e-12);
    let none = assess_with(&body, fs, rows(), &present, 8.0, None).unwrap();
    assert!(none.spine.is_none());
}
