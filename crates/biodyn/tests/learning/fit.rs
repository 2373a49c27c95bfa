//! Fitting against data made by the response solver (`Solver`, the chain
//! path), which shares no code with the fit's own solve and Jacobian.

use biodyn::Rng;
use biodyn::fit::{Bound, FitError, Free, Measured, Settings, fit, free_params};
use biodyn::{Band, Body, Function, Param, Solver};
use std::path::Path;

/// The 4-DOF chain with several k and c changed by up to a factor of 2.
fn true_body() -> Body {
    let mut b = Body::paper(75.0).unwrap();
    b.links[0].k *= 1.6; // k1
    b.links[1].k *= 0.7; // k2
    b.links[3].k *= 2.0; // k4
    b.links[1].c *= 0.5; // c2
    b.links[2].c *= 1.5; // c3
    b.links[3].c *= 1.3; // c4
    b
}

/// A standard normal deviate (Box–Muller).
fn normal(rng: &mut Rng) -> f64 {
    let u1 = 1.0 - rng.next_f64();
    let u2 = rng.next_f64();
    (-2.0 * u1.ln()).sqrt() * (2.0 * std::f64::consts::PI * u2).cos()
}

/// CSV of the given functions (magnitude, and phase when `phase`) over 0.5–20
/// Hz at 0.1 Hz, with magnitudes × (1 + mag_noise·z) and phases + phase_deg·z.
fn synthetic(
    body: &Body,
    functions: &[Function],
    phase: bool,
    mag_noise: f64,
    phase_noise_deg: f64,
    seed: u64,
) -> String {
    let mut rng = Rng::new(seed);
    let mut text = String::from("f_hz");
    for f in functions {
        text += &format!(",{}_mag", f.key());
        if phase {
            text += &format!(",{}_phase_deg", f.key());
        }
    }
    text.push('\n');
    for r in Solver::new(body).sweep(&Band::default()) {
        text += &format!("{}", r.f_hz);
        for &f in functions {
            let mag = r.mag(f) * (1.0 + mag_noise * normal(&mut rng));
            assert!(mag > 0.0);
            text += &format!(",{mag}");
            if phase {
                text += &format!(",{}", r.phase_deg(f) + phase_noise_deg * normal(&mut rng));
            }
        }
        text.push('\n');
    }
    text
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

#[test]
fn exact_data_recover_every_determined_parameter_to_1e_6() {
    let truth = true_body();
    let text = synthetic(&truth, &[Function::Stht, Function::Apms], true, 0.0, 0.0, 0);
    let data = Measured::parse(&text, "exact.csv").unwrap();
    assert_eq!(data.f_hz.len(), 196);
    let start = Body::paper(75.0).unwrap();
    let free = free_params(&start, &[Free::Links], &[]).unwrap();
    let fit = fit(&start, &data, &free, Settings::default()).unwrap();
    assert_eq!(fit.params.len(), 8);
    assert!(fit.cost < 1e-20, "cost {}", fit.cost);
    for p in &fit.params {
        assert!(p.determined, "{} not determined: {p:?}", p.name);
        let want = truth.get(p.param);
        assert!(
            rel(p.value, want) <= 1e-6,
            "{}: {} vs {want}",
            p.name,
            p.value
        );
        assert!(p.covers(p.value), "{p:?}");
    }
    assert!(fit.converged_starts >= 1 && fit.converged_starts <= 8);
    // The fitted body is the start body with the fitted values.
    for p in &fit.params {
        assert_eq!(fit.body.get(p.param), p.value);
    }
}

#[test]
fn noisy_data_intervals_hold_the_truth_at_least_90_percent_of_the_time() {
    let truth = true_body();
    let start = Body::paper(75.0).unwrap();
    let free = free_params(&start, &[Free::Links], &[]).unwrap();
    let (mut inside, mut total, mut determined) = (0, 0, 0);
    let mut misses = Vec::new();
    for seed in 1..=20 {
        let text = synthetic(
            &truth,
            &[Function::Stht, Function::Apms],
            true,
            0.03,
            2.0,
            seed,
        );
        let data = Measured::parse(&text, "noisy.csv").unwrap();
        let fit = fit(&start, &data, &free, Settings::default()).unwrap();
        // The best start reached the best cost, so it counts among the
        // converged ones whatever the noise (a cost well above 0 here).
        assert!(
            (1..=8).contains(&fit.converged_starts),
            "seed {seed}: {} converged starts at cost {}",
            fit.converged_starts,
            fit.cost
        );
        for p in &fit.params {
            let want = truth.get(p.param);
            total += 1;
            determined += usize::from(p.determined);
            if p.covers(want) {
                inside += 1;
            } else {
                misses.push(format!(
                    "seed {seed} {}: {want} outside [{:?}, {:?}]",
                    p.name, p.ci95_low, p.ci95_high
                ));
            }
        }
    }
    assert_eq!(total, 160);
    assert!(
        inside as f64 >= 0.9 * total as f64,
        "{inside}/{total} inside: {misses:#?}"
    );
    // Honest is not vacuous: at 3 % noise the head damping c1 and often c3
    // are not determined (their intervals span more than a factor of 2),
    // and where another minimum the data do not reject lies apart the set
    // takes it in (k2, k3 in some draws), but over half are determined (91
    // of 160 with these seeds; the long study's model B: 66 %).
    assert!(determined >= 80, "only {determined}/160 determined");
    eprintln!("coverage {inside}/{total}, determined {determined}/{total}");
}

#[test]
fn apms_magnitude_alone_leaves_the_head_neck_link_undetermined() {
    let truth = true_body();
    let text = synthetic(&truth, &[Function::Apms], false, 0.03, 0.0, 7);
    let data = Measured::parse(&text, "apms.csv").unwrap();
    let start = Body::paper(75.0).unwrap();
    let free = free_params(&start, &[Free::Links], &[]).unwrap();
    let fit = fit(&start, &data, &free, Settings::default()).unwrap();
    let undetermined: Vec<&str> = fit.undetermined().iter().map(|p| p.name.as_str()).collect();
    assert!(
        undetermined.contains(&"k1") && undetermined.contains(&"c1"),
        "{undetermined:?}"
    );
}

fn paper() -> Body {
    Body::paper(75.0).unwrap()
}

#[test]
fn same_seed_same_bits_and_the_start_model_is_start_one() {
    let text = synthetic(
        &true_body(),
        &[Function::Stht, Function::Apms],
        true,
        0.03,
        2.0,
        3,
    );
    let data = Measured::parse(&text, "n.csv").unwrap();
    let free = free_params(&paper(), &[Free::Links], &[]).unwrap();
    let settings = Settings {
        starts: 4,
        seed: 9,
        ..Settings::default()
    };
    let a = fit(&paper(), &data, &free, settings).unwrap();
    let b = fit(&paper(), &data, &free, settings).unwrap();
    let bits = |f: &biodyn::fit::Fit| {
        let mut v: Vec<u64> = f
            .params
            .iter()
            .flat_map(|p| {
                [
                    p.value.to_bits(),
                    p.ci95_low.map_or(0, f64::to_bits),
                    p.ci95_high.map_or(0, f64::to_bits),
                ]
            })
            .collect();
        v.extend(f.start_costs.iter().map(|c| c.to_bits()));
        v
    };
    assert_eq!(bits(&a), bits(&b));
    // One start from the start model alone gives the first start's cost.
    let one = fit(
        &paper(),
        &data,
        &free,
        Settings {
            starts: 1,
            seed: 9,
            ..Settings::default()
        },
    )
    .unwrap();
    assert_eq!(one.start_costs[0].to_bits(), a.start_costs[0].to_bits());
    assert_eq!(a.start_costs.len(), 4);
    assert!(a.start_costs.iter().all(|&c| c >= a.cost));
}

#[test]
fn body_mass_and_single_masses_are_recovered() {
    let truth = Body::paper(82.0).unwrap();
    let text = synthetic(&truth, &[Function::Apms], true, 0.0, 0.0, 0);
    let data = Measured::parse(&text, "bm.csv").unwrap();
    let free = free_params(&paper(), &[Free::Param(Param::BodyMass)], &[]).unwrap();
    let f = fit(&paper(), &data, &free, Settings::default()).unwrap();
    assert!(rel(f.params[0].value, 82.0) < 1e-9, "{:?}", f.params[0]);
    assert_eq!(f.params[0].name, "body-mass");
    assert!(rel(f.body.segments[1].mass, 0.402 * 82.0) < 1e-9);

    let mut truth = paper();
    truth.segments[0].mass *= 1.3;
    truth.segments[2].mass *= 0.8;
    let text = synthetic(&truth, &[Function::Stht, Function::Dpmi], true, 0.0, 0.0, 0);
    let data = Measured::parse(&text, "m.csv").unwrap();
    let free = free_params(
        &paper(),
        &[
            Free::Param(Param::Mass(0)),
            Free::Param(Param::Mass(2)),
            Free::Param(Param::Stiffness(0)),
        ],
        &[],
    )
    .unwrap();
    let f = fit(&paper(), &data, &free, Settings::default()).unwrap();
    for p in &f.params {
        assert!(rel(p.value, truth.get(p.param)) < 1e-7, "{p:?}");
    }
}

#[test]
fn a_branched_model_is_fitted_through_the_general_solve() {
    use biodyn::{End, Link, Segment};
    let mut start = paper();
    start.segments.push(Segment::new("viscera", 4.0));
    start
        .links
        .push(Link::new("viscera-chest", 4, End::Segment(1), 4e4, 300.0));
    start.validate().unwrap();
    let mut truth = start.clone();
    truth.links[4].k = 6e4;
    truth.links[4].c = 200.0;
    truth.links[3].k = 1.2e5;
    let text = synthetic(&truth, &[Function::Stht, Function::Apms], true, 0.0, 0.0, 0);
    let data = Measured::parse(&text, "b.csv").unwrap();
    let free = free_params(
        &start,
        &[Free::Link(4), Free::Param(Param::Stiffness(3))],
        &[],
    )
    .unwrap();
    let f = fit(&start, &data, &free, Settings::default()).unwrap();
    assert_eq!(f.params.len(), 3);
    for p in &f.params {
        assert!(rel(p.value, truth.get(p.param)) < 1e-7, "{p:?}");
    }
}

#[test]
fn a_bound_that_excludes_the_truth_holds_the_value_on_it() {
    let truth = true_body(); // k4 = 180 000
    let text = synthetic(&truth, &[Function::Stht, Function::Apms], true, 0.0, 0.0, 0);
    let data = Measured::parse(&text, "x.csv").unwrap();
    let bound = Bound {
        param: Param::Stiffness(3),
        lo: Some(1e4),
        hi: Some(1.5e5),
    };
    let free = free_params(&paper(), &[Free::Links], &[bound]).unwrap();
    let f = fit(&paper(), &data, &free, Settings::default()).unwrap();
    let k4 = f.params.iter().find(|p| p.name == "k4").unwrap();
    assert_eq!(k4.value, 1.5e5);
    assert!(k4.at_bound);
    assert!(
        f.params
            .iter()
            .filter(|p| p.name != "k4")
            .all(|p| !p.at_bound)
    );
    assert!(f.cost > 1e-6, "the bound must cost something: {}", f.cost);
}

#[test]
fn constant_relative_sd_weights_change_nothing_but_the_scale_of_the_cost() {
    let text = synthetic(&true_body(), &[Function::Apms], true, 0.03, 2.0, 11);
    let data = Measured::parse(&text, "w.csv").unwrap();
    // The same file with apms_mag_sd = 5 % of the value and a phase sd of
    // 0.05 rad: the same weight on every residual, so the same minimum and
    // the same intervals; only the cost scales (by 1/0.05²).
    let mut weighted = String::from("f_hz,apms_mag,apms_phase_deg,apms_mag_sd,apms_phase_deg_sd\n");
    for line in text.lines().skip(1) {
        let v: Vec<f64> = line.split(',').map(|c| c.parse().unwrap()).collect();
        let phase_sd = 0.05f64.to_degrees();
        weighted += &format!("{},{},{},{},{phase_sd}\n", v[0], v[1], v[2], 0.05 * v[1]);
    }
    let wdata = Measured::parse(&weighted, "w_sd.csv").unwrap();
    let free = free_params(&paper(), &[Free::Link(2), Free::Link(3)], &[]).unwrap();
    let a = fit(&paper(), &data, &free, Settings::default()).unwrap();
    let b = fit(&paper(), &wdata, &free, Settings::default()).unwrap();
    assert!(
        rel(b.cost, a.cost / 0.0025) < 1e-6,
        "{} vs {}",
        a.cost,
        b.cost
    );
    for (p, q) in a.params.iter().zip(&b.params) {
        assert!(rel(q.value, p.value) < 1e-6, "{p:?} vs {q:?}");
        for (a, b) in [(p.ci95_low, q.ci95_low), (p.ci95_high, q.ci95_high)] {
            let (a, b) = (a.expect("bounded"), b.expect("bounded"));
            assert!(rel(b, a) < 1e-4, "{p:?} vs {q:?}");
        }
    }
}

#[test]
fn too_few_values_a_cancel_and_progress() {
    let data = Measured::parse("f_hz,apms_mag\n1,58\n2,60\n3,65\n", "few.csv").unwrap();
    let free = free_params(&paper(), &[Free::Links], &[]).unwrap();
    let e = fit(&paper(), &data, &free, Settings::default()).unwrap_err();
    assert!(
        matches!(
            e,
            FitError::TooFewValues {
                values: 3,
                params: 8,
                ..
            }
        ),
        "{e}"
    );
    assert!(
        e.to_string()
            .starts_with("few.csv: 3 measured values for 8 free parameters"),
        "{e}"
    );

    let text = synthetic(&true_body(), &[Function::Apms], false, 0.03, 0.0, 1);
    let data = Measured::parse(&text, "a.csv").unwrap();
    let free = free_params(&paper(), &[Free::Link(3)], &[]).unwrap();
    let mut seen = Vec::new();
    let e = biodyn::fit::fit_with(
        &paper(),
        &data,
        &free,
        Settings {
            starts: 5,
            seed: 1,
            ..Settings::default()
        },
        &mut |p| {
            seen.push((p.done, p.starts));
            p.done < 3
        },
    )
    .unwrap_err();
    assert!(matches!(e, FitError::Cancelled));
    assert_eq!(seen, vec![(1, 5), (2, 5), (3, 5)]);
    assert!(matches!(
        fit(
            &paper(),
            &data,
            &free,
            Settings {
                starts: 0,
                seed: 1,
                ..Settings::default()
            }
        ),
        Err(FitError::BadStarts { starts: 0, .. })
    ));
}

// ---- the example file ---------------------------------------------------------

/// The example's model: paper-75kg with k2 = 130 000 N/m, k4 = 120 000 N/m,
/// c2 = 3 000 N·s/m, c4 = 2 600 N·s/m (examples/README.md).
fn example_body() -> Body {
    let mut b = paper();
    for (name, v) in [
        ("k2", 130_000.0),
        ("k4", 120_000.0),
        ("c2", 3_000.0),
        ("c4", 2_600.0),
    ] {
        let p = b.param(name).unwrap();
        b.set(p, v).unwrap();
    }
    b
}

const EXAMPLE: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../examples/synthetic-stht-apms-3pct-2deg.csv"
);

