//! The tri-axial hour of docs/speed.md as one process: a generated hour at
//! 1 kHz on x, y and z (seeded random signals) through everything `biodyn
//! assess` does, timed once (wall). With a path, it also writes the same
//! hour as CSV (t_s and three axes at shortest round-trip precision, about
//! 248 MB) for timing `biodyn assess --input` on it:
//!
//! ```sh
//! cargo run --release -p biodyn --example triaxial_hour -- /tmp/hour3.csv
//! /usr/bin/time -f "%e s, %M KB" target/release/biodyn assess --input /tmp/hour3.csv --format json > /dev/null
//! ```

use biodyn::Body;
use biodyn::iso2631::assess_axes;
use biodyn::time::{Axis, Generator, PerAxis, Signal};
use std::io::Write;
use std::time::Instant;

/// The bench's three signals (benches/time.rs, `tri_axial`).
fn rows() -> impl Iterator<Item = [f64; 3]> {
    let g = |spec: &str| {
        Generator::new(&Signal::parse(spec).expect("a valid spec"), 1000.0, 3600.0)
            .expect("an hour at 1 kHz")
    };
    let x = g("random:rms=0.3,band=0.5-80,seed=1");
    let y = g("random:rms=0.2,band=0.5-80,seed=2");
    let z = g("random:rms=0.6,band=0.5-80,seed=3");
    x.zip(y).zip(z).map(|((x, y), z)| [x, y, z])
}

fn main() -> std::io::Result<()> {
    if let Some(path) = std::env::args().nth(1) {
        let mut w = std::io::BufWriter::new(std::fs::File::create(&path)?);
        writeln!(w, "t_s,ax_m_s2,ay_m_s2,az_m_s2")?;
        for (k, [x, y, z]) in rows().enumerate() {
            writeln!(w, "{},{x},{y},{z}", k as f64 / 1000.0)?;
        }
        w.flush()?;
        println!("wrote {path}");
    }
    let body = Body::paper(75.0).expect("the paper's model");
    let mut all = PerAxis::default();
    for a in Axis::ALL {
        all.set(a, ());
    }
    let t = Instant::now();
    let r = assess_axes(&body, 1000.0, rows().map(Ok), &all, 8.0).expect("assessed");
    println!(
        "generated tri-axial hour: A(8) {} m/s² ({}) in {:.3} s",
        r.health.a8,
        r.health.a8_axis,
        t.elapsed().as_secs_f64()
    );
    Ok(())
}
