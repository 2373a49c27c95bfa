//! Frequency response of a body to harmonic seat motion (SPEC §2):
//! A(ω) H(ω) = bk + jω bc with A(ω) = K − ω²M + jωC, and from H the
//! seat-to-head transmissibility, apparent mass and driving-point impedance.

use crate::band::Band;
use crate::body::model::{Body, End};
use crate::freq::banded::{self, Banded};
use crate::freq::chain::{Chain, LANES, chain_sweep};
use crate::freq::topology::Graph;
use crate::freq::tree::Tree;
use crate::linalg::lu;
use crate::linalg::thomas::Factor;
use nalgebra::DMatrix;
use num_complex::Complex64;
use std::f64::consts::PI;

use super::function::Response;

/// Largest model the stack-allocated tridiagonal path takes; bigger chains
/// and all other trees are eliminated from the leaves (`freq::tree`).
const TRI_MAX: usize = 16;

/// Largest model `transfer_general` and the modes' dense fallback take:
/// a dense LU costs n³/3 complex operations and 16·n² bytes.
pub const DENSE_MAX: usize = 2000;

/// Points between two calls of a sweep's progress (a multiple of `LANES`).
pub const SWEEP_BLOCK: usize = 512 * LANES;

/// A model the solver will not take, and why.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SolveError {
    #[error(
        "the links of this {segments}-segment model form loops that a band of half-width {band} must hold after reordering: one frequency point would cost about {work:.1e} operations (limit {max:.0e}); use fewer segments or fewer cross links (links that form a tree are solved in time linear in the segment count, at any size)"
    )]
    LoopsTooWide {
        segments: usize,
        band: usize,
        work: f64,
        max: f64,
    },
}

/// How `at` solves: chosen once from the topology.
#[derive(Debug, Clone)]
enum Path {
    /// A plain chain of up to `CHAIN_MAX` segments: shot from the head down.
    Chain(Chain),
    /// Tridiagonal A(ω), up to `TRI_MAX` segments: Thomas' algorithm.
    Tri,
    /// Links form a tree over segments + seat: O(n) from the leaves, with a
    /// pivoting fallback for a pivot that vanishes exactly.
    Tree(Tree, Option<Banded>),
    /// Links form loops: band LU after reverse Cuthill–McKee, O(n·b²).
    Band(Banded),
    /// Loops too wide for the band solver: refused by `try_new`; `at`
    /// answers NaN rather than spend minutes or gigabytes.
    Refused(SolveError),
}

/// The assembled system of one body, ready to be solved at any frequency.
/// Build once per parameter change. Memory and time per frequency are O(n)
/// for any tree of links, O(n·b²) for loops (b: the band's half-width).
#[derive(Debug, Clone)]
pub struct Solver {
    n: usize,
    head: usize,
    m: Vec<f64>,
    /// Links as declared: (upper, lower, k, c), for the dense matrices.
    links: Vec<(usize, End, f64, f64)>,
    bk: Vec<f64>,
    bc: Vec<f64>,
    /// Seat links (segment, k, c) for the link form of the seat force.
    seat_links: Vec<(usize, f64, f64)>,
    /// A seat model's pan and the body's masses (the seat's parts zeroed):
    /// the functions are then referred to the pan (`Response::on_seat`).
    seat: Option<(usize, Vec<f64>)>,
    path: Path,
    /// Diagonals and first super-diagonals of K and C, for the Thomas path.
    kd: Vec<f64>,
    cd: Vec<f64>,
    ko: Vec<f64>,
    co: Vec<f64>,
}

