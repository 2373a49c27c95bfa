//! One-third-octave band r.m.s. from 0.5 to 80 Hz, streamed.
//!
//! Each band is a 3rd-order Butterworth band-pass (6th order, three
//! biquads; the shape of IEC 61260 class 1 filters) between fc·10^(∓1/20),
//! designed by the bilinear transform with both edges prewarped. A band runs
//! at the lowest rate fs/2^d that is still at least five times its centre:
//! each halving goes through a 4th-order Butterworth low-pass at 0.2 × the
//! rate before it (−45 dB where content would alias into a band, 0.06 % droop
//! at the top band's edge), so the whole bank costs about as much as three
//! bands at the full rate. Seat and head run as two lanes of one bank, and
//! the bands of one stage side by side in 4-wide groups.

use crate::time::biquad::{Biquad, Cascade, butterworth};
use num_complex::Complex64;
use std::f64::consts::PI;

/// Nominal centres (the labels of IEC 61260) with their exact base-10 values.
pub fn band_centres() -> impl Iterator<Item = (f64, f64)> {
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

/// A biquad run on L signals at once (the decimators: seat and head share
/// the coefficients; the lanes vectorise).
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

/// The bands of one stage packed lane by lane (lane k: band k / L, stream
/// k % L) into groups of four, so a sample is one 4-wide biquad step per
/// section and group rather than one per band. Each lane does exactly what
/// [`Lanes::process`] does to it: the same bits.
#[derive(Debug, Clone, Default)]
struct Packed {
    /// Per section, per group: b0, b1, b2, a1, a2.
    coef: Vec<[[f64; 4]; 5]>,
    /// Per section, per group: s1, s2.
    state: Vec<[[f64; 4]; 2]>,
    sum2: Vec<[f64; 4]>,
    groups: usize,
    sections: usize,
}

impl Packed {
    /// Packs `filters` (one cascade per band) for L streams; shorter
    /// cascades are padded with sections that pass the signal unchanged.
    fn new<const L: usize>(filters: &[Cascade]) -> Packed {
        let lanes = filters.len() * L;
        let groups = lanes.div_ceil(4);
        let sections = filters.iter().map(|c| c.sections.len()).max().unwrap_or(0);
        let mut coef = vec![[[0.0; 4]; 5]; sections * groups];
        for (b, c) in filters.iter().enumerate() {
            for sec in 0..sections {
                let q = c
                    .sections
                    .get(sec)
                    .copied()
                    .unwrap_or_else(|| Biquad::new([1.0, 0.0, 0.0], [0.0, 0.0]));
                for l in 0..L {
                    let k = b * L + l;
                    let v = [q.b[0], q.b[1], q.b[2], q.a[0], q.a[1]];
                    for (i, x) in v.into_iter().enumerate() {
                        coef[sec * groups + k / 4][i][k % 4] = x;
                    }
                }
            }
        }
        Packed {
            coef,
            state: vec![[[0.0; 4]; 2]; sections * groups],
            sum2: vec![[0.0; 4]; groups],
            groups,
            sections,
        }
    }

    #[inline(always)]
    fn push<const L: usize>(&mut self, v: [f64; L]) {
        let g = self.groups;
        for grp in 0..g {
            let mut x: [f64; 4] = std::array::from_fn(|i| v[(4 * grp + i) % L]);
            for sec in 0..self.sections {
                let (Some(c), Some(st)) = (
                    self.coef.get(sec * g + grp),
                    self.state.get_mut(sec * g + grp),
                ) else {
                    continue;
                };
                let [b0, b1, b2, a1, a2] = *c;
                let mut y = [0.0; 4];
                for l in 0..4 {
                    y[l] = b0[l] * x[l] + st[0][l];
                    st[0][l] = b1[l] * x[l] - a1[l] * y[l] + st[1][l];
                    st[1][l] = b2[l] * x[l] - a2[l] * y[l];
                }
                x = y;
            }
            if let Some(s2) = self.sum2.get_mut(grp) {
                for l in 0..4 {
                    s2[l] += x[l] * x[l];
                }
            }
        }
    }

    /// Σy² of lane k.
    fn sum2(&self, k: usize) -> f64 {
        self.sum2.get(k / 4).map_or(0.0, |g| g[k % 4])
    }
}

#[derive(Debug, Clone)]
struct Stage<const L: usize> {
    /// Anti-alias low-pass run at the rate before this stage (None at stage 0).
    decimate: Option<Vec<Lanes<L>>>,
    odd: bool,
    /// Band indices (into the centres) of this stage, in lane order.
    bands: Vec<usize>,
    filters: Vec<Cascade>,
    packed: Packed,
    /// Samples this stage has seen.
    n: u64,
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
        for (index, (nominal, fc)) in band_centres().enumerate() {
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
                    filters: Vec::new(),
                    packed: Packed::default(),
                    n: 0,
                });
            }
            stages[d].bands.push(index);
            stages[d]
                .filters
                .push(band_filter(fc, fs / 2f64.powi(d as i32)));
        }
        for st in &mut stages {
            st.packed = Packed::new::<L>(&st.filters);
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
            st.packed.push(v);
            st.n += 1;
        }
    }

    /// Per band: (nominal centre Hz, r.m.s. of each stream in m/s², or None
    /// where fs is too low for the band).
    pub fn levels(&self) -> Vec<(f64, Option<[f64; L]>)> {
        let mut out: Vec<(f64, Option<[f64; L]>)> =
            self.labels.iter().map(|&(f, _)| (f, None)).collect();
        for st in &self.stages {
            let n = st.n.max(1) as f64;
            for (b, &index) in st.bands.iter().enumerate() {
                if let Some(o) = out.get_mut(index) {
                    o.1 = Some(std::array::from_fn(|l| {
                        (st.packed.sum2(b * L + l) / n).sqrt()
                    }));
                }
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::needless_range_loop)]
    use super::*;

    /// One stage run band by band: its decimator, each band's cascade per
    /// stream, each band's Σy² per stream.
    type Alone = (Option<Vec<Lanes<2>>>, Vec<[Cascade; 2]>, Vec<[f64; 2]>);

    /// The packed groups give the bits of each band's cascade run alone on
    /// each stream ([`Cascade::process`], one section at a time).
    #[test]
    fn packed_lanes_match_each_band_alone() {
        let fs = 1000.0;
        let mut bank = BandBank::<2>::new(fs);
        let mut alone: Vec<Alone> = bank
            .stages
            .iter()
            .map(|st| {
                let f = st.filters.iter().map(|c| [c.clone(), c.clone()]).collect();
                (st.decimate.clone(), f, vec![[0.0; 2]; st.filters.len()])
            })
            .collect();
        let mut odd = vec![false; alone.len()];
        for k in 0..20_000 {
            let x = [(k as f64 * 0.173).sin(), (k as f64 * 0.0071).cos() - 0.3];
            bank.push(x);
            let mut v = x;
            for (i, (dec, filters, sums)) in alone.iter_mut().enumerate() {
                if let Some(lp) = dec {
                    v = run(lp, v);
                    odd[i] = !odd[i];
                    if odd[i] {
                        break;
                    }
                }
                for (f, s) in filters.iter_mut().zip(sums.iter_mut()) {
                    for l in 0..2 {
                        let y = f[l].process(v[l]);
                        s[l] += y * y;
                    }
                }
            }
        }
        for (st, (_, _, sums)) in bank.stages.iter().zip(&alone) {
            assert!(st.n > 0);
            for (b, s) in sums.iter().enumerate() {
                for l in 0..2 {
                    assert_eq!(st.packed.sum2(b * 2 + l).to_bits(), s[l].to_bits());
                }
            }
        }
    }
}
