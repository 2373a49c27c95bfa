//! Seat-acceleration records from CSV, streamed row by row, on one to
//! three axes, and the other measuring points' channels beside them where
//! the record has any (backrest, feet, the seat's rotations).
//!
//! The first row is a header (a first row of numbers is refused: it is
//! data, and reading it as names would lose a sample); [`columns`] says
//! which column is time, in which unit, and which is each axis, in which
//! unit. The time column must step uniformly (each step within 0.1 % of
//! the first), which sets fs; a file without one is read with the sampling
//! rate given. Every value is converted to m/s², and, where asked, each
//! channel's mean over the whole record is removed (a second pass over
//! the file). Files are opened through [`crate::io::open_regular`]: regular
//! files only, under the record size cap.

mod columns;
mod decimal;
mod error;
mod header;
mod mean;
mod parallel;
mod reader;
#[cfg(test)]
mod tests_endings;
#[cfg(test)]
mod tests_instruments;
#[cfg(test)]
mod tests_points;

pub use columns::{
    AxisColumn, Columns, Given, NamedBy, PointColumn, TimeName, TimeUnit, UnitBy, axis_of,
    channel_of, parse_axes, parse_channels, time_name,
};
pub use error::RecordError;

use super::discrete::MAX_FS;
use super::{Axis, Frame, PerAxis, PerPoint, PointRow, Row, Unit};
use crate::io::{FileKind, open_regular};
use header::{header_fields, other_separator};
use reader::{Block, Reader, Reading, Rows};
use std::path::{Path, PathBuf};
use std::sync::mpsc;

/// How to read a record: which column is which axis and which is each
/// other point's channel (both empty: from the header), the unit of linear
/// columns whose name gives none, and fs when the file has no time column.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RecordOptions {
    pub axes: PerAxis<String>,
    pub points: PerPoint<String>,
    pub unit: Option<Unit>,
    pub fs: Option<f64>,
    /// Subtract each channel's mean over the record before anything reads
    /// it: the 1 g a DC-coupled accelerometer records, or its offset.
    pub remove_mean: bool,
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

/// Rows handed over at a time by the reading thread.
const BLOCK: usize = 8192;

/// Blocks parsed ahead of the consumer: memory stays a few blocks.
const AHEAD: usize = 4;

/// Rows read at open to find the time step (their mean step): 4096 rows
/// are 4 s at 1 kHz, a record too short for them gives its whole length.
const LEAD: usize = 4096;

/// Where the rows after the first two come from: a thread that splits and
/// parses the file ahead of the consumer (the reading is most of the cost
/// of assessing a record, and runs beside the body on a second core), or,
/// where no thread can be had, this one.
enum Feed {
    Parallel(parallel::Joiner),
    Thread(mpsc::Receiver<Block>),
    Inline(Box<Reader>),
}

/// An open record: a streaming iterator over its rows.
pub struct Record {
    path: PathBuf,
    columns: Columns,
    time_name: String,
    fs: f64,
    t0: f64,
    block: Rows,
    pos: usize,
    feed: Option<Feed>,
    /// An error read inline, given once the rows before it are out.
    pending: Option<RecordError>,
    /// Each channel's mean, subtracted from every row, where asked.
    offset: Option<(Row, PointRow)>,
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

impl Record {
    /// Opens `path`, reads the header and the first two rows (to learn fs),
    /// and starts reading the rest ahead.
    pub fn open(path: &Path, opts: &RecordOptions) -> Result<Record, RecordError> {
        Record::open_with(path, opts, Some(parallel::CHUNK), LEAD)
    }

