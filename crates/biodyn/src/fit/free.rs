//! Which parameters a fit may move, and within what bounds.
//!
//! Every free parameter is fitted as ln p, so it stays positive; its bounds
//! become a box in ln p. Without a bound, a parameter may move three
//! decades either way from its start (and never past the model's limits):
//! wide enough for any body, narrow enough that a parameter the data cannot
//! see does not run off to 0 or infinity. No box reaches below the model's
//! own floor (a mass of 1 g) or above its limits: a fitted value, and an
//! interval end, is always a value the model accepts.

use super::error::FitError;
use crate::body::limits::{MAX_C, MAX_K, MAX_MASS, MIN_MASS};
use crate::body::model::{Body, Param};

/// Default reach of a parameter from its start, as a factor either way.
pub const DEFAULT_REACH: f64 = 1e3;

/// One free parameter with its start value and box.
#[derive(Debug, Clone, PartialEq)]
pub struct FreeParam {
    pub param: Param,
    /// m1, k4, c2, body-mass: the name the report and a bound use.
    pub name: String,
    /// Value in the start model.
    pub start: f64,
    /// Bounds on the value, 0 < lo < hi.
    pub lo: f64,
    pub hi: f64,
}

/// Display name of a parameter: m1.., k1.., c1.. or body-mass.
pub fn name_of(body: &Body, p: Param) -> String {
    match p {
        Param::BodyMass => "body-mass".into(),
        _ => body.label(p),
    }
}

/// The largest value the model accepts for `p`.
fn limit(body: &Body, p: Param) -> f64 {
    match p {
        Param::Mass(_) => MAX_MASS,
        Param::Stiffness(_) => MAX_K,
        Param::Damping(_) => MAX_C,
        Param::BodyMass => {
            let top = body
                .segments
                .iter()
                .filter_map(|s| s.share)
                .fold(0.0f64, f64::max);
            if top > 0.0 { MAX_MASS / top } else { MAX_MASS }
        }
    }
}

/// The smallest value the model accepts for `p` (0: any value > 0).
fn floor(body: &Body, p: Param) -> f64 {
    match p {
        Param::Mass(_) => MIN_MASS,
        Param::Stiffness(_) | Param::Damping(_) => 0.0,
        Param::BodyMass => {
            // Every segment with a share must keep at least the floor.
            let least = body
                .segments
                .iter()
                .filter_map(|s| s.share)
                .filter(|&s| s > 0.0)
                .fold(f64::INFINITY, f64::min);
            if least.is_finite() {
                MIN_MASS / least
            } else {
                MIN_MASS
            }
        }
    }
}

fn sort_key(p: Param) -> (u8, usize) {
    match p {
        Param::BodyMass => (0, 0),
        Param::Mass(i) => (1, i),
        Param::Stiffness(i) => (2, i),
        Param::Damping(i) => (3, i),
    }
}

/// What a fit frees: a group of parameters or one of them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Free {
    /// Every segment mass, stiffness and damping.
    All,
    /// Every link's stiffness and damping.
    Links,
    /// Every segment mass.
    Masses,
    /// One link's stiffness and damping (0-based, in declaration order).
    Link(usize),
    /// One parameter, body mass included.
    Param(Param),
}

/// Whether the body has parameter `p` (an index within its segments or links).
fn exists(body: &Body, p: Param) -> bool {
    match p {
        Param::BodyMass => true,
        Param::Mass(i) => i < body.n(),
        Param::Stiffness(i) | Param::Damping(i) => i < body.links.len(),
    }
}

