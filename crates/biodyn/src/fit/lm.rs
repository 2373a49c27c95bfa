//! Levenberg–Marquardt with box bounds, by projection.
//!
//! Each iteration solves (JᵀJ + μ D²) δ = −Jᵀr with Moré's scaling D (the
//! running maximum of the column norms of J), holding at its bound every
//! parameter whose gradient pushes it outward, then projects θ + δ onto the
//! box. A step is kept when it lowers Σr²; μ follows Nielsen's rule (the
//! attempt and the rule are the shared driver's, [`crate::lm`]). The
//! Jacobian comes with every evaluation (it is cheap here), so a kept step
//! needs no second solve. All work arrays live in [`Workspace`]: nothing
//! allocates inside the loop.

use crate::lm::{Attempt, Model, Nielsen, Solve, attempt};

/// A least-squares problem: m residuals of p parameters.
pub trait Residuals {
    fn m(&self) -> usize;
    fn p(&self) -> usize;
    /// Fills r (and the column-major m×p Jacobian when given: column j,
    /// ∂r/∂θ_j, at `jac[j*m..(j+1)*m]`); returns Σr², or infinity where the
    /// model cannot be evaluated.
    fn eval(&mut self, theta: &[f64], r: &mut [f64], jac: Option<&mut [f64]>) -> f64;
}

/// Most iterations (tried steps) of one run.
pub const MAX_ITER: usize = 400;
/// A run stops when a step moves no parameter by more than this (in ln p).
pub const XTOL: f64 = 1e-13;
/// … or a kept step lowers Σr² by less than this fraction.
pub const FTOL: f64 = 1e-12;

/// How a run ended.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Outcome {
    pub cost: f64,
    pub iterations: usize,
}

/// Scratch space for runs on problems of one size.
#[derive(Debug, Clone)]
pub struct Workspace {
    r: Vec<f64>,
    jac: Vec<f64>,
    r_try: Vec<f64>,
    jac_try: Vec<f64>,
    g: Vec<f64>,
    h: Vec<f64>,
    sys: Vec<f64>,
    delta: Vec<f64>,
    theta_try: Vec<f64>,
    scale: Vec<f64>,
}

impl Workspace {
    pub fn new(m: usize, p: usize) -> Workspace {
        Workspace {
            r: vec![0.0; m],
            jac: vec![0.0; m * p],
            r_try: vec![0.0; m],
            jac_try: vec![0.0; m * p],
            g: vec![0.0; p],
            h: vec![0.0; p * p],
            sys: vec![0.0; p * p],
            delta: vec![0.0; p],
            theta_try: vec![0.0; p],
            scale: vec![0.0; p],
        }
    }
}

/// Minimises Σr² from `theta` (updated in place) within [lo, hi].
pub fn minimise<R: Residuals>(
    prob: &mut R,
    theta: &mut [f64],
    lo: &[f64],
    hi: &[f64],
    ws: &mut Workspace,
) -> Outcome {
    minimise_to(prob, theta, lo, hi, ws, MAX_ITER, FTOL)
}

/// [`minimise`] with its own iteration limit and relative cost tolerance
/// (the profile walks need the cost to a fraction of the threshold only).
pub fn minimise_to<R: Residuals>(
    prob: &mut R,
    theta: &mut [f64],
    lo: &[f64],
    hi: &[f64],
    ws: &mut Workspace,
    max_iter: usize,
    ftol: f64,
) -> Outcome {
    let (m, p) = (prob.m(), prob.p());
    for j in 0..p {
        theta[j] = theta[j].clamp(lo[j], hi[j]);
    }
    let mut cost = prob.eval(theta, &mut ws.r, Some(&mut ws.jac));
    if !cost.is_finite() {
        return Outcome {
            cost: f64::INFINITY,
            iterations: 0,
        };
    }
    ws.scale.fill(0.0);
    let mut boxed = Boxed {
        prob,
        theta,
        lo,
        hi,
        ws,
        p,
    };
    let mut damping = Nielsen::new(1e-3);
    let mut fresh = true;
    let mut iterations = 0;
    while iterations < max_iter && cost > 0.0 {
        iterations += 1;
        if fresh {
            boxed.linearise(m);
            fresh = false;
        }
        match attempt(&mut boxed, &mut damping, cost) {
            Attempt::Kept { after } => {
                let small = cost - after <= ftol * cost;
                cost = after;
                fresh = true;
                if small {
                    break;
                }
            }
            Attempt::Refused => {}
            Attempt::RanAway | Attempt::Stalled => break,
        }
    }
    Outcome { cost, iterations }
}

