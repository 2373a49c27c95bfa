//! The simulator's kernels: the same product q ← Φ q + Γ0 a0 + Γ1 a1 and
//! output rows, laid out three ways. Up to four segments: padded to four,
//! the state in two 4-lane halves, fused multiply–adds ([`Small`]). Five and six: fixed-size
//! arrays the compiler unrolls ([`Fixed`]). More: dense, stored by column
//! ([`Dense`]), 2n·(2n + n + 1) multiply–adds a sample.

// Lane loops index several arrays by the same lane: the form that vectorises.
#![allow(clippy::needless_range_loop)]

use super::discrete::Discrete;
use crate::simd::simd_fn;

/// Four f64 lanes: one AVX2 register.
type V4 = [f64; 4];

const ZERO: V4 = [0.0; 4];

/// acc + a·x lane by lane, each lane one fused multiply–add (a single
/// rounding, IEEE 754 `fusedMultiplyAdd`): the same bits from an FMA
/// instruction or from libm's correctly rounded `fma`, on every CPU.
#[inline(always)]
fn fma4(acc: V4, a: V4, x: f64) -> V4 {
    [
        a[0].mul_add(x, acc[0]),
        a[1].mul_add(x, acc[1]),
        a[2].mul_add(x, acc[2]),
        a[3].mul_add(x, acc[3]),
    ]
}

/// acc + a·b lane by lane, fused.
#[inline(always)]
fn fmav(acc: V4, a: V4, b: V4) -> V4 {
    [
        a[0].mul_add(b[0], acc[0]),
        a[1].mul_add(b[1], acc[1]),
        a[2].mul_add(b[2], acc[2]),
        a[3].mul_add(b[3], acc[3]),
    ]
}

#[inline(always)]
fn add4(a: V4, b: V4) -> V4 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2], a[3] + b[3]]
}

/// The kernel for models of up to four segments, padded to four (idle
/// states stay zero): the state is two AVX2 registers, the accelerations
/// one. Every product is a fused multiply–add (see [`fma4`]): half the
/// floating-point operations of a multiply and an add, and bit-identical
/// results everywhere; with FMA hardware (x86-64 since 2013, every aarch64)
/// a sample is some 40 vector operations, without it libm's `fma` gives the
/// same bits slowly. A partial sum that starts from a product starts as
/// fma(a, x, +0), so a zero product is +0 as in a plain sum from 0.
#[derive(Debug, Clone)]
pub(super) struct Small {
    n: usize,
    /// Column j of Φ, as two halves (z and z').
    phi: [[V4; 2]; 8],
    g0: [V4; 2],
    g1: [V4; 2],
    /// Column j of the acceleration rows.
    acc: [V4; 8],
    /// The seat-force row, as two halves.
    force: [V4; 2],
    pub(super) q: [V4; 2],
    /// Link ends as indices into [z, 0]: index 4 is the seat (always zero).
    links: Vec<(usize, usize)>,
    /// The links are the chain 0–1, 1–2, 2–3, 3–seat, in that order.
    chain4: bool,
}

impl Small {
    pub(super) fn new(d: &Discrete) -> Small {
        let n = d.n;
        // Padded state index of state i of the n-segment model.
        let pad = |i: usize| if i < n { i } else { 4 + i - n };
        let mut phi = [[[0.0; 4]; 2]; 8];
        let mut g0 = [[0.0; 4]; 2];
        let mut g1 = [[0.0; 4]; 2];
        let mut acc = [[0.0; 4]; 8];
        let mut force = [[0.0; 4]; 2];
        for j in 0..2 * n {
            let pj = pad(j);
            for i in 0..2 * n {
                let pi = pad(i);
                phi[pj][pi / 4][pi % 4] = d.phi[(i, j)];
            }
            for (r, a) in acc[pj].iter_mut().enumerate().take(n) {
                *a = d.out[(r, j)];
            }
            force[pj / 4][pj % 4] = d.out[(n, j)];
            g0[pj / 4][pj % 4] = d.g0[j];
            g1[pj / 4][pj % 4] = d.g1[j];
        }
        let links: Vec<(usize, usize)> = d
            .links
            .iter()
            .map(|&(u, l)| (u.min(3), l.map_or(4, |l| l.min(3))))
            .collect();
        let chain4 = n == 4 && links == [(0, 1), (1, 2), (2, 3), (3, 4)];
        Small {
            n,
            phi,
            g0,
            g1,
            acc,
            force,
            q: [[0.0; 4]; 2],
            links,
            chain4,
        }
    }