/// The example file is what examples/README.md says it is. Regenerate with
/// `BIODYN_WRITE_EXAMPLE=1 cargo test -p biodyn --test learning fit::example`.
#[test]
fn example_file_is_regenerated_by_its_stated_recipe() {
    let text = synthetic(
        &example_body(),
        &[Function::Stht, Function::Apms],
        true,
        0.03,
        2.0,
        2026,
    );
    if std::env::var_os("BIODYN_WRITE_EXAMPLE").is_some() {
        std::fs::write(EXAMPLE, &text).unwrap();
    }
    let file = std::fs::read_to_string(Path::new(EXAMPLE)).unwrap();
    let (a, b) = (
        Measured::parse(&text, "made").unwrap(),
        Measured::parse(&file, "file").unwrap(),
    );
    assert_eq!(a.f_hz, b.f_hz);
    assert_eq!(a.column_names(), b.column_names());
    for (x, y) in a.columns.iter().zip(&b.columns) {
        for (u, v) in x.values.iter().zip(&y.values) {
            let (u, v) = (u.unwrap(), v.unwrap());
            // Bit-equal where libm agrees; within 1e-12 anywhere.
            assert!((u - v).abs() <= 1e-12 * u.abs().max(1.0), "{u} vs {v}");
        }
    }
    // And a fit on it finds the model it came from within its intervals.
    let free = free_params(&paper(), &[Free::Links], &[]).unwrap();
    let f = fit(&paper(), &b, &free, Settings::default()).unwrap();
    let truth = example_body();
    for p in f.params.iter().filter(|p| p.determined) {
        let t = truth.get(p.param);
        assert!(p.covers(t), "{p:?} vs {t}");
    }
}