/// The problem inside its box, as the LM driver sees it.
struct Boxed<'a, R> {
    prob: &'a mut R,
    theta: &'a mut [f64],
    lo: &'a [f64],
    hi: &'a [f64],
    ws: &'a mut Workspace,
    p: usize,
}

impl<R: Residuals> Boxed<'_, R> {
    /// Normal equations at θ, and Moré's scaling D: the running maximum of
    /// the column norms of J, floored at 1e-12 of the largest.
    fn linearise(&mut self, m: usize) {
        let (ws, p) = (&mut *self.ws, self.p);
        normal_equations(&ws.jac, &ws.r, m, p, &mut ws.h, &mut ws.g);
        for j in 0..p {
            ws.scale[j] = ws.scale[j].max(ws.h[j * p + j]);
        }
        let top = ws.scale.iter().copied().fold(0.0, f64::max);
        let floor = if top > 0.0 { 1e-12 * top } else { 1.0 };
        for s in &mut ws.scale {
            *s = s.max(floor);
        }
    }
}

impl<R: Residuals> Model for Boxed<'_, R> {
    /// (H + μD) δ = −g on the free (inactive) parameters, held ones δ = 0,
    /// then θ + δ projected onto the box.
    fn solve(&mut self, mu: f64) -> Solve {
        let (theta, lo, hi, ws, p) = (&*self.theta, self.lo, self.hi, &mut *self.ws, self.p);
        for j in 0..p {
            let held = (theta[j] <= lo[j] && ws.g[j] > 0.0) || (theta[j] >= hi[j] && ws.g[j] < 0.0);
            for i in 0..p {
                ws.sys[j * p + i] = if held || is_held(theta, lo, hi, &ws.g, i) {
                    if i == j { 1.0 } else { 0.0 }
                } else {
                    ws.h[j * p + i] + if i == j { mu * ws.scale[j] } else { 0.0 }
                };
            }
            ws.delta[j] = if held { 0.0 } else { -ws.g[j] };
        }
        if !cholesky_solve(&mut ws.sys, &mut ws.delta, p) {
            return Solve::Singular;
        }
        let mut step = 0.0f64;
        for j in 0..p {
            ws.theta_try[j] = (theta[j] + ws.delta[j]).clamp(lo[j], hi[j]);
            ws.delta[j] = ws.theta_try[j] - theta[j];
            step = step.max(ws.delta[j].abs());
        }
        if step <= XTOL {
            return Solve::Stalled;
        }
        Solve::Step
    }

    fn trial_cost(&mut self) -> f64 {
        let ws = &mut *self.ws;
        self.prob
            .eval(&ws.theta_try, &mut ws.r_try, Some(&mut ws.jac_try))
    }

    fn keep(&mut self, cost: f64, cost_try: f64) -> f64 {
        let (ws, p) = (&mut *self.ws, self.p);
        // Predicted decrease of the linear model: −(2gᵀs + sᵀHs).
        let mut pred = 0.0;
        for j in 0..p {
            let mut hs = 0.0;
            for i in 0..p {
                hs += ws.h[j * p + i] * ws.delta[i];
            }
            pred -= ws.delta[j] * (2.0 * ws.g[j] + hs);
        }
        let gain = if pred > 0.0 {
            (cost - cost_try) / pred
        } else {
            0.5
        };
        self.theta.copy_from_slice(&ws.theta_try);
        std::mem::swap(&mut ws.r, &mut ws.r_try);
        std::mem::swap(&mut ws.jac, &mut ws.jac_try);
        gain
    }
}

fn is_held(theta: &[f64], lo: &[f64], hi: &[f64], g: &[f64], j: usize) -> bool {
    (theta[j] <= lo[j] && g[j] > 0.0) || (theta[j] >= hi[j] && g[j] < 0.0)
}

