//! A seat under the body (SPEC §11): its rules, and the body without it.
//!
//! With a seat the base is the cab floor; the seat's segments (a pan, a
//! frame) sit between it and the body. The rules make "the pan" and "the
//! suspension" mean one thing each: every link from the body to the seat goes
//! to the pan (so the pan's force on the body is the whole seat force), no
//! body segment touches the floor, and the suspension joins a seat segment
//! to the floor.

use super::body::{Body, End, Link, Segment};
use super::error::ModelError;
use crate::body::limits::MAX_STROKE_M;
use crate::io::excerpt::quote;

impl Body {
    /// The seat's rules; called by `validate` after the general ones.
    pub(super) fn validate_seat(&self) -> Result<(), ModelError> {
        let name = |i: usize| quote(&self.segments[i].name);
        let Some(seat) = &self.seat else {
            return match self.segments.iter().position(|s| s.seat) {
                Some(i) => Err(ModelError::SeatPartsWithoutSeat(name(i))),
                None => Ok(()),
            };
        };
        let (n, links) = (self.n(), self.links.len());
        if seat.pan >= n {
            return Err(ModelError::BadPan {
                index: seat.pan,
                count: n,
            });
        }
        if !self.segments[seat.pan].seat {
            return Err(ModelError::PanNotSeat(name(seat.pan)));
        }
        if self.segments[self.head].seat {
            return Err(ModelError::HeadOnSeat(name(self.head)));
        }
        if seat.suspension >= links {
            return Err(ModelError::BadSuspension {
                index: seat.suspension,
                count: links,
            });
        }
        let s = &self.links[seat.suspension];
        if s.lower != End::Seat || !self.segments[s.upper].seat {
            return Err(ModelError::SuspensionNotToFloor(quote(&s.name)));
        }
        if !(seat.stroke_m.is_finite() && seat.stroke_m > 0.0 && seat.stroke_m <= MAX_STROKE_M) {
            return Err(ModelError::BadStroke(seat.stroke_m));
        }
        let on_seat = |i: usize| self.segments[i].seat;
        let mut carried = false;
        for l in &self.links {
            let ends = [Some(l.upper), l.lower.segment()];
            let body_end = ends.into_iter().flatten().find(|&i| !on_seat(i));
            let Some(b) = body_end else { continue };
            match l.lower {
                End::Seat => {
                    return Err(ModelError::BodyOnFloor {
                        link: quote(&l.name),
                        segment: name(b),
                    });
                }
                End::Segment(j) => {
                    let other = if j == b { l.upper } else { j };
                    if !on_seat(other) {
                        continue;
                    }
                    if other != seat.pan {
                        return Err(ModelError::BodyOffPan {
                            link: quote(&l.name),
                            ends: Box::new((name(b), name(other), name(seat.pan))),
                        });
                    }
                    carried = true;
                }
            }
        }
        if !carried {
            return Err(ModelError::PanCarriesNothing(name(seat.pan)));
        }
        Ok(())
    }

    /// The pan's index, when the model has a seat.
    pub fn pan(&self) -> Option<usize> {
        self.seat.as_ref().map(|s| s.pan)
    }

    /// The body on a rigid seat: the seat's segments and links dropped, and
    /// every link to the pan made a link to the (rigid) seat. A model without
    /// a seat comes back unchanged.
    pub fn without_seat(&self) -> Body {
        let Some(seat) = &self.seat else {
            return self.clone();
        };
        let mut index = vec![None; self.n()];
        let mut segments: Vec<Segment> = Vec::new();
        for (i, s) in self.segments.iter().enumerate() {
            if !s.seat {
                index[i] = Some(segments.len());
                segments.push(s.clone());
            }
        }
        let links = self
            .links
            .iter()
            .filter_map(|l| {
                let (upper, lower) = match (index[l.upper], l.lower) {
                    (Some(u), End::Segment(j)) => match index[j] {
                        Some(v) => (u, End::Segment(v)),
                        None if j == seat.pan => (u, End::Seat),
                        None => return None,
                    },
                    (None, End::Segment(j)) if l.upper == seat.pan => (index[j]?, End::Seat),
                    _ => return None,
                };
                Some(Link {
                    upper,
                    lower,
                    ..l.clone()
                })
            })
            .collect();
        Body {
            segments,
            links,
            head: index[self.head].unwrap_or(0),
            body_mass: self.body_mass,
            seat: None,
        }
    }
}
