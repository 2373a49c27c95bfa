//! The fit's coverage study (docs/cli-fit.md, "How honest are the
//! intervals"): how often the 95 % intervals hold the true value.
//!
//! Three true models of this study's own (below), each measured as STHT and
//! APMS with phase at 0.5–20 Hz, with 3 % noise on magnitudes and 2° on
//! phases (seeded), fitted from paper-75kg with every link free (8
//! parameters) and the default 8 starts; each draw is fitted with profile
//! and with curvature intervals. For every model and parameter it prints
//! how often each kind of interval covers the truth, over all draws and
//! over the draws where the parameter is determined.
//!
//! ```sh
//! cargo run --release -p biodyn --example fit_coverage -- 200 0.1
//! ```
//!
//! Arguments: draws per model (default 200), frequency step in Hz (default
//! 0.1: 196 frequencies).

use biodyn::fit::{Free, Intervals, Measured, Settings, fit, free_params};
use biodyn::{Band, Body, Function, Rng, Solver};
use std::time::Instant;

/// A standard normal deviate (Box–Muller).
fn normal(rng: &mut Rng) -> f64 {
    let u1 = 1.0 - rng.next_f64();
    let u2 = rng.next_f64();
    (-2.0 * u1.ln()).sqrt() * (2.0 * std::f64::consts::PI * u2).cos()
}

/// STHT and APMS with phase of `body` over `band`, magnitudes × (1 + 0.03 z),
/// phases + 2° z.
fn measure(body: &Body, band: &Band, seed: u64) -> String {
    let mut rng = Rng::new(seed);
    let mut text = String::from("f_hz,stht_mag,stht_phase_deg,apms_mag,apms_phase_deg\n");
    for r in Solver::new(body).sweep(band) {
        text += &format!("{}", r.f_hz);
        for f in [Function::Stht, Function::Apms] {
            let mag = (r.mag(f) * (1.0 + 0.03 * normal(&mut rng))).max(1e-9);
            let phase = r.phase_deg(f) + 2.0 * normal(&mut rng);
            text += &format!(",{mag},{phase}");
        }
        text.push('\n');
    }
    text
}

/// paper-75kg with `changes` (name, factor) applied.
fn model(changes: &[(&str, f64)]) -> Body {
    let mut b = Body::paper(75.0).expect("the paper's model");
    for &(name, factor) in changes {
        let p = b.param(name).expect("a parameter of the paper's model");
        b.set(p, b.get(p) * factor).expect("a valid value");
    }
    b
}

fn main() {
    let mut args = std::env::args().skip(1);
    let draws: u64 = args.next().and_then(|a| a.parse().ok()).unwrap_or(200);
    let step: f64 = args.next().and_then(|a| a.parse().ok()).unwrap_or(0.1);
    let band = Band::new(0.5, 20.0, step).expect("a band");
    let models = [
        (
            "A (the example's: k2, k4, c2, c4 changed)",
            model(&[
                ("k2", 130.0 / 183.0),
                ("k4", 4.0 / 3.0),
                ("c2", 3.0 / 4.75),
                ("c4", 2.6 / 2.064),
            ]),
        ),
        (
            "B (k1 ×1.6, k2 ×0.7, k4 ×2, c2 ×0.5, c3 ×1.5, c4 ×1.3)",
            model(&[
                ("k1", 1.6),
                ("k2", 0.7),
                ("k4", 2.0),
                ("c2", 0.5),
                ("c3", 1.5),
                ("c4", 1.3),
            ]),
        ),
        (
            "C (k1 ×0.8, k3 ×1.4, c1 ×2, c3 ×0.7, k4 ×0.9)",
            model(&[
                ("k1", 0.8),
                ("k3", 1.4),
                ("c1", 2.0),
                ("c3", 0.7),
                ("k4", 0.9),
            ]),
        ),
    ];
    let start = Body::paper(75.0).expect("the paper's model");
    let free = free_params(&start, &[Free::Links], &[]).expect("links are free");
    let clock = Instant::now();
    let mut total = [(0u64, 0u64); 2];
    for (m, (label, truth)) in models.iter().enumerate() {
        // Per parameter: [profile, curvature] × (covers, determined, covers
        // and determined).
        let mut counts = vec![[(0u64, 0u64, 0u64); 2]; free.len()];
        for d in 0..draws {
            let text = measure(truth, &band, 1_000_003 * (m as u64 + 1) + d);
            let data = Measured::parse(&text, "draw.csv").expect("valid data");
            for (k, intervals) in [Intervals::Profile, Intervals::Curvature]
                .into_iter()
                .enumerate()
            {
                let settings = Settings {
                    intervals,
                    ..Settings::default()
                };
                let f = fit(&start, &data, &free, settings).expect("a fit");
                for (j, p) in f.params.iter().enumerate() {
                    let covers = p.covers(truth.get(p.param));
                    let c = &mut counts[j][k];
                    c.0 += u64::from(covers);
                    c.1 += u64::from(p.determined);
                    c.2 += u64::from(covers && p.determined);
                    total[k].0 += u64::from(covers);
                    total[k].1 += 1;
                }
            }
        }
        println!("model {label}, {draws} draws, {} frequencies", band.len());
        println!(
            "param   true      profile: covers  determined  covers|det   curvature: covers  determined  covers|det"
        );
        let pct = |a: u64, b: u64| {
            if b > 0 {
                format!("{:5.1} %", 100.0 * a as f64 / b as f64)
            } else {
                "    –  ".into()
            }
        };
        for (j, p) in free.iter().enumerate() {
            let [pr, cu] = counts[j];
            println!(
                "{:<6} {:>9.0}  {:>15} {:>11} {:>11}  {:>18} {:>11} {:>11}",
                p.name,
                truth.get(p.param),
                pct(pr.0, draws),
                pct(pr.1, draws),
                pct(pr.2, pr.1),
                pct(cu.0, draws),
                pct(cu.1, draws),
                pct(cu.2, cu.1),
            );
        }
        println!();
    }
    println!(
        "all (parameter, draw) pairs: profile {:.1} %, curvature {:.1} %; {:.0} s",
        100.0 * total[0].0 as f64 / total[0].1 as f64,
        100.0 * total[1].0 as f64 / total[1].1 as f64,
        clock.elapsed().as_secs_f64()
    );
}
