//! Levenberg–Marquardt: the control flow the fit (`fit::lm`) and the
//! networks' trainer (`ann::lm`) share.
//!
//! At θ with residuals r and Jacobian J, one attempt solves the damped
//! normal equations
//!
//! ```text
//! (JᵀJ + μ D) δ = −Jᵀr
//! ```
//!
//! and tries θ + δ. A step that lowers the cost is kept and μ falls (the
//! next step leans toward Gauss–Newton); a step that does not, or a system
//! that is not positive definite, is refused and μ rises (toward a short
//! gradient step); when μ runs away no step helps any more. The problem
//! ([`Model`]) supplies the linearisation, the damped solve (its D, its
//! bounds, its factorisation) and the cost; a [`Damping`] rule moves μ; each
//! caller keeps its own stopping rules (iterations, tolerances, epochs,
//! targets) around [`attempt`].

/// What the damped solve gave.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Solve {
    /// A trial point is ready.
    Step,
    /// The damped system is not positive definite at this μ.
    Singular,
    /// The step moves nothing any more: the caller stops.
    Stalled,
}

/// A least-squares problem as the driver sees it, linearised at its
/// current point by the caller.
pub(crate) trait Model {
    /// Solves the system damped by `mu` and sets the trial point aside.
    fn solve(&mut self, mu: f64) -> Solve;
    /// Cost at the trial point (infinity where the model fails there).
    fn trial_cost(&mut self) -> f64;
    /// Makes the trial point current; returns the gain ratio ρ (actual
    /// over predicted decrease) for rules that use it.
    fn keep(&mut self, before: f64, after: f64) -> f64;
}

/// How μ moves.
pub(crate) trait Damping {
    fn mu(&self) -> f64;
    /// After a kept step of gain ratio `gain`.
    fn kept(&mut self, gain: f64);
    /// After a refused step; false when μ ran away.
    fn raise(&mut self) -> bool;
}

/// μ ×10 after a refused step, ÷10 (down to a floor) after a kept one,
/// run away above a ceiling (Marquardt's rule; the networks' trainer).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Tenfold {
    pub mu: f64,
    pub min: f64,
    pub max: f64,
}

impl Damping for Tenfold {
    fn mu(&self) -> f64 {
        self.mu
    }
    fn kept(&mut self, _gain: f64) {
        self.mu = (self.mu / 10.0).max(self.min);
    }
    fn raise(&mut self) -> bool {
        self.mu *= 10.0;
        self.mu <= self.max
    }
}

/// Nielsen's rule: μ·max(1/3, 1 − (2ρ − 1)³) after a kept step, μ·ν with ν
/// doubling after each refused one in a row; runs away above 1e30 (the fit).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Nielsen {
    pub mu: f64,
    pub nu: f64,
}

impl Nielsen {
    pub(crate) fn new(mu: f64) -> Nielsen {
        Nielsen { mu, nu: 2.0 }
    }
}

impl Damping for Nielsen {
    fn mu(&self) -> f64 {
        self.mu
    }
    fn kept(&mut self, gain: f64) {
        self.mu *= (1.0 / 3.0f64).max(1.0 - (2.0 * gain - 1.0).powi(3));
        self.nu = 2.0;
    }
    fn raise(&mut self) -> bool {
        self.mu *= self.nu;
        self.nu *= 2.0;
        // A NaN μ does not stop the run (the fit's rule before the driver).
        self.mu <= 1e30 || self.mu.is_nan()
    }
}

/// What one attempt did.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Attempt {
    /// The step was kept: the cost is now `after`.
    Kept { after: f64 },
    /// Refused (worse, or not positive definite); μ rose.
    Refused,
    /// Refused, and μ ran away.
    RanAway,
    /// The model's step moved nothing.
    Stalled,
}

/// One attempt from the current point of cost `cost`.
pub(crate) fn attempt(model: &mut impl Model, damping: &mut impl Damping, cost: f64) -> Attempt {
    match model.solve(damping.mu()) {
        Solve::Stalled => return Attempt::Stalled,
        Solve::Singular => return refused(damping),
        Solve::Step => {}
    }
    let after = model.trial_cost();
    if after < cost {
        let gain = model.keep(cost, after);
        damping.kept(gain);
        Attempt::Kept { after }
    } else {
        refused(damping)
    }
}

fn refused(damping: &mut impl Damping) -> Attempt {
    if damping.raise() {
        Attempt::Refused
    } else {
        Attempt::RanAway
    }
}
