//! The residuals of SPEC §8 and their exact Jacobian in ln p.
//!
//! Per frequency, A(ω) = K − ω²M + jωC is factored once (Thomas' algorithm
//! when every link joins neighbours or the seat, complex LU with partial
//! pivoting otherwise or when a Thomas pivot cancels) and three systems are
//! solved with it:
//! A H = b for the response, and the adjoints A g_h = e_head, A g_m = m.
//! A is complex symmetric, so for an output y = wᵀH the derivative
//! ∂y/∂p = wᵀ A⁻¹ (∂b/∂p − ∂A/∂p H) = g_wᵀ (∂b/∂p − ∂A/∂p H), and each
//! parameter then costs O(1): a link touches two rows, a mass one. DPMI =
//! jω·APMS, so ln DPMI has the derivatives of ln APMS. Nothing allocates
//! after construction.

use super::data::{Measured, Quantity};
use super::error::FitError;
use crate::body::model::{Body, Param};
use crate::freq::function::{Function, Response, Source};
use crate::linalg::lu::{lu, solve};
use crate::linalg::recip;
use crate::linalg::thomas::Factor;
use num_complex::Complex64;
use std::f64::consts::PI;

/// Largest model a fit takes: the dense solve is O(n³) per frequency.
pub const MAX_SEGMENTS: usize = 64;

const ZERO: Complex64 = Complex64::new(0.0, 0.0);

/// One measured value and how to compare the model with it.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Entry {
    /// Index of the data column it came from.
    pub column: usize,
    pub function: Function,
    pub quantity: Quantity,
    /// ln|H_data| or the data phase in radians.
    pub target: f64,
    /// 1/σ (σ from the `_sd` column, 1 without one).
    pub weight: f64,
}

/// The fit's model of the data: structure of the start body, the free
/// parameters, the measured values, and scratch space for the solves.
#[derive(Debug, Clone)]
pub(crate) struct Engine {
    n: usize,
    head: usize,
    mass0: Vec<f64>,
    share: Vec<f64>,
    k0: Vec<f64>,
    c0: Vec<f64>,
    /// Ends of each link; `None` is the seat.
    ends: Vec<(usize, Option<usize>)>,
    pub free: Vec<Param>,
    /// ω of each row that has values, and the range of its entries.
    rows: Vec<(f64, std::ops::Range<usize>)>,
    pub entries: Vec<Entry>,
    need_stht: bool,
    need_apms: bool,
    /// Every link joins i to i±1 or the seat: A is tridiagonal and the
    /// Thomas algorithm solves it in O(n).
    tri: bool,
    // Scratch.
    mass: Vec<f64>,
    k: Vec<f64>,
    c: Vec<f64>,
    km: Vec<f64>,
    cm: Vec<f64>,
    bk: Vec<f64>,
    bc: Vec<f64>,
    a: Vec<Complex64>,
    perm: Vec<usize>,
    h: Vec<Complex64>,
    gh: Vec<Complex64>,
    gm: Vec<Complex64>,
    ds: Vec<Complex64>,
    da: Vec<Complex64>,
    pvals: Vec<f64>,
    /// Thomas factors of the tridiagonal A(ω).
    thomas: Factor<Vec<Complex64>>,
}

impl Engine {
    pub fn new(body: &Body, data: &Measured, free: &[Param]) -> Result<Engine, FitError> {
        if body.has_seat() {
            return Err(FitError::SeatModel);
        }
        let n = body.n();
        if n > MAX_SEGMENTS {
            return Err(FitError::TooBig {
                n,
                max: MAX_SEGMENTS,
            });
        }
        let mut entries = Vec::new();
        let mut rows = Vec::new();
        for (r, &f) in data.f_hz.iter().enumerate() {
            let begin = entries.len();
            let w = 2.0 * PI * f;
            for (ci, col) in data.columns.iter().enumerate() {
                let Some(v) = col.values.get(r).copied().flatten() else {
                    continue;
                };
                let sd = col.sd.as_ref().and_then(|s| s.get(r).copied().flatten());
                let (target, sigma) = match col.channel.quantity {
                    // σ of ln|H| ≈ sd/|H| for a small sd.
                    Quantity::Mag => (v.ln(), sd.map_or(1.0, |s| s / v)),
                    Quantity::Phase => (v.to_radians(), sd.map_or(1.0, f64::to_radians)),
                };
                entries.push(Entry {
                    column: ci,
                    function: col.channel.function,
                    quantity: col.channel.quantity,
                    target,
                    weight: 1.0 / sigma,
                });
            }
            if entries.len() > begin {
                rows.push((w, begin..entries.len()));
            }
        }
        let need_stht = entries.iter().any(|e| e.function.source() == Source::Head);
        let need_apms = entries
            .iter()
            .any(|e| e.function.source() == Source::SeatForce);
        let p = free.len();
        let cz = vec![ZERO; n];
        Ok(Engine {
            n,
            head: body.head,
            mass0: body.segments.iter().map(|s| s.mass).collect(),
            share: body
                .segments
                .iter()
                .map(|s| s.share.unwrap_or(0.0))
                .collect(),
            k0: body.links.iter().map(|l| l.k).collect(),
            c0: body.links.iter().map(|l| l.c).collect(),
            ends: body
                .links
                .iter()
                .map(|l| (l.upper, l.lower.segment()))
                .collect(),
            free: free.to_vec(),
            rows,
            entries,
            need_stht,
            need_apms,
            tri: body.is_tridiagonal(),
            thomas: Factor::new(vec![ZERO; n], vec![ZERO; n], vec![ZERO; n]),
            mass: vec![0.0; n],
            k: vec![0.0; body.links.len()],
            c: vec![0.0; body.links.len()],
            km: vec![0.0; n * n],
            cm: vec![0.0; n * n],
            bk: vec![0.0; n],
            bc: vec![0.0; n],
            a: vec![ZERO; n * n],
            perm: vec![0; n],
            h: cz.clone(),
            gh: cz.clone(),
            gm: cz,
            ds: vec![ZERO; p],
            da: vec![ZERO; p],
            pvals: vec![0.0; p],
        })
    }

