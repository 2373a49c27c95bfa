//! Which column of a record is time and which is each axis, and in what
//! unit: from the header, or as the user names them. Nothing is guessed
//! that could be wrong: several acceleration columns that do not all name
//! an axis are refused.
//!
//! - Time: a column named `t`, `time`, `t_s` or `time_s` (any case);
//!   without one and without a sampling rate, the first column.
//! - Axes: after a unit suffix (`_m_s2`, `_ms2`, `_g`, `_mm_s2`) is removed,
//!   a header that is `x`/`y`/`z`, ends in `_x`/`_y`/`_z`, or is
//!   `ax`/`ay`/`az` names that axis. One acceleration column with no axis in
//!   its name is z (vertical), and the record says so.
//! - Units: a suffix sets the column's unit; the unit given applies to the
//!   rest (default m/s²); a suffix that contradicts the unit given is refused.

use super::RecordError;
use crate::time::{Axis, PerAxis, Unit};
use std::path::Path;

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
    pub named_by: NamedBy,
}

/// The record's layout: the time column (if any) and each axis present.
#[derive(Debug, Clone, PartialEq)]
pub struct Columns {
    pub time: Option<usize>,
    pub axes: PerAxis<AxisColumn>,
}

/// Time column names (compared in lower case).
const TIME_NAMES: [&str; 4] = ["t", "time", "t_s", "time_s"];

fn is_time(h: &str) -> bool {
    TIME_NAMES.contains(&h.to_ascii_lowercase().as_str())
}

/// The axis a header names, after its unit suffix is removed.
pub fn axis_of(header: &str) -> Option<Axis> {
    let (base, _) = Unit::split_suffix(header.trim());
    let b = base.to_ascii_lowercase();
    if let Some(a) = Axis::parse(&b) {
        return Some(a);
    }
    if let Some(rest) = b.strip_prefix('a')
        && rest.len() == 1
    {
        return Axis::parse(rest);
    }
    if let Some(i) = b.rfind('_')
        && i > 0
    {
        return Axis::parse(&b[i + 1..]);
    }
    None
}

/// Parses `x=COL,y=COL,z=COL` (any subset, any order).
pub fn parse_axes(spec: &str) -> Result<PerAxis<String>, RecordError> {
    let bad = |why: String| RecordError::BadAxes {
        spec: spec.to_string(),
        why,
    };
    let mut out = PerAxis::default();
    for part in spec.split(',').map(str::trim).filter(|p| !p.is_empty()) {
        let Some((a, col)) = part.split_once('=') else {
            return Err(bad(format!("'{part}' is not AXIS=COLUMN")));
        };
        let Some(axis) = Axis::parse(a) else {
            return Err(bad(format!("'{}' is not an axis: x, y or z", a.trim())));
        };
        if out.has(axis) {
            return Err(bad(format!("{axis} is named twice")));
        }
        let col = col.trim();
        if col.is_empty() {
            return Err(bad(format!("{axis} has no column")));
        }
        out.set(axis, col.to_string());
    }
    if out.is_empty() {
        return Err(bad("no axis: e.g. x=ax,y=ay,z=az".into()));
    }
    Ok(out)
}

/// The unit of a column: its suffix's, else the one given, else m/s².
fn unit_of(path: &Path, name: &str, given: Option<Unit>) -> Result<Unit, RecordError> {
    match (Unit::split_suffix(name).1, given) {
        (Some(s), Some(g)) if s != g => Err(RecordError::UnitClash {
            path: path.to_path_buf(),
            column: name.to_string(),
            suffix: s,
            given: g,
        }),
        (Some(s), _) => Ok(s),
        (None, g) => Ok(g.unwrap_or_default()),
    }
}

