//! The streaming simulator: one matrix–vector product per sample, the body's
//! state the only memory. Small models (n ≤ 6 segments) run on fixed-size
//! arrays the compiler unrolls and vectorises (AVX2 picked at run time);
//! larger ones on a dense path costing 2n·(2n + n + 1) multiply–adds a sample.

use super::discrete::{Discrete, SimError};
use crate::body::model::Body;

/// Every output of one sample, in the order of [`Simulator::step`]:
/// the absolute acceleration of each segment (m/s², top to bottom), the
/// dynamic seat force (N, up positive), then each link's deflection (m,
/// upper minus lower end, compression negative).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Layout {
    pub segments: usize,
    pub links: usize,
}

impl Layout {
    pub fn len(&self) -> usize {
        self.segments + 1 + self.links
    }
    pub fn is_empty(&self) -> bool {
        false
    }
    pub fn acc(&self, i: usize) -> usize {
        i
    }
    pub fn force(&self) -> usize {
        self.segments
    }
    pub fn deflection(&self, l: usize) -> usize {
        self.segments + 1 + l
    }
}

/// Four f64 lanes: one AVX2 register.
type V4 = [f64; 4];

#[inline(always)]
fn fma4(acc: V4, a: V4, x: f64) -> V4 {
    [
        acc[0] + a[0] * x,
        acc[1] + a[1] * x,
        acc[2] + a[2] * x,
        acc[3] + a[3] * x,
    ]
}

#[inline(always)]
fn add4(a: V4, b: V4) -> V4 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2], a[3] + b[3]]
}

/// The kernel for models of up to four segments, padded to four (idle
/// states stay zero): the state is two AVX2 registers, the accelerations
/// one, so a sample is some 40 vector operations.
#[derive(Debug, Clone)]
struct Small {
    n: usize,
    /// Column j of Φ, as two halves (z and z').
    phi: [[V4; 2]; 8],
    g0: [V4; 2],
    g1: [V4; 2],
    /// Column j of the acceleration rows.
    acc: [V4; 8],
    /// The seat-force row, as two halves.
    force: [V4; 2],
    q: [V4; 2],
    /// Link ends as indices into [z, 0]: index 4 is the seat (always zero).
    links: Vec<(usize, usize)>,
}

impl Small {
    fn new(d: &Discrete) -> Small {
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
        let links = d
            .links
            .iter()
            .map(|&(u, l)| (u.min(3), l.map_or(4, |l| l.min(3))))
            .collect();
        Small {
            n,
            phi,
            g0,
            g1,
            acc,
            force,
            q: [[0.0; 4]; 2],
            links,
        }
    }

    #[inline(always)]
    fn advance(&mut self, a0: f64, a1: f64) {
        let q = [
            self.q[0][0],
            self.q[0][1],
            self.q[0][2],
            self.q[0][3],
            self.q[1][0],
            self.q[1][1],
            self.q[1][2],
            self.q[1][3],
        ];
        // Four independent partial sums per half: the state is a recurrence,
        // so the add chain, not the multiply count, bounds the time a sample.
        let mut p = [[[0.0; 4]; 2]; 4];
        for j in 0..8 {
            for h in 0..2 {
                p[j % 4][h] = fma4(p[j % 4][h], self.phi[j][h], q[j]);
            }
        }
        for h in 0..2 {
            let g = fma4([0.0; 4], self.g0[h], a0);
            let g = fma4(g, self.g1[h], a1);
            self.q[h] = add4(add4(add4(p[0][h], p[1][h]), add4(p[2][h], p[3][h])), g);
        }
    }

    fn reset(&mut self) {
        self.q = [[0.0; 4]; 2];
    }

