//! `--free LIST` and `--bound NAME=LO..HI` as `biodyn fit` reads them: the
//! text becomes the library's typed selectors and boxes.

use biodyn::Body;
use biodyn::fit::{Bound, Free};
use std::fmt;

/// A `--free` or `--bound` argument that does not parse; the text is the
/// whole message, flag included.
#[derive(Debug)]
pub enum ArgError {
    Free(String),
    Bound(String),
}

impl fmt::Display for ArgError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ArgError::Free(s) | ArgError::Bound(s) => f.write_str(s),
        }
    }
}

impl std::error::Error for ArgError {}

/// Reads a comma-separated list: `links` (every k and c), `masses`, `all`
/// (every m, k and c), a link name (its k and c), or any name
/// `Body::param` knows (m1, k4, c2, chest, pelvis-seat.k, body-mass).
pub fn parse_free(body: &Body, list: &str) -> Result<Vec<Free>, ArgError> {
    let mut out = Vec::new();
    for token in list.split(',').map(str::trim).filter(|t| !t.is_empty()) {
        out.push(match token.to_ascii_lowercase().as_str() {
            "links" => Free::Links,
            "masses" => Free::Masses,
            "all" => Free::All,
            _ => match body.links.iter().position(|l| l.name == token) {
                Some(i) => Free::Link(i),
                None => Free::Param(
                    body.param(token)
                        .map_err(|e| ArgError::Free(format!("--free {token}: {e}")))?,
                ),
            },
        });
    }
    Ok(out)
}

/// A `--bound` as written: the parameter's name and the two ends.
#[derive(Debug, Clone, PartialEq)]
pub struct BoundText {
    pub text: String,
    pub name: String,
    pub lo: Option<f64>,
    pub hi: Option<f64>,
}

/// Parses `NAME=LO..HI` (e.g. `k4=1e4..1e6`, `c1=50..`).
pub fn parse_bound(text: &str) -> Result<BoundText, ArgError> {
    let bad = |reason: &str| ArgError::Bound(format!("--bound {text}: {reason}"));
    let (name, range) = text
        .split_once('=')
        .ok_or_else(|| bad("expected NAME=LO..HI, e.g. --bound k4=1e4..1e6"))?;
    let (lo, hi) = range
        .split_once("..")
        .ok_or_else(|| bad("expected LO..HI after '=', e.g. 1e4..1e6"))?;
    let num = |s: &str, side: &str| -> Result<Option<f64>, ArgError> {
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
    Ok(BoundText {
        text: text.to_string(),
        name: name.trim().to_string(),
        lo,
        hi,
    })
}

/// The parameter each bound names, in the model.
pub fn bounds(body: &Body, texts: &[BoundText]) -> Result<Vec<Bound>, ArgError> {
    texts
        .iter()
        .map(|b| {
            let param = body
                .param(&b.name)
                .map_err(|e| ArgError::Bound(format!("--bound {}: {e}", b.text)))?;
            Ok(Bound {
                param,
                lo: b.lo,
                hi: b.hi,
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use biodyn::Param;

    #[test]
    fn lists_read_groups_links_and_names() {
        let b = Body::paper(75.0).unwrap();
        assert_eq!(
            parse_free(&b, "c1, links ,pelvis-seat").unwrap(),
            vec![Free::Param(Param::Damping(0)), Free::Links, Free::Link(3)]
        );
        assert_eq!(parse_free(&b, " , ").unwrap(), vec![]);
        let e = parse_free(&b, "k9").unwrap_err().to_string();
        assert!(e.starts_with("--free k9: "), "{e}");
    }

    #[test]
    fn bounds_parse() {
        let b = parse_bound("k4=1e4..1e6").unwrap();
        assert_eq!((b.name.as_str(), b.lo, b.hi), ("k4", Some(1e4), Some(1e6)));
        let half = parse_bound("c1=50..").unwrap();
        assert_eq!((half.lo, half.hi), (Some(50.0), None));
        for bad in ["k4", "k4=5..2", "k4=-1..2", "k4=a..2", "=1..2", "k4=1;2"] {
            let e = parse_bound(bad).unwrap_err().to_string();
            assert!(e.starts_with(&format!("--bound {bad}: ")), "{bad}: {e}");
        }
    }
}
