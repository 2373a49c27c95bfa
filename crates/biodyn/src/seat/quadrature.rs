//! The quadrature of ∫ G(f)·Φ(f) df for a floor PSD G and a smooth factor Φ
//! (|W_k|², |T|²·|W_k|², |X_rel/A_floor|²), as weights on a grid of nodes:
//! ∫ G Φ df ≈ Σ w_i Φ(f_i), so a design search evaluates Φ at the nodes only.
//!
//! The nodes are even in u = ln f, step h = [`H0`]/2^level, from the range's
//! ends exactly. Φ is interpolated by a quadratic in f through each pair of
//! steps (nodes 2p, 2p+1, 2p+2: a resonance of damping ratio ζ spans about
//! ζ in u, many steps). What G is between the nodes is then integrated
//! exactly:
//!
//! - a PSD file is linear in f between its own rows (0 outside them): on each
//!   piece between consecutive breakpoints (the rows and the pairs' ends),
//!   G·(the quadratic) is a cubic, which Simpson's rule integrates exactly.
//!   So a narrow peak between two nodes, or zero rows around one, counts in
//!   full (product integration: the rows never have to fall on nodes);
//! - a class's PSD is a smooth formula: Simpson's rule in u on G·Φ·f.
//!
//! Its error is that of the interpolated Φ, third order in h (fourth for a
//! class): halving h takes about 7/8 of the difference between the two
//! results away. [`super::figures`] compares each level with the one below
//! (its even nodes) and refines until they agree.

use super::psd::FloorPsd;

/// The coarsest grid step in u = ln f; the first result is at `H0/2`.
pub const H0: f64 = 0.02;

/// The finest level: h = 0.02/2^8 ≈ 7.8e-5 in ln f.
pub const MAX_LEVEL: usize = 8;

/// One level's nodes and weights, G taken relative to `scale`.
#[derive(Debug, Clone)]
pub struct Level {
    pub f: Vec<f64>,
    /// w_i with Σ w_i Φ(f_i) ≈ ∫ (G/scale) Φ df.
    pub w: Vec<f64>,
}

/// Intervals of level 0 over [lo, hi]: even, at most `H0` in u, at least 2.
pub fn base_intervals(lo: f64, hi: f64) -> usize {
    let span = (hi / lo).ln();
    (2 * (span / (2.0 * H0)).ceil() as usize).max(2)
}

/// The nodes of `level` over [lo, hi]: level 0's intervals × 2^level, even
/// in ln f, the ends exactly. Level k's nodes are level k+1's even ones, to
/// the bit (u0 + 2i·(s/2N) is u0 + i·(s/N)).
pub fn nodes(lo: f64, hi: f64, level: usize) -> Vec<f64> {
    let n = base_intervals(lo, hi) << level;
    let (u0, span) = (lo.ln(), (hi / lo).ln());
    let du = span / n as f64;
    (0..=n)
        .map(|i| match i {
            0 => lo,
            _ if i == n => hi,
            _ => (u0 + du * i as f64).exp(),
        })
        .collect()
}

/// The weights of `level` for `psd` over [lo, hi], G divided by `scale`.
pub fn level(psd: &FloorPsd, lo: f64, hi: f64, scale: f64, level: usize) -> Level {
    let f = nodes(lo, hi, level);
    let w = match psd {
        FloorPsd::Class(_) => simpson_in_u(psd, &f, scale),
        FloorPsd::Table { rows, .. } => product(rows, &f, scale),
    };
    Level { f, w }
}

/// Simpson's rule in u on G·Φ·f (the Jacobian of u = ln f).
fn simpson_in_u(psd: &FloorPsd, f: &[f64], scale: f64) -> Vec<f64> {
    let n = f.len() - 1;
    let du = (f[n] / f[0]).ln() / n as f64;
    f.iter()
        .enumerate()
        .map(|(i, &fi)| {
            let c = match i {
                0 => 1.0,
                _ if i == n => 1.0,
                _ if i % 2 == 1 => 4.0,
                _ => 2.0,
            };
            c * du / 3.0 * fi * psd.at(fi) / scale
        })
        .collect()
}

/// G linear between `rows` (0 outside), its value at `x` from the row
/// segment at or after `*at` (moved forward: the calls come in rising x).
fn g_at(rows: &[(f64, f64)], at: &mut usize, x: f64) -> f64 {
    while *at + 1 < rows.len() && rows[*at + 1].0 < x {
        *at += 1;
    }
    let (f0, g0) = rows[*at];
    match rows.get(*at + 1) {
        _ if x == f0 => g0,
        Some(&(f1, g1)) if x >= f0 && x <= f1 => g0 + (g1 - g0) * (x - f0) / (f1 - f0),
        _ => 0.0,
    }
}