    #[inline(always)]
    fn run(
        &mut self,
        prev: &mut Option<f64>,
        _links: &[(usize, Option<usize>)],
        input: &[f64],
        out: &mut [f64],
        width: usize,
    ) {
        // The paper's shape (a 4-segment chain) gets rows of a fixed width,
        // so the compiler sees every store.
        if self.n == 4 && self.links.len() == 4 && width == 9 {
            for (&a, y) in input.iter().zip(out.chunks_exact_mut(9)) {
                if let Some(p) = prev.replace(a) {
                    self.advance(p, a);
                }
                if let Ok(y) = <&mut [f64; 9]>::try_from(y) {
                    self.emit9(y);
                }
            }
            return;
        }
        for (&a, y) in input.iter().zip(out.chunks_exact_mut(width)) {
            if let Some(p) = prev.replace(a) {
                self.advance(p, a);
            }
            self.emit(&[], y);
        }
    }

    /// [`Small::emit`] for four segments and four links.
    #[inline(always)]
    fn emit9(&self, y: &mut [f64; 9]) {
        let q = [
            self.q[0][0],
            self.q[0][1],
            self.q[0][2],
            self.q[0][3],
            self.q[1][0],
            self.q[1][1],
            self.q[1][2],
            self.q[1][3],
        ];
        let mut a = [0.0; 4];
        let mut b = [0.0; 4];
        let mut fa = [0.0; 4];
        for j in (0..8).step_by(2) {
            a = fma4(a, self.acc[j], q[j]);
            b = fma4(b, self.acc[j + 1], q[j + 1]);
        }
        for h in 0..2 {
            for l in 0..4 {
                fa[l] += self.force[h][l] * q[4 * h + l];
            }
        }
        let acc = add4(a, b);
        let z = [q[0], q[1], q[2], q[3], 0.0];
        y[..4].copy_from_slice(&acc);
        y[4] = (fa[0] + fa[1]) + (fa[2] + fa[3]);
        for (yv, &(u, l)) in y[5..].iter_mut().zip(&self.links) {
            *yv = z[u] - z[l];
        }
    }

