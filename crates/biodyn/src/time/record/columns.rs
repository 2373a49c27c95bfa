//! Which column of a record is time and which is each axis, and in what
//! unit: from the header, or as the user names them. Nothing is guessed
//! that could be wrong: several acceleration columns that do not all name
//! an axis are refused.
//!
//! - Time: a column named `t`, `time` or `sec` (seconds), or with its unit,
//!   `t_s`, `time_ms`, `Time [ms]`, `t (us)` ([`time_name`]); without one and
//!   without a sampling rate, the first column, if its name says time; a
//!   first column whose name says no time unit is refused, never read as s.
//! - Axes: after a unit is removed (a suffix `_m_s2`, `_ms2`, `_g`,
//!   `_mm_s2`, or `[g]`, `(m/s²)`, ` in g` at the end), a header that is
//!   `x`/`y`/`z`, ends in `_x`, ` x` or `-x`, or is `ax`/`ay`/`az` names that
//!   axis. One acceleration column with no axis in its name is z
//!   (vertical), and the record says so.
//! - Other points (ISO 2631-1 §8.2.2): `…backrest_x`, `…feet_z`, `rx`,
//!   `seat_ry`, `…_rz` ([`PointAxis::of_header`]), looked for before the
//!   seat's axes (`backrest_x` ends in `_x` but is not the seat's x).
//! - Units: a suffix sets the column's unit; the unit given applies to the
//!   rest; with neither, m/s² is assumed and every report says so
//!   ([`UnitBy::Assumed`]). A suffix that contradicts the unit given is
//!   refused, and so is a bracketed unit that is no acceleration (`[V]`).
//!   Rotations are in rad/s² (`_rad_s2`, or no suffix): a linear suffix on
//!   one is refused, and so is `_rad_s2` on a linear channel.

use super::RecordError;
use crate::time::point::RAD_S2;
use crate::time::{Axis, Channel, HeaderUnit, PerAxis, PerPoint, PointAxis, Unit, split_unit};
use std::path::Path;
pub use time_name::{SECOND, TimeName, TimeUnit, time_name};

mod time_name;

/// Where a column's unit came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum UnitBy {
    /// Its name (`az_g`, `Acc Z [g]`).
    Header,
    /// The unit the user gave for columns whose name has none.
    Given,
    /// Neither: m/s², assumed, and said in every report.
    Assumed,
}

/// How an axis's column was chosen.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NamedBy {
    /// Its header names the axis.
    Header,
    /// The user named the column for the axis.
    Given,
    /// The record's only acceleration column, with no axis in its name:
    /// taken as z (vertical).
    Only,
}

/// One axis of a record: its column and unit.
#[derive(Debug, Clone, PartialEq)]
pub struct AxisColumn {
    pub name: String,
    pub index: usize,
    pub unit: Unit,
    pub unit_by: UnitBy,
    pub named_by: NamedBy,
    /// The column's mean, m/s² (rad/s²), where it was removed before
    /// anything was judged (a DC-coupled accelerometer's gravity).
    pub mean_removed: Option<f64>,
}

/// One channel at another point: its column and unit.
#[derive(Debug, Clone, PartialEq)]
pub struct PointColumn {
    pub name: String,
    pub index: usize,
    /// None for a rotation: rad/s².
    pub unit: Option<Unit>,
    pub unit_by: UnitBy,
    pub named_by: NamedBy,
    /// The column's mean, m/s² (rad/s²), where it was removed before
    /// anything was judged (a DC-coupled accelerometer's gravity).
    pub mean_removed: Option<f64>,
}

impl PointColumn {
    /// "m/s2", "g", "mm/s2" or "rad/s2".
    pub fn unit_name(&self) -> &'static str {
        self.unit.map_or("rad/s2", Unit::name)
    }

    /// Per unit of the column: m/s² (or rad/s², 1).
    pub fn scale(&self) -> f64 {
        self.unit.map_or(1.0, Unit::to_m_s2)
    }
}

