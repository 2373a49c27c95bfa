//! Band LU with partial pivoting for bodies whose links form loops.
//!
//! The segments are renumbered by reverse Cuthill–McKee (`Graph::rcm`) so
//! that Q(s) = K + sC + s²M has half-bandwidth b; LU with row pivoting then
//! fills at most b more super-diagonals. Cost per frequency: about 2·n·b²
//! complex multiply-adds and 16·n·(4b + 1) bytes. A ring of any length has
//! b = 2; a dense graph has b ≈ n and costs what a dense LU costs, so such
//! models are refused above `MAX_WORK` (see `Solver::try_new`).

use crate::freq::topology::Graph;
use num_complex::Complex64;

/// Largest n·b² taken (≈ 0.2 s per frequency point on one core).
pub const MAX_WORK: f64 = 1e8;
/// Largest n·b taken (the factor's memory, 16·n·(4b + 1) bytes ≈ 256 MB).
pub const MAX_CELLS: f64 = 4e6;

/// Q(s) of a looped body in band order.
#[derive(Debug, Clone)]
pub struct Banded {
    n: usize,
    b: usize,
    /// Segment at each position and position of each segment.
    seg: Vec<usize>,
    pos: Vec<usize>,
    /// Per position: mass, diagonal of K and C, and the seat terms bk, bc.
    m: Vec<f64>,
    kd: Vec<f64>,
    cd: Vec<f64>,
    bk: Vec<f64>,
    bc: Vec<f64>,
    /// Off-diagonal couplings between positions i < j: (i, j, k, c).
    off: Vec<(usize, usize, f64, f64)>,
}

/// LU of a band matrix: row i holds columns i − b ..= i + 2b.
#[derive(Debug, Clone)]
pub struct BandFactor {
    n: usize,
    b: usize,
    a: Vec<Complex64>,
    l: Vec<Complex64>,
    piv: Vec<usize>,
}

impl Banded {
    pub fn of(graph: &Graph, masses: &[f64]) -> Banded {
        let n = graph.n;
        let (seg, b) = graph.rcm();
        let mut pos = vec![0; n];
        for (p, &s) in seg.iter().enumerate() {
            pos[s] = p;
        }
        let mut me = Banded {
            n,
            b,
            m: seg.iter().map(|&s| masses[s]).collect(),
            kd: vec![0.0; n],
            cd: vec![0.0; n],
            bk: vec![0.0; n],
            bc: vec![0.0; n],
            off: Vec::new(),
            seg,
            pos: pos.clone(),
        };
        for e in &graph.edges {
            let i = pos[e.a];
            me.kd[i] += e.k;
            me.cd[i] += e.c;
            match e.b {
                Some(other) => {
                    let j = pos[other];
                    me.kd[j] += e.k;
                    me.cd[j] += e.c;
                    me.off.push((i.min(j), i.max(j), e.k, e.c));
                }
                None => {
                    me.bk[i] += e.k;
                    me.bc[i] += e.c;
                }
            }
        }
        me
    }

    pub fn bandwidth(&self) -> usize {
        self.b
    }

    /// n·b², the multiply-adds of one factorisation up to a small factor.
    pub fn work(&self) -> f64 {
        self.n as f64 * (self.b as f64).powi(2)
    }

    /// True when the factor fits `MAX_WORK` and `MAX_CELLS`.
    pub fn affordable(&self) -> bool {
        self.work() <= MAX_WORK && (self.n as f64) * (self.b as f64) <= MAX_CELLS
    }

    /// LU of Q(s) with partial pivoting; None when it is exactly singular.
    pub fn factor(&self, s: Complex64) -> Option<BandFactor> {
        let (n, b) = (self.n, self.b);
        let w = 3 * b + 1;
        let mut f = BandFactor {
            n,
            b,
            a: vec![Complex64::new(0.0, 0.0); n * w],
            l: vec![Complex64::new(0.0, 0.0); n * b],
            piv: vec![0; n],
        };
        let s2 = s * s;
        for i in 0..n {
            *f.at(i, i) = s2 * self.m[i] + s * self.cd[i] + self.kd[i];
        }
        for &(i, j, k, c) in &self.off {
            let q = -(s * c + k);
            *f.at(i, j) += q;
            *f.at(j, i) += q;
        }
        for i in 0..n {
            let last = (i + b).min(n - 1);
            let mut best = i;
            for r in i + 1..=last {
                if f.at(r, i).norm_sqr() > f.at(best, i).norm_sqr() {
                    best = r;
                }
            }
            f.piv[i] = best;
            let hi = (i + 2 * b).min(n - 1);
            if best != i {
                for j in i..=hi {
                    let tmp = *f.at(i, j);
                    *f.at(i, j) = *f.at(best, j);
                    *f.at(best, j) = tmp;
                }
            }
            let p = *f.at(i, i);
            if p.norm_sqr() == 0.0 || !p.is_finite() {
                return None;
            }
            for r in i + 1..=last {
                let lr = *f.at(r, i) / p;
                f.l[i * b.max(1) + (r - i - 1)] = lr;
                *f.at(r, i) = Complex64::new(0.0, 0.0);
                if lr.norm_sqr() == 0.0 {
                    continue;
                }
                for j in i + 1..=hi {
                    let u = *f.at(i, j);
                    *f.at(r, j) -= lr * u;
                }
            }
        }
        Some(f)
    }

    /// Solves Q(s) X = b + x0·(bk + s·bc) (b and X indexed by segment).
    pub fn solve(
        &self,
        f: &BandFactor,
        s: Complex64,
        x0: Complex64,
        b: &[Complex64],
    ) -> Vec<Complex64> {
        let n = self.n;
        let mut y: Vec<Complex64> = (0..n)
            .map(|p| b[self.seg[p]] + x0 * (s * self.bc[p] + self.bk[p]))
            .collect();
        let x = f.solve(&mut y);
        (0..n).map(|s| x[self.pos[s]]).collect()
    }

    /// The seat-driven response X (X0 = 1) in segment order.
    pub fn transfer(&self, s: Complex64) -> Option<Vec<Complex64>> {
        let f = self.factor(s)?;
        let zero = vec![Complex64::new(0.0, 0.0); self.n];
        Some(self.solve(&f, s, Complex64::new(1.0, 0.0), &zero))
    }
}

impl BandFactor {
    #[inline]
    fn at(&mut self, i: usize, j: usize) -> &mut Complex64 {
        let w = 3 * self.b + 1;
        &mut self.a[i * w + (j + self.b - i)]
    }

    fn get(&self, i: usize, j: usize) -> Complex64 {
        let w = 3 * self.b + 1;
        self.a[i * w + (j + self.b - i)]
    }

    /// Forward with the recorded pivots, then back substitution; `y` is
    /// overwritten and the solution (in band order) returned.
    fn solve(&self, y: &mut [Complex64]) -> Vec<Complex64> {
        let (n, b) = (self.n, self.b);
        for i in 0..n {
            let p = self.piv[i];
            if p != i {
                y.swap(i, p);
            }
            let last = (i + b).min(n - 1);
            for r in i + 1..=last {
                let lr = self.l[i * b.max(1) + (r - i - 1)];
                let yi = y[i];
                y[r] -= lr * yi;
            }
        }
        let mut x = vec![Complex64::new(0.0, 0.0); n];
        for i in (0..n).rev() {
            let hi = (i + 2 * b).min(n - 1);
            let mut acc = y[i];
            for (j, xj) in x.iter().enumerate().take(hi + 1).skip(i + 1) {
                acc -= self.get(i, j) * xj;
            }
            x[i] = acc / self.get(i, i);
        }
        x
    }
}
