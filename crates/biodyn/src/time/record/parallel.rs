//! The rest of a record read on both cores: one thread cuts the file into
//! chunks of whole lines, two parse alternate chunks, and the consumer
//! takes the parsed chunks back in order. Parsing decimals is most of the
//! cost of a record, so this roughly halves the time to read one; the rows,
//! the errors and their line numbers are those of reading it in one pass.
//!
//! Each parser checks the time steps inside its chunk; the step across a
//! chunk boundary and the sample cap are checked where the chunks meet
//! again, in order.

use super::RecordError;
use super::reader::{Block, Parser, Rest, Rows};
use crate::time::limits::{MAX_LINE, MAX_SAMPLES};
use std::io::Read;
use std::sync::mpsc::{Receiver, SyncSender, sync_channel};

/// Bytes a chunk holds before it is cut at its last newline.
pub const CHUNK: usize = 1 << 19;

/// Chunks waiting at each parser, and parsed chunks waiting for the consumer.
const QUEUE: usize = 2;

/// Whole lines of the file, from line `first_line`; or the error that
/// stopped the cutting, in its place in the order.
enum Chunk {
    Lines { first_line: u64, bytes: Vec<u8> },
    Failed(RecordError),
}

/// A parsed chunk: its rows, the times of the first and last, the line of
/// the first, and the error that ended it early.
pub struct Parsed {
    rows: Rows,
    first: Option<(f64, u64)>,
    last_t: f64,
    error: Option<RecordError>,
}

/// Where the parsed chunks meet again: the step across each boundary and
/// the count of rows.
pub struct Joiner {
    results: [Receiver<Parsed>; 2],
    next: usize,
    dt: Option<f64>,
    last_t: f64,
    count: usize,
    path: std::path::PathBuf,
    /// The error to give once the rows before it are out.
    pending: Option<RecordError>,
    done: bool,
}

/// Reads up to `chunk` more bytes onto the end of `buf`; true at the end
/// of the file.
fn read_more(file: &mut std::fs::File, buf: &mut Vec<u8>, chunk: usize) -> std::io::Result<bool> {
    let old = buf.len();
    buf.resize(old + chunk, 0);
    loop {
        match file.read(&mut buf[old..]) {
            Ok(n) => {
                buf.truncate(old + n);
                return Ok(n == 0);
            }
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => {}
            Err(e) => {
                buf.truncate(old);
                return Err(e);
            }
        }
    }
}

/// Cuts `rest` into chunks and sends chunk k to parser k mod 2.
fn cut(mut rest: Rest, chunk: usize, to: [SyncSender<Chunk>; 2]) {
    let mut buf = std::mem::take(&mut rest.ahead);
    let mut line = rest.line;
    let mut k = 0;
    let mut eof = rest.eof;
    let path = rest.parser.path.clone();
    // An error goes where the next chunk would have: after every row before it.
    let fail = |k: usize, e: RecordError| {
        let _ = to[k % 2].send(Chunk::Failed(e));
    };
    let io = |e| {
        RecordError::Read(crate::io::ReadError::Io {
            path: path.clone(),
            source: e,
        })
    };
    loop {
        while !eof && buf.len() < chunk {
            match read_more(&mut rest.file, &mut buf, chunk) {
                Ok(end) => eof = end,
                Err(e) => return fail(k, io(e)),
            }
        }
        if buf.is_empty() {
            return;
        }
        let cut_at = match memchr::memrchr(b'\n', &buf) {
            Some(i) => i + 1,
            None if eof => buf.len(),
            None if buf.len() > MAX_LINE => {
                return fail(
                    k,
                    RecordError::LineTooLong {
                        path: path.clone(),
                        line,
                    },
                );
            }
            // One long line still under the cap: read on.
            None => {
                match read_more(&mut rest.file, &mut buf, chunk) {
                    Ok(end) => eof = end,
                    Err(e) => return fail(k, io(e)),
                }
                continue;
            }
        };
        let tail = buf.split_off(cut_at);
        let lines = memchr::memchr_iter(b'\n', &buf).count() as u64;
        let bytes = std::mem::replace(&mut buf, tail);
        // The consumer may have stopped reading: nothing to hand over to.
        if to[k % 2]
            .send(Chunk::Lines {
                first_line: line,
                bytes,
            })
            .is_err()
        {
            return;
        }
        line += lines;
        k += 1;
    }
}