/// The parameters `free` selects, in the model's order (body mass, masses,
/// k, c), each once. Body mass with a single mass is refused: body mass
/// already scales every segment.
pub fn resolve(body: &Body, free: &[Free]) -> Result<Vec<Param>, FitError> {
    let mut out: Vec<Param> = Vec::new();
    let links = (0..body.links.len()).flat_map(|i| [Param::Stiffness(i), Param::Damping(i)]);
    let masses = (0..body.n()).map(Param::Mass);
    for &f in free {
        match f {
            Free::Links => out.extend(links.clone()),
            Free::Masses => out.extend(masses.clone()),
            Free::All => out.extend(masses.clone().chain(links.clone())),
            Free::Link(i) if i < body.links.len() => {
                out.extend([Param::Stiffness(i), Param::Damping(i)]);
            }
            Free::Link(i) => return Err(FitError::NoSuchLink { index: i }),
            Free::Param(p) if exists(body, p) => out.push(p),
            Free::Param(p) => {
                return Err(FitError::NotInModel {
                    name: body.label(p),
                });
            }
        }
    }
    if out.is_empty() {
        return Err(FitError::EmptyFree);
    }
    out.sort_by_key(|&p| sort_key(p));
    out.dedup();
    if out.first() == Some(&Param::BodyMass)
        && let Some(&m) = out.get(1)
        && matches!(m, Param::Mass(_))
    {
        return Err(FitError::MassTwice {
            mass: body.label(m),
        });
    }
    if out.first() == Some(&Param::BodyMass) {
        check_body_mass(body)?;
    }
    Ok(out)
}

/// Fitting body mass moves every segment to share × body mass, so the start
/// model must already be built that way, or the fit would not start from it.
fn check_body_mass(body: &Body) -> Result<(), FitError> {
    let Some(bm) = body.body_mass else {
        return Err(FitError::NoBodyMass);
    };
    for s in &body.segments {
        match s.share {
            None => {
                return Err(FitError::NoShare {
                    segment: s.name.clone(),
                });
            }
            Some(share) if (share * bm - s.mass).abs() > 1e-9 * s.mass => {
                return Err(FitError::OffShare {
                    segment: s.name.clone(),
                    mass: s.mass,
                    share,
                    body_mass: bm,
                });
            }
            Some(_) => {}
        }
    }
    Ok(())
}

/// A box for one free parameter, `0 < lo < hi`; an end left `None` keeps
/// its default.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bound {
    pub param: Param,
    pub lo: Option<f64>,
    pub hi: Option<f64>,
}

