//! Seat-acceleration records from CSV, streamed row by row.
//!
//! The first row is a header. The time column is the one named `t_s`, else
//! the first column; it must step uniformly (each step within 0.1 % of the
//! first), which sets fs. The acceleration column is the one named, else
//! the first column that is not time. A file without a `t_s` column read
//! with a sampling rate given has no time column: every column is data, sampled at fs.
//! Files are opened through [`crate::io::open_regular`]: regular files only,
//! under the record size cap.

use super::discrete::MAX_FS;
use super::limits::{MAX_ACC, MAX_SAMPLES};
use crate::io::excerpt::{excerpt, message, num, quote};
use crate::io::{FileKind, ReadError, open_regular};
use std::collections::VecDeque;
use std::fs::File;
use std::io::Read;
use std::path::{Path, PathBuf};

/// Why a record cannot be read; each names the file, and the line and column
/// where there is one.
#[derive(Debug, thiserror::Error)]
pub enum RecordError {
    #[error(transparent)]
    Read(#[from] ReadError),
    #[error("{path}: line {line}: {}", message(.msg))]
    Csv {
        path: PathBuf,
        line: u64,
        msg: String,
    },
    #[error("{path}: the file is empty: it needs a header row, e.g. t_s,acc_m_s2")]
    NoHeader { path: PathBuf },
    #[error("{path}: no column named '{}'; the columns are {}", quote(.name), excerpt(.available, 160))]
    MissingColumn {
        path: PathBuf,
        name: String,
        available: String,
    },
    #[error(
        "{path}: only one column and no time column: give its sampling rate (fs), or add a t_s column"
    )]
    NeedFs { path: PathBuf },
    #[error("{path}: line {line}, column '{}': '{}' is not a number", quote(.column), quote(.text))]
    Text {
        path: PathBuf,
        line: u64,
        column: String,
        text: String,
    },
    #[error(
        "{path}: line {line}, column '{}': {} is not a finite number (NaN or infinite)",
        quote(.column),
        quote(.text)
    )]
    NotFinite {
        path: PathBuf,
        line: u64,
        column: String,
        text: String,
    },
    #[error("{path}: line {line}: row has no column '{}' (too few fields)", quote(.column))]
    ShortRow {
        path: PathBuf,
        line: u64,
        column: String,
    },
    #[error("{path}: {rows} data row(s): a record needs at least two")]
    TooFewRows { path: PathBuf, rows: usize },
    #[error(
        "{path}: line {line}: time step {} s differs from the first step {} s by more than 0.1 %: resample the record uniformly",
        num(*.step),
        num(*.expected)
    )]
    Uneven {
        path: PathBuf,
        line: u64,
        step: f64,
        expected: f64,
    },
    #[error(
        "{path}: line {line}: the first time step is {} s: time must increase, at a rate of at most 1e6 Hz",
        num(*.step)
    )]
    BadStep { path: PathBuf, line: u64, step: f64 },
    #[error(
        "{path}: the time column gives {} Hz but the sampling rate given is {} Hz: leave it out or fix it",
        num(*.file),
        num(*.given)
    )]
    FsMismatch {
        path: PathBuf,
        file: f64,
        given: f64,
    },
    #[error(
        "sampling rate {} Hz: it must be a finite number > 0 and at most 1e6",
        num(*.0)
    )]
    BadFs(f64),
    #[error("{path}: more than {cap} samples: split the record")]
    TooLong { path: PathBuf, cap: usize },
    #[error(
        "{path}: line {line} is over {} KiB: a record has one short row per line (is this a CSV file?)",
        MAX_LINE / 1024
    )]
    LineTooLong { path: PathBuf, line: u64 },
    #[error(
        "{path}: line {line}, column '{}': {} m/s² is over the {} m/s² cap (≈ 1000 g, beyond any seat vibration or shock): check the unit",
        quote(.column),
        num(*.value),
        num(MAX_ACC)
    )]
    TooLarge {
        path: PathBuf,
        line: u64,
        column: String,
        value: f64,
    },
}

/// How to read a record: which acceleration column, and fs when the file
/// has no time column.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RecordOptions {
    pub column: Option<String>,
    pub fs: Option<f64>,
}

/// An open record: a streaming iterator over its acceleration samples.
pub struct Record {
    reader: csv::Reader<LineCap<File>>,
    path: PathBuf,
    row: csv::ByteRecord,
    time: Option<usize>,
    acc: usize,
    acc_name: String,
    time_name: String,
    fs: f64,
    t0: f64,
    /// Step between the first two rows, and the last time read.
    dt: f64,
    last_t: f64,
    pending: VecDeque<f64>,
    count: usize,
    failed: bool,
}

impl std::fmt::Debug for Record {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Record")
            .field("path", &self.path)
            .field("fs", &self.fs)
            .field("column", &self.acc_name)
            .finish()
    }
}