impl Solver {
    /// Assembles the model. The body is assumed valid (see `Body::validate`).
    /// A looped model too wide for the band solver answers NaN: use
    /// `try_new` to be told instead.
    pub fn new(body: &Body) -> Solver {
        let n = body.n();
        let mut bk = vec![0.0; n];
        let mut bc = vec![0.0; n];
        let mut kd = vec![0.0; n];
        let mut cd = vec![0.0; n];
        let tri = body.is_tridiagonal() && n <= TRI_MAX;
        let mut ko = vec![0.0; if tri { n.saturating_sub(1) } else { 0 }];
        let mut co = ko.clone();
        let mut seat_links = Vec::new();
        for l in &body.links {
            let i = l.upper;
            kd[i] += l.k;
            cd[i] += l.c;
            match l.lower {
                End::Segment(j) => {
                    kd[j] += l.k;
                    cd[j] += l.c;
                    if tri {
                        ko[i.min(j)] -= l.k;
                        co[i.min(j)] -= l.c;
                    }
                }
                End::Seat => {
                    bk[i] += l.k;
                    bc[i] += l.c;
                    seat_links.push((i, l.k, l.c));
                }
            }
        }
        let m: Vec<f64> = body.segments.iter().map(|s| s.mass).collect();
        let seat = body.pan().map(|pan| {
            let on_body = body.segments.iter();
            (
                pan,
                on_body.map(|s| if s.seat { 0.0 } else { s.mass }).collect(),
            )
        });
        // The chain kernel gives the head and Σ m_i H_i only; a seat model
        // needs the pan's motion too, so it takes the paths that give all H.
        let chain = if seat.is_some() {
            None
        } else {
            Chain::of(body)
        };
        let path = match chain {
            Some(ch) => Path::Chain(ch),
            None if tri => Path::Tri,
            None => {
                let graph = Graph::of(body);
                match Tree::of(&graph, &m, body.head) {
                    Some(tree) => {
                        let band = Banded::of(&graph, &m);
                        let fallback = band.affordable().then_some(band);
                        Path::Tree(tree, fallback)
                    }
                    None => {
                        let band = Banded::of(&graph, &m);
                        if band.affordable() {
                            Path::Band(band)
                        } else {
                            Path::Refused(SolveError::LoopsTooWide {
                                segments: n,
                                band: band.bandwidth(),
                                work: band.work(),
                                max: banded::MAX_WORK,
                            })
                        }
                    }
                }
            }
        };
        Solver {
            n,
            path,
            kd,
            cd,
            ko,
            co,
            head: body.head,
            m,
            links: body
                .links
                .iter()
                .map(|l| (l.upper, l.lower, l.k, l.c))
                .collect(),
            bk,
            bc,
            seat_links,
            seat,
        }
    }

    /// As `new`, but refuses a looped model the band solver cannot take in
    /// bounded time and memory (see `freq::banded`).
    pub fn try_new(body: &Body) -> Result<Solver, SolveError> {
        let s = Solver::new(body);
        match &s.path {
            Path::Refused(e) => Err(e.clone()),
            _ => Ok(s),
        }
    }

    pub fn n(&self) -> usize {
        self.n
    }

    /// True when the model has a seat: the functions are then at the pan.
    pub fn has_seat(&self) -> bool {
        self.seat.is_some()
    }

