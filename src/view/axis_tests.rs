//! Tick choice: round values, magnitude floors, log 1-2-5, cell mapping.
use super::*;

fn labels(p: &Plan) -> Vec<&str> {
    p.ticks.iter().map(|t| t.label.as_str()).collect()
}

/// Room for `n` ticks at most.
fn at_most(n: usize) -> impl Fn(f64, f64, &[Tick]) -> bool {
    move |_, _, t| t.len() <= n
}

#[test]
fn linear_ticks_are_round_and_cover_the_data() {
    let p = plan(
        0.5,
        20.0,
        Scale::Linear {
            pad: 0.0,
            floor_zero: false,
        },
        &at_most(6),
    );
    assert_eq!((p.lo, p.hi), (0.0, 20.0));
    assert_eq!(labels(&p), ["0", "5", "10", "15", "20"]);
    let p = plan(
        0.93,
        1.78,
        Scale::Linear {
            pad: 0.05,
            floor_zero: false,
        },
        &at_most(6),
    );
    // Steps of 0.1 and 0.2 need 11 and 7 ticks: 0.5 it is.
    assert_eq!(labels(&p), ["0.5", "1", "1.5", "2"]);
    assert!(p.lo <= 0.93 && p.hi >= 1.78);
}

#[test]
fn a_magnitude_axis_starts_at_zero_never_below() {
    // The DPMI of a study once ran from -5000 to 5000.
    for n in [2, 3, 5, 8] {
        let p = plan(
            12.0,
            4100.0,
            Scale::Linear {
                pad: 0.05,
                floor_zero: true,
            },
            &at_most(n),
        );
        assert_eq!(p.lo, 0.0, "{n} ticks: {p:?}");
        assert!(p.hi >= 4100.0 && p.hi <= 10000.0, "{p:?}");
        assert!(p.ticks.iter().all(|t| t.at >= 0.0), "{p:?}");
    }
    // A phase may be negative.
    let p = plan(
        -170.0,
        30.0,
        Scale::Linear {
            pad: 0.05,
            floor_zero: true,
        },
        &at_most(5),
    );
    assert!(p.lo <= -170.0 && p.hi >= 30.0);
    assert!(labels(&p).contains(&"0"), "{p:?}");
}

#[test]
fn log_ticks_follow_1_2_5() {
    let (a, b) = (0.5f64.log10(), 20f64.log10());
    let p = plan(a, b, Scale::Log, &at_most(8));
    assert_eq!(labels(&p), ["0.5", "1", "2", "5", "10", "20"]);
    assert!((p.lo - a).abs() < 1e-12 && (p.hi - b).abs() < 1e-12);
    let p = plan(a, b, Scale::Log, &at_most(3));
    assert_eq!(labels(&p), ["1", "10"]);
    // Bounds round out to 1-2-5 values.
    let p = plan(0.3f64.log10(), 1.7f64.log10(), Scale::Log, &at_most(8));
    assert!((10f64.powf(p.lo) - 0.2).abs() < 1e-12, "{p:?}");
    assert!((10f64.powf(p.hi) - 2.0).abs() < 1e-12, "{p:?}");
    // RMS errors over four decades.
    let p = plan(-4.2, -0.1, Scale::Log, &at_most(6));
    assert_eq!(labels(&p), ["0.0001", "0.001", "0.01", "0.1", "1"]);
    // Under a decade: linear round steps at their log positions.
    let p = plan(1.1f64.log10(), 1.9f64.log10(), Scale::Log, &at_most(6));
    assert_eq!(labels(&p), ["1", "1.2", "1.4", "1.6", "1.8", "2"]);
}

#[test]
fn fixed_bounds_are_kept() {
    let p = plan(-0.3, 2.7, Scale::Fixed { log: false }, &at_most(4));
    assert_eq!((p.lo, p.hi), (-0.3, 2.7));
    assert_eq!(labels(&p), ["0", "1", "2"]);
}

#[test]
fn nothing_fits_gives_no_labels() {
    let none = |_: f64, _: f64, t: &[Tick]| t.is_empty();
    let p = plan(
        0.0,
        1.0,
        Scale::Linear {
            pad: 0.0,
            floor_zero: true,
        },
        &none,
    );
    assert!(p.ticks.is_empty() && p.hi > p.lo);
}

#[test]
fn tick_texts() {
    assert_eq!(tick_text(15.0, 5.0), "15");
    assert_eq!(tick_text(1.5, 0.5), "1.5");
    assert_eq!(tick_text(0.25, 0.05), "0.25");
    assert_eq!(tick_text(-0.0, 0.5), "0");
    assert_eq!(tick_text(2_500_000.0, 500_000.0), "2.5e6");
    assert_eq!(tick_text(3000.0, 1000.0), "3000");
    assert_eq!(tick_text(2e-5, 1e-5), "2e-5");
}

#[test]
fn cells_follow_ratatui_canvas_and_agree_across_resolutions() {
    let m = Mapping {
        lo: 0.0,
        hi: 20.0,
        cells: 74,
        sub: 2,
        flip: false,
    };
    assert_eq!(m.cell(0.0), Some(0));
    assert_eq!(m.cell(20.0), Some(73));
    assert_eq!(m.cell(20.1), None);
    // 15 Hz: dot round(0.75 * 147) = 110, cell 55.
    assert_eq!(m.cell(15.0), Some(55));
    for k in [1u16, 2, 4] {
        let res = f64::from(74 * k);
        for i in 0..=2000 {
            let t = f64::from(i) / 2000.0;
            let want = m.cell(t * 20.0).unwrap();
            let tk = m.renorm(t, k);
            let got = ((tk * (res - 1.0)).round() as u32 / u32::from(k)) as u16;
            assert_eq!(got, want, "k {k} t {t}");
        }
    }
}
