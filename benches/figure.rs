//! The time to write a study figure as SVG (`plot apms --study
//! mass=65,75,85 --format svg` without the solve): issue 20's target is
//! ≤ 50 ms. The study is computed once, outside the timed loop; the loop
//! builds the figure and writes the SVG text.

use biodyn::{Band, Function, Preset};
use biodyn_app::view::report::study::figure_svg;
use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;

fn bench(c: &mut Criterion) {
    let preset = Preset::builtin_default();
    let band = Band::new(0.5, 20.0, 0.1).expect("the default band");
    let steps = [65.0, 75.0, 85.0].map(biodyn::freq::Step::Value);
    let study = biodyn::freq::run_study(&preset.body, biodyn::Param::BodyMass, &steps, &band)
        .expect("the mass study");
    c.bench_function("study figure svg (3 curves x 196 points)", |b| {
        b.iter(|| black_box(figure_svg(black_box(&study), Function::Apms, false)))
    });
    c.bench_function("study figure svg, log axes", |b| {
        b.iter(|| black_box(figure_svg(black_box(&study), Function::Apms, true)))
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