    #[inline(always)]
    fn emit(&self, _links: &[(usize, Option<usize>)], y: &mut [f64]) {
        let q = [
            self.q[0][0],
            self.q[0][1],
            self.q[0][2],
            self.q[0][3],
            self.q[1][0],
            self.q[1][1],
            self.q[1][2],
            self.q[1][3],
        ];
        let mut a = [0.0; 4];
        let mut b = [0.0; 4];
        for j in (0..8).step_by(2) {
            a = fma4(a, self.acc[j], q[j]);
            b = fma4(b, self.acc[j + 1], q[j + 1]);
        }
        let acc = add4(a, b);
        let f = add4(
            [
                self.force[0][0] * q[0],
                self.force[0][1] * q[1],
                self.force[0][2] * q[2],
                self.force[0][3] * q[3],
            ],
            [
                self.force[1][0] * q[4],
                self.force[1][1] * q[5],
                self.force[1][2] * q[6],
                self.force[1][3] * q[7],
            ],
        );
        let force = (f[0] + f[1]) + (f[2] + f[3]);
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
struct Fixed<const N: usize, const S: usize, const R: usize> {
    /// Columns of Φ and of the output rows, so a product is S scaled adds.
    phi: [[f64; S]; S],
    g0: [f64; S],
    g1: [f64; S],
    out: [[f64; R]; S],
    q: [f64; S],
}

impl<const N: usize, const S: usize, const R: usize> Fixed<N, S, R> {
    fn new(d: &Discrete) -> Self {
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
    fn advance(&mut self, a0: f64, a1: f64) {
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

    fn reset(&mut self) {
        self.q = [0.0; S];
    }

    #[inline(always)]
    fn emit(&self, links: &[(usize, Option<usize>)], y: &mut [f64]) {
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
    fn run(
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
struct Dense {
    n: usize,
    phi: Vec<f64>,
    out: Vec<f64>,
    g0: Vec<f64>,
    g1: Vec<f64>,
    links: Vec<(usize, Option<usize>)>,
    q: Vec<f64>,
    next: Vec<f64>,
    rows: Vec<f64>,
}

impl Dense {
    fn new(d: &Discrete) -> Dense {
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

    fn advance(&mut self, a0: f64, a1: f64) {
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

    fn emit(&mut self, y: &mut [f64]) {
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

#[derive(Debug, Clone)]
enum Kernel {
    Small(Box<Small>),
    F5(Box<Fixed<5, 10, 6>>),
    F6(Box<Fixed<6, 12, 7>>),
    Dense(Box<Dense>),
}

/// Runs a body, at rest at the first sample, through a seat-acceleration
/// record one sample (or one block) at a time.
#[derive(Debug, Clone)]
pub struct Simulator {
    kernel: Kernel,
    links: Vec<(usize, Option<usize>)>,
    layout: Layout,
    head: usize,
    fs: f64,
    /// The previous input sample; None before the first.
    prev: Option<f64>,
}

macro_rules! each_kernel {
    ($k:expr, $f:ident => $body:expr, $d:ident => $dense:expr) => {
        match $k {
            Kernel::Small($f) => $body,
            Kernel::F5($f) => $body,
            Kernel::F6($f) => $body,
            Kernel::Dense($d) => $dense,
        }
    };
}

impl Simulator {
    /// Validates and discretises `body` at `fs` Hz.
    pub fn new(body: &Body, fs: f64) -> Result<Simulator, SimError> {
        let d = Discrete::new(body, fs)?;
        let kernel = match d.n {
            1..=4 => Kernel::Small(Box::new(Small::new(&d))),
            5 => Kernel::F5(Box::new(Fixed::new(&d))),
            6 => Kernel::F6(Box::new(Fixed::new(&d))),
            _ => Kernel::Dense(Box::new(Dense::new(&d))),
        };
        Ok(Simulator {
            kernel,
            links: d.links.clone(),
            layout: Layout {
                segments: d.n,
                links: d.links.len(),
            },
            head: body.head,
            fs,
            prev: None,
        })
    }

    pub fn layout(&self) -> Layout {
        self.layout
    }

    /// Index of the head segment (the model's STHT segment) in the outputs.
    pub fn head(&self) -> usize {
        self.head
    }

    pub fn fs(&self) -> f64 {
        self.fs
    }

    /// Back to rest, before the first sample.
    pub fn reset(&mut self) {
        self.prev = None;
        each_kernel!(&mut self.kernel, f => f.reset(), d => d.q.fill(0.0));
    }

    /// Takes the next seat-acceleration sample (m/s²) and writes that
    /// sample's outputs (see [`Layout`]) into `y`; a short `y` gets a prefix.
    pub fn step(&mut self, a: f64, y: &mut [f64]) {
        let prev = self.prev.replace(a);
        let links = &self.links;
        each_kernel!(&mut self.kernel, f => {
            if let Some(p) = prev { f.advance(p, a); }
            f.emit(links, y)
        }, d => {
            if let Some(p) = prev { d.advance(p, a); }
            d.emit(y)
        });
    }

    /// A block of samples: `out` gets one row of `layout().len()` values per
    /// input sample (as many as fit). Same results as [`Simulator::step`].
    pub fn run(&mut self, input: &[f64], out: &mut [f64]) {
        let width = self.layout.len();
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU has AVX2, checked just above.
            unsafe { self.run_avx2(input, out, width) };
            return;
        }
        self.run_plain(input, out, width);
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn run_avx2(&mut self, input: &[f64], out: &mut [f64], width: usize) {
        self.run_plain(input, out, width);
    }

    #[inline(always)]
    fn run_plain(&mut self, input: &[f64], out: &mut [f64], width: usize) {
        let (prev, links) = (&mut self.prev, &self.links);
        each_kernel!(&mut self.kernel, f => f.run(prev, links, input, out, width), d => {
            for (&a, y) in input.iter().zip(out.chunks_exact_mut(width)) {
                if let Some(p) = prev.replace(a) { d.advance(p, a); }
                d.emit(y);
            }
        });
    }
}
