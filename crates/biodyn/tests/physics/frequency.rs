//! Physics checks against independent computations: the reference tables of
//! an outside implementation, a dense LU against the tridiagonal solve, a
//! time-domain integration to steady state, the two seat-force formulas, and
//! the low-frequency limits.

use biodyn::freq::phase_deg;
use biodyn::{Band, Body, End, Function, Link, Preset, Segment, Solver};
use num_complex::Complex64;
use std::f64::consts::PI;

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(1e-300)
}

/// Phase difference in degrees, wrapped, relative to 180°.
fn phase_err(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(360.0);
    d.min(360.0 - d) / 180.0
}

fn reference(name: &str) -> Vec<Vec<f64>> {
    let path = format!(
        "{}/../../tests/data/reference/{name}.csv",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next().unwrap(),
        "f_hz,stht_mag,stht_phase_deg,dpmi_mag,dpmi_phase_deg,apms_mag,apms_phase_deg"
    );
    lines
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect()
}

#[test]
fn matches_independent_reference_tables_to_1e9() {
    for name in [
        "boileau-rakheja-1998",
        "paper-65kg",
        "paper-75kg",
        "paper-85kg",
    ] {
        let preset = Preset::builtin(name).unwrap().unwrap();
        let solver = Solver::new(&preset.body);
        let rows = reference(name);
        let band = Band::default();
        assert_eq!(rows.len(), band.len(), "{name}");
        let mut worst = 0.0f64;
        for (i, row) in rows.iter().enumerate() {
            let f = band.freq(i);
            assert_eq!(f, row[0], "{name}: grid point {i}");
            let r = solver.at(f);
            for (k, func) in Function::ALL.iter().enumerate() {
                worst = worst.max(rel(r.mag(*func), row[1 + 2 * k]));
                worst = worst.max(phase_err(r.phase_deg(*func), row[2 + 2 * k]));
            }
        }
        assert!(worst < 1e-9, "{name}: worst relative difference {worst:e}");
    }
}

#[test]
fn seat_force_by_links_equals_newton_on_the_whole_body() {
    for body in [Body::paper(75.0).unwrap(), branched()] {
        let s = Solver::new(&body);
        for f in Band::new(0.1, 40.0, 0.05).unwrap().freqs() {
            let h = s.transfer(f);
            let by_links = s.seat_force_links(f, &h);
            let by_newton = s.seat_force_newton(f, &h);
            assert!(
                (by_links - by_newton).norm() <= 1e-9 * by_newton.norm(),
                "{f} Hz: {by_links} vs {by_newton}"
            );
            // And the reported APMS and DPMI are that force per unit acceleration/velocity.
            let r = s.at(f);
            let w = 2.0 * PI * f;
            let apms = by_links / Complex64::new(-w * w, 0.0);
            let dpmi = by_links / Complex64::new(0.0, w);
            assert!((r.apms - apms).norm() <= 1e-9 * apms.norm());
            assert!((r.dpmi - dpmi).norm() <= 1e-9 * dpmi.norm());
        }
    }
}

#[test]
fn low_frequency_limits() {
    for body in [Body::paper(65.0).unwrap(), branched()] {
        let s = Solver::new(&body);
        let r = s.at(1e-4);
        assert!(
            (r.stht - Complex64::new(1.0, 0.0)).norm() < 1e-6,
            "{}",
            r.stht
        );
        assert!(rel(r.apms.norm(), body.seated_mass()) < 1e-6);
        // DPMI → 0 like ω·Σm (a rigid mass seen through velocity).
        let w = 2.0 * PI * 1e-4;
        assert!(rel(r.dpmi.norm(), w * body.seated_mass()) < 1e-6);
        assert!((r.phase_deg(Function::Dpmi) - 90.0).abs() < 1e-3);
    }
}

#[test]
fn high_frequency_isolation() {
    // Far above every mode the body barely moves: STHT → 0 and APMS falls.
    let s = Solver::new(&Body::paper(75.0).unwrap());
    let r = s.at(500.0);
    assert!(r.stht.norm() < 1e-3);
    assert!(r.apms.norm() < 0.1 * 0.781 * 75.0);
}

#[test]
fn single_mass_matches_closed_form() {
    // One mass on one Kelvin–Voigt link: H = (k + jωc) / (k − ω²m + jωc).
    let (m, k, c) = (60.0, 80_000.0, 1_500.0);
    let body = Body::chain(
        vec![Segment {
            name: "body".into(),
            mass: m,
            share: None,
            seat: false,
        }],
        &[k],
        &[c],
    );
    body.validate().unwrap();
    let s = Solver::new(&body);
    for f in [0.3, 2.0, 5.8, 13.0] {
        let w = 2.0 * PI * f;
        let h = Complex64::new(k, w * c) / Complex64::new(k - w * w * m, w * c);
        let r = s.at(f);
        assert!((r.stht - h).norm() < 1e-12 * h.norm());
        assert!((r.apms - h * m).norm() < 1e-12 * m * h.norm());
        assert!(rel(r.phase_deg(Function::Stht), phase_deg(h)) < 1e-12);
    }
}

