//! The seat's speed (issue 18): one SEAT figure in the frequency domain
//! (SEAT %, both a_w and the r.m.s. stroke on the 401-node grid, target
//! ≤ 200 µs) on the shipped 6-DOF suspension seat under EM6, and a
//! two-parameter design search (suspension k and c, a 21 × 21 map and the
//! compass refinement, target ≤ 1 s).
//!
//! Times are the benchmark thread's CPU time (`CLOCK_THREAD_CPUTIME_ID`),
//! not wall time: the build machine is shared, and wall time there
//! measures the neighbours. On a quiet machine the two agree.

use biodyn::Preset;
use biodyn::seat::{FloorPsd, SeatGrid, Vary, design};
use biodyn::time::InputClass;
#[path = "common/cpu.rs"]
mod cpu;
use cpu::cpu_iter;
use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use std::time::Duration;

fn seat(c: &mut Criterion) {
    let body = Preset::open("paper-75kg-suspension-seat")
        .expect("the shipped seat")
        .body;
    let em6 = InputClass::parse("EM6").expect("EM6");
    let grid = SeatGrid::new(&FloorPsd::Class(em6)).expect("EM6's grid");
    let mut g = c.benchmark_group("seat");
    g.bench_function("figures/em6-6dof", |b| {
        cpu_iter(b, || grid.figures(black_box(&body)).expect("figures"))
    });
    let vary = [
        Vary::new(&body, "suspension.k", 4000.0, 20000.0).expect("k"),
        Vary::new(&body, "suspension.c", 200.0, 4000.0).expect("c"),
    ];
    g.sample_size(10).measurement_time(Duration::from_secs(5));
    g.bench_function("design/k-c-em2", |b| {
        let em2 = SeatGrid::new(&FloorPsd::Class(InputClass::parse("EM2").expect("EM2")))
            .expect("EM2's grid");
        cpu_iter(b, || design(&body, &em2, &vary, 0.012).expect("a design"))
    });
    g.finish();
}

criterion_group!(benches, seat);
criterion_main!(benches);
