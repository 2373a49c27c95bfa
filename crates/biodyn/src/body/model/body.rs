//! The body's parts: segments, links and their ends, and the paper's chain.

use super::error::ModelError;
use serde::{Deserialize, Serialize};
use std::fmt;

/// One rigid mass of the body.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Segment {
    pub name: String,
    /// Mass in kg.
    pub mass: f64,
    /// Anthropometric share of total body mass, when the model is built the
    /// paper's way (segment mass = share × body mass).
    pub share: Option<f64>,
    /// A part of the seat under the body (the pan, a frame), not of the
    /// body: left out of the body mass, the pan's force and the networks.
    #[serde(default)]
    pub seat: bool,
}

impl Segment {
    /// A segment with a mass set directly (no share of body mass).
    pub fn new(name: &str, mass: f64) -> Segment {
        Segment {
            name: name.to_string(),
            mass,
            share: None,
            seat: false,
        }
    }
}

impl Link {
    pub fn new(name: &str, upper: usize, lower: End, k: f64, c: f64) -> Link {
        Link {
            name: name.to_string(),
            upper,
            lower,
            k,
            c,
        }
    }
}

/// The lower end of a link: another segment, or the seat.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum End {
    Segment(usize),
    Seat,
}

/// A spring k (N/m) in parallel with a damper c (N·s/m).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Link {
    pub name: String,
    /// Index of the upper segment.
    pub upper: usize,
    pub lower: End,
    pub k: f64,
    pub c: f64,
}

/// A seated body: segments, links, and which segment is the head (for STHT).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Body {
    pub segments: Vec<Segment>,
    pub links: Vec<Link>,
    pub head: usize,
    /// Total body mass in kg when the masses came from shares.
    pub body_mass: Option<f64>,
    /// The seat under the body, when the model has one (SPEC §11): the base
    /// is then the cab floor and the seat segments sit between it and the body.
    #[serde(default)]
    pub seat: Option<Seat>,
}

/// Where a seat's measurements are taken (ISO 10326-1): the segment the
/// seat-pan accelerometer sits on and the link whose deflection is the
/// suspension travel, with the travel available end-stop to end-stop.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Seat {
    /// Index of the pan segment (a seat segment the body rests on).
    pub pan: usize,
    /// Index of the suspension link (from a seat segment to the floor).
    pub suspension: usize,
    /// Available travel in m, end-stop to end-stop.
    pub stroke_m: f64,
}

/// The paper's anthropometric shares (SPEC §1), top to bottom.
pub const PAPER_SHARES: [f64; 4] = [0.075, 0.402, 0.122, 0.182];
/// Table 1 stiffnesses k1..k4 in N/m.
pub const PAPER_K: [f64; 4] = [310_000.0, 183_000.0, 162_800.0, 90_000.0];
/// Table 1 dampings c1..c4 in N·s/m.
pub const PAPER_C: [f64; 4] = [400.0, 4_750.0, 4_585.0, 2_064.0];
/// Segment names of the paper's model, top to bottom.
pub const PAPER_SEGMENTS: [&str; 4] = ["head-neck", "chest", "lower-torso", "pelvis"];

impl Body {
    /// The Boileau & Rakheja serial chain with the paper's shares × `body_mass`.
    pub fn paper(body_mass: f64) -> Result<Body, ModelError> {
        let segments = PAPER_SEGMENTS
            .iter()
            .zip(PAPER_SHARES)
            .map(|(name, share)| Segment {
                name: (*name).to_string(),
                mass: share * body_mass,
                share: Some(share),
                seat: false,
            })
            .collect();
        let mut body = Body::chain(segments, &PAPER_K, &PAPER_C);
        body.body_mass = Some(body_mass);
        body.validate()?;
        Ok(body)
    }

    /// A serial chain: link i joins segment i to i+1, the last one to the seat.
    /// Link names are "`upper`-`lower`" (e.g. "pelvis-seat"). `k` and `c` must have one entry per segment.
    pub fn chain(segments: Vec<Segment>, k: &[f64], c: &[f64]) -> Body {
        let n = segments.len();
        let links = (0..n)
            .map(|i| {
                let lower = if i + 1 < n {
                    End::Segment(i + 1)
                } else {
                    End::Seat
                };
                let lower_name = match lower {
                    End::Segment(j) => segments[j].name.as_str(),
                    End::Seat => "seat",
                };
                Link {
                    name: format!("{}-{}", segments[i].name, lower_name),
                    upper: i,
                    lower,
                    k: k.get(i).copied().unwrap_or(0.0),
                    c: c.get(i).copied().unwrap_or(0.0),
                }
            })
            .collect();
        Body {
            segments,
            links,
            head: 0,
            body_mass: None,
            seat: None,
        }
    }

    pub fn n(&self) -> usize {
        self.segments.len()
    }

    /// Σ m_i over the body's segments (not the seat's): the mass the seat
    /// carries, the low-frequency limit of APMS.
    pub fn seated_mass(&self) -> f64 {
        self.segments
            .iter()
            .filter(|s| !s.seat)
            .map(|s| s.mass)
            .sum()
    }

    /// True when the model has a seat between the floor and the body.
    pub fn has_seat(&self) -> bool {
        self.seat.is_some()
    }

    /// True when every link joins i to i+1 or i to the seat: then A(ω) is
    /// tridiagonal and the O(n) solve applies.
    pub fn is_tridiagonal(&self) -> bool {
        self.links.iter().all(|l| match l.lower {
            End::Segment(j) => j.abs_diff(l.upper) == 1,
            End::Seat => true,
        })
    }
}

impl End {
    /// The segment at the lower end, or None for the seat.
    pub fn segment(self) -> Option<usize> {
        match self {
            End::Segment(j) => Some(j),
            End::Seat => None,
        }
    }
}

impl fmt::Display for End {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            End::Segment(i) => write!(f, "segment {}", i + 1),
            End::Seat => f.write_str("seat"),
        }
    }
}
