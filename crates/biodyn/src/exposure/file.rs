//! The day file (TOML): the operations of a working day, each with its
//! hours and either the measured a_w per axis or a record to assess.
//!
//! ```toml
//! [[operation]]
//! name = "haul road"
//! hours = 3.25
//! aw_m_s2 = { x = 0.36, y = 0.21, z = 0.52 }   # any subset of axes, before k
//! vdv_m_s175 = { x = 5.1, z = 7.0 }             # optional, with measured_s
//! measured_s = 600
//!
//! [[operation]]
//! name = "loading"
//! hours = 2.5
//! record = "loading.csv"                        # relative to the file's folder
//! axes = "x=ax,y=ay,z=az"                       # optional
//! unit = "g"                                    # optional: m/s2, g, mm/s2
//! ```
//!
//! `hours` is a number or a text as people write it (`"3:15"`, `"3h15"`,
//! `"45min"`: [`super::hours`]), or `minutes = 195` instead. A record
//! operation may give its sampling rate, `fs = 1000` (Hz, for a record
//! without a time column), and `remove_mean = true` (subtract each
//! channel's mean before judging: a DC-coupled accelerometer's gravity).
//! A `[report]` table holds the report's details ([`Meta`]'s keys).
//!
//! With `spine = "age=25,years=10,days=240,sex=male"` at the top, the day
//! also gets ISO 2631-5's daily dose and risk; every operation then needs
//! its z dose: `dz_m_s2` (with `measured_s`) or a record.
//!
//! Unknown keys are errors (a typo never falls back to a default). Reading
//! goes through [`crate::io::read_text`] ([`FileKind::Day`]'s cap), saving
//! through [`crate::io::save_atomic`]; a file that would not load back is
//! not written.

use super::error::DayError;
use super::meta::{Meta, MetaToml};
use crate::io::{FileKind, ReadError, read_text};
use crate::iso2631::spine::Person;
use crate::time::{Axis, PerAxis, Unit};
use serde::Deserialize;
use std::path::{Path, PathBuf};
use toml::Spanned;

/// The day-file format version this build reads and writes.
pub const SCHEMA: u32 = 1;

/// The most hours a day's operations add up to.
pub const MAX_DAY_H: f64 = 24.0;

/// Longest operation name, characters.
pub const MAX_OPERATION_NAME: usize = 200;

/// A day file, checked: every operation has a name, hours in (0, 24] and
/// exactly one source.
#[derive(Debug, Clone, PartialEq)]
pub struct DayFile {
    /// Where it came from, for messages (a path, or a label).
    pub origin: String,
    pub operations: Vec<OperationSpec>,
    /// ISO 2631-5's person, when the day is to be judged for the spine.
    pub spine: Option<Person>,
    /// The `[report]` table: who, where, when, with what (empty when none).
    pub report: Meta,
}

/// One operation as written.
#[derive(Debug, Clone, PartialEq)]
pub struct OperationSpec {
    pub name: String,
    pub hours: f64,
    pub source: Source,
}

/// Where an operation's vibration comes from.
#[derive(Debug, Clone, PartialEq)]
pub enum Source {
    /// Measured a_w (m/s², before k) per axis; VDVs (m/s^1.75, before k)
    /// measured over `measured_s` seconds, where known.
    Measured {
        aw: PerAxis<f64>,
        vdv: PerAxis<f64>,
        measured_s: Option<f64>,
        /// ISO 2631-5's acceleration dose of z over `measured_s`, m/s².
        dz: Option<f64>,
    },
    /// A record to assess per axis.
    Record(RecordSource),
}

/// A record operation's file and how to read it.
#[derive(Debug, Clone, PartialEq)]
pub struct RecordSource {
    /// As written in the day file.
    pub path: String,
    /// `path` from the day file's folder.
    pub resolved: PathBuf,
    /// Columns named per axis (`x=ax,y=ay,z=az`), when given.
    pub axes: Option<PerAxis<String>>,
    /// The unit of every column, when given.
    pub unit: Option<Unit>,
    /// The sampling rate, Hz, for a record without a time column.
    pub fs: Option<f64>,
    /// Subtract each channel's mean before judging (a DC-coupled
    /// accelerometer's gravity); the output says so.
    pub remove_mean: bool,
}