/// The free parameters with their start values and boxes. A bound error
/// names the bound by its place in `bounds` and the parameter by its name.
pub fn free_params(
    body: &Body,
    free: &[Free],
    bounds: &[Bound],
) -> Result<Vec<FreeParam>, FitError> {
    let params = resolve(body, free)?;
    let mut out = Vec::with_capacity(params.len());
    for p in params {
        let start = body.get(p);
        let name = name_of(body, p);
        if start.is_nan() || start <= 0.0 {
            return Err(FitError::ZeroStart { name, value: start });
        }
        let (min, max) = (floor(body, p), limit(body, p));
        out.push(FreeParam {
            param: p,
            name,
            start,
            lo: (start / DEFAULT_REACH).max(min),
            hi: (start * DEFAULT_REACH).min(max),
        });
    }
    for (i, b) in bounds.iter().enumerate() {
        let p = b.param;
        let Some(f) = out.iter_mut().find(|f| f.param == p) else {
            return Err(FitError::BoundNotFree {
                bound: i,
                name: name_of(body, p),
            });
        };
        if bounds[..i].iter().any(|o| o.param == p) {
            return Err(FitError::BoundTwice {
                bound: i,
                name: f.name.clone(),
            });
        }
        for v in [b.lo, b.hi].into_iter().flatten() {
            if !(v.is_finite() && v > 0.0) {
                return Err(FitError::BadBound {
                    bound: i,
                    name: f.name.clone(),
                    value: v,
                });
            }
        }
        let (min, max) = (floor(body, p), limit(body, p));
        if let Some(lo) = b.lo {
            if lo < min {
                return Err(FitError::BelowLimit {
                    bound: i,
                    name: f.name.clone(),
                    lo,
                    min,
                    unit: p.unit(),
                });
            }
            f.lo = lo;
        }
        if let Some(hi) = b.hi {
            if hi > max {
                return Err(FitError::AboveLimit {
                    bound: i,
                    name: f.name.clone(),
                    hi,
                    max,
                    unit: p.unit(),
                });
            }
            f.hi = hi;
        }
        if f.lo >= f.hi {
            return Err(FitError::EmptyBox {
                bound: i,
                name: f.name.clone(),
                lo: f.lo,
                hi: f.hi,
            });
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn groups_and_names_resolve_in_model_order() {
        let b = Body::paper(75.0).unwrap();
        let k1 = Free::Param(Param::Stiffness(0));
        let c1 = Free::Param(Param::Damping(0));
        let p = resolve(&b, &[c1, Free::Links, k1]).unwrap();
        assert_eq!(p.len(), 8);
        assert_eq!(p[0], Param::Stiffness(0));
        assert_eq!(p[4], Param::Damping(0));
        assert_eq!(resolve(&b, &[Free::All]).unwrap().len(), 12);
        assert_eq!(
            resolve(&b, &[Free::Link(3), Free::Param(Param::Mass(1))]).unwrap(),
            vec![Param::Mass(1), Param::Stiffness(3), Param::Damping(3)]
        );
        let bm = Free::Param(Param::BodyMass);
        assert_eq!(resolve(&b, &[bm]).unwrap(), vec![Param::BodyMass]);
        assert!(matches!(
            resolve(&b, &[bm, Free::Param(Param::Mass(1))]),
            Err(FitError::MassTwice { .. })
        ));
        assert!(matches!(resolve(&b, &[]), Err(FitError::EmptyFree)));
        assert!(matches!(
            resolve(&b, &[Free::Param(Param::Stiffness(8))]),
            Err(FitError::NotInModel { .. })
        ));
        assert!(matches!(
            resolve(&b, &[Free::Link(4)]),
            Err(FitError::NoSuchLink { index: 4 })
        ));
    }

    #[test]
    fn bounds_apply() {
        let b = Body::paper(75.0).unwrap();
        let k4 = Param::Stiffness(3);
        let bound = |param, lo, hi| Bound { param, lo, hi };
        let f = free_params(&b, &[Free::Links], &[bound(k4, Some(1e4), Some(1e6))]).unwrap();
        assert_eq!((f[3].lo, f[3].hi), (1e4, 1e6));
        assert_eq!((f[0].lo, f[0].hi), (310.0, 3.1e8));
        let only_k4 = [Free::Param(k4)];
        let r = free_params(
            &b,
            &[Free::Param(Param::Stiffness(0))],
            &[bound(k4, Some(1.0), Some(2.0))],
        );
        assert!(
            matches!(r, Err(FitError::BoundNotFree { bound: 0, .. })),
            "{r:?}"
        );
        let r = free_params(&b, &only_k4, &[bound(k4, Some(1.0), Some(2e13))]);
        assert!(matches!(r, Err(FitError::AboveLimit { .. })), "{r:?}");
        let m1 = [Free::Param(Param::Mass(0))];
        let r = free_params(&b, &m1, &[bound(Param::Mass(0), Some(1e-4), None)]);
        assert!(matches!(r, Err(FitError::BelowLimit { .. })), "{r:?}");
        let r = free_params(&b, &only_k4, &[bound(k4, Some(1e9), None)]);
        assert!(matches!(r, Err(FitError::EmptyBox { .. })), "{r:?}");
        let r = free_params(&b, &only_k4, &[bound(k4, Some(-1.0), None)]);
        assert!(matches!(r, Err(FitError::BadBound { .. })), "{r:?}");
        let twice = [bound(k4, Some(1.0), None), bound(k4, None, Some(1e6))];
        let r = free_params(&b, &only_k4, &twice);
        assert!(
            matches!(r, Err(FitError::BoundTwice { bound: 1, .. })),
            "{r:?}"
        );
    }

    /// No default box reaches below a gram, for a mass or for body mass
    /// (whose smallest share must keep its gram).
    #[test]
    fn default_boxes_keep_the_model_s_floor() {
        let mut b = Body::paper(75.0).unwrap();
        b.set(Param::Mass(0), 0.5).unwrap();
        let f = free_params(&b, &[Free::Param(Param::Mass(0))], &[]).unwrap();
        assert_eq!(f[0].lo, MIN_MASS);
        let b = Body::paper(75.0).unwrap();
        let f = free_params(&b, &[Free::Param(Param::BodyMass)], &[]).unwrap();
        let least = b
            .segments
            .iter()
            .filter_map(|s| s.share)
            .fold(1.0, f64::min);
        assert!(f[0].lo * least >= MIN_MASS * (1.0 - 1e-12), "{f:?}");
    }

    #[test]
    fn a_zero_start_is_refused() {
        let mut b = Body::paper(75.0).unwrap();
        b.links[0].c = 0.0;
        let e = free_params(&b, &[Free::Links], &[])
            .unwrap_err()
            .to_string();
        assert!(e.contains("c1") && e.contains("ln c1"), "{e}");
    }
}
