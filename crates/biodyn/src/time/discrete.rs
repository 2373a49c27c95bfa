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

use super::limits::{MAX_SEGMENTS, MIN_FS};
use crate::body::model::{Body, End, ModelError};
use crate::io::excerpt::num;
use nalgebra::{DMatrix, DVector};

/// Highest sampling rate accepted, Hz: the running r.m.s. window (1 s) is
/// held in memory, 8 MB at this rate.
pub const MAX_FS: f64 = 1.0e6;

/// Why a body cannot be simulated at a rate.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SimError {
    #[error(
        "sampling rate {} Hz{}: the simulator takes a finite rate from 1e-3 to 1e6 Hz (a step from 1 µs to 1000 s)",
        num(*.0),
        step_words(*.0)
    )]
    BadFs(f64),
    #[error(transparent)]
    Model(#[from] ModelError),
    #[error(
        "at {} Hz (a step of {} s) the model's state matrix times the step overflows: raise the sampling rate",
        num(*.0),
        step(*.0)
    )]
    Overflow(f64),
    #[error(
        "the model has {n} segments: the time domain takes at most {max} (its exact step is dense, 6·n² multiply-adds a sample and 32·n² bytes; discretising it grows as n³, about 1 s at {max}); responses and peaks work at any size"
    )]
    TooManySegments { n: usize, max: usize },
}

/// " (a step of 1e300 s)" for a positive finite rate; nothing otherwise.
fn step_words(fs: f64) -> String {
    if fs.is_finite() && fs > 0.0 {
        format!(" (a step of {} s)", step(fs))
    } else {
        String::new()
    }
}

/// 1/fs to three digits, trailing zeros dropped: 1e300, 0.001, 3.33e-7.
fn step(fs: f64) -> String {
    let e = format!("{:.2e}", 1.0 / fs);
    let (mantissa, exp) = e.split_once('e').unwrap_or((&e, "0"));
    let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
    match exp.parse::<i32>() {
        Ok(x) if (-3..=3).contains(&x) => num(1.0 / fs),
        _ => format!("{mantissa}e{exp}"),
    }
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
        if !(fs.is_finite() && (MIN_FS..=MAX_FS).contains(&fs)) {
            return Err(SimError::BadFs(fs));
        }
        body.validate()?;
        let n = body.n();
        // Refused before any (2n + 2)² matrix is allocated.
        if n > MAX_SEGMENTS {
            return Err(SimError::TooManySegments {
                n,
                max: MAX_SEGMENTS,
            });
        }
        let s = 2 * n;
        let h = 1.0 / fs;
        let (a, b) = state_space(body);
        let mut aug = DMatrix::zeros(s + 2, s + 2);
        aug.view_mut((0, 0), (s, s)).copy_from(&(&a * h));
        aug.view_mut((0, s), (s, 1)).copy_from(&(&b * h));
        aug[(s, s + 1)] = 1.0;
        // exp's Padé solve unwraps: never hand it a non-finite matrix.
        if aug.iter().any(|v| !v.is_finite()) {
            return Err(SimError::Overflow(fs));
        }
        let e = aug.exp();
        if e.iter().any(|v| !v.is_finite()) {
            return Err(SimError::Overflow(fs));
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::body::model::Segment;

    fn chain(n: usize) -> Body {
        let segments = (0..n)
            .map(|i| Segment {
                name: format!("s{i}"),
                mass: 1.0,
                share: None,
                seat: false,
            })
            .collect();
        Body::chain(segments, &vec![1e6; n], &vec![50.0; n])
    }

    #[test]
    fn a_model_past_the_limit_is_refused_with_the_reason() {
        let e = Discrete::new(&chain(MAX_SEGMENTS + 1), 1000.0).unwrap_err();
        assert_eq!(
            e,
            SimError::TooManySegments {
                n: MAX_SEGMENTS + 1,
                max: MAX_SEGMENTS
            }
        );
        let t = e.to_string();
        assert!(
            t.contains("501 segments") && t.contains("at most 500"),
            "{t}"
        );
        assert!(Discrete::new(&chain(8), 1000.0).is_ok());
    }

    #[test]
    fn a_rate_out_of_range_blames_the_rate_and_gives_the_range() {
        let body = Body::paper(75.0).unwrap();
        for fs in [1e-300, 1e-4, 0.0, -1.0, f64::NAN, 2e6] {
            let e = Discrete::new(&body, fs).unwrap_err();
            let t = e.to_string();
            assert!(matches!(e, SimError::BadFs(_)), "{fs}: {t}");
            assert!(t.contains("from 1e-3 to 1e6 Hz"), "{t}");
            assert!(!t.contains("mass"), "{t}");
        }
        let t = Discrete::new(&body, 1e-300).unwrap_err().to_string();
        assert!(t.contains("a step of 1e300 s"), "{t}");
        // Both ends of the range simulate, the stiffest model included.
        let mut stiff = chain(3);
        for s in &mut stiff.segments {
            s.mass = 1e-3;
        }
        for l in &mut stiff.links {
            l.k = 1e12;
            l.c = 1e10;
        }
        for fs in [MIN_FS, MAX_FS] {
            let d = Discrete::new(&body, fs).unwrap();
            assert!(d.phi.iter().all(|v| v.is_finite()));
            let d = Discrete::new(&stiff, fs).unwrap();
            assert!(d.phi.iter().chain(d.g0.iter()).all(|v| v.is_finite()));
        }
    }
}