/// The record's layout: the time column (if any), each seat axis present
/// and each channel at another point.
#[derive(Debug, Clone, PartialEq)]
pub struct Columns {
    pub time: Option<usize>,
    /// The time column's unit (seconds without one).
    pub time_unit: TimeUnit,
    pub axes: PerAxis<AxisColumn>,
    pub points: PerPoint<PointColumn>,
}

/// What a column names: a point's channel first, else a seat axis.
pub fn channel_of(header: &str) -> Option<Channel> {
    PointAxis::of_header(header)
        .map(Channel::Point)
        .or_else(|| axis_of(header).map(Channel::Seat))
}

/// The axis a header names, after its unit is removed.
pub fn axis_of(header: &str) -> Option<Axis> {
    let (base, _) = split_unit(header.trim());
    let b = base.to_ascii_lowercase();
    if let Some(a) = Axis::parse(&b) {
        return Some(a);
    }
    if let Some(rest) = b.strip_prefix('a')
        && rest.len() == 1
    {
        return Axis::parse(rest);
    }
    if let Some(i) = b.trim_end().rfind(['_', ' ', '-'])
        && i > 0
    {
        return Axis::parse(b[i + 1..].trim_end());
    }
    None
}

/// Parses `x=COL,y=COL,z=COL` (any subset, any order): the seat's axes only.
pub fn parse_axes(spec: &str) -> Result<PerAxis<String>, RecordError> {
    let (axes, points) = parse_channels(spec)?;
    if let Some(p) = points.channels().next() {
        return Err(RecordError::BadAxes {
            spec: spec.to_string(),
            why: format!("'{p}' is another measuring point: only the seat's x, y and z here"),
        });
    }
    Ok(axes)
}

/// Parses `x=COL,…,backrest_x=COL,feet_z=COL,rx=COL` (any subset, any
/// order): the seat's axes and the other points' channels.
pub fn parse_channels(spec: &str) -> Result<(PerAxis<String>, PerPoint<String>), RecordError> {
    let bad = |why: String| RecordError::BadAxes {
        spec: spec.to_string(),
        why,
    };
    let mut axes = PerAxis::default();
    let mut points = PerPoint::default();
    for part in spec.split(',').map(str::trim).filter(|p| !p.is_empty()) {
        let Some((a, col)) = part.split_once('=') else {
            return Err(bad(format!("'{part}' is not AXIS=COLUMN")));
        };
        let channel = match (Axis::parse(a), PointAxis::parse(a)) {
            (Some(axis), _) => Channel::Seat(axis),
            (None, Some(p)) => Channel::Point(p),
            (None, None) => {
                return Err(bad(format!(
                    "'{}' is not an axis: x, y or z, or another point's backrest_x, feet_z, rx …",
                    a.trim()
                )));
            }
        };
        let twice = match channel {
            Channel::Seat(axis) => axes.has(axis),
            Channel::Point(p) => points.has(p),
        };
        if twice {
            return Err(bad(format!("{channel} is named twice")));
        }
        let col = col.trim();
        if col.is_empty() {
            return Err(bad(format!("{channel} has no column")));
        }
        match channel {
            Channel::Seat(axis) => axes.set(axis, col.to_string()),
            Channel::Point(p) => points.set(p, col.to_string()),
        }
    }
    if axes.is_empty() && points.is_empty() {
        return Err(bad("no axis: e.g. x=ax,y=ay,z=az".into()));
    }
    Ok((axes, points))
}