impl RecordSource {
    /// The axes as written: `x=ax,y=ay,z=az`.
    pub fn axes_text(&self) -> Option<String> {
        self.axes.as_ref().map(axes_text)
    }
}

/// `x=COL,y=COL` from a column per axis.
pub fn axes_text(axes: &PerAxis<String>) -> String {
    axes.iter()
        .map(|(a, c)| format!("{a}={c}"))
        .collect::<Vec<_>>()
        .join(",")
}

/// `x=COL,y=COL,z=COL` (any subset, each axis once, no empty column), or
/// why not: the record reader's own grammar.
pub fn parse_axes(s: &str) -> Result<PerAxis<String>, String> {
    crate::time::parse_axes(s).map_err(|e| match e {
        crate::time::RecordError::BadAxes { why, .. } => why,
        other => other.to_string(),
    })
}

// ---- the format on disk ----------------------------------------------------

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct DayToml {
    #[serde(default)]
    pub schema: Option<Spanned<i64>>,
    #[serde(default)]
    pub spine: Option<Spanned<String>>,
    #[serde(default)]
    pub report: Option<MetaToml>,
    #[serde(rename = "operation", default)]
    pub operations: Vec<Spanned<OperationToml>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct OperationToml {
    pub name: Option<Spanned<String>>,
    pub hours: Option<Spanned<HoursToml>>,
    pub minutes: Option<Spanned<f64>>,
    pub aw_m_s2: Option<Spanned<AxesToml>>,
    pub vdv_m_s175: Option<Spanned<AxesToml>>,
    pub measured_s: Option<Spanned<f64>>,
    pub dz_m_s2: Option<Spanned<f64>>,
    pub record: Option<Spanned<String>>,
    pub axes: Option<Spanned<String>>,
    pub unit: Option<Spanned<String>>,
    pub fs: Option<Spanned<f64>>,
    pub remove_mean: Option<Spanned<bool>>,
}

/// `hours` as written: a number, or a text such as `"3:15"`.
#[derive(Debug, Clone, PartialEq)]
pub(super) enum HoursToml {
    Number(f64),
    Text(String),
}

impl<'de> Deserialize<'de> for HoursToml {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl serde::de::Visitor<'_> for V {
            type Value = HoursToml;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("hours as a number (3.25) or a text (\"3:15\", \"3h15\", \"45min\")")
            }
            fn visit_f64<E>(self, v: f64) -> Result<HoursToml, E> {
                Ok(HoursToml::Number(v))
            }
            fn visit_i64<E>(self, v: i64) -> Result<HoursToml, E> {
                Ok(HoursToml::Number(v as f64))
            }
            fn visit_u64<E>(self, v: u64) -> Result<HoursToml, E> {
                Ok(HoursToml::Number(v as f64))
            }
            fn visit_str<E>(self, v: &str) -> Result<HoursToml, E> {
                Ok(HoursToml::Text(v.to_string()))
            }
        }
        d.deserialize_any(V)
    }
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct AxesToml {
    pub x: Option<Spanned<f64>>,
    pub y: Option<Spanned<f64>>,
    pub z: Option<Spanned<f64>>,
}

impl AxesToml {
    pub fn get(&self, a: Axis) -> Option<&Spanned<f64>> {
        match a {
            Axis::X => self.x.as_ref(),
            Axis::Y => self.y.as_ref(),
            Axis::Z => self.z.as_ref(),
        }
    }
}

// ---- load and save ---------------------------------------------------------