    #[inline(always)]
    fn flat(&self) -> [f64; 8] {
        let [a, b] = self.q;
        [a[0], a[1], a[2], a[3], b[0], b[1], b[2], b[3]]
    }

    /// q ← Φ q + Γ0 a0 + Γ1 a1. The state is a recurrence, so the latency
    /// from q to q bounds a sample: four partial sums of two fused
    /// products each (the input terms ride on the first), then two adds.
    #[inline(always)]
    pub(super) fn advance(&mut self, a0: f64, a1: f64) {
        let q = self.flat();
        let phi = &self.phi;
        for h in 0..2 {
            let g = fma4(fma4(ZERO, self.g0[h], a0), self.g1[h], a1);
            let p0 = fma4(fma4(g, phi[0][h], q[0]), phi[4][h], q[4]);
            let p1 = fma4(fma4(ZERO, phi[1][h], q[1]), phi[5][h], q[5]);
            let p2 = fma4(fma4(ZERO, phi[2][h], q[2]), phi[6][h], q[6]);
            let p3 = fma4(fma4(ZERO, phi[3][h], q[3]), phi[7][h], q[7]);
            self.q[h] = add4(add4(p0, p1), add4(p2, p3));
        }
    }

    pub(super) fn reset(&mut self) {
        self.q = [[0.0; 4]; 2];
    }

    #[inline(always)]
    pub(super) fn run(
        &mut self,
        prev: &mut Option<f64>,
        _links: &[(usize, Option<usize>)],
        input: &[f64],
        out: &mut [f64],
        width: usize,
    ) {
        // The paper's shape (a 4-segment chain) gets rows of a fixed width,
        // so the compiler sees every store.
        if self.chain4 && width == 9 {
            run9(self, prev, input, out);
            return;
        }
        for (&a, y) in input.iter().zip(out.chunks_exact_mut(width)) {
            if let Some(p) = prev.replace(a) {
                self.advance(p, a);
            }
            self.emit(&[], y);
        }
    }

