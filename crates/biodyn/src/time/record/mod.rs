//! Seat-acceleration records from CSV, streamed row by row, on one to
//! three axes.
//!
//! The first row is a header; [`columns`] says which column is time and
//! which is each axis, in which unit. The time column must step uniformly
//! (each step within 0.1 % of the first), which sets fs; a file without
//! one is read with the sampling rate given. Every value is converted to
//! m/s². Files are opened through [`crate::io::open_regular`]: regular
//! files only, under the record size cap.

mod columns;
mod error;
mod line_cap;

pub use columns::{AxisColumn, Columns, NamedBy, axis_of, parse_axes};
pub use error::RecordError;

use super::discrete::MAX_FS;
use super::limits::{MAX_ACC, MAX_SAMPLES};
use super::{Axis, PerAxis, Unit};
use crate::io::{FileKind, open_regular};
use line_cap::{LineCap, csv_error};
use std::collections::VecDeque;
use std::fs::File;
use std::path::{Path, PathBuf};

/// One row of a record: the acceleration on x, y, z in m/s² (0 on an
/// axis the record does not have).
pub type Row = [f64; 3];

/// How to read a record: which column is which axis (empty: from the
/// header), the unit of columns whose name gives none, and fs when the
/// file has no time column.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RecordOptions {
    pub axes: PerAxis<String>,
    pub unit: Option<Unit>,
    pub fs: Option<f64>,
}

impl RecordOptions {
    /// Reads `column` as the z axis (the vertical record of old).
    pub fn z_column(column: &str) -> RecordOptions {
        let mut axes = PerAxis::default();
        axes.set(Axis::Z, column.to_string());
        RecordOptions {
            axes,
            ..RecordOptions::default()
        }
    }
}

/// One axis as read: where it came from and how it is scaled to m/s².
#[derive(Debug, Clone)]
struct Reading {
    axis: Axis,
    index: usize,
    scale: f64,
    name: String,
}

/// An open record: a streaming iterator over its rows.
pub struct Record {
    reader: csv::Reader<LineCap<File>>,
    path: PathBuf,
    row: csv::ByteRecord,
    columns: Columns,
    readings: Vec<Reading>,
    time_name: String,
    fs: f64,
    t0: f64,
    /// Step between the first two rows, and the last time read.
    dt: f64,
    last_t: f64,
    pending: VecDeque<Row>,
    count: usize,
    failed: bool,
}

impl std::fmt::Debug for Record {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Record")
            .field("path", &self.path)
            .field("fs", &self.fs)
            .field("columns", &self.columns)
            .finish()
    }
}

fn parse_field(
    path: &Path,
    line: u64,
    column: &str,
    field: Option<&[u8]>,
) -> Result<f64, RecordError> {
    let Some(bytes) = field else {
        return Err(RecordError::ShortRow {
            path: path.to_path_buf(),
            line,
            column: column.to_string(),
        });
    };
    let text = String::from_utf8_lossy(bytes);
    let t = text.trim();
    match t.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        Ok(_) => Err(RecordError::NotFinite {
            path: path.to_path_buf(),
            line,
            column: column.to_string(),
            text: t.to_string(),
        }),
        Err(_) => Err(RecordError::Text {
            path: path.to_path_buf(),
            line,
            column: column.to_string(),
            text: t.to_string(),
        }),
    }
}

impl Record {
    /// Opens `path`, reads the header and the first two rows (to learn fs).
    pub fn open(path: &Path, opts: &RecordOptions) -> Result<Record, RecordError> {
        if let Some(fs) = opts.fs
            && !(fs.is_finite() && fs > 0.0 && fs <= MAX_FS)
        {
            return Err(RecordError::BadFs(fs));
        }
        let (file, _) = open_regular(path, FileKind::Record)?;
        let mut reader = csv::ReaderBuilder::new()
            .has_headers(true)
            .buffer_capacity(1 << 16)
            .from_reader(LineCap::new(file));
        let p = path.to_path_buf();
        let header: Vec<String> = reader
            .headers()
            .map_err(|e| csv_error(e, &p, 1))?
            .iter()
            .map(|h| h.trim().to_string())
            .collect();
        if header.iter().all(String::is_empty) {
            return Err(RecordError::NoHeader { path: p });
        }
        let columns = columns::map_columns(&p, &header, &opts.axes, opts.unit, opts.fs.is_some())?;
        let readings = columns
            .axes
            .iter()
            .map(|(axis, c)| Reading {
                axis,
                index: c.index,
                scale: c.unit.to_m_s2(),
                name: c.name.clone(),
            })
            .collect();
        let time_name = columns
            .time
            .and_then(|t| header.get(t).cloned())
            .unwrap_or_default();
        let mut rec = Record {
            reader,
            path: p,
            row: csv::ByteRecord::new(),
            columns,
            readings,
            time_name,
            fs: opts.fs.unwrap_or(0.0),
            t0: 0.0,
            dt: 0.0,
            last_t: 0.0,
            pending: VecDeque::with_capacity(2),
            count: 0,
            failed: false,
        };
        let mut first = Vec::with_capacity(2);
        for _ in 0..2 {
            match rec.read_row()? {
                Some(v) => first.push(v),
                None => {
                    return Err(RecordError::TooFewRows {
                        path: rec.path.clone(),
                        rows: first.len(),
                    });
                }
            }
        }
        if let [(t0, _), (t1, _)] = first[..] {
            rec.t0 = t0;
            if rec.columns.time.is_some() {
                let step = t1 - t0;
                let file_fs = 1.0 / step;
                if !(step.is_finite() && step > 0.0 && file_fs <= MAX_FS) {
                    return Err(RecordError::BadStep {
                        path: rec.path.clone(),
                        line: 3,
                        step,
                    });
                }
                if let Some(given) = opts.fs
                    && (given - file_fs).abs() > 1e-3 * file_fs
                {
                    return Err(RecordError::FsMismatch {
                        path: rec.path.clone(),
                        file: file_fs,
                        given,
                    });
                }
                rec.dt = step;
                rec.fs = file_fs;
                rec.last_t = t1;
            }
        }
        rec.pending.extend(first.iter().map(|&(_, a)| a));
        Ok(rec)
    }