/// Parses every chunk `from` sends, in order, into `to`.
fn parse(parser: Parser, dt: Option<f64>, from: Receiver<Chunk>, to: SyncSender<Parsed>) {
    let mut spans = Vec::new();
    for chunk in from {
        let parsed = match chunk {
            Chunk::Failed(e) => Parsed {
                rows: Rows::default(),
                first: None,
                last_t: 0.0,
                error: Some(e),
            },
            Chunk::Lines { first_line, bytes } => {
                lines(&parser, dt, first_line, &bytes, &mut spans)
            }
        };
        let stop = parsed.error.is_some();
        if to.send(parsed).is_err() || stop {
            return;
        }
    }
}

/// The rows of one chunk of whole lines.
fn lines(
    parser: &Parser,
    dt: Option<f64>,
    first_line: u64,
    bytes: &[u8],
    spans: &mut Vec<(usize, usize)>,
) -> Parsed {
    let has_points = parser.has_points();
    let mut points = [0.0; 9];
    let mut out = Parsed {
        rows: Rows::with_capacity(bytes.len() / 24, has_points),
        first: None,
        last_t: 0.0,
        error: None,
    };
    let mut at = 0;
    let mut line = first_line;
    while at < bytes.len() {
        let end = memchr::memchr(b'\n', &bytes[at..]).map_or(bytes.len(), |i| at + i);
        let mut l = &bytes[at..end];
        at = end + 1;
        let n = line;
        line += 1;
        if l.len() > MAX_LINE {
            out.error = Some(RecordError::LineTooLong {
                path: parser.path.clone(),
                line: n,
            });
            return out;
        }
        if let [rest @ .., b'\r'] = l {
            l = rest;
        }
        if l.is_empty() {
            continue;
        }
        match parser.row(n, l, spans, &mut points) {
            Ok((t, row)) => {
                if out.first.is_none() {
                    out.first = Some((t, n));
                } else if let Some(dt) = dt {
                    let step = t - out.last_t;
                    if (step - dt).abs() > 1e-3 * dt {
                        out.error = Some(RecordError::Uneven {
                            path: parser.path.clone(),
                            line: n,
                            step,
                            expected: dt,
                        });
                        return out;
                    }
                }
                out.last_t = t;
                out.rows.seat.push(row);
                if has_points {
                    out.rows.points.push(points);
                }
            }
            Err(e) => {
                out.error = Some(e);
                return out;
            }
        }
    }
    out
}

/// Starts the cutter and two parsers on `rest`; `rest` back where the
/// threads cannot be had (then the caller reads on one thread).
pub fn start(rest: Rest, chunk: usize) -> Result<Joiner, Box<Rest>> {
    let (c0, r0) = sync_channel::<Chunk>(QUEUE);
    let (c1, r1) = sync_channel::<Chunk>(QUEUE);
    let (p0, q0) = sync_channel::<Parsed>(QUEUE);
    let (p1, q1) = sync_channel::<Parsed>(QUEUE);
    let path = rest.parser.path.clone();
    let (dt, last_t, count) = (rest.dt, rest.last_t, rest.count);
    let spawn = |name: &str, f: Box<dyn FnOnce() + Send>| {
        std::thread::Builder::new()
            .name(name.into())
            .spawn(f)
            .is_ok()
    };
    let (pa, pb) = (rest.parser.clone(), rest.parser.clone());
    // The parsers first: if one cannot start, nothing has been read yet.
    if !spawn("record-parse", Box::new(move || parse(pa, dt, r0, p0))) {
        return Err(Box::new(rest));
    }
    if !spawn("record-parse", Box::new(move || parse(pb, dt, r1, p1))) {
        return Err(Box::new(rest));
    }
    // The cutter takes the file only once it runs.
    let (give, take) = sync_channel::<Rest>(1);
    let cutter = std::thread::Builder::new()
        .name("record-cut".into())
        .spawn(move || {
            if let Ok(rest) = take.recv() {
                cut(rest, chunk, [c0, c1]);
            }
        });
    if cutter.is_err() {
        return Err(Box::new(rest));
    }
    if let Err(std::sync::mpsc::SendError(rest)) = give.send(rest) {
        return Err(Box::new(rest));
    }
    Ok(Joiner {
        results: [q0, q1],
        next: 0,
        dt,
        last_t,
        count,
        path,
        pending: None,
        done: false,
    })
}