/// The unit of a column: its name's, else the one given, else m/s²
/// (assumed, and said); a bracketed unit that is no acceleration is refused.
fn unit_of(path: &Path, name: &str, given: Option<Unit>) -> Result<(Unit, UnitBy), RecordError> {
    match (split_unit(name).1, given) {
        (HeaderUnit::Other(unit), _) => Err(RecordError::UnknownUnit {
            path: path.to_path_buf(),
            column: name.to_string(),
            unit: unit.to_string(),
        }),
        (HeaderUnit::Known(s), Some(g)) if s != g => Err(RecordError::UnitClash {
            path: path.to_path_buf(),
            column: name.to_string(),
            suffix: s,
            given: g,
        }),
        (HeaderUnit::Known(s), _) => Ok((s, UnitBy::Header)),
        (HeaderUnit::None, Some(g)) => Ok((g, UnitBy::Given)),
        (HeaderUnit::None, None) => Ok((Unit::default(), UnitBy::Assumed)),
    }
}

/// The unit of a column at another point: rad/s² (None) for a rotation,
/// refusing a linear suffix; a linear unit otherwise, refusing `_rad_s2`.
fn point_unit(
    path: &Path,
    name: &str,
    p: PointAxis,
    given: Option<Unit>,
) -> Result<(Option<Unit>, UnitBy), RecordError> {
    let rad = name.to_ascii_lowercase().ends_with(RAD_S2);
    match (p.point.is_angular(), rad, Unit::split_suffix(name).1) {
        (true, true, _) => Ok((None, UnitBy::Header)),
        (true, false, None) => Ok((None, UnitBy::Assumed)),
        (true, false, Some(suffix)) => Err(RecordError::RotationUnit {
            path: path.to_path_buf(),
            column: name.to_string(),
            channel: p,
            suffix,
        }),
        (false, true, _) => Err(RecordError::RadOnLinear {
            path: path.to_path_buf(),
            column: name.to_string(),
            channel: p,
        }),
        (false, false, _) => unit_of(path, name, given).map(|(u, by)| (Some(u), by)),
    }
}

/// The columns the user named for the seat's axes and the other points.
#[derive(Debug, Clone, Copy)]
pub struct Given<'a> {
    pub axes: &'a PerAxis<String>,
    pub points: &'a PerPoint<String>,
}

impl Given<'_> {
    fn is_empty(&self) -> bool {
        self.axes.is_empty() && self.points.is_empty()
    }

    fn iter(&self) -> impl Iterator<Item = (Channel, &String)> {
        let axes = self.axes.iter().map(|(a, n)| (Channel::Seat(a), n));
        axes.chain(self.points.iter().map(|(p, n)| (Channel::Point(p), n)))
    }
}

impl Columns {
    /// Sets `channel`'s column.
    fn set(
        &mut self,
        path: &Path,
        channel: Channel,
        name: &str,
        index: usize,
        unit: Option<Unit>,
        named_by: NamedBy,
    ) -> Result<(), RecordError> {
        let name = name.trim().to_string();
        match channel {
            Channel::Seat(axis) => {
                let (unit, unit_by) = unit_of(path, &name, unit)?;
                let c = AxisColumn {
                    name,
                    index,
                    unit,
                    unit_by,
                    named_by,
                    mean_removed: None,
                };
                self.axes.set(axis, c);
            }
            Channel::Point(p) => {
                let (unit, unit_by) = point_unit(path, &name, p, unit)?;
                let c = PointColumn {
                    name,
                    index,
                    unit,
                    unit_by,
                    named_by,
                    mean_removed: None,
                };
                self.points.set(p, c);
            }
        }
        Ok(())
    }

    /// The channel already read from column `index`.
    fn at(&self, index: usize) -> Option<Channel> {
        let seat = self.axes.iter().find(|(_, c)| c.index == index);
        let point = self.points.iter().find(|(_, c)| c.index == index);
        seat.map(|(a, _)| Channel::Seat(a))
            .or(point.map(|(p, _)| Channel::Point(p)))
    }

    /// The name of the column read for `channel`.
    fn name_of(&self, channel: Channel) -> Option<&str> {
        match channel {
            Channel::Seat(a) => self.axes.get(a).map(|c| c.name.as_str()),
            Channel::Point(p) => self.points.get(p).map(|c| c.name.as_str()),
        }
    }
}

