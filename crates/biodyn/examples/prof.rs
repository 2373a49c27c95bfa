use biodyn::iso2631::{Weighting, bands::BandBank, metrics::Accumulator};
use biodyn::time::{Generator, Signal, Simulator};
struct Instant(f64);
impl Instant { fn now() -> Instant { let mut t = libc::timespec{tv_sec:0,tv_nsec:0}; unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut t) }; Instant(t.tv_sec as f64 + t.tv_nsec as f64*1e-9) }
 fn elapsed(&self) -> Dur { Dur(Instant::now().0 - self.0) } }
#[derive(Debug)] struct Dur(f64);
impl Dur { fn as_nanos(&self) -> f64 { self.0*1e9 } }
fn main() {
    let n = 3_600_000usize;
    let fs = 1000.0;
    let t = Instant::now();
    let sig = Signal::parse("random:rms=1,band=0.5-80,seed=1").unwrap();
    let g = Generator::new(&sig, fs, 3600.0).unwrap();
    println!("gen pass1 {:?}", t.elapsed());
    let t = Instant::now();
    let x: Vec<f64> = g.collect();
    println!("gen pass2 {:?}", t.elapsed());
    let body = biodyn::Body::paper(75.0).unwrap();
    let mut sim = Simulator::new(&body, fs).unwrap();
    let mut out = vec![0.0; 4096 * 9];
    let t = Instant::now();
    for c in x.chunks(4096) { sim.run(c, &mut out); }
    println!("sim {:?} = {:.2} ns/sample", t.elapsed(), t.elapsed().as_nanos() / n as f64);
    let mut w = Weighting::Wk.digital(fs);
    let t = Instant::now();
    let mut s = 0.0;
    for &v in &x { s += w.process(v); }
    println!("wk {:?} {s}", t.elapsed());
    let mut acc = Accumulator::new(fs);
    let t = Instant::now();
    for &v in &x { acc.push(v); }
    println!("acc {:?}", t.elapsed());
    let mut b = BandBank::<2>::new(fs);
    let t = Instant::now();
    for &v in &x { b.push([v, v]); }
    println!("bands {:?}", t.elapsed());
}