    /// Number of residuals.
    pub fn m(&self) -> usize {
        self.entries.len()
    }

    /// Number of free parameters.
    pub fn p(&self) -> usize {
        self.free.len()
    }

    /// Puts the parameters ln p = `theta` into the model and assembles K, C, b.
    fn load(&mut self, theta: &[f64]) {
        self.mass.copy_from_slice(&self.mass0);
        self.k.copy_from_slice(&self.k0);
        self.c.copy_from_slice(&self.c0);
        for (j, (&param, &t)) in self.free.iter().zip(theta).enumerate() {
            let v = t.exp();
            self.pvals[j] = v;
            match param {
                Param::BodyMass => {
                    for (m, s) in self.mass.iter_mut().zip(&self.share) {
                        *m = s * v;
                    }
                }
                Param::Mass(i) => self.mass[i] = v,
                Param::Stiffness(l) => self.k[l] = v,
                Param::Damping(l) => self.c[l] = v,
            }
        }
        let n = self.n;
        self.km.fill(0.0);
        self.cm.fill(0.0);
        self.bk.fill(0.0);
        self.bc.fill(0.0);
        for (l, &(u, lower)) in self.ends.iter().enumerate() {
            let (k, c) = (self.k[l], self.c[l]);
            self.km[u * n + u] += k;
            self.cm[u * n + u] += c;
            match lower {
                Some(v) => {
                    self.km[v * n + v] += k;
                    self.cm[v * n + v] += c;
                    self.km[u * n + v] -= k;
                    self.km[v * n + u] -= k;
                    self.cm[u * n + v] -= c;
                    self.cm[v * n + u] -= c;
                }
                None => {
                    self.bk[u] += k;
                    self.bc[u] += c;
                }
            }
        }
    }

