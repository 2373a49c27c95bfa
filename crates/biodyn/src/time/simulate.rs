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

    #[inline(always)]
    fn advance(&mut self, a0: f64, a1: f64) {
        let mut next: [f64; S] = std::array::from_fn(|i| self.g0[i] * a0 + self.g1[i] * a1);
        for j in 0..S {
            let qj = self.q[j];
            for (nx, p) in next.iter_mut().zip(&self.phi[j]) {
                *nx += p * qj;
            }
        }
        self.q = next;
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

/// The dense kernel for any n.
#[derive(Debug, Clone)]
struct Dense {
    d: Discrete,
    q: Vec<f64>,
    next: Vec<f64>,
}

impl Dense {
    fn advance(&mut self, a0: f64, a1: f64) {
        let s = self.q.len();
        for i in 0..s {
            self.next[i] = self.d.g0[i] * a0 + self.d.g1[i] * a1;
        }
        for j in 0..s {
            let qj = self.q[j];
            let col = self.d.phi.column(j);
            for (nx, p) in self.next.iter_mut().zip(col.iter()) {
                *nx += p * qj;
            }
        }
        std::mem::swap(&mut self.q, &mut self.next);
    }

    fn emit(&self, y: &mut [f64]) {
        let rows = self.d.n + 1;
        for (r, yv) in y.iter_mut().take(rows).enumerate() {
            *yv = self
                .d
                .out
                .row(r)
                .iter()
                .zip(&self.q)
                .map(|(o, q)| o * q)
                .sum();
        }
        for (yv, &(u, l)) in y.iter_mut().skip(rows).zip(&self.d.links) {
            *yv = self.q[u] - l.map_or(0.0, |l| self.q[l]);
        }
    }
}

#[derive(Debug, Clone)]
enum Kernel {
    F1(Fixed<1, 2, 2>),
    F2(Fixed<2, 4, 3>),
    F3(Fixed<3, 6, 4>),
    F4(Fixed<4, 8, 5>),
    F5(Fixed<5, 10, 6>),
    F6(Fixed<6, 12, 7>),
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
            Kernel::F1($f) => $body,
            Kernel::F2($f) => $body,
            Kernel::F3($f) => $body,
            Kernel::F4($f) => $body,
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
            1 => Kernel::F1(Fixed::new(&d)),
            2 => Kernel::F2(Fixed::new(&d)),
            3 => Kernel::F3(Fixed::new(&d)),
            4 => Kernel::F4(Fixed::new(&d)),
            5 => Kernel::F5(Fixed::new(&d)),
            6 => Kernel::F6(Fixed::new(&d)),
            _ => Kernel::Dense(Box::new(Dense {
                q: vec![0.0; 2 * d.n],
                next: vec![0.0; 2 * d.n],
                d: d.clone(),
            })),
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
        each_kernel!(&mut self.kernel, f => f.q.fill(0.0), d => d.q.fill(0.0));
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