/// Maps `header` to time and axes.
pub fn map_columns(
    path: &Path,
    header: &[String],
    axes: &PerAxis<String>,
    unit: Option<Unit>,
    fs_given: bool,
) -> Result<Columns, RecordError> {
    let p = || path.to_path_buf();
    let listed = || header.join(", ");
    let named_time = header.iter().position(|h| is_time(h));
    let time = match named_time {
        Some(i) => Some(i),
        None if fs_given => None,
        None if header.len() >= 2 && axis_of(&header[0]).is_none() => Some(0),
        None => return Err(RecordError::NeedFs { path: p() }),
    };
    let mut out = Columns {
        time,
        axes: PerAxis::default(),
    };
    if !axes.is_empty() {
        for (axis, name) in axes.iter() {
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
                    axis,
                });
            }
            if let Some((other, _)) = out.axes.iter().find(|(_, c)| c.index == index) {
                return Err(RecordError::ColumnTwice {
                    path: p(),
                    column: name.clone(),
                    first: other,
                    second: axis,
                });
            }
            let unit = unit_of(path, name, unit)?;
            out.axes.set(
                axis,
                AxisColumn {
                    name: name.trim().to_string(),
                    index,
                    unit,
                    named_by: NamedBy::Given,
                },
            );
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
    let mapped: Vec<(usize, Option<Axis>)> =
        acc.iter().map(|&i| (i, axis_of(&header[i]))).collect();
    if acc.len() == 1 && mapped[0].1.is_none() {
        out.axes.set(
            Axis::Z,
            AxisColumn {
                name: header[only].clone(),
                index: only,
                unit: unit_of(path, &header[only], unit)?,
                named_by: NamedBy::Only,
            },
        );
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
    for (index, axis) in mapped {
        let Some(axis) = axis else { continue };
        let name = &header[index];
        if let Some(first) = out.axes.get(axis) {
            return Err(RecordError::SameAxis {
                path: p(),
                axis,
                first: first.name.clone(),
                second: name.clone(),
            });
        }
        out.axes.set(
            axis,
            AxisColumn {
                name: name.clone(),
                index,
                unit: unit_of(path, name, unit)?,
                named_by: NamedBy::Header,
            },
        );
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn h(cols: &str) -> Vec<String> {
        cols.split(',').map(String::from).collect()
    }

    fn map(cols: &str, axes: &str, unit: Option<Unit>) -> Result<Columns, RecordError> {
        let a = if axes.is_empty() {
            PerAxis::default()
        } else {
            parse_axes(axes).unwrap()
        };
        map_columns(Path::new("r.csv"), &h(cols), &a, unit, false)
    }

    fn names(c: &Columns) -> Vec<(Axis, String, Unit)> {
        c.axes
            .iter()
            .map(|(a, c)| (a, c.name.clone(), c.unit))
            .collect()
    }

    #[test]
    fn headers_name_their_axes() {
        for (head, want) in [
            ("x", Some(Axis::X)),
            ("seat_x_m_s2", Some(Axis::X)),
            ("acc_z", Some(Axis::Z)),
            ("az_g", Some(Axis::Z)),
            ("AY", Some(Axis::Y)),
            ("y_mm_s2", Some(Axis::Y)),
            ("z_ms2", Some(Axis::Z)),
            ("acc", None),
            ("speed", None),
            ("axz", None),
            ("_z", None),
            ("acc_m_s2", None),
        ] {
            assert_eq!(axis_of(head), want, "{head}");
        }
    }

    #[test]
    fn a_tri_axial_header_maps_every_axis_with_units() {
        let c = map("t_s,ax,ay_g,az_mm_s2", "", None).unwrap();
        assert_eq!(c.time, Some(0));
        use Unit::*;
        assert_eq!(
            names(&c),
            vec![
                (Axis::X, "ax".into(), MetrePerSecondSquared),
                (Axis::Y, "ay_g".into(), G),
                (Axis::Z, "az_mm_s2".into(), MillimetrePerSecondSquared)
            ]
        );
        let g = map("time,x,y,z", "", Some(G)).unwrap();
        assert!(
            g.axes
                .iter()
                .all(|(_, c)| c.unit == G && c.named_by == NamedBy::Header)
        );
    }

    #[test]
    fn one_unnamed_column_is_z_and_says_so() {
        let c = map("t_s,acc_m_s2", "", None).unwrap();
        let z = c.axes.get(Axis::Z).unwrap();
        assert_eq!((z.index, z.named_by), (1, NamedBy::Only));
        // Without a time name, the first column is time as before.
        assert_eq!(map("sec,acc", "", None).unwrap().time, Some(0));
    }

    #[test]
    fn ambiguous_records_are_refused() {
        let e = map("t_s,ax,ay,az,speed", "", None).unwrap_err().to_string();
        assert!(
            e.contains("columns ax, ay, az, speed, and no axis in the name of speed:"),
            "{e}"
        );
        let e = map("t_s,a1,a2", "", None).unwrap_err();
        assert!(matches!(e, RecordError::Unnamed { .. }), "{e}");
        let e = map("t_s,az,acc_z", "", None).unwrap_err();
        assert!(
            matches!(e, RecordError::SameAxis { axis: Axis::Z, .. }),
            "{e}"
        );
        let e = map("t_s,az_g", "", Some(Unit::MetrePerSecondSquared)).unwrap_err();
        assert!(matches!(e, RecordError::UnitClash { .. }), "{e}");
        // A header of axes only and no rate: no column is time.
        let e = map("x,y,z", "", None).unwrap_err();
        assert!(matches!(e, RecordError::NeedFs { .. }), "{e}");
    }

    #[test]
    fn given_axes_pick_their_columns() {
        let c = map("t_s,a1,a2,a3", "z=a3,x=a1", None).unwrap();
        assert_eq!(c.axes.get(Axis::Z).unwrap().index, 3);
        assert_eq!(c.axes.get(Axis::X).unwrap().index, 1);
        assert!(!c.axes.has(Axis::Y));
        let e = map("t_s,a1", "z=a9", None).unwrap_err();
        assert!(matches!(e, RecordError::MissingColumn { .. }), "{e}");
        let e = map("t_s,a1", "z=t_s", None).unwrap_err();
        assert!(matches!(e, RecordError::TimeAsAxis { .. }), "{e}");
        let e = map("t_s,a1", "z=a1,x=a1", None).unwrap_err();
        assert!(matches!(e, RecordError::ColumnTwice { .. }), "{e}");
    }

    #[test]
    fn axes_specs_parse_or_say_why() {
        let a = parse_axes(" z = acc , x=f").unwrap();
        assert_eq!(a.get(Axis::Z).map(String::as_str), Some("acc"));
        assert_eq!(a.get(Axis::X).map(String::as_str), Some("f"));
        for bad in ["", "q=a", "z", "z=", "z=a,z=b"] {
            assert!(
                matches!(parse_axes(bad), Err(RecordError::BadAxes { .. })),
                "{bad}"
            );
        }
    }
}