    /// As [`Record::open`], the rest cut into chunks of about `chunk` bytes
    /// parsed on two threads, or on one thread without `chunk` (the tests
    /// cut small chunks, and read on one thread for reference); the step
    /// from the first `lead` rows (tests take 2, so that small files
    /// still reach the chunked reader).
    fn open_with(
        path: &Path,
        opts: &RecordOptions,
        chunk: Option<usize>,
        lead: usize,
    ) -> Result<Record, RecordError> {
        if let Some(fs) = opts.fs
            && !(fs.is_finite() && fs > 0.0 && fs <= MAX_FS)
        {
            return Err(RecordError::BadFs(fs));
        }
        let (file, _) = open_regular(path, FileKind::Record)?;
        let p = path.to_path_buf();
        let mut reader = Reader::new(file, path);
        let header = loop {
            match reader.next_line()? {
                None => return Err(RecordError::NoHeader { path: p }),
                Some((_, s, e)) if s == e => continue,
                Some((n, s, e)) => break header_fields(&p, n, reader.bytes(s, e))?,
            }
        };
        if header.iter().all(String::is_empty) {
            return Err(RecordError::NoHeader { path: p });
        }
        header::refuse_numbers(&p, &header)?;
        if let [only] = &header[..]
            && let Some(sep) = other_separator(only)
        {
            return Err(RecordError::Delimiter { path: p, sep });
        }
        let given = columns::Given {
            axes: &opts.axes,
            points: &opts.points,
        };
        let mut columns = columns::map_columns(&p, &header, given, opts.unit, opts.fs.is_some())?;
        let offset = match opts.remove_mean {
            true => {
                let first = RecordOptions {
                    remove_mean: false,
                    ..opts.clone()
                };
                let frames = Record::open(path, &first)?.frames();
                Some(mean::means(frames, &mut columns)?)
            }
            false => None,
        };
        let readings = columns
            .axes
            .iter()
            .map(|(axis, c)| Reading {
                slot: axis.index(),
                index: c.index,
                scale: c.unit.to_m_s2(),
                name: c.name.clone(),
            })
            .collect();
        let points = columns
            .points
            .iter()
            .map(|(p, c)| Reading {
                slot: p.slot(),
                index: c.index,
                scale: c.scale(),
                name: c.name.clone(),
            })
            .collect();
        let time_name = columns
            .time
            .and_then(|t| header.get(t).cloned())
            .unwrap_or_default();
        reader.set_columns(
            header.len(),
            readings,
            points,
            columns
                .time
                .map(|t| (t, time_name.clone(), columns.time_unit.seconds)),
        );
        // The time step is the mean over the first rows (up to LEAD): one
        // step of a clock at t = 1e9 s is off by an ulp of 1e9 (1.2e-7 s,
        // fs 999.953 Hz at 1 kHz), the mean of 4095 by 1/4095 of it.
        let lead = lead.max(2);
        let mut first: Vec<(f64, u64)> = Vec::with_capacity(lead);
        let mut block = Rows::with_capacity(lead, reader.has_points());
        // An error past the first two rows comes after the rows before it,
        // as it would without the look-ahead.
        let mut pending = None;
        while first.len() < lead {
            let (t, row) = match reader.next_row() {
                Ok(Some(r)) => r,
                Ok(None) => break,
                Err(e) if first.len() >= 2 => {
                    pending = Some(e);
                    break;
                }
                Err(e) => return Err(e),
            };
            first.push((t, reader.last_line()));
            block.seat.push(row);
            if reader.has_points() {
                block.points.push(reader.last_points());
            }
        }
        if first.len() < 2 {
            return Err(RecordError::TooFewRows {
                path: p,
                rows: first.len(),
            });
        }
        let mut fs = opts.fs.unwrap_or(0.0);
        let (t0, _) = first[0];
        if columns.time.is_some() {
            let first_step = first[1].0 - t0;
            if !(first_step.is_finite() && first_step > 0.0 && 1.0 / first_step <= MAX_FS) {
                return Err(RecordError::BadStep {
                    path: p,
                    line: first[1].1,
                    step: first_step,
                });
            }
            // Each step within 0.1 % of the first (which names the row
            // that is off); rows from an uneven one on are not delivered.
            if let Some(i) = (2..first.len()).find(|&i| {
                let s = first[i].0 - first[i - 1].0;
                // NaN counts as off.
                let even = (s - first_step).abs() <= 1e-3 * first_step;
                !even
            }) {
                pending = Some(RecordError::Uneven {
                    path: p.clone(),
                    line: first[i].1,
                    step: first[i].0 - first[i - 1].0,
                    expected: first_step,
                });
                first.truncate(i);
                block.seat.truncate(i);
                block.points.truncate(i.min(block.points.len()));
            }
            let t1 = first[first.len() - 1].0;
            let step = (t1 - t0) / (first.len() - 1) as f64;
            let file_fs = 1.0 / step;
            if let Some(given) = opts.fs
                && (given - file_fs).abs() > 1e-3 * file_fs
            {
                return Err(RecordError::FsMismatch {
                    path: p,
                    file: file_fs,
                    given,
                });
            }
            reader.set_timing(step, t1);
            fs = file_fs;
        }
        // Nothing is read past an error.
        let feed = match (&pending, chunk) {
            (Some(_), _) => None,
            (None, Some(c)) => Some(ahead(reader, c)),
            (None, None) => Some(one_ahead(reader)),
        };
        Ok(Record {
            path: p,
            columns,
            time_name,
            fs,
            t0,
            block,
            pos: 0,
            pending,
            feed,
            offset,
        })
    }