    /// One row as (time, accelerations); time is 0 without a time column.
    fn read_row(&mut self) -> Result<Option<(f64, Row)>, RecordError> {
        match self.reader.read_byte_record(&mut self.row) {
            Ok(false) => return Ok(None),
            Ok(true) => {}
            Err(e) => return Err(csv_error(e, &self.path, 0)),
        }
        self.count += 1;
        let line = self.row.position().map_or(0, |p| p.line());
        if self.count > MAX_SAMPLES {
            return Err(RecordError::TooLong {
                path: self.path.clone(),
                cap: MAX_SAMPLES,
            });
        }
        let mut out = [0.0; 3];
        for r in &self.readings {
            let a = parse_field(&self.path, line, &r.name, self.row.get(r.index))? * r.scale;
            if a.abs() > MAX_ACC {
                return Err(RecordError::TooLarge {
                    path: self.path.clone(),
                    line,
                    column: r.name.clone(),
                    value: a,
                });
            }
            out[r.axis.index()] = a;
        }
        let t = match self.columns.time {
            Some(i) => parse_field(&self.path, line, &self.time_name, self.row.get(i))?,
            None => 0.0,
        };
        Ok(Some((t, out)))
    }

    /// Sampling rate, Hz (from the time column, or as given).
    pub fn fs(&self) -> f64 {
        self.fs
    }

    /// Time of the first row, s (0 without a time column).
    pub fn t0(&self) -> f64 {
        self.t0
    }

    /// Which column is time and which is each axis.
    pub fn columns(&self) -> &Columns {
        &self.columns
    }

    /// The axes the record has.
    pub fn axes(&self) -> PerAxis<()> {
        self.columns.axes.map(|_, _| ())
    }

    /// The time column's name ("" without one).
    pub fn time_column(&self) -> &str {
        &self.time_name
    }

    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The z (vertical) axis alone, the body model's input; refused when
    /// the record has no z column.
    pub fn vertical(self) -> Result<impl Iterator<Item = Result<f64, RecordError>>, RecordError> {
        if !self.columns.axes.has(Axis::Z) {
            return Err(RecordError::NoVertical {
                path: self.path.clone(),
                axes: self
                    .columns
                    .axes
                    .iter()
                    .map(|(a, c)| format!("{a} ({})", c.name))
                    .collect::<Vec<_>>()
                    .join(", "),
            });
        }
        Ok(self.map(|r| r.map(|row| row[Axis::Z.index()])))
    }
}

impl Iterator for Record {
    type Item = Result<Row, RecordError>;

    fn next(&mut self) -> Option<Self::Item> {
        if let Some(a) = self.pending.pop_front() {
            return Some(Ok(a));
        }
        if self.failed {
            return None;
        }
        let r = match self.read_row() {
            Ok(None) => return None,
            Ok(Some((t, a))) => {
                if self.columns.time.is_some() {
                    let step = t - self.last_t;
                    self.last_t = t;
                    if (step - self.dt).abs() > 1e-3 * self.dt {
                        let line = self.row.position().map_or(0, |p| p.line());
                        Err(RecordError::Uneven {
                            path: self.path.clone(),
                            line,
                            step,
                            expected: self.dt,
                        })
                    } else {
                        Ok(a)
                    }
                } else {
                    Ok(a)
                }
            }
            Err(e) => Err(e),
        };
        self.failed = r.is_err();
        Some(r)
    }
}