/// Longest line a record may have, bytes: a row of a few numbers is under
/// 100 bytes; the cap keeps the CSV reader's buffer (and memory) bounded
/// when a file has no newlines (1 GiB of NUL bytes).
pub const MAX_LINE: u64 = 64 * 1024;

/// The error [`LineCap`] returns, found again by [`csv_error`].
#[derive(Debug)]
struct LineTooLong {
    line: u64,
}

impl std::fmt::Display for LineTooLong {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "line {} is over {} KiB", self.line, MAX_LINE / 1024)
    }
}

impl std::error::Error for LineTooLong {}

/// A reader that fails once a line passes [`MAX_LINE`] bytes.
struct LineCap<R> {
    inner: R,
    /// Bytes since the last newline, and 1-based line number.
    run: u64,
    line: u64,
}

impl<R> LineCap<R> {
    fn new(inner: R) -> Self {
        LineCap {
            inner,
            run: 0,
            line: 1,
        }
    }
}

impl<R: Read> Read for LineCap<R> {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        let n = self.inner.read(buf)?;
        for &b in buf.get(..n).unwrap_or_default() {
            if b == b'\n' {
                self.run = 0;
                self.line += 1;
            } else {
                self.run += 1;
                if self.run > MAX_LINE {
                    return Err(std::io::Error::new(
                        std::io::ErrorKind::InvalidData,
                        LineTooLong { line: self.line },
                    ));
                }
            }
        }
        Ok(n)
    }
}

/// A CSV error as a record error: a too-long line gets its own message.
fn csv_error(e: csv::Error, path: &Path, default_line: u64) -> RecordError {
    if let csv::ErrorKind::Io(io) = e.kind()
        && let Some(long) = io.get_ref().and_then(|r| r.downcast_ref::<LineTooLong>())
    {
        return RecordError::LineTooLong {
            path: path.to_path_buf(),
            line: long.line,
        };
    }
    RecordError::Csv {
        path: path.to_path_buf(),
        line: e.position().map_or(default_line, |p| p.line()),
        msg: e.to_string(),
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
        let csv_err = |e: csv::Error, p: &Path| csv_error(e, p, 1);
        let header: Vec<String> = reader
            .headers()
            .map_err(|e| csv_err(e, &p))?
            .iter()
            .map(|h| h.trim().to_string())
            .collect();
        if header.iter().all(String::is_empty) {
            return Err(RecordError::NoHeader { path: p });
        }
        let named_time = header.iter().position(|h| h == "t_s");
        let time = match (named_time, opts.fs) {
            (Some(i), _) => Some(i),
            (None, Some(_)) => None,
            (None, None) if header.len() >= 2 => Some(0),
            (None, None) => return Err(RecordError::NeedFs { path: p }),
        };
        let acc = match &opts.column {
            Some(name) => header
                .iter()
                .position(|h| h == name.trim())
                .ok_or_else(|| RecordError::MissingColumn {
                    path: p.clone(),
                    name: name.clone(),
                    available: header.join(", "),
                })?,
            None => (0..header.len())
                .find(|&i| Some(i) != time)
                .ok_or_else(|| RecordError::MissingColumn {
                    path: p.clone(),
                    name: "(an acceleration column besides t_s)".into(),
                    available: header.join(", "),
                })?,
        };
        let mut rec = Record {
            reader,
            path: p,
            row: csv::ByteRecord::new(),
            time,
            acc,
            acc_name: header.get(acc).cloned().unwrap_or_default(),
            time_name: time
                .and_then(|t| header.get(t).cloned())
                .unwrap_or_default(),
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
            if rec.time.is_some() {
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

    /// One row as (time, acceleration); time is 0 without a time column.
    fn read_row(&mut self) -> Result<Option<(f64, f64)>, RecordError> {
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
        let a = parse_field(&self.path, line, &self.acc_name, self.row.get(self.acc))?;
        if a.abs() > MAX_ACC {
            return Err(RecordError::TooLarge {
                path: self.path.clone(),
                line,
                column: self.acc_name.clone(),
                value: a,
            });
        }
        let t = match self.time {
            Some(i) => parse_field(&self.path, line, &self.time_name, self.row.get(i))?,
            None => 0.0,
        };
        Ok(Some((t, a)))
    }

    /// Sampling rate, Hz (from the time column, or as given).
    pub fn fs(&self) -> f64 {
        self.fs
    }

    /// Time of the first row, s (0 without a time column).
    pub fn t0(&self) -> f64 {
        self.t0
    }

    /// Name of the acceleration column read.
    pub fn column(&self) -> &str {
        &self.acc_name
    }

    pub fn path(&self) -> &Path {
        &self.path
    }
}

impl Iterator for Record {
    type Item = Result<f64, RecordError>;

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
                if self.time.is_some() {
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
