use biodyn::{Band, Body, Solver};
fn main() {
    let s = Solver::new(&Body::paper(75.0).unwrap());
    let b = Band::new(0.5, 20.0, 0.01).unwrap();
    let f = b.freqs();
    let t = std::time::Instant::now();
    let mut acc = 0.0;
    let n = 5000;
    for _ in 0..n {
        acc += s.sweep_freqs(std::hint::black_box(&f))[7].stht.re;
    }
    println!(
        "{} ns/pt {acc}",
        t.elapsed().as_nanos() as f64 / (n * f.len()) as f64
    );
}
