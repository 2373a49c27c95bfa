//! The record's rows, split and parsed straight from the file's bytes:
//! lines found with memchr in a 1 MiB buffer, fields split on commas, only
//! the columns read are parsed. A line with a quote goes through the csv
//! crate, so quoted fields read as before. Lines are capped at
//! [`MAX_LINE`] bytes, so a file without newlines (1 GiB of NUL bytes)
//! cannot grow the buffer without bound.

use super::RecordError;
use crate::time::limits::{MAX_ACC, MAX_LINE, MAX_SAMPLES};
use crate::time::{PointRow, Row};
use std::fs::File;
use std::io::Read;
use std::path::{Path, PathBuf};

const BUFFER: usize = 1 << 20;

/// One column read: where, and how it is scaled to m/s² (rad/s²).
#[derive(Debug, Clone)]
pub struct Reading {
    /// Its place in the seat's [`Row`], or in the [`PointRow`].
    pub slot: usize,
    pub index: usize,
    pub scale: f64,
    pub name: String,
}

/// The time step check: each step within 0.1 % of the first.
#[derive(Debug, Clone, Copy)]
struct Timing {
    dt: f64,
    last_t: f64,
}

/// Rows of the seat and, only where the record has other points, of
/// those (one [`PointRow`] per seat row; empty otherwise).
#[derive(Debug, Default)]
pub struct Rows {
    pub seat: Vec<Row>,
    pub points: Vec<PointRow>,
}

impl Rows {
    pub fn with_capacity(n: usize, points: bool) -> Rows {
        Rows {
            seat: Vec::with_capacity(n),
            points: Vec::with_capacity(if points { n } else { 0 }),
        }
    }

    pub fn clear(&mut self) {
        self.seat.clear();
        self.points.clear();
    }

    pub fn len(&self) -> usize {
        self.seat.len()
    }

    pub fn is_empty(&self) -> bool {
        self.seat.is_empty()
    }

    /// The first `n` rows.
    pub fn truncate(&mut self, n: usize) {
        self.seat.truncate(n);
        self.points.truncate(n);
    }
}

/// Rows handed over at a time, or the error that ended them.
pub type Block = Result<Rows, RecordError>;

/// How one line becomes a row: the header's width, the columns read and
/// the time column. Shared by the reader and the parallel parsers.
#[derive(Debug, Clone)]
pub struct Parser {
    pub path: PathBuf,
    fields: usize,
    readings: Vec<Reading>,
    /// The other points' columns (none: the seat's rows alone are kept).
    points: Vec<Reading>,
    /// The time column: its index, name and seconds per unit.
    time: Option<(usize, String, f64)>,
}

/// Lines of a file, and the rows parsed from them.
pub struct Reader {
    file: File,
    buf: Vec<u8>,
    start: usize,
    end: usize,
    eof: bool,
    /// 1-based number of the next line.
    line: u64,
    parser: Parser,
    timing: Option<Timing>,
    count: usize,
    /// Scratch for split fields: (start, end) within the line.
    spans: Vec<(usize, usize)>,
    /// The other points of the last row read.
    last_points: PointRow,
}

/// What is left of a reader once its first rows are read: the file where
/// it stopped, the bytes read ahead, the next line's number, the parser and
/// the time step.
pub struct Rest {
    pub file: File,
    pub ahead: Vec<u8>,
    pub eof: bool,
    pub line: u64,
    pub parser: Parser,
    pub dt: Option<f64>,
    pub last_t: f64,
    pub count: usize,
}

impl Reader {
    pub fn new(file: File, path: &Path) -> Reader {
        Reader {
            file,
            buf: vec![0; BUFFER],
            start: 0,
            end: 0,
            eof: false,
            line: 1,
            parser: Parser {
                path: path.to_path_buf(),
                fields: 0,
                readings: Vec::new(),
                points: Vec::new(),
                time: None,
            },
            timing: None,
            count: 0,
            spans: Vec::new(),
            last_points: [0.0; 9],
        }
    }

    /// What to read of each row, once the header is known.
    pub fn set_columns(
        &mut self,
        fields: usize,
        readings: Vec<Reading>,
        points: Vec<Reading>,
        time: Option<(usize, String, f64)>,
    ) {
        self.parser.fields = fields;
        self.parser.readings = readings;
        self.parser.points = points;
        self.parser.time = time;
    }

    /// The other points of the row [`Reader::next_row`] gave last.
    pub fn last_points(&self) -> PointRow {
        self.last_points
    }

    /// Whether the record has other points.
    pub fn has_points(&self) -> bool {
        self.parser.has_points()
    }

