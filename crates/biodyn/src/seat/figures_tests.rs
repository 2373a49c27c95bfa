//! The seat's figures against a brute-force integration: each row interval
//! of a PSD file cut into pieces of 1e-4 in ln f (at least 64), Simpson's
//! rule on G·Φ with Φ solved at every point, nothing shared with the
//! quadrature but the model's solver and the weighting's formula. The four
//! floors the fixed 400-step grid got wrong (zero rows around a narrow peak
//! −24 %, a narrow peak refused as "weighted r.m.s. 0", a measured PSD
//! −2.7 %, a band from 1e-300 Hz: SEAT 144 % and a NaN stroke) each agree
//! to 1e-5.

use super::error::SeatError;
use super::figures::{MIN_HZ, SeatFigures, SeatGrid};
use super::psd::FloorPsd;
use crate::body::model::Body;
use crate::freq::response::Solver;
use crate::iso2631::Weighting;
use crate::time::CLASSES;
use std::f64::consts::PI;

fn seat_body() -> Body {
    crate::body::preset::Preset::builtin("paper-75kg-suspension-seat")
        .expect("a built-in")
        .expect("it loads")
        .body
}

fn table(rows: Vec<(f64, f64)>) -> FloorPsd {
    FloorPsd::Table {
        name: "t.csv".into(),
        rows,
    }
}

/// (floor a_w, pan a_w, r.m.s. travel) by brute force over [lo, hi].
fn brute(psd: &FloorPsd, body: &Body, lo: f64, hi: f64) -> (f64, f64, f64) {
    let seat = body.seat.as_ref().expect("a seat");
    let upper = body.links[seat.suspension].upper;
    let solver = Solver::new(body);
    let integrand = |f: f64| {
        let g = psd.at(f);
        let h = solver.transfer(f);
        let wk2 = Weighting::Wk.analog(f).norm_sqr();
        let w2 = (2.0 * PI * f).powi(2);
        [
            g * wk2,
            g * wk2 * h[seat.pan].norm_sqr(),
            g * (h[upper] - 1.0).norm_sqr() / (w2 * w2),
        ]
    };
    // The breakpoints: the rows inside [lo, hi], or the ends for a class.
    let mut cuts = vec![lo];
    if let FloorPsd::Table { rows, .. } = psd {
        cuts.extend(rows.iter().map(|r| r.0).filter(|&f| f > lo && f < hi));
    }
    cuts.push(hi);
    let mut sum = [0.0; 3];
    for w in cuts.windows(2) {
        let (a, b) = (w[0], w[1]);
        let n = 2 * (((b / a).ln() / 2e-4).ceil() as usize).max(32);
        let h = (b - a) / n as f64;
        for i in 0..=n {
            let c = match i {
                0 => 1.0,
                _ if i == n => 1.0,
                _ if i % 2 == 1 => 4.0,
                _ => 2.0,
            };
            let v = integrand(a + h * i as f64);
            for j in 0..3 {
                sum[j] += c * h / 3.0 * v[j];
            }
        }
    }
    (sum[0].sqrt(), sum[1].sqrt(), sum[2].sqrt())
}

/// The figures agree with the brute force to `tol` (relative).
fn agrees(f: &SeatFigures, b: (f64, f64, f64), tol: f64, what: &str) {
    let close = |x: f64, y: f64| (x / y - 1.0).abs() <= tol;
    assert!(
        close(f.floor_aw_m_s2, b.0),
        "{what}: floor {} vs {}",
        f.floor_aw_m_s2,
        b.0
    );
    assert!(
        close(f.pan_aw_m_s2, b.1),
        "{what}: pan {} vs {}",
        f.pan_aw_m_s2,
        b.1
    );
    assert!(
        close(f.stroke_rms_m, b.2),
        "{what}: travel {} vs {}",
        f.stroke_rms_m,
        b.2
    );
    assert!(
        close(f.seat_pct, 100.0 * b.1 / b.0),
        "{what}: SEAT {}",
        f.seat_pct
    );
}

fn figures_of(psd: &FloorPsd, body: &Body) -> (SeatFigures, (f64, f64)) {
    let g = SeatGrid::new(psd).expect("a grid");
    (g.figures(body).expect("figures"), g.range())
}

/// Zero rows around a narrow peak: the triangle 4.9–5.1 Hz counts in full
/// (the fixed grid read a_w 24 % low).
#[test]
fn zero_rows_around_a_narrow_peak_count_in_full() {
    let body = seat_body();
    let psd = table(vec![
        (0.5, 0.0),
        (4.9, 0.0),
        (5.0, 1.0),
        (5.1, 0.0),
        (20.0, 0.0),
    ]);
    let (f, (lo, hi)) = figures_of(&psd, &body);
    agrees(&f, brute(&psd, &body, lo, hi), 1e-5, "4.9–5.1 Hz");
    // The triangle's area is 0.1 (m/s²)²: a_w² = 0.1·|W_k(5)|² to its curvature.
    let wk5 = Weighting::Wk.analog(5.0).norm();
    assert!((f.floor_aw_m_s2 / (0.1f64.sqrt() * wk5) - 1.0).abs() < 1e-3);
}

/// A peak 2 mHz wide, between two nodes of any grid, is integrated, not
/// refused as "the floor's weighted r.m.s. is 0".
#[test]
fn a_narrow_peak_between_nodes_is_integrated() {
    let body = seat_body();
    let psd = table(vec![
        (0.5, 0.0),
        (4.999, 0.0),
        (5.0, 1.0),
        (5.001, 0.0),
        (20.0, 0.0),
    ]);
    let (f, (lo, hi)) = figures_of(&psd, &body);
    agrees(&f, brute(&psd, &body, lo, hi), 1e-5, "a 2 mHz peak");
    let wk5 = Weighting::Wk.analog(5.0).norm();
    assert!((f.floor_aw_m_s2 / (0.001f64.sqrt() * wk5) - 1.0).abs() < 1e-5);
}