impl Joiner {
    /// The next block of rows in order, the error after the rows before it,
    /// or None at the end.
    pub fn next_block(&mut self) -> Option<Block> {
        if let Some(e) = self.pending.take() {
            self.done = true;
            return Some(Err(e));
        }
        if self.done {
            return None;
        }
        let Ok(p) = self.results[self.next % 2].recv() else {
            self.done = true;
            return None;
        };
        self.next += 1;
        let mut rows = p.rows;
        let mut error = p.error;
        if let (Some((t, line)), Some(dt)) = (p.first, self.dt) {
            let step = t - self.last_t;
            if (step - dt).abs() > 1e-3 * dt {
                rows.clear();
                error = Some(RecordError::Uneven {
                    path: self.path.clone(),
                    line,
                    step,
                    expected: dt,
                });
            }
        }
        if p.first.is_some() {
            self.last_t = p.last_t;
        }
        if self.count + rows.len() > MAX_SAMPLES {
            rows.truncate(MAX_SAMPLES - self.count);
            error = Some(RecordError::TooLong {
                path: self.path.clone(),
                cap: MAX_SAMPLES,
            });
        }
        self.count += rows.len();
        self.pending = error;
        Some(Ok(rows))
    }
}

#[cfg(test)]
mod tests {
    use super::super::{Record, RecordOptions};
    use crate::time::Row;

    /// Chunks of about 100 bytes: a boundary every four lines or so.
    const CHUNK_UNDER_TEST: usize = 100;

    /// Rows and the final error (as text) of `path`, in parallel (small
    /// chunks) and on one thread.
    /// With the step from the first two rows; the same rows and error as
    /// from the default look-ahead (all of a small file) are asserted here.
    fn both(path: &std::path::Path) -> [(Vec<Row>, Option<String>); 2] {
        let read = |chunk: Option<usize>, lead: usize| {
            let rec = Record::open_with(path, &RecordOptions::default(), chunk, lead).unwrap();
            if lead == 2 {
                assert_eq!(
                    matches!(rec.feed, Some(super::super::Feed::Parallel(_))),
                    chunk.is_some()
                );
            }
            let mut rows = Vec::new();
            for r in rec {
                match r {
                    Ok(row) => rows.push(row),
                    Err(e) => return (rows, Some(e.to_string())),
                }
            }
            (rows, None)
        };
        let one = read(None, 2);
        assert_eq!(read(None, super::super::LEAD), one, "{}", path.display());
        [read(Some(CHUNK_UNDER_TEST), 2), one]
    }

    fn write(
        dir: &std::path::Path,
        name: &str,
        rows: usize,
        bad: Option<(usize, &str)>,
    ) -> std::path::PathBuf {
        let mut s = String::from("t_s,ax,az\n");
        for k in 0..rows {
            match bad {
                Some((at, line)) if at == k => s.push_str(line),
                _ => s.push_str(&format!(
                    "{},{},{}\n",
                    k as f64 / 1000.0,
                    (k as f64 * 0.37).sin(),
                    k as f64 * 1e-4
                )),
            }
        }
        let p = dir.join(name);
        std::fs::write(&p, s).unwrap();
        p
    }

    /// Many chunks: the same rows in the same order as one thread; and an
    /// error at any line (so at every kind of place: inside a chunk, first
    /// or last in one) comes after the rows before it, with the same line.
    #[test]
    fn chunks_parsed_on_two_threads_read_as_one_pass() {
        let dir = tempfile::tempdir().unwrap();
        let n = 300;
        let ok = write(dir.path(), "ok.csv", n, None);
        let [p, s] = both(&ok);
        assert_eq!(p.0.len(), n);
        assert_eq!(p, s);
        for at in 2..n {
            let t = at as f64 / 1000.0;
            let cases = [
                format!("{t},x,1\n"),
                format!("{},1,1\n", t + 0.0005),
                format!("{t},1,1,1\n"),
                "\n".to_string(),
                format!("{t},1,1\r\n"),
                format!("{t},\"2\",1\n"),
            ];
            for line in &cases {
                let p_bad = write(dir.path(), "bad.csv", n, Some((at, line)));
                let [p, s] = both(&p_bad);
                assert_eq!(p, s, "{line:?} at {at}");
            }
        }
        // A long file in the real chunk size: the same too.
        let big = write(dir.path(), "big.csv", 60_000, Some((41_234, "41.2,1,1\n")));
        let rec = |chunk| {
            let r = Record::open_with(&big, &RecordOptions::default(), chunk, 2).unwrap();
            let mut rows = 0;
            let mut err = None;
            for x in r {
                match x {
                    Ok(_) => rows += 1,
                    Err(e) => err = Some(e.to_string()),
                }
            }
            (rows, err)
        };
        assert_eq!(rec(Some(super::CHUNK)), rec(None));
        assert_eq!(rec(None).0, 41_234);
    }
}
