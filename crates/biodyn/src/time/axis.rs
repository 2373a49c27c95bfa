//! The three axes of a seat record (ISO 2631-1 §4, basicentric, seated):
//! x fore-and-aft, y lateral, z vertical; and values held per axis.
//!
//! The axis is a property of the record (which column is which direction);
//! what each axis is weighted with and its k factors belong to ISO 2631-1
//! (`iso2631::AXES`).

use std::fmt;

/// One translational axis at the seat surface.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Axis {
    /// Fore-and-aft (back to chest).
    X,
    /// Lateral (right to left side).
    Y,
    /// Vertical (buttocks to head): the axis the body model is driven on.
    Z,
}

impl Axis {
    /// In the standard's order, which is also the order ties are broken in.
    pub const ALL: [Axis; 3] = [Axis::X, Axis::Y, Axis::Z];

    /// "x", "y" or "z".
    pub fn name(self) -> &'static str {
        match self {
            Axis::X => "x",
            Axis::Y => "y",
            Axis::Z => "z",
        }
    }

    /// The direction in words, for reports.
    pub fn direction(self) -> &'static str {
        match self {
            Axis::X => "fore-and-aft",
            Axis::Y => "lateral",
            Axis::Z => "vertical",
        }
    }

    /// 0, 1, 2.
    pub fn index(self) -> usize {
        self as usize
    }

    /// `x`, `y` or `z`, any case.
    pub fn parse(s: &str) -> Option<Axis> {
        match s.trim().to_ascii_lowercase().as_str() {
            "x" => Some(Axis::X),
            "y" => Some(Axis::Y),
            "z" => Some(Axis::Z),
            _ => None,
        }
    }
}

impl fmt::Display for Axis {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// One row of a record: the acceleration on x, y, z in m/s² (0 on an
/// axis the record does not have).
pub type Row = [f64; 3];

/// A value for each axis a record or an operation has (any subset).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PerAxis<T>(pub [Option<T>; 3]);

impl<T> Default for PerAxis<T> {
    fn default() -> Self {
        PerAxis([None, None, None])
    }
}

impl<T> PerAxis<T> {
    pub fn get(&self, axis: Axis) -> Option<&T> {
        self.0[axis.index()].as_ref()
    }

    pub fn set(&mut self, axis: Axis, value: T) {
        self.0[axis.index()] = Some(value);
    }

    pub fn has(&self, axis: Axis) -> bool {
        self.0[axis.index()].is_some()
    }

    pub fn is_empty(&self) -> bool {
        self.0.iter().all(Option::is_none)
    }

    /// The axes present, with their values, in x, y, z order.
    pub fn iter(&self) -> impl Iterator<Item = (Axis, &T)> {
        Axis::ALL
            .into_iter()
            .filter_map(move |a| self.get(a).map(|v| (a, v)))
    }

    /// The axes present, with their values to change.
    pub fn iter_mut(&mut self) -> impl Iterator<Item = (Axis, &mut T)> {
        Axis::ALL
            .into_iter()
            .zip(self.0.iter_mut())
            .filter_map(|(a, v)| v.as_mut().map(|v| (a, v)))
    }

    pub fn axes(&self) -> impl Iterator<Item = Axis> + '_ {
        self.iter().map(|(a, _)| a)
    }

    pub fn map<U>(&self, mut f: impl FnMut(Axis, &T) -> U) -> PerAxis<U> {
        let mut out = PerAxis::default();
        for (a, v) in self.iter() {
            out.set(a, f(a, v));
        }
        out
    }
}

impl PerAxis<f64> {
    /// The axis with the largest value, and the value; on a tie the first in
    /// x, y, z order. None when no axis is present.
    pub fn highest(&self) -> Option<(Axis, f64)> {
        let mut best: Option<(Axis, f64)> = None;
        for (a, &v) in self.iter() {
            if best.is_none_or(|(_, b)| v > b) {
                best = Some((a, v));
            }
        }
        best
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn highest_is_the_largest_and_ties_go_to_the_first_axis() {
        let mut v = PerAxis::default();
        assert_eq!(v.highest(), None);
        v.set(Axis::Z, 0.5);
        v.set(Axis::X, 0.7);
        assert_eq!(v.highest(), Some((Axis::X, 0.7)));
        v.set(Axis::Y, 0.9);
        assert_eq!(v.highest(), Some((Axis::Y, 0.9)));
        let mut t = PerAxis::default();
        t.set(Axis::Z, 1.0);
        t.set(Axis::Y, 1.0);
        assert_eq!(t.highest(), Some((Axis::Y, 1.0)));
    }

    #[test]
    fn parse_names_and_indices() {
        for a in Axis::ALL {
            assert_eq!(Axis::parse(&a.name().to_uppercase()), Some(a));
            assert_eq!(Axis::ALL[a.index()], a);
        }
        assert_eq!(Axis::parse("w"), None);
    }
}
