//! A reader that bounds each line, so a file without newlines (1 GiB of
//! NUL bytes) cannot grow the CSV reader's buffer without bound.

use super::RecordError;
use std::io::Read;
use std::path::Path;

/// Longest line a record may have, bytes: a row of a few numbers is under
/// 100 bytes.
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
pub struct LineCap<R> {
    inner: R,
    /// Bytes since the last newline, and 1-based line number.
    run: u64,
    line: u64,
}

impl<R> LineCap<R> {
    pub fn new(inner: R) -> Self {
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
        let got = buf.get(..n).unwrap_or_default();
        // Fast path: find newlines with memchr-like slicing instead of a
        // byte loop's branch per byte.
        let mut rest = got;
        while let Some(i) = rest.iter().position(|&b| b == b'\n') {
            if self.run + i as u64 > MAX_LINE {
                return Err(too_long(self.line));
            }
            self.run = 0;
            self.line += 1;
            rest = &rest[i + 1..];
        }
        self.run += rest.len() as u64;
        if self.run > MAX_LINE {
            return Err(too_long(self.line));
        }
        Ok(n)
    }
}

fn too_long(line: u64) -> std::io::Error {
    std::io::Error::new(std::io::ErrorKind::InvalidData, LineTooLong { line })
}

/// A CSV error as a record error: a too-long line gets its own message.
pub fn csv_error(e: csv::Error, path: &Path, default_line: u64) -> RecordError {
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

#[cfg(test)]
mod tests {
    use super::*;

    /// The cap counts bytes since the last newline across reads.
    #[test]
    fn a_line_over_the_cap_fails_with_its_number() {
        let ok = vec![b'a'; MAX_LINE as usize];
        let mut text = b"h\n".to_vec();
        text.extend(&ok);
        text.push(b'\n');
        let mut r = LineCap::new(&text[..]);
        assert!(std::io::copy(&mut r, &mut std::io::sink()).is_ok());
        text.extend(&ok);
        text.push(b'a');
        let mut r = LineCap::new(&text[..]);
        let e = std::io::copy(&mut r, &mut std::io::sink()).unwrap_err();
        assert_eq!(
            e.to_string(),
            format!("line 3 is over {} KiB", MAX_LINE / 1024)
        );
    }
}