/// A measured PSD (Welch's 100/1024 Hz resolution, 0.098 to 50 Hz, EM6's
/// shape scattered ±30 % row to row as an estimate of 16 averages is):
/// the fixed grid read it 2.7 % low; the rows as they are agree to 1e-5.
#[test]
fn a_measured_psd_agrees_with_the_brute_force() {
    let body = seat_body();
    let em6 = &CLASSES[5];
    let mut rng = crate::Rng::new(7);
    let df = 100.0 / 1024.0;
    let rows: Vec<(f64, f64)> = (1..=512)
        .map(|i| {
            let f = df * f64::from(i);
            (f, em6.psd(f) * (1.0 + rng.symmetric(0.3)))
        })
        .collect();
    let psd = table(rows);
    let (f, (lo, hi)) = figures_of(&psd, &body);
    assert_eq!((lo, hi), (MIN_HZ, 50.0), "clipped to 0.1 Hz at the bottom");
    agrees(&f, brute(&psd, &body, lo, hi), 1e-5, "measured");
}

/// A band from 1e-300 Hz is integrated from 0.1 Hz: finite figures, no NaN
/// stroke (the fixed grid gave SEAT 144 % and a NaN).
#[test]
fn a_band_from_1e_300_hz_is_integrated_from_the_lower_limit() {
    let body = seat_body();
    let psd = table(vec![(1e-300, 1.0), (100.0, 1.0)]);
    let (f, (lo, hi)) = figures_of(&psd, &body);
    assert_eq!((lo, hi), (MIN_HZ, 100.0));
    assert!(
        f.stroke_rms_m.is_finite() && f.seat_pct.is_finite(),
        "{f:?}"
    );
    agrees(&f, brute(&psd, &body, lo, hi), 1e-5, "1e-300 to 100 Hz");
    // What is left out below 0.1 Hz: under 0.1 % of the floor's a_w².
    let below = brute(&psd, &body, 1e-3, MIN_HZ).0;
    assert!((below / f.floor_aw_m_s2).powi(2) < 1e-3, "{below}");
}

/// Every class agrees with the brute force, as do the PSDs' levels: 1e-300
/// and 1e300 times a PSD give the same SEAT and scaled a_w.
#[test]
fn every_class_agrees_with_the_brute_force() {
    let body = seat_body();
    for c in &CLASSES {
        let psd = FloorPsd::Class(c);
        let (f, (lo, hi)) = figures_of(&psd, &body);
        agrees(&f, brute(&psd, &body, lo, hi), 1e-5, c.name);
    }
    let rows = |k: f64| table(vec![(1.0, k), (3.0, 2.0 * k), (10.0, k)]);
    let (one, _) = figures_of(&rows(1.0), &body);
    for k in [1e-300, 1e300] {
        let (f, _) = figures_of(&rows(k), &body);
        assert!((f.seat_pct / one.seat_pct - 1.0).abs() < 1e-12, "{k}");
        assert!((f.pan_aw_m_s2 / (one.pan_aw_m_s2 * k.sqrt()) - 1.0).abs() < 1e-12);
    }
}

/// A file wholly below 0.1 Hz (or above 1 kHz) is refused with its range.
#[test]
fn a_psd_outside_the_integrated_range_is_refused() {
    let e = SeatGrid::new(&table(vec![(0.01, 1.0), (0.1, 1.0)])).unwrap_err();
    assert_eq!(
        e,
        SeatError::OutsideRange {
            from_hz: 0.01,
            to_hz: 0.1
        }
    );
    assert!(
        e.to_string()
            .contains("0.01 to 0.1 Hz, outside the 0.1 to 1000 Hz"),
        "{e}"
    );
    assert!(SeatGrid::new(&table(vec![(1000.0, 1.0), (2000.0, 1.0)])).is_err());
}

/// A lightly damped suspension (ζ about 0.005) starts on a grid fine enough
/// for its resonance and still agrees with the brute force.
#[test]
fn a_sharp_resonance_is_resolved() {
    let mut body = seat_body();
    let c = body.param("suspension.c").expect("the suspension");
    body.set(c, 8.0).expect("a valid damping");
    let psd = table(vec![(0.5, 1.0), (20.0, 1.0)]);
    let (f, (lo, hi)) = figures_of(&psd, &body);
    agrees(&f, brute(&psd, &body, lo, hi), 1e-5, "ζ 0.005");
}

/// Undamped links make a resonance whose integral has no finite value:
/// refused, not a number; the first grid is the finest then.
#[test]
fn an_undamped_model_is_refused() {
    let mut body = seat_body();
    for i in 0..body.links.len() {
        body.set(crate::Param::Damping(i), 0.0)
            .expect("c = 0 is valid");
    }
    let grid = SeatGrid::new(&table(vec![(0.5, 1.0), (20.0, 1.0)])).expect("a grid");
    assert_eq!(grid.first_level(&body), super::quadrature::MAX_LEVEL);
    let e = grid.figures(&body).unwrap_err();
    assert!(matches!(e, SeatError::Unresolved { .. }), "{e}");
    // The paper's seat starts on the first grid (its smallest ζ is 0.18 in the range).
    assert_eq!(grid.first_level(&seat_body()), 1);
}