/// Maps `header` to time, the seat's axes and the other points' channels.
pub fn map_columns(
    path: &Path,
    header: &[String],
    given: Given<'_>,
    unit: Option<Unit>,
    fs_given: bool,
) -> Result<Columns, RecordError> {
    let p = || path.to_path_buf();
    let listed = || header.join(", ");
    let named_time = header.iter().position(|h| time_name(h) != TimeName::No);
    let time = match named_time {
        Some(i) => Some(i),
        None if fs_given => None,
        None if header.len() >= 2 && channel_of(&header[0]).is_none() => {
            return Err(RecordError::TimeUnknown {
                path: p(),
                column: header[0].clone(),
            });
        }
        None => return Err(RecordError::NeedFs { path: p() }),
    };
    let time_unit = match time.map(|i| time_name(&header[i])) {
        Some(TimeName::Unknown(unit)) => {
            return Err(RecordError::TimeUnit {
                path: p(),
                column: time.map(|i| header[i].clone()).unwrap_or_default(),
                unit: unit.to_string(),
            });
        }
        Some(TimeName::Unit(u)) => u,
        _ => SECOND,
    };
    let mut out = Columns {
        time,
        time_unit,
        axes: PerAxis::default(),
        points: PerPoint::default(),
    };
    if !given.is_empty() {
        for (channel, name) in given.iter() {
            let index = header
                .iter()
                .position(|h| h == name.trim())
                .ok_or_else(|| RecordError::MissingColumn {
                    path: p(),
                    name: name.clone(),
                    available: listed(),
                })?;
            if Some(index) == time {
                return Err(RecordError::TimeAsAxis {
                    path: p(),
                    column: name.clone(),
                    axis: channel,
                });
            }
            if let Some(first) = out.at(index) {
                return Err(RecordError::ColumnTwice {
                    path: p(),
                    column: name.clone(),
                    first,
                    second: channel,
                });
            }
            out.set(path, channel, name, index, unit, NamedBy::Given)?;
        }
        return Ok(out);
    }
    let acc: Vec<usize> = (0..header.len()).filter(|&i| Some(i) != time).collect();
    let Some(&only) = acc.first() else {
        return Err(RecordError::MissingColumn {
            path: p(),
            name: "(an acceleration column besides time)".into(),
            available: listed(),
        });
    };
    let mapped: Vec<(usize, Option<Channel>)> =
        acc.iter().map(|&i| (i, channel_of(&header[i]))).collect();
    if acc.len() == 1 && mapped[0].1.is_none() {
        let z = Channel::Seat(Axis::Z);
        out.set(path, z, &header[only], only, unit, NamedBy::Only)?;
        return Ok(out);
    }
    let unnamed: Vec<&str> = mapped
        .iter()
        .filter(|(_, a)| a.is_none())
        .map(|&(i, _)| header[i].as_str())
        .collect();
    if !unnamed.is_empty() {
        return Err(RecordError::Unnamed {
            path: p(),
            columns: acc
                .iter()
                .map(|&i| header[i].as_str())
                .collect::<Vec<_>>()
                .join(", "),
            unnamed: unnamed.join(", "),
        });
    }
    for (index, channel) in mapped {
        let Some(channel) = channel else { continue };
        let name = &header[index];
        if let Some(first) = out.name_of(channel) {
            let (first, second) = (first.to_string(), name.clone());
            return Err(match channel {
                Channel::Seat(axis) => RecordError::SameAxis {
                    path: p(),
                    axis,
                    first,
                    second,
                },
                Channel::Point(point) => RecordError::SamePoint {
                    path: p(),
                    channel: point,
                    first,
                    second,
                },
            });
        }
        out.set(path, channel, name, index, unit, NamedBy::Header)?;
    }
    Ok(out)
}

#[cfg(test)]
mod tests;
