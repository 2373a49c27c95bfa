//! The measuring points of a seated person besides the seat surface's
//! translations (ISO 2631-1:1997 §8.2.2, Figure 1): the backrest, the feet
//! and the seat's rotations; their channels and how a header names them.
//!
//! Like [`Axis`], a point is a property of the record (which column was
//! measured where); what each channel is weighted with and its comfort
//! factor belong to ISO 2631-1 (`iso2631::POINTS`).

use super::{Axis, Row, Unit};
use std::fmt;

/// A measuring point other than the seat surface's translations.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Point {
    /// The backrest, at the back (x, y, z translations).
    Backrest,
    /// The feet, on the floor (x, y, z translations).
    Feet,
    /// The seat surface's rotations: roll (rx), pitch (ry), yaw (rz), rad/s².
    Rotation,
}

impl Point {
    pub const ALL: [Point; 3] = [Point::Backrest, Point::Feet, Point::Rotation];

    /// "backrest", "feet", "rotation": the JSON key and the report's word.
    pub fn name(self) -> &'static str {
        match self {
            Point::Backrest => "backrest",
            Point::Feet => "feet",
            Point::Rotation => "rotation",
        }
    }

    /// 0, 1, 2.
    pub fn index(self) -> usize {
        self as usize
    }

    /// Rotations are angular accelerations (rad/s²), the others linear (m/s²).
    pub fn is_angular(self) -> bool {
        self == Point::Rotation
    }
}

/// One channel at another point: the point and the axis it is along (or,
/// for rotations, about).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct PointAxis {
    pub point: Point,
    pub axis: Axis,
}

/// Every channel's acceleration at one instant, in [`PointAxis::slot`]
/// order: m/s² for the backrest and feet, rad/s² for the rotations (0 for a
/// channel the record does not have).
pub type PointRow = [f64; 9];

/// One instant at the seat and at the other points.
pub type Frame = (Row, PointRow);

/// The header suffix of an angular acceleration.
pub const RAD_S2: &str = "_rad_s2";

impl PointAxis {
    /// Backrest x, y, z; feet x, y, z; rx, ry, rz: [`PointRow`]'s order.
    pub const ALL: [PointAxis; 9] = {
        let mut out = [PointAxis {
            point: Point::Backrest,
            axis: Axis::X,
        }; 9];
        let mut i = 0;
        while i < 9 {
            out[i] = PointAxis {
                point: Point::ALL[i / 3],
                axis: Axis::ALL[i % 3],
            };
            i += 1;
        }
        out
    };

    pub fn new(point: Point, axis: Axis) -> PointAxis {
        PointAxis { point, axis }
    }

    /// Its place in a [`PointRow`].
    pub fn slot(self) -> usize {
        self.point.index() * 3 + self.axis.index()
    }

    /// `backrest_x`, `feet_z`, `rx`: the column name that names it.
    pub fn name(self) -> &'static str {
        const NAMES: [&str; 9] = [
            "backrest_x",
            "backrest_y",
            "backrest_z",
            "feet_x",
            "feet_y",
            "feet_z",
            "rx",
            "ry",
            "rz",
        ];
        NAMES[self.slot()]
    }

    /// `backrest_x`, `feet_y`, `rx` or `seat_rx` (any case), as `--axes`
    /// keys them.
    pub fn parse(s: &str) -> Option<PointAxis> {
        let b = s.trim().to_ascii_lowercase();
        let b = b
            .strip_prefix("seat_")
            .filter(|r| r.starts_with('r'))
            .unwrap_or(&b);
        PointAxis::ALL.into_iter().find(|p| p.name() == b)
    }

    /// The channel a header names, after its unit suffix is removed:
    /// `…backrest_x`, `…feet_z` (e.g. `acc_backrest_x_g`), `rx`, `seat_ry`,
    /// `…_rz_rad_s2`. None for anything else (a seat axis among them).
    pub fn of_header(header: &str) -> Option<PointAxis> {
        let h = header.trim();
        let lower = h.to_ascii_lowercase();
        let base = match lower.strip_suffix(RAD_S2).filter(|b| !b.is_empty()) {
            Some(b) => b.to_string(),
            None => Unit::split_suffix(h).0.to_ascii_lowercase(),
        };
        let (stem, last) = match base.rfind('_') {
            Some(i) => (&base[..i], &base[i + 1..]),
            None => ("", base.as_str()),
        };
        if let Some(a) = last.strip_prefix('r').and_then(Axis::parse)
            && last.len() == 2
        {
            return Some(PointAxis::new(Point::Rotation, a));
        }
        let axis = Axis::parse(last).filter(|_| last.len() == 1)?;
        let at = |word: &str| stem == word || stem.ends_with(&format!("_{word}"));
        if at("backrest") {
            Some(PointAxis::new(Point::Backrest, axis))
        } else if at("feet") {
            Some(PointAxis::new(Point::Feet, axis))
        } else {
            None
        }
    }
}

