//! One-third-octave band r.m.s. from 0.5 to 80 Hz, streamed.
//!
//! Each band is a 3rd-order Butterworth band-pass (6th order, three
//! biquads; the shape of IEC 61260 class 1 filters) between fc·10^(∓1/20),
//! designed by the bilinear transform with both edges prewarped. A band runs
//! at the lowest rate fs/2^d that is still at least five times its centre:
//! each halving goes through a 4th-order Butterworth low-pass at 0.2 × the
//! rate before it (−45 dB where content would alias into a band, 0.06 % droop
//! at the top band's edge), so the whole bank costs about as much as three
//! bands at the full rate. Seat and head run as two lanes of one bank.

use crate::time::biquad::{Biquad, Cascade, butterworth};
use num_complex::Complex64;
use std::f64::consts::PI;

/// Nominal centres (the labels of IEC 61260) with their exact base-10 values.
pub fn centres() -> impl Iterator<Item = (f64, f64)> {
    const NOMINAL: [f64; 23] = [
        0.5, 0.63, 0.8, 1.0, 1.25, 1.6, 2.0, 2.5, 3.15, 4.0, 5.0, 6.3, 8.0, 10.0, 12.5, 16.0, 20.0,
        25.0, 31.5, 40.0, 50.0, 63.0, 80.0,
    ];
    NOMINAL
        .into_iter()
        .enumerate()
        .map(|(i, f)| (f, 10f64.powf((i as f64 - 33.0) / 10.0) * 1000.0))
}

/// The band-pass of centre `fc` at rate `r`: three sections, unit gain at fc.
pub fn band_filter(fc: f64, r: f64) -> Cascade {
    let k = 2.0 * r;
    let warp = |f: f64| k * (PI * f / r).tan();
    let (w1, w2) = (warp(fc * 10f64.powf(-0.05)), warp(fc * 10f64.powf(0.05)));
    let w0sq = w1 * w2;
    let bw = w2 - w1;
    let mut sections = Vec::with_capacity(3);
    for kk in 0..3 {
        let p = Complex64::from_polar(1.0, PI * (2 * kk + 4) as f64 / 6.0);
        let pb = p * bw;
        let root = (pb * pb - 4.0 * w0sq).sqrt();
        for s in [(pb + root) / 2.0, (pb - root) / 2.0] {
            if s.im > 0.0 {
                let z = (k + s) / (k - s);
                sections.push(Biquad::new([1.0, 0.0, -1.0], [-2.0 * z.re, z.norm_sqr()]));
            }
        }
    }
    let mut c = Cascade::new(sections);
    let g = c.response(fc, r).norm();
    let per = g.powf(-1.0 / c.sections.len() as f64);
    for s in &mut c.sections {
        s.b.iter_mut().for_each(|b| *b *= per);
    }
    c
}

/// A biquad run on L signals at once (seat and head share the coefficients;
/// the lanes vectorise).
#[derive(Debug, Clone)]
struct Lanes<const L: usize> {
    b: [f64; 3],
    a: [f64; 2],
    s1: [f64; L],
    s2: [f64; L],
}

impl<const L: usize> Lanes<L> {
    fn of(q: &Biquad) -> Self {
        Lanes {
            b: q.b,
            a: q.a,
            s1: [0.0; L],
            s2: [0.0; L],
        }
    }

    #[inline(always)]
    fn process(&mut self, x: [f64; L]) -> [f64; L] {
        let mut y = [0.0; L];
        for l in 0..L {
            y[l] = self.b[0] * x[l] + self.s1[l];
            self.s1[l] = self.b[1] * x[l] - self.a[0] * y[l] + self.s2[l];
            self.s2[l] = self.b[2] * x[l] - self.a[1] * y[l];
        }
        y
    }
}

fn lanes<const L: usize>(c: &Cascade) -> Vec<Lanes<L>> {
    c.sections.iter().map(Lanes::of).collect()
}

#[inline(always)]
fn run<const L: usize>(c: &mut [Lanes<L>], x: [f64; L]) -> [f64; L] {
    c.iter_mut().fold(x, |v, s| s.process(v))
}

#[derive(Debug, Clone)]
struct Band<const L: usize> {
    index: usize,
    filter: Vec<Lanes<L>>,
    sum2: [f64; L],
    n: u64,
}

#[derive(Debug, Clone)]
struct Stage<const L: usize> {
    /// Anti-alias low-pass run at the rate before this stage (None at stage 0).
    decimate: Option<Vec<Lanes<L>>>,
    odd: bool,
    bands: Vec<Band<L>>,
}

/// One-third-octave r.m.s. of L streams at once, bands 0.5–80 Hz.
#[derive(Debug, Clone)]
pub struct BandBank<const L: usize = 1> {
    stages: Vec<Stage<L>>,
    /// (nominal centre, computed?) for every band.
    labels: Vec<(f64, bool)>,
}

impl<const L: usize> BandBank<L> {
    /// The bank for rate `fs`; bands whose upper edge reaches 0.45 fs are left out.
    pub fn new(fs: f64) -> Self {
        let mut stages: Vec<Stage<L>> = Vec::new();
        let mut labels = Vec::new();
        for (index, (nominal, fc)) in centres().enumerate() {
            let ok = fc * 10f64.powf(0.05) < 0.45 * fs;
            labels.push((nominal, ok));
            if !ok {
                continue;
            }
            let mut d = 0;
            while fc <= fs / 2f64.powi(d + 1) / 5.0 {
                d += 1;
            }
            let d = d as usize;
            while stages.len() <= d {
                let i = stages.len();
                stages.push(Stage {
                    decimate: (i > 0).then(|| {
                        let parent = fs / 2f64.powi(i as i32 - 1);
                        lanes(&butterworth(4, 0.2 * parent, parent, false))
                    }),
                    odd: false,
                    bands: Vec::new(),
                });
            }
            stages[d].bands.push(Band {
                index,
                filter: lanes(&band_filter(fc, fs / 2f64.powi(d as i32))),
                sum2: [0.0; L],
                n: 0,
            });
        }
        BandBank { stages, labels }
    }

    /// The next sample of each of the L streams.
    #[inline(always)]
    pub fn push(&mut self, x: [f64; L]) {
        let mut v = x;
        for st in &mut self.stages {
            if let Some(lp) = &mut st.decimate {
                v = run(lp, v);
                st.odd = !st.odd;
                if st.odd {
                    return;
                }
            }
            for b in &mut st.bands {
                let y = run(&mut b.filter, v);
                for (s, y) in b.sum2.iter_mut().zip(y) {
                    *s += y * y;
                }
                b.n += 1;
            }
        }
    }

    /// Per band: (nominal centre Hz, r.m.s. of each stream in m/s², or None
    /// where fs is too low for the band).
    pub fn levels(&self) -> Vec<(f64, Option<[f64; L]>)> {
        let mut out: Vec<(f64, Option<[f64; L]>)> =
            self.labels.iter().map(|&(f, _)| (f, None)).collect();
        for st in &self.stages {
            for b in &st.bands {
                if let Some(o) = out.get_mut(b.index) {
                    let n = b.n.max(1) as f64;
                    o.1 = Some(std::array::from_fn(|l| (b.sum2[l] / n).sqrt()));
                }
            }
        }
        out
    }
}