impl DayFile {
    /// Reads and checks a day file: a regular file within
    /// [`FileKind::Day`]'s cap; record paths are taken from its folder.
    pub fn load(path: &Path) -> Result<DayFile, DayError> {
        let shown = path.display().to_string();
        let text = read_text(path, FileKind::Day).map_err(|e: ReadError| DayError::Read {
            path: shown.clone(),
            reason: e.reason(),
        })?;
        let folder = path.parent().unwrap_or(Path::new(""));
        DayFile::parse(&text, &shown, folder)
    }

    /// The day as TOML, in the order written; loads back to the same day.
    pub fn to_toml(&self) -> String {
        let mut s = format!(
            "# biodyn day file (schema {SCHEMA}). a_w in m/s² and VDV in m/s^1.75, before k; hours of each operation.\nschema = {SCHEMA}\n"
        );
        let str_ = |v: &str| toml::Value::String(v.to_string()).to_string();
        let float = |v: f64| toml::Value::Float(v).to_string();
        if let Some(p) = &self.spine {
            s.push_str(&format!("spine = {}\n", str_(&p.spec())));
        }
        if !self.report.is_empty() {
            s.push_str(&format!("\n[report]\n{}", self.report.to_toml()));
        }
        let axes = |p: &PerAxis<f64>| {
            let inner: Vec<String> = p
                .iter()
                .map(|(a, v)| format!("{a} = {}", float(*v)))
                .collect();
            format!("{{ {} }}", inner.join(", "))
        };
        for o in &self.operations {
            s.push_str(&format!(
                "\n[[operation]]\nname = {}\nhours = {}\n",
                str_(&o.name),
                float(o.hours)
            ));
            match &o.source {
                Source::Measured {
                    aw,
                    vdv,
                    measured_s,
                    dz,
                } => {
                    s.push_str(&format!("aw_m_s2 = {}\n", axes(aw)));
                    if !vdv.is_empty() {
                        s.push_str(&format!("vdv_m_s175 = {}\n", axes(vdv)));
                    }
                    if let Some(d) = dz {
                        s.push_str(&format!("dz_m_s2 = {}\n", float(*d)));
                    }
                    if let Some(t) = measured_s {
                        s.push_str(&format!("measured_s = {}\n", float(*t)));
                    }
                }
                Source::Record(r) => {
                    s.push_str(&format!("record = {}\n", str_(&r.path)));
                    if let Some(a) = r.axes_text() {
                        s.push_str(&format!("axes = {}\n", str_(&a)));
                    }
                    if let Some(u) = r.unit {
                        s.push_str(&format!("unit = {}\n", str_(u.name())));
                    }
                    if let Some(fs) = r.fs {
                        s.push_str(&format!("fs = {}\n", float(fs)));
                    }
                    if r.remove_mean {
                        s.push_str("remove_mean = true\n");
                    }
                }
            }
        }
        s
    }

    /// Writes the day through [`crate::io::save_atomic`]; a day that would
    /// not load back (refused by [`DayFile::parse`], or over the cap) is
    /// not written.
    pub fn save(&self, path: &Path) -> Result<(), DayError> {
        self.save_guarded(path, &crate::io::Guard::default())
    }

    /// [`save`](Self::save) held to `guard`: not over a file the day reads
    /// (its records), a read-only file only when forced.
    pub fn save_guarded(&self, path: &Path, guard: &crate::io::Guard) -> Result<(), DayError> {
        let shown = path.display().to_string();
        let refuse = |reason: String| DayError::Save {
            path: shown.clone(),
            reason,
        };
        let text = self.to_toml();
        let cap = FileKind::Day.cap();
        if text.len() as u64 > cap {
            return Err(refuse(format!(
                "the day is {} bytes, over the {} MiB a day file may hold",
                text.len(),
                cap >> 20
            )));
        }
        let folder = path.parent().unwrap_or(Path::new(""));
        if let Err(e) = DayFile::parse(&text, "day to save", folder) {
            return Err(refuse(format!("it would not load back: {e}")));
        }
        crate::io::save_guarded(path, guard, text.as_bytes()).map_err(|e| refuse(e.reason()))
    }
}