    /// [`Small::run`] for the 4-segment chain in AVX2 and FMA intrinsics,
    /// the state held in two registers across the block (the compiler's own
    /// vectorisation stored and reloaded it every sample, in pieces, and
    /// stalled on the reload). Lane for lane the same operations in the same
    /// order as [`Small::advance`] and [`Small::emit9`]: the same bits.
    #[inline(always)]
    fn run9_plain(&mut self, prev: &mut Option<f64>, input: &[f64], out: &mut [f64]) {
        for (&a, y) in input.iter().zip(out.chunks_exact_mut(9)) {
            if let Some(p) = prev.replace(a) {
                self.advance(p, a);
            }
            if let Ok(y) = <&mut [f64; 9]>::try_from(y) {
                self.emit9(y);
            }
        }
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    fn run9_fma(&mut self, prev: &mut Option<f64>, input: &[f64], out: &mut [f64]) {
        use std::arch::x86_64::*;
        // SAFETY (every load and store below): pointers into arrays of
        // four f64, or into a row of nine at offsets 0, 4 and 5..9.
        let zero = _mm256_setzero_pd();
        let mut phi = [[zero; 2]; 8];
        let mut c = [zero; 8];
        let (mut g0, mut g1, mut force, mut q) = ([zero; 2], [zero; 2], [zero; 2], [zero; 2]);
        unsafe {
            for j in 0..8 {
                for h in 0..2 {
                    phi[j][h] = _mm256_loadu_pd(self.phi[j][h].as_ptr());
                }
                c[j] = _mm256_loadu_pd(self.acc[j].as_ptr());
            }
            for h in 0..2 {
                g0[h] = _mm256_loadu_pd(self.g0[h].as_ptr());
                g1[h] = _mm256_loadu_pd(self.g1[h].as_ptr());
                force[h] = _mm256_loadu_pd(self.force[h].as_ptr());
                q[h] = _mm256_loadu_pd(self.q[h].as_ptr());
            }
        }
        let mut last = *prev;
        for (&a, y) in input.iter().zip(out.chunks_exact_mut(9)) {
            let qs = [
                _mm256_permute4x64_pd::<0x00>(q[0]),
                _mm256_permute4x64_pd::<0x55>(q[0]),
                _mm256_permute4x64_pd::<0xaa>(q[0]),
                _mm256_permute4x64_pd::<0xff>(q[0]),
                _mm256_permute4x64_pd::<0x00>(q[1]),
                _mm256_permute4x64_pd::<0x55>(q[1]),
                _mm256_permute4x64_pd::<0xaa>(q[1]),
                _mm256_permute4x64_pd::<0xff>(q[1]),
            ];
            if let Some(p) = last {
                let (a0, a1) = (_mm256_set1_pd(p), _mm256_set1_pd(a));
                let mut next = [zero; 2];
                for h in 0..2 {
                    let g = _mm256_fmadd_pd(g1[h], a1, _mm256_fmadd_pd(g0[h], a0, zero));
                    let p0 =
                        _mm256_fmadd_pd(phi[4][h], qs[4], _mm256_fmadd_pd(phi[0][h], qs[0], g));
                    let p1 =
                        _mm256_fmadd_pd(phi[5][h], qs[5], _mm256_fmadd_pd(phi[1][h], qs[1], zero));
                    let p2 =
                        _mm256_fmadd_pd(phi[6][h], qs[6], _mm256_fmadd_pd(phi[2][h], qs[2], zero));
                    let p3 =
                        _mm256_fmadd_pd(phi[7][h], qs[7], _mm256_fmadd_pd(phi[3][h], qs[3], zero));
                    next[h] = _mm256_add_pd(_mm256_add_pd(p0, p1), _mm256_add_pd(p2, p3));
                }
                q = next;
            }
            last = Some(a);
            let qs = [
                _mm256_permute4x64_pd::<0x00>(q[0]),
                _mm256_permute4x64_pd::<0x55>(q[0]),
                _mm256_permute4x64_pd::<0xaa>(q[0]),
                _mm256_permute4x64_pd::<0xff>(q[0]),
                _mm256_permute4x64_pd::<0x00>(q[1]),
                _mm256_permute4x64_pd::<0x55>(q[1]),
                _mm256_permute4x64_pd::<0xaa>(q[1]),
                _mm256_permute4x64_pd::<0xff>(q[1]),
            ];
            let mut ra = _mm256_fmadd_pd(c[0], qs[0], zero);
            let mut rb = _mm256_fmadd_pd(c[1], qs[1], zero);
            for j in (2..8).step_by(2) {
                ra = _mm256_fmadd_pd(c[j], qs[j], ra);
                rb = _mm256_fmadd_pd(c[j + 1], qs[j + 1], rb);
            }
            let acc = _mm256_add_pd(ra, rb);
            let f = _mm256_fmadd_pd(force[1], q[1], _mm256_fmadd_pd(force[0], q[0], zero));
            let (lo, hi) = (_mm256_castpd256_pd128(f), _mm256_extractf128_pd::<1>(f));
            // [f0 + f1, f2 + f3], then their sum.
            let pair = _mm_add_pd(_mm_unpacklo_pd(lo, hi), _mm_unpackhi_pd(lo, hi));
            let fsum = _mm_add_sd(pair, _mm_unpackhi_pd(pair, pair));
            // [z1, z2, z3, 0]: each link's lower end.
            let lower =
                _mm256_blend_pd::<0b1000>(_mm256_permute4x64_pd::<0b00_11_10_01>(q[0]), zero);
            let defl = _mm256_sub_pd(q[0], lower);
            let yp = y.as_mut_ptr();
            unsafe {
                _mm256_storeu_pd(yp, acc);
                _mm_store_sd(yp.add(4), fsum);
                _mm256_storeu_pd(yp.add(5), defl);
            }
        }
        *prev = last;
        unsafe {
            _mm256_storeu_pd(self.q[0].as_mut_ptr(), q[0]);
            _mm256_storeu_pd(self.q[1].as_mut_ptr(), q[1]);
        }
    }

    /// The acceleration rows (padded to four) and the seat force.
    #[inline(always)]
    fn rows(&self) -> (V4, f64) {
        let q = self.flat();
        let c = &self.acc;
        let a = fma4(
            fma4(fma4(fma4(ZERO, c[0], q[0]), c[2], q[2]), c[4], q[4]),
            c[6],
            q[6],
        );
        let b = fma4(
            fma4(fma4(fma4(ZERO, c[1], q[1]), c[3], q[3]), c[5], q[5]),
            c[7],
            q[7],
        );
        let f = fmav(
            fmav(ZERO, self.force[0], self.q[0]),
            self.force[1],
            self.q[1],
        );
        (add4(a, b), (f[0] + f[1]) + (f[2] + f[3]))
    }

    /// [`Small::emit`] for the 4-segment chain (links 0–1, 1–2, 2–3,
    /// 3–seat): the same numbers, the deflections as one vector subtract.
    #[inline(always)]
    pub(super) fn emit9(&self, y: &mut [f64; 9]) {
        let (acc, force) = self.rows();
        let z = self.q[0];
        let d = [z[0] - z[1], z[1] - z[2], z[2] - z[3], z[3] - 0.0];
        y[..4].copy_from_slice(&acc);
        y[4] = force;
        y[5..].copy_from_slice(&d);
    }

    #[inline(always)]
    pub(super) fn emit(&self, _links: &[(usize, Option<usize>)], y: &mut [f64]) {
        let (acc, force) = self.rows();
        let q = self.q[0];
        let z = [q[0], q[1], q[2], q[3], 0.0];
        let n = self.n;
        for (yv, a) in y.iter_mut().zip(&acc[..n]) {
            *yv = *a;
        }
        if let Some(yv) = y.get_mut(n) {
            *yv = force;
        }
        for (yv, &(u, l)) in y.iter_mut().skip(n + 1).zip(&self.links) {
            *yv = z[u] - z[l];
        }
    }
}

/// Fixed-size kernel: N segments, S = 2N states, R = N + 1 output rows.
#[derive(Debug, Clone)]
pub(super) struct Fixed<const N: usize, const S: usize, const R: usize> {
    /// Columns of Φ and of the output rows, so a product is S scaled adds.
    phi: [[f64; S]; S],
    g0: [f64; S],
    g1: [f64; S],
    out: [[f64; R]; S],
    pub(super) q: [f64; S],
}

impl<const N: usize, const S: usize, const R: usize> Fixed<N, S, R> {
    pub(super) fn new(d: &Discrete) -> Self {
        Fixed {
            phi: std::array::from_fn(|j| std::array::from_fn(|i| d.phi[(i, j)])),
            g0: std::array::from_fn(|i| d.g0[i]),
            g1: std::array::from_fn(|i| d.g1[i]),
            out: std::array::from_fn(|j| std::array::from_fn(|r| d.out[(r, j)])),
            q: [0.0; S],
        }
    }

