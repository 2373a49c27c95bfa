//! Response-engine speed: one frequency point of the 4-DOF chain (all three
//! functions), a fine sweep, the general LU path, modes and a study.

use biodyn::{Band, Body, Param, Solver};
use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;

fn bench(c: &mut Criterion) {
    let body = Body::paper(75.0).expect("paper model");
    let solver = Solver::new(&body);

    c.bench_function("point_4dof_tridiagonal", |b| {
        let mut f = 4.5;
        b.iter(|| {
            f = if f > 19.0 { 0.5 } else { f + 0.37 };
            black_box(solver.at(black_box(f)))
        })
    });
    c.bench_function("point_4dof_general_lu", |b| {
        b.iter(|| black_box(solver.transfer_general(black_box(4.5))))
    });
    let fine = Band::new(0.5, 20.0, 0.01).expect("band");
    c.bench_function("sweep_1951_points", |b| {
        b.iter(|| black_box(solver.sweep(black_box(&fine))))
    });
    c.bench_function("solver_assemble", |b| {
        b.iter(|| black_box(Solver::new(black_box(&body))))
    });
    c.bench_function("modes_4dof", |b| {
        b.iter(|| black_box(biodyn::freq::analyse_modes(black_box(&body))))
    });
    // The whole process, start to exit, as a script would run it.
    c.bench_function("process_biodyn_response_csv", |b| {
        b.iter(|| {
            let out = std::process::Command::new(env!("CARGO_BIN_EXE_biodyn"))
                .args(["response", "--format", "csv"])
                .output()
                .expect("run biodyn");
            assert!(out.status.success());
            black_box(out.stdout.len())
        })
    });
    let steps = biodyn::freq::parse_steps("-40%,0%,+40%").expect("steps");
    c.bench_function("study_k4_3_variants_default_band", |b| {
        b.iter(|| {
            black_box(biodyn::freq::run_study(
                &body,
                Param::Stiffness(3),
                &steps,
                &Band::default(),
            ))
        })
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(50).measurement_time(std::time::Duration::from_secs(2)).warm_up_time(std::time::Duration::from_millis(500));
    targets = bench
}
criterion_main!(benches);
