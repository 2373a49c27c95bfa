//! Edits of the day's operations, each checked as the day file's parser
//! checks it (`exposure::DayFile::parse`): a name of 1 to 200 printable
//! characters, hours over 0 with the day at most 24 h, a_w finite and
//! ≥ 0 (m/s², before k), a record path with the record reader's `axes`
//! grammar and units. One exception: an operation may have no a_w yet
//! (just added); it counts for nothing and the day file refuses to save
//! it until it has one.

use biodyn::exposure::{
    MAX_DAY_H, MAX_OPERATION_NAME, Measured, OperationSpec, RecordSource, Source, axes_text,
    parse_axes,
};
use biodyn::time::{Axis, PerAxis, Unit};
use std::path::Path;

/// A column of the operations table.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Col {
    Name,
    Hours,
    Aw(Axis),
    Record,
}

impl Col {
    pub const ALL: [Col; 6] = [
        Col::Name,
        Col::Hours,
        Col::Aw(Axis::X),
        Col::Aw(Axis::Y),
        Col::Aw(Axis::Z),
        Col::Record,
    ];

    pub fn index(self) -> usize {
        Col::ALL.iter().position(|&c| c == self).unwrap_or(0)
    }

    /// What a field editing it is labelled.
    pub fn label(self) -> String {
        match self {
            Col::Name => "name".into(),
            Col::Hours => "hours a day".into(),
            Col::Aw(a) => format!("a_w {a} ({}), m/s² before k; empty: not measured", a.direction()),
            Col::Record => "record: PATH [axes=x=COL,y=COL,z=COL] [unit=m/s2|g|mm/s2]; empty: none".into(),
        }
    }
}

/// A number as the edit field shows it: shortest round trip.
fn plain(v: f64) -> String {
    biodyn::io::num(v)
}

/// A record as one line: `loading.csv axes=x=ax,z=az unit=g`.
pub fn record_text(r: &RecordSource) -> String {
    let mut s = r.path.clone();
    if let Some(a) = &r.axes {
        s.push_str(&format!(" axes={}", axes_text(a)));
    }
    if let Some(u) = r.unit {
        s.push_str(&format!(" unit={}", u.name()));
    }
    if let Some(fs) = r.fs {
        s.push_str(&format!(" fs={}", plain(fs)));
    }
    if r.remove_mean {
        s.push_str(" remove_mean");
    }
    s
}

/// What a field editing `col` of `op` starts with.
pub fn cell_text(op: &OperationSpec, col: Col) -> String {
    match (col, &op.source) {
        (Col::Name, _) => op.name.clone(),
        (Col::Hours, _) => plain(op.hours),
        (Col::Aw(a), Source::Measured { aw, .. }) => aw.get(a).map_or(String::new(), |v| plain(*v)),
        (Col::Aw(_), Source::Record(_)) => String::new(),
        (Col::Record, Source::Record(r)) => record_text(r),
        (Col::Record, Source::Measured { .. }) => String::new(),
    }
}

/// A record line (`PATH [axes=…] [unit=…] [fs=HZ] [remove_mean]`) read,
/// its path taken from `folder` (the day file's); None for an empty line.
/// The words are the day file's keys, so an edit keeps what the file said.
pub fn parse_record(text: &str, folder: &Path) -> Result<Option<RecordSource>, String> {
    let mut path = Vec::new();
    let (mut axes, mut unit, mut fs, mut remove_mean) = (None, None, None, false);
    for word in text.split_whitespace() {
        if word == "remove_mean" {
            remove_mean = true;
            continue;
        }
        if let Some(f) = word.strip_prefix("fs=") {
            let v = number(f, "fs", "fs=1000")?;
            if !(v > 0.0 && v <= 1e6) {
                return Err(format!("fs={f}: the sampling rate is over 0 and at most 1e6 Hz; write e.g. fs=1000"));
            }
            fs = Some(v);
            continue;
        }
        if let Some(a) = word.strip_prefix("axes=") {
            axes = Some(parse_axes(a).map_err(|why| format!("axes={a}: {why}; write e.g. axes=x=ax,y=ay,z=az"))?);
        } else if let Some(u) = word.strip_prefix("unit=") {
            unit = Some(Unit::parse(u).ok_or_else(|| format!("unit={u}: the units are m/s2, g and mm/s2"))?);
        } else {
            path.push(word);
        }
    }
    let path = path.join(" ");
    if path.is_empty() {
        if axes.is_some() || unit.is_some() || fs.is_some() || remove_mean {
            return Err("give the record's path before axes=, unit=, fs= and remove_mean".into());
        }
        return Ok(None);
    }
    Ok(Some(RecordSource {
        resolved: folder.join(&path),
        path,
        axes,
        unit,
        fs,
        remove_mean,
    }))
}