    /// q ← Φ q + Γ0 a0 + Γ1 a1. The sum over Φ's columns runs in four
    /// independent partial sums: the state is a recurrence, so the length of
    /// this add chain, not the number of multiplies, sets the time per sample.
    #[inline(always)]
    pub(super) fn advance(&mut self, a0: f64, a1: f64) {
        let mut part = [[0.0; S]; 4];
        for j in 0..S {
            let qj = self.q[j];
            for (nx, p) in part[j % 4].iter_mut().zip(&self.phi[j]) {
                *nx += p * qj;
            }
        }
        self.q = std::array::from_fn(|i| {
            (self.g0[i] * a0 + self.g1[i] * a1)
                + ((part[0][i] + part[1][i]) + (part[2][i] + part[3][i]))
        });
    }

    pub(super) fn reset(&mut self) {
        self.q = [0.0; S];
    }

    #[inline(always)]
    pub(super) fn emit(&self, links: &[(usize, Option<usize>)], y: &mut [f64]) {
        let mut r = [0.0; R];
        for j in 0..S {
            let qj = self.q[j];
            for (rv, o) in r.iter_mut().zip(&self.out[j]) {
                *rv += o * qj;
            }
        }
        for (yv, rv) in y.iter_mut().zip(r) {
            *yv = rv;
        }
        for (yv, &(u, l)) in y.iter_mut().skip(R).zip(links) {
            let lower = l.map_or(0.0, |l| self.q.get(l).copied().unwrap_or(0.0));
            *yv = self.q.get(u).copied().unwrap_or(0.0) - lower;
        }
    }

