//! Elimination from the leaves for a body whose links form a tree over
//! segments + seat: O(n) per frequency, no size cut-off.
//!
//! With Q(s) = K + sC + s²M (s = jω gives A(ω)), take a segment p, its link
//! z_p = k_p + s·c_p to its parent, and T_p = s²m_p + Σ_children z_c·T_c/(z_c + T_c),
//! the force needed to move p with its subtree hanging off it. Then
//! X_p / X_parent = z_p / (z_p + T_p) and the seat force is Σ over the seat's
//! children of z·T/(z + T). Every step is a product or a quotient of physical
//! impedances, so nothing cancels and nothing grows with the chain's length
//! (shooting from the head down overflows past a few hundred segments).
//! z_p + T_p vanishes only where the subtree of p, clamped at its parent,
//! has an undamped mode; then the caller falls back to a pivoting solver.

use crate::freq::topology::Graph;
use num_complex::Complex64;
use std::collections::VecDeque;

/// Parent marker for a segment linked to the seat.
const SEAT: u32 = u32::MAX;

/// A tree of segments in elimination order (children before parents).
#[derive(Debug, Clone)]
pub struct Tree {
    n: usize,
    /// Segment at each position.
    seg: Vec<usize>,
    /// Position of each position's parent, or `SEAT`.
    parent: Vec<u32>,
    m: Vec<f64>,
    /// Link to the parent.
    k: Vec<f64>,
    c: Vec<f64>,
    /// Positions from the head up to the segment on the seat.
    head_path: Vec<u32>,
}

/// Q(s) eliminated from the leaves: pivots d_p = z_p + T_p and links z_p.
#[derive(Debug, Clone)]
pub struct TreeFactor {
    d: Vec<Complex64>,
    z: Vec<Complex64>,
}

impl Tree {
    /// The elimination order of a graph that is a tree; None otherwise.
    pub fn of(graph: &Graph, masses: &[f64], head: usize) -> Option<Tree> {
        let n = graph.n;
        if !graph.is_tree() || masses.len() != n || head >= n {
            return None;
        }
        let adj = graph.adjacency(true);
        // Link values by (child, parent) once the BFS fixes directions.
        let mut link_of = std::collections::HashMap::with_capacity(graph.edges.len());
        for e in &graph.edges {
            let b = e.b.unwrap_or(n);
            link_of.insert((e.a.min(b), e.a.max(b)), (e.k, e.c));
        }
        // BFS from the seat: every node appears after its parent.
        let mut bfs = Vec::with_capacity(n);
        let mut up = vec![usize::MAX; n + 1];
        let mut seen = vec![false; n + 1];
        seen[n] = true;
        let mut queue = VecDeque::from([n]);
        while let Some(u) = queue.pop_front() {
            for &v in &adj[u] {
                if !seen[v] {
                    seen[v] = true;
                    up[v] = u;
                    bfs.push(v);
                    queue.push_back(v);
                }
            }
        }
        if bfs.len() != n {
            return None;
        }
        let seg: Vec<usize> = bfs.into_iter().rev().collect();
        let mut pos = vec![0u32; n];
        for (p, &s) in seg.iter().enumerate() {
            pos[s] = p as u32;
        }
        let mut tree = Tree {
            n,
            parent: Vec::with_capacity(n),
            m: Vec::with_capacity(n),
            k: Vec::with_capacity(n),
            c: Vec::with_capacity(n),
            head_path: Vec::new(),
            seg,
        };
        for &s in &tree.seg {
            let p = up[s];
            let (k, c) = *link_of.get(&(s.min(p), s.max(p)))?;
            tree.parent.push(if p == n { SEAT } else { pos[p] });
            tree.m.push(masses[s]);
            tree.k.push(k);
            tree.c.push(c);
        }
        let mut p = pos[head];
        loop {
            tree.head_path.push(p);
            match tree.parent[p as usize] {
                SEAT => break,
                q => p = q,
            }
        }
        Some(tree)
    }

    /// (STHT, APMS) at angular frequency `w`; `t` and `r` are scratch of length n.
    /// Non-finite when a pivot vanished (see the module note).
    pub fn at(&self, w: f64, t: &mut [Complex64], r: &mut [Complex64]) -> (Complex64, Complex64) {
        let w2 = w * w;
        for (t, &m) in t.iter_mut().zip(&self.m) {
            *t = Complex64::new(-w2 * m, 0.0);
        }
        let mut force = Complex64::new(0.0, 0.0);
        for p in 0..self.n {
            let z = Complex64::new(self.k[p], w * self.c[p]);
            let tp = t[p];
            let ratio = z / (z + tp);
            r[p] = ratio;
            let series = tp * ratio;
            match self.parent[p] {
                SEAT => force += series,
                q => t[q as usize] += series,
            }
        }
        let head = self
            .head_path
            .iter()
            .fold(Complex64::new(1.0, 0.0), |h, &p| h * r[p as usize]);
        (head, force / (-w2))
    }

    /// Eliminates Q(s) = K + sC + s²M from the leaves.
    pub fn factor(&self, s: Complex64) -> TreeFactor {
        let s2 = s * s;
        let mut t: Vec<Complex64> = self.m.iter().map(|&m| s2 * m).collect();
        let mut d = Vec::with_capacity(self.n);
        let mut z = Vec::with_capacity(self.n);
        for p in 0..self.n {
            let zp = s * self.c[p] + self.k[p];
            let dp = zp + t[p];
            if let Some(q) = self.up(p) {
                let add = t[p] * zp / dp;
                t[q] += add;
            }
            d.push(dp);
            z.push(zp);
        }
        TreeFactor { d, z }
    }

    fn up(&self, p: usize) -> Option<usize> {
        match self.parent[p] {
            SEAT => None,
            q => Some(q as usize),
        }
    }

    /// Solves Q(s) X = b with the seat at `x0` (b and X indexed by segment).
    pub fn solve(&self, f: &TreeFactor, x0: Complex64, b: &[Complex64]) -> Vec<Complex64> {
        let n = self.n;
        let mut g: Vec<Complex64> = self.seg.iter().map(|&s| b[s]).collect();
        for p in 0..n {
            if let Some(q) = self.up(p) {
                let add = f.z[p] * g[p] / f.d[p];
                g[q] += add;
            }
        }
        let mut x = vec![Complex64::new(0.0, 0.0); n];
        for p in (0..n).rev() {
            let above = self.up(p).map_or(x0, |q| x[q]);
            x[p] = (g[p] + f.z[p] * above) / f.d[p];
        }
        let mut out = vec![Complex64::new(0.0, 0.0); n];
        for (p, &s) in self.seg.iter().enumerate() {
            out[s] = x[p];
        }
        out
    }
}