    /// The time column's unit (seconds without one).
    pub fn time_unit(&self) -> TimeUnit {
        self.columns.time_unit
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

    /// The other points' channels the record has.
    pub fn points(&self) -> PerPoint<()> {
        let mut out = PerPoint::default();
        for p in self.columns.points.channels() {
            out.set(p, ());
        }
        out
    }

    /// Each row with the other points' channels beside it (all 0 where the
    /// record has none): what an assessment of comfort at every point reads.
    /// The seat's rows alone ([`Record`] as an iterator) carry less.
    pub fn frames(mut self) -> impl Iterator<Item = Result<Frame, RecordError>> {
        std::iter::from_fn(move || {
            let row = self.next()?;
            let mut points: PointRow = match self.pos.checked_sub(1) {
                Some(i) => self.block.points.get(i).copied().unwrap_or([0.0; 9]),
                None => [0.0; 9],
            };
            if let Some((_, o)) = &self.offset {
                for (p, m) in points.iter_mut().zip(o) {
                    *p -= m;
                }
            }
            Some(row.map(|r| (r, points)))
        })
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

/// Reads the rest ahead: on two parsers where the machine has two cores
/// or more, else on one thread, else inline.
fn ahead(reader: Reader, chunk: usize) -> Feed {
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    if cores < 2 {
        return one_ahead(reader);
    }
    match parallel::start(reader.into_rest(), chunk) {
        Ok(j) => Feed::Parallel(j),
        Err(rest) => one_ahead(Reader::from_rest(*rest)),
    }
}

/// Starts a thread reading `reader` ahead in blocks; inline without one.
fn one_ahead(reader: Reader) -> Feed {
    let (tx, rx) = mpsc::sync_channel::<Block>(AHEAD);
    // The reader goes to the thread only once it runs, so a failed spawn
    // leaves it here.
    let (give, take) = mpsc::channel::<Reader>();
    let spawned = std::thread::Builder::new()
        .name("record".into())
        .spawn(move || {
            let Ok(mut reader) = take.recv() else {
                return;
            };
            loop {
                let mut v = Rows::with_capacity(BLOCK, reader.has_points());
                let (rows, error) = match reader.block(&mut v, BLOCK) {
                    Ok(true) => (v, None),
                    Ok(false) => return,
                    // The rows before the error first, then the error.
                    Err(e) => (v, Some(e)),
                };
                // The consumer may have stopped reading: nothing to hand over to.
                if tx.send(Ok(rows)).is_err() {
                    return;
                }
                if let Some(e) = error {
                    let _ = tx.send(Err(e));
                    return;
                }
            }
        });
    if spawned.is_err() {
        return Feed::Inline(Box::new(reader));
    }
    match give.send(reader) {
        Ok(()) => Feed::Thread(rx),
        Err(mpsc::SendError(reader)) => Feed::Inline(Box::new(reader)),
    }
}

impl Iterator for Record {
    type Item = Result<Row, RecordError>;

    fn next(&mut self) -> Option<Self::Item> {
        loop {
            if let Some(&row) = self.block.seat.get(self.pos) {
                self.pos += 1;
                return Some(Ok(match &self.offset {
                    Some((o, _)) => [row[0] - o[0], row[1] - o[1], row[2] - o[2]],
                    None => row,
                }));
            }
            // The rows before an error first, then the error, then nothing.
            if let Some(e) = self.pending.take() {
                self.feed = None;
                return Some(Err(e));
            }
            let next = match self.feed.as_mut()? {
                Feed::Parallel(j) => j.next_block(),
                Feed::Thread(rx) => rx.recv().ok(),
                Feed::Inline(reader) => {
                    let mut v = std::mem::take(&mut self.block);
                    match reader.block(&mut v, BLOCK) {
                        Ok(true) => Some(Ok(v)),
                        Ok(false) => None,
                        Err(e) => {
                            self.pending = Some(e);
                            Some(Ok(v))
                        }
                    }
                }
            };
            match next {
                Some(Ok(v)) => {
                    self.block = v;
                    self.pos = 0;
                }
                Some(Err(e)) => {
                    self.feed = None;
                    return Some(Err(e));
                }
                None => {
                    self.feed = None;
                    return None;
                }
            }
        }
    }
}