fn number(text: &str, what: &str, example: &str) -> Result<f64, String> {
    let t = text.trim();
    t.parse::<f64>()
        .ok()
        .filter(|v| v.is_finite())
        .ok_or_else(|| format!("'{}' is not a number; type the {what}, e.g. {example}", biodyn::io::short_quote(t)))
}

/// Hours of every operation but `skip`.
fn other_hours(ops: &[OperationSpec], skip: Option<usize>) -> f64 {
    ops.iter()
        .enumerate()
        .filter(|(i, _)| Some(*i) != skip)
        .map(|(_, o)| o.hours)
        .sum()
}

/// Sets cell `col` of operation `i` from `text`; what changed ("hours of
/// 'loading' 2.5 → 3"), or why not.
pub fn set(
    ops: &mut [OperationSpec],
    i: usize,
    col: Col,
    text: &str,
    folder: &Path,
) -> Result<String, String> {
    let others = other_hours(ops, Some(i));
    let op = ops.get_mut(i).ok_or("no operation selected: a adds one")?;
    let t = text.trim();
    let name = op.name.clone();
    match col {
        Col::Name => {
            let bad = |c: char| c.is_control();
            if t.is_empty() || t.chars().any(bad) || t.chars().count() > MAX_OPERATION_NAME {
                return Err(format!(
                    "a name is one line of 1 to {MAX_OPERATION_NAME} printable characters, e.g. haul road"
                ));
            }
            op.name = t.to_string();
            Ok(format!("renamed '{name}' to '{t}'"))
        }
        Col::Hours => {
            // As a day file's hours: 2.5, 2:30, 2h30, 150min (one parser).
            let h = biodyn::exposure::parse_hours(t).map_err(|e| format!("hours: {e}"))?;
            if others + h > MAX_DAY_H + biodyn::exposure::HOURS_TOLERANCE {
                let said = biodyn::exposure::hours_text;
                return Err(format!(
                    "hours = {}: the day would hold {}, over 24 h; the other operations take {}",
                    said(h),
                    said(others + h),
                    said(others)
                ));
            }
            let old = op.hours;
            op.hours = h;
            Ok(format!("hours of '{name}' {} → {}", plain(old), plain(h)))
        }
        Col::Aw(a) => {
            let Source::Measured { aw, vdv, measured_s, dz } = &mut op.source else {
                return Err(format!(
                    "'{name}' takes its a_w from its record; clear the record (Backspace on it) to type them"
                ));
            };
            let old = aw.get(a).map_or("-".to_string(), |v| plain(*v));
            if t.is_empty() {
                clear_axis(aw, vdv, measured_s, dz, a);
                return Ok(format!("a_w {a} of '{name}' {old} → not measured"));
            }
            let v = number(t, "measured a_w in m/s², before k", "0.52")?;
            if v < 0.0 {
                return Err(format!("a_w {a} = {}: must be ≥ 0 (m/s², before k)", plain(v)));
            }
            aw.set(a, v);
            Ok(format!("a_w {a} of '{name}' {old} → {}", plain(v)))
        }
        Col::Record => match parse_record(t, folder)? {
            Some(r) => {
                let line = record_text(&r);
                op.source = Source::Record(r);
                Ok(format!("'{name}' reads {line}"))
            }
            None => Err(format!(
                "to drop the record of '{name}', press Backspace on it (its measured a_w stay, typed in)"
            )),
        },
    }
}

/// Drops axis `a` of a measured operation, with its VDV.
/// z's ISO 2631-5 dose goes with z's a_w; the duration with the last VDV or dose.
fn clear_axis(
    aw: &mut PerAxis<f64>,
    vdv: &mut PerAxis<f64>,
    measured_s: &mut Option<f64>,
    dz: &mut Option<f64>,
    a: Axis,
) {
    let keep = |p: &PerAxis<f64>| {
        let mut out = PerAxis::default();
        for (b, v) in p.iter().filter(|(b, _)| *b != a) {
            out.set(b, *v);
        }
        out
    };
    *aw = keep(aw);
    *vdv = keep(vdv);
    if a == Axis::Z {
        *dz = None;
    }
    if vdv.is_empty() && dz.is_none() {
        *measured_s = None;
    }
}