    /// Fills the weighted residuals `r` (and, when given, the m×p Jacobian
    /// in ln p, column-major) at `theta`; returns Σr², or infinity when the
    /// model cannot be solved there.
    pub fn eval(&mut self, theta: &[f64], r: &mut [f64], mut jac: Option<&mut [f64]>) -> f64 {
        self.load(theta);
        let n = self.n;
        let p = self.free.len();
        let mut cost = 0.0;
        for ri in 0..self.rows.len() {
            let (w, range) = (self.rows[ri].0, self.rows[ri].1.clone());
            let w2 = w * w;
            let thomas = self.tri && self.thomas_factor(w);
            if !thomas {
                for i in 0..n {
                    for j in 0..n {
                        self.a[i * n + j] =
                            Complex64::new(self.km[i * n + j], w * self.cm[i * n + j]);
                    }
                    self.a[i * n + i].re -= w2 * self.mass[i];
                }
                if !lu(&mut self.a, &mut self.perm, n) {
                    return f64::INFINITY;
                }
            }
            for i in 0..n {
                self.h[i] = Complex64::new(self.bk[i], w * self.bc[i]);
            }
            self.solve_with(thomas, Which::H);
            let stht = self.h[self.head];
            let apms: Complex64 = self.h.iter().zip(&self.mass).map(|(h, m)| h * m).sum();
            let want_jac = jac.is_some();
            if want_jac {
                if self.need_stht {
                    self.gh.fill(ZERO);
                    self.gh[self.head] = Complex64::new(1.0, 0.0);
                    self.solve_with(thomas, Which::Gh);
                }
                if self.need_apms {
                    for i in 0..n {
                        self.gm[i] = Complex64::new(self.mass[i], 0.0);
                    }
                    self.solve_with(thomas, Which::Gm);
                }
                self.derivatives(w);
                // d ln y = dy / y: one reciprocal per function and row.
                let (is, ia) = (recip(stht), recip(apms));
                for j in 0..p {
                    self.ds[j] *= is;
                    self.da[j] *= ia;
                }
            }
            let at = Response::of(w / (2.0 * PI), w, stht, apms);
            for e in range {
                let en = self.entries[e];
                let y = at.get(en.function);
                let (res, dln) = match en.quantity {
                    Quantity::Mag => (0.5 * y.norm_sqr().ln() - en.target, 0),
                    Quantity::Phase => (wrap(y.im.atan2(y.re) - en.target), 1),
                };
                let res = res * en.weight;
                if !res.is_finite() {
                    return f64::INFINITY;
                }
                r[e] = res;
                cost += res * res;
                if let Some(jac) = jac.as_deref_mut() {
                    let d = match en.function.source() {
                        // Data columns name the body's functions only (a
                        // seat model is refused in `new`): Pan never occurs.
                        Source::Head | Source::Pan => &self.ds,
                        Source::SeatForce => &self.da,
                    };
                    let m = self.entries.len();
                    for (j, dl) in d.iter().enumerate() {
                        jac[j * m + e] = en.weight * if dln == 0 { dl.re } else { dl.im };
                    }
                }
            }
        }
        cost
    }

    /// Factors the tridiagonal A(ω) without pivoting; false (use the dense
    /// LU instead) when a pivot is lost to cancellation.
    fn thomas_factor(&mut self, w: f64) -> bool {
        let (n, w2) = (self.n, w * w);
        let (km, cm, mass) = (&self.km, &self.cm, &self.mass);
        self.thomas.factor(
            n,
            |i| Complex64::new(km[i * n + i] - w2 * mass[i], w * cm[i * n + i]),
            |i| Complex64::new(km[(i + 1) * n + i], w * cm[(i + 1) * n + i]),
            Some(1e-20),
        )
    }

    /// Solves A x = rhs in place for one of the three right-hand sides.
    #[inline]
    fn solve_with(&mut self, thomas: bool, which: Which) {
        let n = self.n;
        let x = match which {
            Which::H => &mut self.h,
            Which::Gh => &mut self.gh,
            Which::Gm => &mut self.gm,
        };
        if thomas {
            self.thomas.solve(n, x);
        } else {
            solve(&self.a, &self.perm, n, x);
        }
    }

    /// p·∂STHT/∂p and p·∂APMS/∂p for every free parameter at one frequency,
    /// from H and the adjoints.
    fn derivatives(&mut self, w: f64) {
        let w2 = w * w;
        let one = Complex64::new(1.0, 0.0);
        for (j, &param) in self.free.iter().enumerate() {
            let v = self.pvals[j];
            let (ds, da) = match param {
                Param::Mass(i) => (
                    self.gh[i] * self.h[i] * (w2 * v),
                    (self.gm[i] * w2 + one) * self.h[i] * v,
                ),
                Param::BodyMass => {
                    let mut ds = ZERO;
                    let mut da = ZERO;
                    for i in 0..self.n {
                        let m = self.mass[i];
                        ds += self.gh[i] * self.h[i] * (w2 * m);
                        da += (self.gm[i] * w2 + one) * self.h[i] * m;
                    }
                    (ds, da)
                }
                Param::Stiffness(l) | Param::Damping(l) => {
                    let (u, lower) = self.ends[l];
                    let (hv, ghv, gmv) = match lower {
                        Some(x) => (self.h[x], self.gh[x], self.gm[x]),
                        None => (one, ZERO, ZERO),
                    };
                    let delta = self.h[u] - hv;
                    let scale = if matches!(param, Param::Stiffness(_)) {
                        Complex64::new(-v, 0.0)
                    } else {
                        Complex64::new(0.0, -w * v)
                    };
                    (
                        (self.gh[u] - ghv) * delta * scale,
                        (self.gm[u] - gmv) * delta * scale,
                    )
                }
            };
            self.ds[j] = ds;
            self.da[j] = da;
        }
    }
}

/// The three right-hand sides solved per frequency.
#[derive(Clone, Copy)]
enum Which {
    H,
    Gh,
    Gm,
}

/// x wrapped into [−π, π].
pub(crate) fn wrap(x: f64) -> f64 {
    if (-PI..=PI).contains(&x) {
        x
    } else {
        x - 2.0 * PI * (x / (2.0 * PI)).round()
    }
}

#[cfg(test)]
mod tests;