/// Product integration: each pair's quadratic Φ against the rows' linear
/// G, piece by piece between the rows, Simpson's rule exact on the cubic.
fn product(rows: &[(f64, f64)], f: &[f64], scale: f64) -> Vec<f64> {
    let mut w = vec![0.0; f.len()];
    let mut at = 0;
    // Rows strictly inside the current pair, found by a moving index.
    let mut next_row = rows.partition_point(|r| r.0 <= f[0]);
    for p in 0..(f.len() - 1) / 2 {
        let (a, m, b) = (f[2 * p], f[2 * p + 1], f[2 * p + 2]);
        // The Lagrange basis on (a, m, b), in f.
        let basis = |x: f64| {
            [
                (x - m) * (x - b) / ((a - m) * (a - b)),
                (x - a) * (x - b) / ((m - a) * (m - b)),
                (x - a) * (x - m) / ((b - a) * (b - m)),
            ]
        };
        let mut x0 = a;
        let mut g0 = g_at(rows, &mut at, a) / scale;
        let mut l0 = basis(a);
        loop {
            let x1 = match rows.get(next_row) {
                Some(&(fr, _)) if fr < b => {
                    next_row += 1;
                    fr
                }
                _ => b,
            };
            if x1 > x0 {
                let xm = 0.5 * (x0 + x1);
                let gm = g_at(rows, &mut at, xm) / scale;
                let g1 = g_at(rows, &mut at, x1) / scale;
                let (lm, l1) = (basis(xm), basis(x1));
                let h6 = (x1 - x0) / 6.0;
                for q in 0..3 {
                    w[2 * p + q] += h6 * (g0 * l0[q] + 4.0 * gm * lm[q] + g1 * l1[q]);
                }
                (x0, g0, l0) = (x1, g1, l1);
            }
            if x1 >= b {
                break;
            }
        }
    }
    w
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table(rows: &[(f64, f64)]) -> FloorPsd {
        FloorPsd::Table {
            name: "t".into(),
            rows: rows.to_vec(),
        }
    }

    /// Level k's nodes are level k+1's even nodes, bit for bit, with the
    /// range's ends exact and the step at most H0/2^k in ln f.
    #[test]
    fn levels_nest_bit_for_bit() {
        let (lo, hi) = (0.1, 80.0);
        for k in 0..4 {
            let a = nodes(lo, hi, k);
            let b = nodes(lo, hi, k + 1);
            assert_eq!(b.len(), 2 * a.len() - 1);
            for (i, x) in a.iter().enumerate() {
                assert_eq!(x.to_bits(), b[2 * i].to_bits(), "level {k} node {i}");
            }
            assert_eq!((a[0], a[a.len() - 1]), (lo, hi));
            let step = (hi / lo).ln() / (a.len() - 1) as f64;
            assert!(step <= H0 / f64::from(1 << k) + 1e-15, "{step}");
        }
        assert_eq!(base_intervals(1.0, 1.0001), 2);
    }

    /// Product integration is exact where Φ is a quadratic in f on each
    /// pair: ∫ G·1 df and ∫ G·f² df of a narrow triangle between two
    /// nodes, and of rows that fall anywhere, to rounding.
    #[test]
    fn rows_between_nodes_are_integrated_exactly() {
        // A triangle of height 1 from 4.99 to 5.01 Hz, nowhere near a node.
        let t = table(&[
            (0.5, 0.0),
            (4.99, 0.0),
            (5.0, 1.0),
            (5.01, 0.0),
            (20.0, 0.0),
        ]);
        let l = level(&t, 0.5, 20.0, 1.0, 1);
        let area: f64 = l.w.iter().sum();
        assert!((area - 0.01).abs() < 1e-15, "{area}");
        let second: f64 = l.w.iter().zip(&l.f).map(|(w, f)| w * f * f).sum();
        // ∫ tri(f)·f² df = 0.01·(25 + 0.01²/6) exactly for a symmetric triangle.
        let want = 0.01 * (25.0 + 0.01f64.powi(2) / 6.0);
        assert!((second / want - 1.0).abs() < 1e-13, "{second} vs {want}");
        // A ramp over many nodes: ∫ f·f df from 1 to 10 = 333.
        let ramp = table(&[(1.0, 1.0), (10.0, 10.0)]);
        let l = level(&ramp, 1.0, 10.0, 1.0, 0);
        let s: f64 = l.w.iter().zip(&l.f).map(|(w, f)| w * f).sum();
        assert!((s - 333.0).abs() < 1e-10, "{s}");
    }

    /// G read between rows: linear, the rows' own values, 0 outside.
    #[test]
    fn g_between_rows() {
        let rows = [(1.0, 2.0), (3.0, 4.0), (4.0, 0.0)];
        let mut at = 0;
        let got: Vec<f64> = [0.5, 1.0, 2.0, 3.0, 3.5, 4.0, 5.0]
            .iter()
            .map(|&x| g_at(&rows, &mut at, x))
            .collect();
        assert_eq!(got, [0.0, 2.0, 3.0, 4.0, 2.0, 0.0, 0.0]);
    }
}