    /// A reader again from its parts (where the rest cannot be read in
    /// parallel).
    pub fn from_rest(r: Rest) -> Reader {
        let end = r.ahead.len();
        let mut buf = r.ahead;
        buf.resize(end.max(BUFFER), 0);
        Reader {
            file: r.file,
            buf,
            start: 0,
            end,
            eof: r.eof,
            line: r.line,
            parser: r.parser,
            timing: r.dt.map(|dt| Timing {
                dt,
                last_t: r.last_t,
            }),
            count: r.count,
            spans: Vec::new(),
            last_points: [0.0; 9],
        }
    }

    /// The reader taken apart, to read the rest elsewhere.
    pub fn into_rest(self) -> Rest {
        Rest {
            ahead: self.buf[self.start..self.end].to_vec(),
            file: self.file,
            eof: self.eof,
            line: self.line,
            parser: self.parser,
            dt: self.timing.map(|t| t.dt),
            last_t: self.timing.map_or(0.0, |t| t.last_t),
            count: self.count,
        }
    }

    /// Starts the step check from the first two rows' times.
    pub fn set_timing(&mut self, dt: f64, last_t: f64) {
        self.timing = Some(Timing { dt, last_t });
    }

    fn io(&self, e: std::io::Error) -> RecordError {
        RecordError::Read(crate::io::ReadError::Io {
            path: self.parser.path.clone(),
            source: e,
        })
    }

    /// The next line's number and byte range in `buf` (without its end of
    /// line), or None at the end of the file.
    pub fn next_line(&mut self) -> Result<Option<(u64, usize, usize)>, RecordError> {
        loop {
            if let Some(i) = memchr::memchr(b'\n', &self.buf[self.start..self.end]) {
                let (s, e) = (self.start, self.start + i);
                if i > MAX_LINE {
                    return Err(self.too_long());
                }
                self.start = e + 1;
                let n = self.line;
                self.line += 1;
                let e = if e > s && self.buf[e - 1] == b'\r' {
                    e - 1
                } else {
                    e
                };
                return Ok(Some((n, s, e)));
            }
            if self.end - self.start > MAX_LINE {
                return Err(self.too_long());
            }
            if self.eof {
                if self.start == self.end {
                    return Ok(None);
                }
                let (s, mut e) = (self.start, self.end);
                self.start = self.end;
                let n = self.line;
                self.line += 1;
                if e > s && self.buf[e - 1] == b'\r' {
                    e -= 1;
                }
                return Ok(Some((n, s, e)));
            }
            self.buf.copy_within(self.start..self.end, 0);
            self.end -= self.start;
            self.start = 0;
            let got = loop {
                match self.file.read(&mut self.buf[self.end..]) {
                    Ok(n) => break n,
                    Err(e) if e.kind() == std::io::ErrorKind::Interrupted => {}
                    Err(e) => return Err(self.io(e)),
                }
            };
            self.eof = got == 0;
            self.end += got;
        }
    }

    fn too_long(&self) -> RecordError {
        RecordError::LineTooLong {
            path: self.parser.path.clone(),
            line: self.line,
        }
    }

    /// The bytes of a line.
    pub fn bytes(&self, s: usize, e: usize) -> &[u8] {
        &self.buf[s..e]
    }

    /// The next row as (time, accelerations in m/s²); blank lines are
    /// skipped, as the csv crate does.
    /// The line the last row came from (1 is the header).
    pub fn last_line(&self) -> u64 {
        self.line - 1
    }

    pub fn next_row(&mut self) -> Result<Option<(f64, Row)>, RecordError> {
        let (line, s, e) = loop {
            match self.next_line()? {
                None => return Ok(None),
                Some((_, s, e)) if s == e => continue,
                Some(l) => break l,
            }
        };
        self.count += 1;
        if self.count > MAX_SAMPLES {
            return Err(RecordError::TooLong {
                path: self.parser.path.clone(),
                cap: MAX_SAMPLES,
            });
        }
        let bytes = &self.buf[s..e];
        let r = self
            .parser
            .row(line, bytes, &mut self.spans, &mut self.last_points);
        r.map(Some)
    }

    /// Fills `out` with up to `max` rows, checking each time step; false
    /// at the end of the file. On an error `out` holds the rows before it.
    pub fn block(&mut self, out: &mut Rows, max: usize) -> Result<bool, RecordError> {
        out.clear();
        let points = self.parser.has_points();
        while out.len() < max {
            let Some((t, row)) = self.next_row()? else {
                return Ok(!out.is_empty());
            };
            if let Some(tm) = &mut self.timing {
                let step = t - tm.last_t;
                tm.last_t = t;
                if (step - tm.dt).abs() > 1e-3 * tm.dt {
                    return Err(RecordError::Uneven {
                        path: self.parser.path.clone(),
                        line: self.line - 1,
                        step,
                        expected: tm.dt,
                    });
                }
            }
            out.seat.push(row);
            if points {
                out.points.push(self.last_points);
            }
        }
        Ok(true)
    }
}

