//! Big models: a 1000-segment chain's response on the default band (196
//! points) and its peaks, modes of a 400-segment chain, a 1000-segment
//! random tree, a 1000-segment ring (the band solver), and the paper's
//! 4-DOF chain on a 1951-point sweep (the AVX2 kernel, for regressions).

use biodyn::{Band, Body, End, Function, Link, Segment, Solver, freq};
use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use std::time::Duration;

fn chain(n: usize) -> Body {
    let segs = (0..n)
        .map(|i| Segment::new(&format!("s{i}"), 1.0))
        .collect();
    Body::chain(segs, &vec![1e6; n], &vec![50.0; n])
}

/// Segment i hangs off a pseudo-random earlier segment (xorshift, seed 7).
fn random_tree(n: usize) -> Body {
    let mut x = 7u64;
    let mut next = move || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        x
    };
    let segments = (0..n)
        .map(|i| Segment::new(&format!("s{i}"), 0.5 + (next() % 100) as f64 / 10.0))
        .collect();
    let links = (0..n)
        .map(|i| {
            let lower = if i == 0 {
                End::Seat
            } else {
                End::Segment((next() % i as u64) as usize)
            };
            Link::new(
                &format!("l{i}"),
                i,
                lower,
                1e5 + (next() % 1000) as f64 * 1e3,
                200.0,
            )
        })
        .collect();
    Body {
        segments,
        links,
        head: n - 1,
        body_mass: None,
        seat: None,
    }
}

fn bench(c: &mut Criterion) {
    let band = Band::default();
    let c1000 = Solver::new(&chain(1000));
    c.bench_function("chain1000_response_196_points", |b| {
        b.iter(|| black_box(c1000.sweep(black_box(&band))))
    });
    c.bench_function("chain1000_peaks_3_functions", |b| {
        b.iter(|| {
            let curve = c1000.sweep(&band);
            black_box(
                Function::ALL
                    .iter()
                    .map(|&f| freq::find_peaks_in(&c1000, &curve, f).len())
                    .sum::<usize>(),
            )
        })
    });
    let tree = random_tree(1000);
    tree.validate().expect("tree");
    let t1000 = Solver::new(&tree);
    assert_eq!(t1000.method(), "tree");
    c.bench_function("tree1000_response_196_points", |b| {
        b.iter(|| black_box(t1000.sweep(black_box(&band))))
    });
    let mut ring = chain(1000);
    ring.links
        .push(Link::new("close", 0, End::Segment(999), 1e5, 10.0));
    let r1000 = Solver::new(&ring);
    assert_eq!(r1000.method(), "band");
    c.bench_function("ring1000_response_196_points", |b| {
        b.iter(|| black_box(r1000.sweep(black_box(&band))))
    });
    let paper = Solver::new(&Body::paper(75.0).expect("paper"));
    let fine = Band::new(0.5, 20.0, 0.01).expect("band");
    c.bench_function("paper_4dof_sweep_1951_points", |b| {
        b.iter(|| black_box(paper.sweep(black_box(&fine))))
    });
    let mut slow = c.benchmark_group("modes");
    slow.sample_size(10)
        .warm_up_time(Duration::from_millis(100))
        .measurement_time(Duration::from_secs(20));
    let c400 = chain(400);
    slow.bench_function("chain400_modes", |b| {
        b.iter(|| black_box(freq::analyse_modes(black_box(&c400)).map(|m| m.damped.len())))
    });
    slow.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(20).measurement_time(Duration::from_secs(3)).warm_up_time(Duration::from_secs(1));
    targets = bench
}
criterion_main!(benches);
