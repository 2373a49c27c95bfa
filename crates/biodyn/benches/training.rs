//! Training speed: the paper's back-propagation per architecture (epochs/s),
//! the logistic neuron it spends most of its time in, Levenberg–Marquardt on
//! one case, and the worker's overhead with a receiver attached. Sample
//! sizes are small: this is a gauge, not a study.

use biodyn::ann::{
    self, Case, Dataset, Encoded, Event, Flow, Network, Settings, Trainer, Worker, logistic_lanes,
    train,
};
use biodyn::{Body, Rng, Segment};
use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use std::hint::black_box;
use std::sync::mpsc;
use std::time::Duration;

const EPOCHS: u64 = 200;

fn setup(case: Case, s: &Settings) -> (Network, Encoded) {
    let data = Dataset::build_on(case, s.base.as_ref(), &s.train_values, &s.grid).unwrap();
    let enc = Encoded::new(&data, s).unwrap();
    let net = Network::new(
        &s.layers,
        s.activation,
        s.gain,
        s.init_range,
        &mut Rng::new(1),
    )
    .unwrap();
    (net, enc)
}

fn backprop_epochs(c: &mut Criterion) {
    let mut g = c.benchmark_group("backprop");
    g.sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(2))
        .throughput(Throughput::Elements(EPOCHS));
    for case in [Case::MassStht, Case::MassDpmi, Case::K4Stht] {
        let mut s = Settings::paper(case);
        s.epochs = EPOCHS;
        s.stop_when_all_right = false;
        let (net0, enc) = setup(case, &s);
        let name = s
            .layers
            .iter()
            .map(|n| n.to_string())
            .collect::<Vec<_>>()
            .join("-");
        g.bench_function(format!("{name} ({case}), {EPOCHS} epochs"), |b| {
            b.iter(|| {
                let mut net = net0.clone();
                let mut rng = Rng::new(1);
                black_box(ann::run_backprop(
                    &mut net,
                    &enc,
                    &s,
                    &mut rng,
                    0,
                    ann::Halt::default(),
                    &mut |_| Flow::Continue,
                ))
            })
        });
    }
    g.finish();
}

/// A chain of 1000 five-neuron logistic layers, each fed by the sum of the
/// last: the latency that bounds online training (each pattern's forward pass
/// waits for the previous update), ours against the formula on libm's exp.
fn logistic_chain(c: &mut Criterion) {
    const LAYERS: u64 = 1000;
    let mut g = c.benchmark_group("logistic");
    g.sample_size(10)
        .warm_up_time(Duration::from_millis(200))
        .measurement_time(Duration::from_secs(1))
        .throughput(Throughput::Elements(LAYERS));
    fn inputs(y: &[f64; 5]) -> [f64; 5] {
        let s: f64 = y.iter().sum();
        [
            0.1 * s,
            0.2 * s,
            0.3 * s - 1.0,
            0.4 * s - 1.0,
            0.5 * s - 1.0,
        ]
    }
    g.bench_function("5 wide, biodyn::ann::exp", |b| {
        b.iter(|| {
            let mut y = black_box([0.3; 5]);
            for _ in 0..LAYERS {
                y = logistic_lanes(inputs(&y));
            }
            y
        })
    });
    g.bench_function("5 wide, 1/(1 + f64::exp(-v))", |b| {
        b.iter(|| {
            let mut y = black_box([0.3; 5]);
            for _ in 0..LAYERS {
                y = inputs(&y).map(|v| 1.0 / (1.0 + (-v).exp()));
            }
            y
        })
    });
    g.finish();
}

fn lm_case(c: &mut Criterion) {
    let mut g = c.benchmark_group("lm");
    g.sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(2));
    let case = Case::MassStht;
    let s = Settings::lm(case);
    let (net0, enc) = setup(case, &s);
    g.bench_function("mass-stht, one member, 300 iterations", |b| {
        b.iter(|| {
            let mut net = net0.clone();
            black_box(ann::run_lm(
                &mut net,
                &enc,
                &s,
                0,
                ann::Halt::default(),
                &mut |_| Flow::Continue,
            ))
        })
    });
    g.finish();
}

/// A five-segment chain (masses set directly): a mass case on it has six
/// inputs, a shape without the paper's fixed-size fast path.
fn five_segments() -> Body {
    let segs = ["head", "chest", "belly", "pelvis", "thighs"]
        .iter()
        .zip([5.0, 22.0, 9.0, 10.0, 6.0])
        .map(|(n, m)| Segment::new(n, m))
        .collect();
    Body::chain(
        segs,
        &[3.1e5, 1.83e5, 1.628e5, 9.0e4, 6.0e4],
        &[400.0, 4750.0, 4585.0, 2064.0, 1500.0],
    )
}

/// Training on a model other than the paper's: the data set, back-
/// propagation on 6-6-4-2-1 and one LM member on it, beside the paper's.
fn on_a_base(c: &mut Criterion) {
    let mut g = c.benchmark_group("base");
    g.sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(2));
    let case = Case::MassStht;
    for (name, base) in [("paper", None), ("5 segments", Some(five_segments()))] {
        let s = Settings::for_trainer_on(case, Trainer::Lm, base.clone()).unwrap();
        g.bench_function(format!("dataset, mass-stht on {name}"), |b| {
            b.iter(|| {
                black_box(Dataset::build_on(case, base.as_ref(), &s.train_values, &s.grid).unwrap())
            })
        });
        let (net0, enc) = setup(case, &s);
        g.bench_function(
            format!("lm, mass-stht on {name}, one member, 300 iterations"),
            |b| {
                b.iter(|| {
                    let mut net = net0.clone();
                    black_box(ann::run_lm(
                        &mut net,
                        &enc,
                        &s,
                        0,
                        ann::Halt::default(),
                        &mut |_| Flow::Continue,
                    ))
                })
            },
        );
        let mut bp = Settings::for_trainer_on(case, Trainer::Backprop, base).unwrap();
        bp.epochs = EPOCHS;
        bp.stop_when_all_right = false;
        let (net0, enc) = setup(case, &bp);
        g.bench_function(
            format!("backprop, mass-stht on {name}, {EPOCHS} epochs"),
            |b| {
                b.iter(|| {
                    let mut net = net0.clone();
                    let mut rng = Rng::new(1);
                    black_box(ann::run_backprop(
                        &mut net,
                        &enc,
                        &bp,
                        &mut rng,
                        0,
                        ann::Halt::default(),
                        &mut |_| Flow::Continue,
                    ))
                })
            },
        );
    }
    g.finish();
}

fn worker_overhead(c: &mut Criterion) {
    let mut g = c.benchmark_group("worker");
    g.sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(4));
    let case = Case::K4Stht;
    let mut s = Settings::paper(case);
    s.epochs = 10_000;
    s.stop_when_all_right = false;
    g.bench_function("bare train(), k4-stht 10000 epochs", |b| {
        b.iter(|| black_box(train(case, &s, &mut |_| Flow::Continue).unwrap()))
    });
    g.bench_function("worker with receiver, k4-stht 10000 epochs", |b| {
        b.iter(|| {
            let (tx, rx) = mpsc::channel::<Event>();
            let w = Worker::start(case, s.clone(), tx, |e| e).unwrap();
            let out = w.join().unwrap();
            black_box((out, rx.try_iter().count()))
        })
    });
    g.finish();
}

criterion_group!(
    benches,
    backprop_epochs,
    logistic_chain,
    lm_case,
    on_a_base,
    worker_overhead
);
criterion_main!(benches);
