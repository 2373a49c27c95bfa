//! Which parameters a fit may move, and within what bounds.
//!
//! Every free parameter is fitted as ln p, so it stays positive; its bounds
//! become a box in ln p. Without a `--bound`, a parameter may move three
//! decades either way from its start (and never past the model's limits):
//! wide enough for any body, narrow enough that a parameter the data cannot
//! see does not run off to 0 or infinity.

use super::error::FitError;
use crate::body::model::{Body, MAX_C, MAX_K, MAX_MASS, Param};

/// Default reach of a parameter from its start, as a factor either way.
pub const DEFAULT_REACH: f64 = 1e3;

/// One free parameter with its start value and box.
#[derive(Debug, Clone, PartialEq)]
pub struct FreeParam {
    pub param: Param,
    /// m1, k4, c2, body-mass: the name the report and `--bound` use.
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

fn sort_key(p: Param) -> (u8, usize) {
    match p {
        Param::BodyMass => (0, 0),
        Param::Mass(i) => (1, i),
        Param::Stiffness(i) => (2, i),
        Param::Damping(i) => (3, i),
    }
}

/// Resolves a comma-separated list: `links` (every k and c), `masses`,
/// `all` (every m, k and c), a link name (its k and c), or any name
/// `Body::param` knows (m1, k4, c2, chest, pelvis-seat.k, body-mass).
/// The result is in the model's order: body mass, masses, k, c.
pub fn parse_free(body: &Body, list: &str) -> Result<Vec<Param>, FitError> {
    let mut out: Vec<Param> = Vec::new();
    let links = (0..body.links.len()).flat_map(|i| [Param::Stiffness(i), Param::Damping(i)]);
    let masses = (0..body.n()).map(Param::Mass);
    for token in list.split(',').map(str::trim).filter(|t| !t.is_empty()) {
        match token.to_ascii_lowercase().as_str() {
            "links" => out.extend(links.clone()),
            "masses" => out.extend(masses.clone()),
            "all" => out.extend(masses.clone().chain(links.clone())),
            _ => {
                if let Some(i) = body.links.iter().position(|l| l.name == token) {
                    out.extend([Param::Stiffness(i), Param::Damping(i)]);
                } else {
                    let p = body.param(token).map_err(|source| FitError::UnknownFree {
                        name: token.to_string(),
                        source,
                    })?;
                    out.push(p);
                }
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
    let reason = |r: String| Err(FitError::NoBodyMass { reason: r });
    let Some(bm) = body.body_mass else {
        return reason(
            "the model gives no body mass; set one with --body-mass KG, or free single masses"
                .into(),
        );
    };
    for s in &body.segments {
        match s.share {
            None => {
                return reason(format!(
                    "segment '{}' has no share of body mass, so body mass cannot scale it; free single masses instead",
                    s.name
                ));
            }
            Some(share) if (share * bm - s.mass).abs() > 1e-9 * s.mass => {
                return reason(format!(
                    "segment '{}' has {} kg, not its share {share} × {bm} kg; free single masses instead",
                    s.name, s.mass
                ));
            }
            Some(_) => {}
        }
    }
    Ok(())
}

/// A parsed `NAME=LO..HI`; either side may be left empty for its default.
#[derive(Debug, Clone, PartialEq)]
pub struct Bound {
    pub text: String,
    pub name: String,
    pub lo: Option<f64>,
    pub hi: Option<f64>,
}

/// Parses `NAME=LO..HI` (e.g. `k4=1e4..1e6`, `c1=50..`).
pub fn parse_bound(text: &str) -> Result<Bound, FitError> {
    let bad = |reason: &str| FitError::BadBound {
        text: text.to_string(),
        reason: reason.to_string(),
    };
    let (name, range) = text
        .split_once('=')
        .ok_or_else(|| bad("expected NAME=LO..HI, e.g. --bound k4=1e4..1e6"))?;
    let (lo, hi) = range
        .split_once("..")
        .ok_or_else(|| bad("expected LO..HI after '=', e.g. 1e4..1e6"))?;
    let num = |s: &str, side: &str| -> Result<Option<f64>, FitError> {
        let s = s.trim();
        if s.is_empty() {
            return Ok(None);
        }
        match s.parse::<f64>() {
            Ok(v) if v.is_finite() && v > 0.0 => Ok(Some(v)),
            _ => Err(bad(&format!(
                "{side} bound '{s}' is not a number > 0 (parameters are positive)"
            ))),
        }
    };
    let (lo, hi) = (num(lo, "lower")?, num(hi, "upper")?);
    if let (Some(l), Some(h)) = (lo, hi)
        && l >= h
    {
        return Err(bad("the lower bound must be below the upper one"));
    }
    if name.trim().is_empty() {
        return Err(bad("the parameter name is empty"));
    }
    Ok(Bound {
        text: text.to_string(),
        name: name.trim().to_string(),
        lo,
        hi,
    })
}

/// The free parameters with their start values and boxes.
pub fn free_params(body: &Body, list: &str, bounds: &[Bound]) -> Result<Vec<FreeParam>, FitError> {
    let params = parse_free(body, list)?;
    let mut out = Vec::with_capacity(params.len());
    for p in params {
        let start = body.get(p);
        let name = name_of(body, p);
        if start.is_nan() || start <= 0.0 {
            return Err(FitError::ZeroStart { name, value: start });
        }
        let max = limit(body, p);
        out.push(FreeParam {
            param: p,
            name,
            start,
            lo: start / DEFAULT_REACH,
            hi: (start * DEFAULT_REACH).min(max),
        });
    }
    for (i, b) in bounds.iter().enumerate() {
        let p = body.param(&b.name).map_err(|e| FitError::BadBound {
            text: b.text.clone(),
            reason: e.to_string(),
        })?;
        let Some(f) = out.iter_mut().find(|f| f.param == p) else {
            return Err(FitError::BoundNotFree {
                text: b.text.clone(),
                name: name_of(body, p),
            });
        };
        if bounds[..i]
            .iter()
            .any(|o| body.param(&o.name).ok() == Some(p))
        {
            return Err(FitError::BadBound {
                text: b.text.clone(),
                reason: format!(
                    "{} is bounded twice; give one --bound per parameter",
                    f.name
                ),
            });
        }
        let max = limit(body, p);
        if let Some(lo) = b.lo {
            f.lo = lo;
        }
        if let Some(hi) = b.hi {
            if hi > max {
                return Err(FitError::BadBound {
                    text: b.text.clone(),
                    reason: format!("{hi} is above the model's limit {max} {}", p.unit()),
                });
            }
            f.hi = hi;
        }
        if f.lo >= f.hi {
            return Err(FitError::BadBound {
                text: b.text.clone(),
                reason: format!("the box [{}, {}] is empty; give both ends", f.lo, f.hi),
            });
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shortcuts_and_names_resolve_in_model_order() {
        let b = Body::paper(75.0).unwrap();
        let p = parse_free(&b, "c1, links ,k1").unwrap();
        assert_eq!(p.len(), 8);
        assert_eq!(p[0], Param::Stiffness(0));
        assert_eq!(p[4], Param::Damping(0));
        assert_eq!(parse_free(&b, "all").unwrap().len(), 12);
        assert_eq!(
            parse_free(&b, "pelvis-seat,chest").unwrap(),
            vec![Param::Mass(1), Param::Stiffness(3), Param::Damping(3)]
        );
        assert_eq!(parse_free(&b, "body-mass").unwrap(), vec![Param::BodyMass]);
        assert!(matches!(
            parse_free(&b, "body-mass,m2"),
            Err(FitError::MassTwice { .. })
        ));
        assert!(matches!(parse_free(&b, " , "), Err(FitError::EmptyFree)));
        assert!(matches!(
            parse_free(&b, "k9"),
            Err(FitError::UnknownFree { .. })
        ));
    }

    #[test]
    fn bounds_parse_and_apply() {
        let b = Body::paper(75.0).unwrap();
        let bound = parse_bound("k4=1e4..1e6").unwrap();
        let f = free_params(&b, "links", &[bound]).unwrap();
        assert_eq!((f[3].lo, f[3].hi), (1e4, 1e6));
        assert_eq!((f[0].lo, f[0].hi), (310.0, 3.1e8));
        let half = parse_bound("c1=50..").unwrap();
        assert_eq!((half.lo, half.hi), (Some(50.0), None));
        for bad in [
            "k4", "k4=1..", "k4=5..2", "k4=-1..2", "k4=a..2", "=1..2", "k4=1;2",
        ] {
            let r = parse_bound(bad).and_then(|x| free_params(&b, "k4", &[x]));
            assert!(
                matches!(r, Err(FitError::BadBound { .. })) || bad == "k4=1..",
                "{bad}: {r:?}"
            );
        }
        let r = free_params(&b, "k1", &[parse_bound("k4=1..2").unwrap()]);
        assert!(matches!(r, Err(FitError::BoundNotFree { .. })), "{r:?}");
        let r = free_params(&b, "k4", &[parse_bound("k4=1..2e13").unwrap()]);
        assert!(matches!(r, Err(FitError::BadBound { .. })), "{r:?}");
    }

    #[test]
    fn a_zero_start_is_refused() {
        let mut b = Body::paper(75.0).unwrap();
        b.links[0].c = 0.0;
        let e = free_params(&b, "links", &[]).unwrap_err().to_string();
        assert!(e.contains("c1") && e.contains("ln c1"), "{e}");
    }
}