/// H = JᵀJ and g = Jᵀr for a column-major m×p J: dot products of
/// contiguous columns, which the compiler vectorises.
pub fn normal_equations(jac: &[f64], r: &[f64], m: usize, p: usize, h: &mut [f64], g: &mut [f64]) {
    let r = &r[..m];
    for a in 0..p {
        let ca = &jac[a * m..(a + 1) * m];
        g[a] = dot(ca, r);
        for b in a..p {
            let v = dot(ca, &jac[b * m..(b + 1) * m]);
            h[a * p + b] = v;
            h[b * p + a] = v;
        }
    }
}

/// Σ x_i y_i in four independent sums (same order every call: same bits).
fn dot(x: &[f64], y: &[f64]) -> f64 {
    let n = x.len().min(y.len());
    let (x, y) = (&x[..n], &y[..n]);
    let mut acc = [0.0f64; 4];
    let split = n - n % 4;
    for (a, b) in x[..split].chunks_exact(4).zip(y[..split].chunks_exact(4)) {
        for k in 0..4 {
            acc[k] += a[k] * b[k];
        }
    }
    let mut v = (acc[0] + acc[1]) + (acc[2] + acc[3]);
    for (a, b) in x[split..].iter().zip(&y[split..]) {
        v += a * b;
    }
    v
}

/// Solves the symmetric positive definite system in place (a is destroyed);
/// false when it is not positive definite.
fn cholesky_solve(a: &mut [f64], x: &mut [f64], p: usize) -> bool {
    for j in 0..p {
        let mut d = a[j * p + j];
        for k in 0..j {
            d -= a[j * p + k] * a[j * p + k];
        }
        if !(d > 0.0 && d.is_finite()) {
            return false;
        }
        let d = d.sqrt();
        a[j * p + j] = d;
        for i in j + 1..p {
            let mut s = a[i * p + j];
            for k in 0..j {
                s -= a[i * p + k] * a[j * p + k];
            }
            a[i * p + j] = s / d;
        }
    }
    for i in 0..p {
        let mut s = x[i];
        for k in 0..i {
            s -= a[i * p + k] * x[k];
        }
        x[i] = s / a[i * p + i];
    }
    for i in (0..p).rev() {
        let mut s = x[i];
        for k in i + 1..p {
            s -= a[k * p + i] * x[k];
        }
        x[i] = s / a[i * p + i];
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rosenbrock as least squares: r = (10(y − x²), 1 − x).
    struct Rosen;
    impl Residuals for Rosen {
        fn m(&self) -> usize {
            2
        }
        fn p(&self) -> usize {
            2
        }
        fn eval(&mut self, t: &[f64], r: &mut [f64], jac: Option<&mut [f64]>) -> f64 {
            r[0] = 10.0 * (t[1] - t[0] * t[0]);
            r[1] = 1.0 - t[0];
            if let Some(j) = jac {
                j.copy_from_slice(&[-20.0 * t[0], -1.0, 10.0, 0.0]);
            }
            r[0] * r[0] + r[1] * r[1]
        }
    }

    #[test]
    fn finds_the_rosenbrock_minimum() {
        let mut ws = Workspace::new(2, 2);
        let mut t = [-1.2, 1.0];
        let o = minimise(&mut Rosen, &mut t, &[-5.0; 2], &[5.0; 2], &mut ws);
        assert!(o.cost < 1e-20, "{o:?}");
        assert!(
            (t[0] - 1.0).abs() < 1e-10 && (t[1] - 1.0).abs() < 1e-10,
            "{t:?}"
        );
    }

    #[test]
    fn a_bound_holds_and_the_rest_is_optimal_on_it() {
        // With x ≤ 0.5 the constrained minimum is x = 0.5, y = 0.25.
        let mut ws = Workspace::new(2, 2);
        let mut t = [-1.2, 1.0];
        minimise(&mut Rosen, &mut t, &[-5.0, -5.0], &[0.5, 5.0], &mut ws);
        assert_eq!(t[0], 0.5);
        assert!((t[1] - 0.25).abs() < 1e-8, "{t:?}");
    }
}
