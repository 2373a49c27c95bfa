//! Exact discretisation of the body under a piecewise-linear seat
//! acceleration (first-order hold), SPEC §6.
//!
//! Relative coordinates z = x − x0 give M z'' + C z' + K z = −M·1·a_s, state
//! q = [z, z'], q' = A q + B a_s. For an input linear between samples the
//! solution is exact: the matrix exponential of Van Loan's augmented matrix
//! [[A h, B h, 0], [0, 0, I], [0, 0, 0]] holds Φ, Γ0, Γ1 with
//! q[k+1] = Φ q[k] + Γ0 a[k] + Γ1 a[k+1] (the convention of scipy's `lsim`).
//! nalgebra's `exp` is Higham's scaling-and-squaring Padé 13, so a stiff model
//! (‖A h‖ in the thousands) is squared down rather than summed badly.

use crate::body::model::{Body, End, ModelError};
use nalgebra::{DMatrix, DVector};

/// Highest sampling rate accepted, Hz: the running r.m.s. window (1 s) is
/// held in memory, 8 MB at this rate.
pub const MAX_FS: f64 = 1.0e6;

/// Why a body cannot be simulated at a rate.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SimError {
    #[error("sampling rate {0:?} Hz: it must be a finite number > 0 and at most 1e6")]
    BadFs(f64),
    #[error(transparent)]
    Model(#[from] ModelError),
    #[error(
        "the model's state matrix overflows (a mass too small for its links): masses of at least 1e-6 kg simulate"
    )]
    Overflow,
}

/// Φ, Γ0, Γ1 and the output rows of one body at one rate; dense, any size.
#[derive(Debug, Clone)]
pub struct Discrete {
    /// Number of segments n; the state has 2n entries.
    pub n: usize,
    pub phi: DMatrix<f64>,
    pub g0: DVector<f64>,
    pub g1: DVector<f64>,
    /// n + 1 rows over the state: the absolute acceleration of each segment,
    /// −(M⁻¹(C z' + K z))_i, then the seat force −1ᵀ(C z' + K z).
    pub out: DMatrix<f64>,
    /// Each link's ends as state indices (upper, lower; None = the seat):
    /// its deflection is z_upper − z_lower.
    pub links: Vec<(usize, Option<usize>)>,
}

/// K and C of a body in relative coordinates (the seat links stay on the diagonal).
pub fn stiffness_damping(body: &Body) -> (DMatrix<f64>, DMatrix<f64>) {
    let n = body.n();
    let mut k = DMatrix::zeros(n, n);
    let mut c = DMatrix::zeros(n, n);
    for l in &body.links {
        let i = l.upper;
        k[(i, i)] += l.k;
        c[(i, i)] += l.c;
        if let End::Segment(j) = l.lower {
            k[(j, j)] += l.k;
            c[(j, j)] += l.c;
            k[(i, j)] -= l.k;
            k[(j, i)] -= l.k;
            c[(i, j)] -= l.c;
            c[(j, i)] -= l.c;
        }
    }
    (k, c)
}

/// The continuous state matrices A (2n × 2n) and B (2n) of SPEC §6.
pub fn state_space(body: &Body) -> (DMatrix<f64>, DVector<f64>) {
    let n = body.n();
    let (k, c) = stiffness_damping(body);
    let mut a = DMatrix::zeros(2 * n, 2 * n);
    let mut b = DVector::zeros(2 * n);
    for i in 0..n {
        a[(i, n + i)] = 1.0;
        let m = body.segments[i].mass;
        for j in 0..n {
            a[(n + i, j)] = -k[(i, j)] / m;
            a[(n + i, n + j)] = -c[(i, j)] / m;
        }
        b[n + i] = -1.0;
    }
    (a, b)
}

impl Discrete {
    /// Validates the body and discretises it at `fs`.
    pub fn new(body: &Body, fs: f64) -> Result<Discrete, SimError> {
        if !(fs.is_finite() && fs > 0.0 && fs <= MAX_FS) {
            return Err(SimError::BadFs(fs));
        }
        body.validate()?;
        let n = body.n();
        let s = 2 * n;
        let h = 1.0 / fs;
        let (a, b) = state_space(body);
        let mut aug = DMatrix::zeros(s + 2, s + 2);
        aug.view_mut((0, 0), (s, s)).copy_from(&(&a * h));
        aug.view_mut((0, s), (s, 1)).copy_from(&(&b * h));
        aug[(s, s + 1)] = 1.0;
        // exp's Padé solve unwraps: never hand it a non-finite matrix.
        if aug.iter().any(|v| !v.is_finite()) {
            return Err(SimError::Overflow);
        }
        let e = aug.exp();
        if e.iter().any(|v| !v.is_finite()) {
            return Err(SimError::Overflow);
        }
        let phi = e.view((0, 0), (s, s)).into_owned();
        let g1: DVector<f64> = e.view((0, s + 1), (s, 1)).column(0).into_owned();
        let g0: DVector<f64> = e.view((0, s), (s, 1)).column(0) - &g1;

        let (k, c) = stiffness_damping(body);
        let mut out = DMatrix::zeros(n + 1, s);
        for i in 0..n {
            let m = body.segments[i].mass;
            for j in 0..n {
                out[(i, j)] = -k[(i, j)] / m;
                out[(i, n + j)] = -c[(i, j)] / m;
                out[(n, j)] -= k[(i, j)];
                out[(n, n + j)] -= c[(i, j)];
            }
        }
        let links = body
            .links
            .iter()
            .map(|l| (l.upper, l.lower.segment()))
            .collect();
        Ok(Discrete {
            n,
            phi,
            g0,
            g1,
            out,
            links,
        })
    }
}