    #[inline(always)]
    pub(super) fn run(
        &mut self,
        prev: &mut Option<f64>,
        links: &[(usize, Option<usize>)],
        input: &[f64],
        out: &mut [f64],
        width: usize,
    ) {
        for (&a, y) in input.iter().zip(out.chunks_exact_mut(width)) {
            if let Some(p) = *prev {
                self.advance(p, a);
            }
            *prev = Some(a);
            self.emit(links, y);
        }
    }
}

/// The dense kernel for any n: Φ and the output rows stored by column, so
/// both products are contiguous scaled adds.
#[derive(Debug, Clone)]
pub(super) struct Dense {
    n: usize,
    phi: Vec<f64>,
    out: Vec<f64>,
    g0: Vec<f64>,
    g1: Vec<f64>,
    links: Vec<(usize, Option<usize>)>,
    pub(super) q: Vec<f64>,
    next: Vec<f64>,
    rows: Vec<f64>,
}

impl Dense {
    pub(super) fn new(d: &Discrete) -> Dense {
        let s = 2 * d.n;
        Dense {
            n: d.n,
            phi: d.phi.as_slice().to_vec(),
            out: d.out.as_slice().to_vec(),
            g0: d.g0.as_slice().to_vec(),
            g1: d.g1.as_slice().to_vec(),
            links: d.links.clone(),
            q: vec![0.0; s],
            next: vec![0.0; s],
            rows: vec![0.0; d.n + 1],
        }
    }

    pub(super) fn advance(&mut self, a0: f64, a1: f64) {
        let s = self.q.len();
        for ((nx, g0), g1) in self.next.iter_mut().zip(&self.g0).zip(&self.g1) {
            *nx = g0 * a0 + g1 * a1;
        }
        for (col, &qj) in self.phi.chunks_exact(s).zip(&self.q) {
            for (nx, p) in self.next.iter_mut().zip(col) {
                *nx += p * qj;
            }
        }
        std::mem::swap(&mut self.q, &mut self.next);
    }

    pub(super) fn emit(&mut self, y: &mut [f64]) {
        let rows = self.n + 1;
        self.rows.fill(0.0);
        for (col, &qj) in self.out.chunks_exact(rows).zip(&self.q) {
            for (r, o) in self.rows.iter_mut().zip(col) {
                *r += o * qj;
            }
        }
        for (yv, r) in y.iter_mut().zip(&self.rows) {
            *yv = *r;
        }
        for (yv, &(u, l)) in y.iter_mut().skip(rows).zip(&self.links) {
            let z = |i: usize| self.q.get(i).copied().unwrap_or(0.0);
            *yv = z(u) - l.map_or(0.0, z);
        }
    }
}

simd_fn! {
    /// [`Small::run`] for the 4-segment chain: the AVX2 clone runs the
    /// intrinsics kernel, the baseline clone the plain loop (same bits).
    fn run9(k: &mut Small, prev: &mut Option<f64>, input: &[f64], out: &mut [f64]) {
        multiversion::target::match_target! {
            "x86_64+avx2+fma" => k.run9_fma(prev, input, out),
            _ => k.run9_plain(prev, input, out),
        }
    }
}
