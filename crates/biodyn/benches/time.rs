//! Time-domain speed (issue 9): the 4-DOF simulation with every output per
//! sample (target ≤ 10 ns; scipy.signal.lsim ≈ 4.8 µs), the Wk weighting per
//! sample (lsim ≈ 17 µs), the whole assessment pipeline per sample, signal
//! generation, and reading an hour-long 1 kHz CSV record (3.6 M rows,
//! target ≤ 1.5 s).
//!
//! Times are the benchmark thread's CPU time (`CLOCK_THREAD_CPUTIME_ID`; for
//! `assess`, which runs two threads, the process's), not wall time: the build machine is shared, and wall time there measures the
//! neighbours. On a quiet machine the two agree.

use biodyn::Body;
use biodyn::iso2631::{Weighting, assess};
use biodyn::time::{Generator, Record, RecordOptions, Signal, Simulator, TimeError};
use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use std::hint::black_box;
use std::io::Write;
use std::time::Duration;

const BLOCK: usize = 4096;

/// CPU time of this thread.
fn cpu_now() -> Duration {
    let mut t = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: a valid pointer to a timespec; the clock id is a constant.
    unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut t) };
    Duration::new(t.tv_sec as u64, t.tv_nsec as u32)
}

/// CPU time of the whole process, every thread (`assess` runs two).
fn process_cpu_now() -> Duration {
    let mut t = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: a valid pointer to a timespec; the clock id is a constant.
    unsafe { libc::clock_gettime(libc::CLOCK_PROCESS_CPUTIME_ID, &mut t) };
    Duration::new(t.tv_sec as u64, t.tv_nsec as u32)
}

/// `b.iter(f)` timed on the process's CPU clock: every thread's time.
fn process_cpu_iter<O>(b: &mut criterion::Bencher, mut f: impl FnMut() -> O) {
    b.iter_custom(|iters| {
        let start = process_cpu_now();
        for _ in 0..iters {
            black_box(f());
        }
        process_cpu_now() - start
    })
}

/// `b.iter(f)` timed on the thread's CPU clock.
fn cpu_iter<O>(b: &mut criterion::Bencher, mut f: impl FnMut() -> O) {
    b.iter_custom(|iters| {
        let start = cpu_now();
        for _ in 0..iters {
            black_box(f());
        }
        cpu_now() - start
    })
}

fn noise(n: usize) -> Vec<f64> {
    let sig = Signal::parse("random:rms=1,band=0.5-80,seed=1").unwrap();
    Generator::new(&sig, 1000.0, n as f64 / 1000.0)
        .unwrap()
        .collect()
}

fn simulation(c: &mut Criterion) {
    let body = Body::paper(75.0).unwrap();
    let input = noise(BLOCK);
    let mut g = c.benchmark_group("simulate");
    g.throughput(Throughput::Elements(BLOCK as u64));
    let mut sim = Simulator::new(&body, 1000.0).unwrap();
    let mut out = vec![0.0; BLOCK * sim.layout().len()];
    g.bench_function("paper_4dof_every_output", |b| {
        cpu_iter(b, || {
            sim.run(black_box(&input), &mut out);
            black_box(out[out.len() - 1])
        })
    });
    // The dense path: a 10-segment chain (20 states).
    let segs = (0..10)
        .map(|i| biodyn::Segment::new(&format!("s{i}"), 5.0))
        .collect();
    let big = Body::chain(segs, &[9e4; 10], &[2e3; 10]);
    let mut sim = Simulator::new(&big, 1000.0).unwrap();
    let mut out = vec![0.0; BLOCK * sim.layout().len()];
    g.bench_function("chain_10_dense", |b| {
        cpu_iter(b, || {
            sim.run(black_box(&input), &mut out);
            black_box(out[out.len() - 1])
        })
    });
    g.finish();
}

fn weighting(c: &mut Criterion) {
    let input = noise(BLOCK);
    let mut g = c.benchmark_group("weighting");
    g.throughput(Throughput::Elements(BLOCK as u64));
    for w in Weighting::ALL {
        let mut f = w.digital(1000.0);
        g.bench_function(w.name(), |b| {
            cpu_iter(b, || {
                let mut s = 0.0;
                for &x in black_box(&input) {
                    s += f.process(x);
                }
                black_box(s)
            })
        });
    }
    g.finish();
}

fn pipeline(c: &mut Criterion) {
    // One minute through everything `biodyn assess` does after generation.
    let body = Body::paper(75.0).unwrap();
    let n = 60_000;
    let input = noise(n);
    let mut g = c.benchmark_group("assess");
    g.sample_size(10).throughput(Throughput::Elements(n as u64));
    // CPU of both threads: the sum of the work, not the time to answer.
    g.bench_function("paper_4dof_wk_all_metrics_bands", |b| {
        process_cpu_iter(b, || {
            let r = assess(
                &body,
                1000.0,
                input.iter().map(|&v| Ok::<f64, TimeError>(v)),
                8.0,
            )
            .unwrap();
            black_box(r.seat.metrics.aw)
        })
    });
    g.bench_function("generate_random_two_passes", |b| {
        let sig = Signal::parse("random:rms=1,band=0.5-80,seed=1").unwrap();
        cpu_iter(b, || {
            Generator::new(&sig, 1000.0, 60.0).unwrap().sum::<f64>()
        })
    });
    g.finish();
}

fn csv_hour(c: &mut Criterion) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("hour.csv");
    {
        let f = std::fs::File::create(&path).unwrap();
        let mut w = std::io::BufWriter::new(f);
        writeln!(w, "t_s,acc_m_s2").unwrap();
        let sig = Signal::parse("random:rms=1,band=0.5-80,seed=1").unwrap();
        for (k, a) in Generator::new(&sig, 1000.0, 3600.0).unwrap().enumerate() {
            writeln!(w, "{},{a}", k as f64 / 1000.0).unwrap();
        }
    }
    let mut g = c.benchmark_group("record");
    g.sample_size(10)
        .measurement_time(Duration::from_secs(10))
        .throughput(Throughput::Elements(3_600_000));
    g.bench_function("csv_hour_1khz_3_6m_rows", |b| {
        cpu_iter(b, || {
            let r = Record::open(&path, &RecordOptions::default()).unwrap();
            let mut s = 0.0;
            for v in r {
                s += v.unwrap()[2];
            }
            black_box(s)
        })
    });
    g.finish();
}

criterion_group!(benches, simulation, weighting, pipeline, csv_hour);
criterion_main!(benches);