impl Parser {
    #[cold]
    fn too_large(&self, line: u64, r: &Reading, value: f64) -> RecordError {
        RecordError::TooLarge {
            path: self.path.clone(),
            line,
            column: r.name.clone(),
            value,
        }
    }

    /// Whether any other point's column is read.
    pub fn has_points(&self) -> bool {
        !self.points.is_empty()
    }

    /// Fields of a line with a quote, through the csv crate.
    fn quoted(&self, line: u64, bytes: &[u8]) -> Result<Vec<Vec<u8>>, RecordError> {
        let mut r = csv::ReaderBuilder::new()
            .has_headers(false)
            .flexible(true)
            .from_reader(bytes);
        let mut rec = csv::ByteRecord::new();
        match r.read_byte_record(&mut rec) {
            Ok(_) => Ok(rec.iter().map(<[u8]>::to_vec).collect()),
            Err(e) => Err(RecordError::Csv {
                path: self.path.clone(),
                line,
                msg: e.to_string(),
            }),
        }
    }

    /// One line (without its end of line, not blank) as (time, row); the
    /// other points' values into `points`.
    pub fn row(
        &self,
        line: u64,
        bytes: &[u8],
        spans: &mut Vec<(usize, usize)>,
        points: &mut PointRow,
    ) -> Result<(f64, Row), RecordError> {
        spans.clear();
        if memchr::memchr(b'"', bytes).is_some() {
            let owned = self.quoted(line, bytes)?;
            let mut joined = Vec::new();
            for f in &owned {
                spans.push((joined.len(), joined.len() + f.len()));
                joined.extend_from_slice(f);
            }
            self.parse(line, spans, &joined, points)
        } else {
            let mut at = 0;
            for i in memchr::memchr_iter(b',', bytes) {
                spans.push((at, i));
                at = i + 1;
            }
            spans.push((at, bytes.len()));
            self.parse(line, spans, bytes, points)
        }
    }

    /// Parses the read columns of one line split at `spans`.
    fn parse(
        &self,
        line: u64,
        spans: &[(usize, usize)],
        bytes: &[u8],
        points: &mut PointRow,
    ) -> Result<(f64, Row), RecordError> {
        if spans.len() != self.fields {
            return Err(RecordError::Csv {
                path: self.path.clone(),
                line,
                msg: format!(
                    "found record with {} fields, but the header has {}",
                    spans.len(),
                    self.fields
                ),
            });
        }
        let field = |i: usize| spans.get(i).map(|&(s, e)| &bytes[s..e]);
        let mut out = [0.0; 3];
        for r in &self.readings {
            let a = number(&self.path, line, &r.name, field(r.index))? * r.scale;
            if a.abs() > MAX_ACC {
                return Err(self.too_large(line, r, a));
            }
            out[r.slot] = a;
        }
        // Apart from the seat's loop, which stays as it was without points.
        for r in &self.points {
            let a = number(&self.path, line, &r.name, field(r.index))? * r.scale;
            if a.abs() > MAX_ACC {
                return Err(self.too_large(line, r, a));
            }
            points[r.slot] = a;
        }
        let t = match &self.time {
            Some((i, name, seconds)) => number(&self.path, line, name, field(*i))? * seconds,
            None => 0.0,
        };
        Ok((t, out))
    }
}

/// One field as a finite number, or why not.
fn number(path: &Path, line: u64, column: &str, field: Option<&[u8]>) -> Result<f64, RecordError> {
    let Some(bytes) = field else {
        return Err(RecordError::ShortRow {
            path: path.to_path_buf(),
            line,
            column: column.to_string(),
        });
    };
    let t = bytes.trim_ascii();
    let parsed = super::decimal::parse(t);
    match parsed {
        Some(v) if v.is_finite() => Ok(v),
        Some(_) => Err(RecordError::NotFinite {
            path: path.to_path_buf(),
            line,
            column: column.to_string(),
            text: String::from_utf8_lossy(t).into_owned(),
        }),
        None => Err(RecordError::Text {
            path: path.to_path_buf(),
            line,
            column: column.to_string(),
            text: String::from_utf8_lossy(t).into_owned(),
        }),
    }
}