/// Backspace on a cell: an a_w axis becomes not measured; a record is
/// replaced by what it measured (`measured`, when known), typed in.
pub fn clear(
    ops: &mut [OperationSpec],
    i: usize,
    col: Col,
    measured: Option<&PerAxis<Measured>>,
) -> Result<String, String> {
    let op = ops.get_mut(i).ok_or("no operation selected: a adds one")?;
    let name = op.name.clone();
    match (col, &mut op.source) {
        (Col::Aw(a), Source::Measured { aw, vdv, measured_s, dz }) => {
            if !aw.has(a) {
                return Err(format!("a_w {a} of '{name}' is not measured already"));
            }
            clear_axis(aw, vdv, measured_s, dz, a);
            Ok(format!("a_w {a} of '{name}' → not measured"))
        }
        (Col::Record, Source::Record(r)) => {
            let m = measured.ok_or_else(|| {
                format!("the record of '{name}' is not measured (yet): its a_w are unknown; fix it, or delete the operation")
            })?;
            let path = r.path.clone();
            let aw = m.map(|_, x| x.aw);
            let vdv = m.map(|_, x| x.vdv);
            let all_vdv = vdv.iter().all(|(_, v)| v.is_some());
            let mut vdvs = PerAxis::default();
            if all_vdv {
                for (a, v) in vdv.iter() {
                    if let Some(v) = v {
                        vdvs.set(a, *v);
                    }
                }
            }
            let measured_s = m.iter().next().and_then(|(_, x)| x.measured_s).filter(|_| all_vdv);
            let vdvs = if measured_s.is_some() { vdvs } else { PerAxis::default() };
            // The record's z dose goes with its VDVs and their duration.
            let dz = m.get(Axis::Z).and_then(|x| x.dz).filter(|_| measured_s.is_some());
            op.source = Source::Measured { aw, vdv: vdvs, measured_s, dz };
            Ok(format!("'{name}' no longer reads {path}: its measured a_w are typed in"))
        }
        (Col::Name | Col::Hours, _) => Err("a name and hours are needed: Enter edits them".into()),
        (Col::Aw(_), Source::Record(_)) => Err(format!(
            "'{name}' takes its a_w from its record; clear the record (Backspace on it) first"
        )),
        (Col::Record, Source::Measured { .. }) => Err(format!("'{name}' has no record")),
    }
}

/// A new operation named `name` after `at` (or first): 1 h, or what is
/// left of the day; no a_w yet.
pub fn add(ops: &mut Vec<OperationSpec>, at: Option<usize>, name: &str) -> Result<(usize, String), String> {
    let t = name.trim();
    if t.is_empty() || t.chars().any(char::is_control) || t.chars().count() > MAX_OPERATION_NAME {
        return Err(format!("a name is one line of 1 to {MAX_OPERATION_NAME} printable characters, e.g. haul road"));
    }
    let left = MAX_DAY_H - other_hours(ops, None);
    if left <= 0.0 {
        return Err("the day's operations already take 24 h: shorten one first".into());
    }
    let op = OperationSpec {
        name: t.to_string(),
        hours: left.min(1.0),
        source: Source::Measured {
            aw: PerAxis::default(),
            vdv: PerAxis::default(),
            measured_s: None,
            dz: None,
        },
    };
    let i = at.map_or(0, |i| (i + 1).min(ops.len()));
    ops.insert(i, op);
    Ok((i, format!("add operation '{t}'")))
}

/// Record paths taken again from `folder` (after the day moved).
pub fn resolve(ops: &mut [OperationSpec], folder: &Path) {
    for o in ops {
        if let Source::Record(r) = &mut o.source {
            r.resolved = folder.join(&r.path);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A record cell says every key the day file can (fs, remove_mean), so
    /// an edit of it keeps them: the round trip is exact.
    #[test]
    fn a_record_cell_keeps_fs_and_remove_mean() {
        let folder = Path::new("/days");
        let r = parse_record("lift.csv axes=z=az unit=g fs=500 remove_mean", folder)
            .unwrap()
            .unwrap();
        assert_eq!((r.fs, r.remove_mean), (Some(500.0), true));
        assert_eq!(record_text(&r), "lift.csv axes=z=az unit=g fs=500 remove_mean");
        assert_eq!(parse_record(&record_text(&r), folder).unwrap(), Some(r));
        let plain = parse_record("lift.csv", folder).unwrap().unwrap();
        assert_eq!((plain.fs, plain.remove_mean), (None, false));
        assert!(parse_record("lift.csv fs=0", folder).is_err());
        assert!(parse_record("remove_mean", folder).is_err());
    }
}
