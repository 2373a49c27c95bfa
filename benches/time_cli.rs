//! `biodyn assess` as a whole process on an hour at 1 kHz (issue 9's target:
//! ≤ 0.25 s, under 100 MB resident). Wall time of the real binary, start to
//! exit; measure the resident size with `/usr/bin/time -v` (README).

use criterion::{Criterion, criterion_group, criterion_main};
use std::process::{Command, Stdio};
use std::time::Duration;

fn assess_hour(c: &mut Criterion) {
    let mut g = c.benchmark_group("process");
    g.sample_size(10).measurement_time(Duration::from_secs(8));
    g.bench_function("assess_random_hour_1khz_json", |b| {
        b.iter(|| {
            let st = Command::new(env!("CARGO_BIN_EXE_biodyn"))
                .args([
                    "assess",
                    "--signal",
                    "random:rms=1,band=0.5-80,seed=1",
                    "--duration",
                    "3600",
                    "--fs",
                    "1000",
                    "--format",
                    "json",
                ])
                .stdout(Stdio::null())
                .status()
                .expect("biodyn runs");
            assert!(st.success());
        })
    });
    g.finish();
}

criterion_group!(benches, assess_hour);
criterion_main!(benches);