/// Five segments with a viscera mass hanging off the chest and a second
/// seat link: not a chain, so the general path is exercised.
fn branched() -> Body {
    let seg = Segment::new;
    let link = Link::new;
    let body = Body {
        segments: vec![
            seg("head-neck", 5.3),
            seg("chest", 22.0),
            seg("lower-torso", 8.6),
            seg("pelvis", 12.8),
            seg("viscera", 6.5),
        ],
        links: vec![
            link("neck", 0, End::Segment(1), 310_000.0, 400.0),
            link("spine", 1, End::Segment(2), 183_000.0, 4_750.0),
            link("lumbar", 2, End::Segment(3), 162_800.0, 4_585.0),
            link("pelvis-seat", 3, End::Seat, 90_000.0, 2_064.0),
            link("viscera-chest", 4, End::Segment(1), 40_000.0, 900.0),
            link("lower-torso-seat", 2, End::Seat, 20_000.0, 300.0),
        ],
        head: 0,
        body_mass: None,
        seat: None,
    };
    body.validate().unwrap();
    assert!(!body.is_tridiagonal());
    body
}

/// Steady-state amplitude and phase of every segment under x0 = sin(ωt),
/// integrated in the time domain with RK4 (no frequency-domain algebra).
fn time_domain_transfer(body: &Body, f: f64) -> Vec<Complex64> {
    let n = body.n();
    let w = 2.0 * PI * f;
    let m: Vec<f64> = body.segments.iter().map(|s| s.mass).collect();
    // Accelerations straight from the link forces, written independently of Solver.
    let accel = |t: f64, x: &[f64], v: &[f64], a: &mut [f64]| {
        let (x0, v0) = ((w * t).sin(), w * (w * t).cos());
        a.iter_mut().for_each(|ai| *ai = 0.0);
        for l in &body.links {
            let (xl, vl) = match l.lower {
                End::Segment(j) => (x[j], v[j]),
                End::Seat => (x0, v0),
            };
            let force = l.k * (x[l.upper] - xl) + l.c * (v[l.upper] - vl);
            a[l.upper] -= force;
            if let End::Segment(j) = l.lower {
                a[j] += force;
            }
        }
        for i in 0..n {
            a[i] /= m[i];
        }
    };
    let period_steps = 4000usize;
    let dt = 1.0 / f / period_steps as f64;
    let settle_periods = (4.0 * f).ceil() as usize; // 4 s: slowest transient e^-48
    let (mut x, mut v) = (vec![0.0; n], vec![0.0; n]);
    let mut t = 0.0;
    let (mut k1x, mut k1v, mut k2x, mut k2v) =
        (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    let (mut k3x, mut k3v, mut k4x, mut k4v) =
        (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    let (mut xs, mut vs) = (vec![0.0; n], vec![0.0; n]);
    let mut sin_acc = vec![0.0; n];
    let mut cos_acc = vec![0.0; n];
    for step in 0..(settle_periods + 1) * period_steps {
        if step >= settle_periods * period_steps {
            for i in 0..n {
                sin_acc[i] += x[i] * (w * t).sin();
                cos_acc[i] += x[i] * (w * t).cos();
            }
        }
        k1x.copy_from_slice(&v);
        accel(t, &x, &v, &mut k1v);
        for i in 0..n {
            xs[i] = x[i] + 0.5 * dt * k1x[i];
            vs[i] = v[i] + 0.5 * dt * k1v[i];
        }
        k2x.copy_from_slice(&vs);
        accel(t + 0.5 * dt, &xs, &vs, &mut k2v);
        for i in 0..n {
            xs[i] = x[i] + 0.5 * dt * k2x[i];
            vs[i] = v[i] + 0.5 * dt * k2v[i];
        }
        k3x.copy_from_slice(&vs);
        accel(t + 0.5 * dt, &xs, &vs, &mut k3v);
        for i in 0..n {
            xs[i] = x[i] + dt * k3x[i];
            vs[i] = v[i] + dt * k3v[i];
        }
        k4x.copy_from_slice(&vs);
        accel(t + dt, &xs, &vs, &mut k4v);
        for i in 0..n {
            x[i] += dt / 6.0 * (k1x[i] + 2.0 * k2x[i] + 2.0 * k3x[i] + k4x[i]);
            v[i] += dt / 6.0 * (k1v[i] + 2.0 * k2v[i] + 2.0 * k3v[i] + k4v[i]);
        }
        t += dt;
    }
    // x_i(t) = Re(H e^{jωt}) for x0 = sin: x_i = |H| sin(ωt + φ) → H = a + jb
    // with a = (2/N) Σ x sin, b = (2/N) Σ x cos.
    let scale = 2.0 / period_steps as f64;
    (0..n)
        .map(|i| Complex64::new(sin_acc[i] * scale, cos_acc[i] * scale))
        .collect()
}

#[test]
fn time_domain_steady_state_agrees_with_frequency_response() {
    for body in [Body::paper(75.0).unwrap(), branched()] {
        let s = Solver::new(&body);
        for f in [2.0, 5.0, 12.5] {
            let td = time_domain_transfer(&body, f);
            let fd = s.transfer(f);
            for (a, b) in td.iter().zip(&fd) {
                assert!(
                    (a - b).norm() < 1e-6 * b.norm().max(1e-3),
                    "{f} Hz: time {a} vs freq {b}"
                );
            }
        }
    }
}

#[test]
fn general_lu_agrees_with_tridiagonal_over_the_band() {
    let s = Solver::new(&Body::paper(85.0).unwrap());
    for f in Band::new(0.05, 60.0, 0.05).unwrap().freqs() {
        let a = s.transfer(f);
        let b = s.transfer_general(f);
        for (x, y) in a.iter().zip(&b) {
            assert!((x - y).norm() <= 1e-11 * y.norm(), "{f}: {x} vs {y}");
        }
    }
}

#[test]
fn chain_shooting_agrees_with_general_lu_and_sweep_with_points() {
    // The default path for a chain shoots from the head down; check it
    // against the dense LU from 0.05 to 200 Hz on three bodies.
    for kg in [40.0, 75.0, 120.0] {
        let s = Solver::new(&Body::paper(kg).unwrap());
        let freqs = Band::new(0.05, 200.0, 0.05).unwrap().freqs();
        let sweep = s.sweep_freqs(&freqs);
        for (r, &f) in sweep.iter().zip(&freqs) {
            let h = s.transfer_general(f);
            let w = 2.0 * PI * f;
            let apms: Complex64 = h.iter().zip(&s_masses(kg)).map(|(h, m)| h * m).sum();
            assert!(
                (r.stht - h[0]).norm() <= 1e-10 * h[0].norm(),
                "{kg} kg {f} Hz"
            );
            assert!(
                (r.apms - apms).norm() <= 1e-10 * apms.norm(),
                "{kg} kg {f} Hz"
            );
            assert!((r.dpmi - Complex64::new(0.0, w) * apms).norm() <= 1e-10 * w * apms.norm());
            let p = s.at(f);
            assert!((p.stht - r.stht).norm() <= 1e-14 * p.stht.norm());
            assert!((p.apms - r.apms).norm() <= 1e-14 * p.apms.norm());
        }
    }
}

fn s_masses(kg: f64) -> Vec<f64> {
    biodyn::body::PAPER_SHARES.iter().map(|s| s * kg).collect()
}

#[test]
fn reference_peaks_of_boileau_rakheja() {
    let p = Preset::builtin("boileau-rakheja-1998").unwrap().unwrap();
    let s = Solver::new(&p.body);
    let curve = s.sweep(&Band::default());
    let want = [
        (Function::Stht, 4.676, 1.7807),
        (Function::Dpmi, 5.462, 2847.1),
        (Function::Apms, 4.570, 90.48),
    ];
    for (f, hz, mag) in want {
        let pk = biodyn::freq::main_peak(&s, &curve, f).unwrap();
        assert!((pk.f_hz - hz).abs() < 0.001, "{f:?}: {} Hz", pk.f_hz);
        assert!(rel(pk.mag, mag) < 1e-4, "{f:?}: {}", pk.mag);
    }
}

#[test]
fn paper_trend_claims_for_pelvic_damping() {
    // The paper: responses fall with pelvic damping. Check the peaks directly.
    let base = Body::paper(75.0).unwrap();
    let peaks: Vec<f64> = [0.6, 1.0, 1.4]
        .iter()
        .map(|x| {
            let mut b = base.clone();
            b.links[3].c *= x;
            let s = Solver::new(&b);
            let c = s.sweep(&Band::default());
            biodyn::freq::main_peak(&s, &c, Function::Stht).unwrap().mag
        })
        .collect();
    assert!(peaks[0] > peaks[1] && peaks[1] > peaks[2], "{peaks:?}");
}
