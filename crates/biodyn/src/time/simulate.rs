//! The streaming simulator: one matrix–vector product per sample, the body's
//! state the only memory. Models of up to six segments run on fixed-size
//! kernels the compiler unrolls and vectorises (AVX2 and FMA picked once
//! at run time, [`crate::simd`]; the FMA kernel's bits do not depend on it, see [`super::kernel`]),
//! larger ones on a dense path ([`super::kernel`]).

use super::discrete::{Discrete, SimError};
use super::kernel::{Dense, Fixed, Small};
use crate::body::model::Body;
use crate::simd::simd_fn;

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

/// The columns of a simulated record as `biodyn simulate` writes them:
/// time, seat and head acceleration, seat force, then every segment's
/// acceleration and every link's deflection, named after them.
/// With a seat model the input is the floor, and the force is the floor's
/// on the seat (Σ m_i x_i'' over seat and body): `floor_acc_m_s2` and
/// `floor_force_n`; the pan's acceleration is its segment's column.
pub fn record_columns(body: &Body) -> Vec<String> {
    let first = if body.has_seat() {
        ["t_s", "floor_acc_m_s2", "head_acc_m_s2", "floor_force_n"]
    } else {
        ["t_s", "seat_acc_m_s2", "head_acc_m_s2", "seat_force_n"]
    };
    let mut c: Vec<String> = first.map(String::from).to_vec();
    c.extend(body.segments.iter().map(|s| format!("acc_{}_m_s2", s.name)));
    c.extend(body.links.iter().map(|l| format!("defl_{}_m", l.name)));
    c
}

/// Samples a [`Simulator::stream`] runs at once.
const STREAM_BLOCK: usize = 4096;

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
        run_block(self, input, out, width);
    }

    /// Runs every sample of `samples` through the body in blocks and hands
    /// each to `each(k, seat, y)`: its index, the seat sample and its output
    /// row (see [`Layout`]). Stops at the first sample that is an error, or
    /// the first error `each` returns, and returns it after every sample
    /// before it was handed on; otherwise the number of samples.
    pub fn stream<E>(
        &mut self,
        samples: impl Iterator<Item = Result<f64, E>>,
        mut each: impl FnMut(u64, f64, &[f64]) -> Result<(), E>,
    ) -> Result<u64, E> {
        let width = self.layout.len();
        let mut block = Vec::with_capacity(STREAM_BLOCK);
        let mut out = vec![0.0; STREAM_BLOCK * width];
        let mut samples = samples;
        let mut k: u64 = 0;
        loop {
            block.clear();
            let mut failed = None;
            for s in samples.by_ref() {
                match s {
                    Ok(v) => block.push(v),
                    Err(e) => {
                        failed = Some(e);
                        break;
                    }
                }
                if block.len() == STREAM_BLOCK {
                    break;
                }
            }
            self.run(&block, &mut out);
            for (&seat, y) in block.iter().zip(out.chunks_exact(width)) {
                each(k, seat, y)?;
                k += 1;
            }
            if let Some(e) = failed {
                return Err(e);
            }
            if block.len() < STREAM_BLOCK {
                return Ok(k);
            }
        }
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

simd_fn! {
    /// [`Simulator::run`], compiled for the crate's SIMD targets.
    fn run_block(sim: &mut Simulator, input: &[f64], out: &mut [f64], width: usize) {
        sim.run_plain(input, out, width);
    }
}
