//! The paper's case, a plain chain of up to eight segments, solved by a
//! head-down recurrence several frequencies at a time (AVX2 when the CPU
//! has it). Longer chains and other trees go through `freq::tree`.

use crate::body::model::{Body, End};
use crate::freq::function::Response;
use crate::simd::simd_fn;
use num_complex::Complex64;
use std::f64::consts::PI;

/// A plain serial chain, top to bottom, in fixed-size arrays.
///
/// Equilibrium of the segments above link i gives
/// X_i − X_{i+1} = ω² Σ_{j≤i} m_j X_j / z_i with z_i = k_i + jωc_i, so with
/// X_top = 1 the displacements follow from the top down; the seat's X0 comes
/// out last and one division by it normalises everything. The link
/// reciprocals do not depend on each other, so they pipeline, unlike the
/// serial pivots of Thomas' algorithm.
#[derive(Debug, Clone)]
pub(crate) struct Chain {
    n: usize,
    head: usize,
    m: [f64; CHAIN_MAX],
    k: [f64; CHAIN_MAX],
    c: [f64; CHAIN_MAX],
}

const CHAIN_MAX: usize = 8;
/// Frequencies solved together in a sweep.
pub(crate) const LANES: usize = 8;

impl Chain {
    pub(crate) fn of(body: &Body) -> Option<Chain> {
        let n = body.n();
        if n > CHAIN_MAX || body.links.len() != n {
            return None;
        }
        let mut ch = Chain {
            n,
            head: body.head,
            m: [0.0; CHAIN_MAX],
            k: [0.0; CHAIN_MAX],
            c: [0.0; CHAIN_MAX],
        };
        for (i, s) in body.segments.iter().enumerate() {
            ch.m[i] = s.mass;
        }
        // Exactly one link per level i -> i+1 (the last to the seat), each
        // carrying something, in any declaration order.
        let mut seen = [false; CHAIN_MAX];
        for l in &body.links {
            let want = if l.upper + 1 < n {
                End::Segment(l.upper + 1)
            } else {
                End::Seat
            };
            if l.lower != want || seen[l.upper] || (l.k <= 0.0 && l.c <= 0.0) {
                return None;
            }
            seen[l.upper] = true;
            ch.k[l.upper] = l.k;
            ch.c[l.upper] = l.c;
        }
        Some(ch)
    }

    /// (STHT, APMS) at angular frequency `w`.
    #[inline]
    pub(crate) fn at(&self, w: f64) -> (Complex64, Complex64) {
        match self.n {
            1 => self.shoot::<1>(w),
            2 => self.shoot::<2>(w),
            3 => self.shoot::<3>(w),
            4 => self.shoot::<4>(w),
            5 => self.shoot::<5>(w),
            6 => self.shoot::<6>(w),
            7 => self.shoot::<7>(w),
            _ => self.shoot::<8>(w),
        }
    }

    /// `at` for LANES frequencies at once.
    #[inline(always)]
    fn at_lanes(&self, w: &[f64; LANES]) -> ([Complex64; LANES], [Complex64; LANES]) {
        match self.n {
            1 => self.shoot_lanes::<1>(w),
            2 => self.shoot_lanes::<2>(w),
            3 => self.shoot_lanes::<3>(w),
            4 => self.shoot_lanes::<4>(w),
            5 => self.shoot_lanes::<5>(w),
            6 => self.shoot_lanes::<6>(w),
            7 => self.shoot_lanes::<7>(w),
            _ => self.shoot_lanes::<8>(w),
        }
    }

    /// The same recurrence as `shoot`, lane-wise in separate re/im arrays.
    #[inline(always)]
    fn shoot_lanes<const N: usize>(
        &self,
        w: &[f64; LANES],
    ) -> ([Complex64; LANES], [Complex64; LANES]) {
        let mut xr = [1.0; LANES];
        let mut xi = [0.0; LANES];
        let mut sr = [0.0; LANES];
        let mut si = [0.0; LANES];
        let (mut hr, mut hi) = (xr, xi);
        for i in 0..N {
            let (k, c, m) = (self.k[i], self.c[i], self.m[i]);
            if i == self.head {
                (hr, hi) = (xr, xi);
            }
            for l in 0..LANES {
                let ki = w[l] * c;
                let d = w[l] * w[l] / (k * k + ki * ki);
                let (gr, gi) = (k * d, -ki * d);
                sr[l] += xr[l] * m;
                si[l] += xi[l] * m;
                xr[l] -= sr[l] * gr - si[l] * gi;
                xi[l] -= sr[l] * gi + si[l] * gr;
            }
        }
        let mut stht = [Complex64::new(0.0, 0.0); LANES];
        let mut apms = stht;
        for l in 0..LANES {
            let d = 1.0 / (xr[l] * xr[l] + xi[l] * xi[l]);
            let inv = Complex64::new(xr[l] * d, -xi[l] * d);
            stht[l] = Complex64::new(hr[l], hi[l]) * inv;
            apms[l] = Complex64::new(sr[l], si[l]) * inv;
        }
        (stht, apms)
    }

    #[inline(always)]
    fn shoot<const N: usize>(&self, w: f64) -> (Complex64, Complex64) {
        let w2 = w * w;
        let mut x = Complex64::new(1.0, 0.0);
        let mut sum = Complex64::new(0.0, 0.0);
        let mut head = x;
        for i in 0..N {
            if i == self.head {
                head = x;
            }
            // ω² / z_i: independent of x, so these divisions overlap.
            let (k, ki) = (self.k[i], w * self.c[i]);
            let d = w2 / (k * k + ki * ki);
            sum += x * self.m[i];
            x -= sum * Complex64::new(k * d, -ki * d);
        }
        // x is now X0 for X_top = 1.
        let d = 1.0 / x.norm_sqr();
        let inv = Complex64::new(x.re * d, -x.im * d);
        (head * inv, sum * inv)
    }
}

simd_fn! {
    /// The chain's lane kernel over blocks of frequencies, compiled for the
    /// crate's SIMD targets ([`crate::simd`]): with 4-wide registers the
    /// divisions vectorise and a sweep takes half the time. No FMA contraction
    /// happens either way, so both give the same bits.
    pub(crate) fn chain_sweep(ch: &Chain, blocks: &[[f64; LANES]], out: &mut Vec<Response>) {
        for f in blocks {
            let w: [f64; LANES] = std::array::from_fn(|l| 2.0 * PI * f[l]);
            let (stht, apms) = ch.at_lanes(&w);
            for l in 0..LANES {
                out.push(Response::of(f[l], w[l], stht[l], apms[l]));
            }
        }
    }
}