    /// Which solver `at` uses, for reports and benches: "chain", "tridiagonal",
    /// "tree", "band" or "refused".
    pub fn method(&self) -> &'static str {
        match self.path {
            Path::Chain(_) => "chain",
            Path::Tri => "tridiagonal",
            Path::Tree(..) => "tree",
            Path::Band(_) => "band",
            Path::Refused(_) => "refused",
        }
    }

    /// True when no link has damping: every resonance is then unbounded.
    pub fn undamped(&self) -> bool {
        self.links.iter().all(|l| l.3 == 0.0)
    }

    /// Segment masses in kg.
    pub fn masses(&self) -> &[f64] {
        &self.m
    }

    pub fn mass_matrix(&self) -> DMatrix<f64> {
        DMatrix::from_diagonal(&nalgebra::DVector::from_column_slice(&self.m))
    }

    /// Dense K, built on demand (16·n² bytes: meant for small models and checks).
    pub fn stiffness_matrix(&self) -> DMatrix<f64> {
        self.dense(|l| l.2)
    }

    /// Dense C, built on demand.
    pub fn damping_matrix(&self) -> DMatrix<f64> {
        self.dense(|l| l.3)
    }

    fn dense(&self, value: impl Fn(&(usize, End, f64, f64)) -> f64) -> DMatrix<f64> {
        let n = self.n;
        let mut a = DMatrix::zeros(n, n);
        for l in &self.links {
            let (i, v) = (l.0, value(l));
            a[(i, i)] += v;
            if let End::Segment(j) = l.1 {
                a[(j, j)] += v;
                a[(i, j)] -= v;
                a[(j, i)] -= v;
            }
        }
        a
    }

    /// The functions at `f_hz`.
    pub fn at(&self, f_hz: f64) -> Response {
        let w = 2.0 * PI * f_hz;
        if let Some((pan, body)) = &self.seat {
            let h = self.transfer(f_hz);
            return Response::on_seat(f_hz, w, h[self.head], h[*pan], weighted_sum(body, &h));
        }
        match &self.path {
            Path::Chain(ch) => {
                let (stht, apms) = ch.at(w);
                self.assemble(f_hz, w, stht, apms)
            }
            Path::Tri => {
                let mut h = [Complex64::new(0.0, 0.0); TRI_MAX];
                let h = &mut h[..self.n];
                self.solve_tri(w, h);
                self.assemble(f_hz, w, h[self.head], weighted_sum(&self.m, h))
            }
            Path::Tree(tree, _) => {
                let mut t = vec![Complex64::new(0.0, 0.0); 2 * self.n];
                let (t, r) = t.split_at_mut(self.n);
                self.tree_at(tree, f_hz, w, t, r)
            }
            Path::Band(_) | Path::Refused(_) => {
                let h = self.transfer(f_hz);
                self.assemble(f_hz, w, h[self.head], weighted_sum(&self.m, &h))
            }
        }
    }

    fn tree_at(
        &self,
        tree: &Tree,
        f_hz: f64,
        w: f64,
        t: &mut [Complex64],
        r: &mut [Complex64],
    ) -> Response {
        let (stht, apms) = tree.at(w, t, r);
        if stht.is_finite() && apms.is_finite() {
            return self.assemble(f_hz, w, stht, apms);
        }
        // A clamped subtree resonates exactly here: pivot instead.
        let h = self.transfer(f_hz);
        self.assemble(f_hz, w, h[self.head], weighted_sum(&self.m, &h))
    }

    fn assemble(&self, f_hz: f64, w: f64, stht: Complex64, apms: Complex64) -> Response {
        Response::of(f_hz, w, stht, apms)
    }

    /// The band's grid, one `Response` per frequency.
    pub fn sweep(&self, band: &Band) -> Vec<Response> {
        self.sweep_by(band.len(), |i| band.freq(i))
    }

    /// [`Solver::sweep`], calling `progress(done, total)` before the first
    /// point and after each block of [`SWEEP_BLOCK`] points. The blocks are
    /// whole multiples of the chain's lanes, so every point is solved by the
    /// same path as in one sweep: the same bits.
    pub fn sweep_with(&self, band: &Band, progress: &mut dyn FnMut(usize, usize)) -> Vec<Response> {
        let len = band.len();
        let mut out = Vec::with_capacity(len);
        progress(0, len);
        while out.len() < len {
            let start = out.len();
            let n = SWEEP_BLOCK.min(len - start);
            out.extend(self.sweep_by(n, |i| band.freq(start + i)));
            progress(out.len(), len);
        }
        out
    }

    /// One `Response` per given frequency. A chain is solved `LANES`
    /// frequencies at a time in structure-of-arrays form, which lets the
    /// compiler use SIMD and the CPU overlap the divisions.
    pub fn sweep_freqs(&self, freqs: &[f64]) -> Vec<Response> {
        self.sweep_by(freqs.len(), |i| freqs[i])
    }

    fn sweep_by(&self, len: usize, freq: impl Fn(usize) -> f64) -> Vec<Response> {
        let mut out = Vec::with_capacity(len);
        let ch = match &self.path {
            _ if self.seat.is_some() => {
                out.extend((0..len).map(|i| self.at(freq(i))));
                return out;
            }
            Path::Chain(ch) => ch,
            Path::Tree(tree, _) => {
                let mut t = vec![Complex64::new(0.0, 0.0); 2 * self.n];
                let (t, r) = t.split_at_mut(self.n);
                out.extend((0..len).map(|i| {
                    let f = freq(i);
                    self.tree_at(tree, f, 2.0 * PI * f, t, r)
                }));
                return out;
            }
            _ => {
                out.extend((0..len).map(|i| self.at(freq(i))));
                return out;
            }
        };
        let whole = len - len % LANES;
        let blocks: Vec<[f64; LANES]> = (0..whole)
            .step_by(LANES)
            .map(|start| std::array::from_fn(|l| freq(start + l)))
            .collect();
        chain_sweep(ch, &blocks, &mut out);
        out.extend((whole..len).map(|i| self.at(freq(i))));
        out
    }

    /// H_i = X_i / X0 for every segment, through the fastest exact path.
    pub fn transfer(&self, f_hz: f64) -> Vec<Complex64> {
        let w = 2.0 * PI * f_hz;
        let s = Complex64::new(0.0, w);
        let one = Complex64::new(1.0, 0.0);
        let nan = || vec![Complex64::new(f64::NAN, f64::NAN); self.n];
        match &self.path {
            Path::Chain(_) | Path::Tri => {
                let mut h = vec![Complex64::new(0.0, 0.0); self.n];
                self.solve_tri(w, &mut h);
                h
            }
            Path::Tree(tree, fallback) => {
                let zero = vec![Complex64::new(0.0, 0.0); self.n];
                let h = tree.solve(&tree.factor(s), one, &zero);
                if h.iter().all(|z| z.is_finite()) {
                    return h;
                }
                match fallback {
                    Some(band) => band.transfer(s).unwrap_or_else(nan),
                    None if self.n <= DENSE_MAX => self.transfer_general(f_hz),
                    None => nan(),
                }
            }
            Path::Band(band) => band.transfer(s).unwrap_or_else(nan),
            Path::Refused(_) => nan(),
        }
    }

    /// H through a dense complex LU with partial pivoting: valid for any
    /// topology, and an independent check on the fast paths. O(n³) time and
    /// O(n²) memory: NaN above `DENSE_MAX` segments.
    pub fn transfer_general(&self, f_hz: f64) -> Vec<Complex64> {
        let w = 2.0 * PI * f_hz;
        let n = self.n;
        if n > DENSE_MAX {
            return vec![Complex64::new(f64::NAN, f64::NAN); n];
        }
        let (k, c) = (self.stiffness_matrix(), self.damping_matrix());
        let mut a = vec![Complex64::new(0.0, 0.0); n * n];
        for i in 0..n {
            for j in 0..n {
                a[i * n + j] = Complex64::new(k[(i, j)], w * c[(i, j)]);
            }
            a[i * n + i].re -= w * w * self.m[i];
        }
        let mut perm = vec![0; n];
        let mut x: Vec<Complex64> = (0..n)
            .map(|i| Complex64::new(self.bk[i], w * self.bc[i]))
            .collect();
        if !lu::lu(&mut a, &mut perm, n) {
            return vec![Complex64::new(f64::NAN, f64::NAN); n];
        }
        lu::solve(&a, &perm, n, &mut x);
        x
    }

    /// Energy dissipated per radian over the energy the motion at `f_hz`
    /// holds (Σ ω c |ΔH|² over Σ k |ΔH|² + ω² Σ m |H|²): about 2ζ at a
    /// resonance of damping ratio ζ, near 0 where the motion works no damper.
    pub fn loss_factor(&self, f_hz: f64) -> f64 {
        let w = 2.0 * PI * f_hz;
        let h = self.transfer(f_hz);
        let one = Complex64::new(1.0, 0.0);
        let (mut lost, mut held) = (0.0, 0.0);
        for &(i, lower, k, c) in &self.links {
            let other = match lower {
                End::Segment(j) => h[j],
                End::Seat => one,
            };
            let d = (h[i] - other).norm_sqr();
            lost += w * c * d;
            held += k * d;
        }
        held += w
            * w
            * self
                .m
                .iter()
                .zip(&h)
                .map(|(m, h)| m * h.norm_sqr())
                .sum::<f64>();
        lost / held
    }

    /// Seat force per unit seat displacement through the seat links:
    /// Σ (k + jωc)(1 − H_i).
    pub fn seat_force_links(&self, f_hz: f64, h: &[Complex64]) -> Complex64 {
        let w = 2.0 * PI * f_hz;
        self.seat_links
            .iter()
            .map(|&(i, k, c)| Complex64::new(k, w * c) * (Complex64::new(1.0, 0.0) - h[i]))
            .sum()
    }

    /// Seat force per unit seat displacement by Newton on the whole body:
    /// −ω² Σ m_i H_i.
    pub fn seat_force_newton(&self, f_hz: f64, h: &[Complex64]) -> Complex64 {
        let w = 2.0 * PI * f_hz;
        -(w * w) * weighted_sum(&self.m, h)
    }

    /// Thomas algorithm on the symmetric tridiagonal A(ω); O(n), no allocation.
    fn solve_tri(&self, w: f64, x: &mut [Complex64]) {
        let (n, w2) = (self.n, w * w);
        let zero = [Complex64::new(0.0, 0.0); TRI_MAX];
        let mut f = Factor::new(zero, zero, zero);
        f.factor(
            n,
            |i| Complex64::new(self.kd[i] - w2 * self.m[i], w * self.cd[i]),
            |i| Complex64::new(self.ko[i], w * self.co[i]),
            None,
        );
        for (i, x) in x.iter_mut().enumerate().take(n) {
            *x = Complex64::new(self.bk[i], w * self.bc[i]);
        }
        f.solve(n, x);
    }
}

fn weighted_sum(m: &[f64], h: &[Complex64]) -> Complex64 {
    m.iter().zip(h).map(|(&m, &h)| h * m).sum()
}

#[cfg(test)]
mod tests;