impl fmt::Display for PointAxis {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Any channel a record's column can be: a seat axis or another point's.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Channel {
    Seat(Axis),
    Point(PointAxis),
}

impl fmt::Display for Channel {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Channel::Seat(a) => a.fmt(f),
            Channel::Point(p) => p.fmt(f),
        }
    }
}

/// A value for each channel at the other points a record has (any subset).
#[derive(Debug, Clone, PartialEq)]
pub struct PerPoint<T>(pub [Option<T>; 9]);

impl<T> Default for PerPoint<T> {
    fn default() -> Self {
        PerPoint(std::array::from_fn(|_| None))
    }
}

impl<T> PerPoint<T> {
    pub fn get(&self, p: PointAxis) -> Option<&T> {
        self.0[p.slot()].as_ref()
    }

    pub fn set(&mut self, p: PointAxis, value: T) {
        self.0[p.slot()] = Some(value);
    }

    pub fn has(&self, p: PointAxis) -> bool {
        self.0[p.slot()].is_some()
    }

    pub fn is_empty(&self) -> bool {
        self.0.iter().all(Option::is_none)
    }

    /// The channels present, with their values, in [`PointAxis::ALL`] order.
    pub fn iter(&self) -> impl Iterator<Item = (PointAxis, &T)> {
        PointAxis::ALL
            .into_iter()
            .filter_map(move |p| self.get(p).map(|v| (p, v)))
    }

    /// The channels present, with their values to change.
    pub fn iter_mut(&mut self) -> impl Iterator<Item = (PointAxis, &mut T)> {
        PointAxis::ALL
            .into_iter()
            .zip(self.0.iter_mut())
            .filter_map(|(p, v)| v.as_mut().map(|v| (p, v)))
    }

    pub fn channels(&self) -> impl Iterator<Item = PointAxis> + '_ {
        self.iter().map(|(p, _)| p)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slots_names_and_parsing_agree() {
        for (i, p) in PointAxis::ALL.into_iter().enumerate() {
            assert_eq!(p.slot(), i);
            assert_eq!(PointAxis::parse(&p.name().to_uppercase()), Some(p));
            assert_eq!(PointAxis::of_header(p.name()), Some(p));
        }
        let rx = PointAxis::new(Point::Rotation, Axis::X);
        assert_eq!(PointAxis::parse("seat_rx"), Some(rx));
        assert_eq!(PointAxis::parse("seat_x"), None);
        assert_eq!(PointAxis::parse("x"), None);
    }

    #[test]
    fn headers_name_their_points() {
        use Axis::*;
        use Point::*;
        for (head, want) in [
            ("backrest_x", Some((Backrest, X))),
            ("backrest_y_m_s2", Some((Backrest, Y))),
            ("acc_backrest_z_g", Some((Backrest, Z))),
            ("FEET_Z_mm_s2", Some((Feet, Z))),
            ("feet_x", Some((Feet, X))),
            ("rx", Some((Rotation, X))),
            ("seat_ry_rad_s2", Some((Rotation, Y))),
            ("rz_rad_s2", Some((Rotation, Z))),
            // The seat's own axes, and names that are no point.
            ("seat_x", None),
            ("az", None),
            ("x_g", None),
            ("notbackrest_x", None),
            ("feet", None),
            ("rxy", None),
            ("_rad_s2", None),
            ("backrest_w", None),
        ] {
            assert_eq!(
                PointAxis::of_header(head),
                want.map(|(p, a)| PointAxis::new(p, a)),
                "{head}"
            );
        }
    }
}
