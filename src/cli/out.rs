//! The one way output leaves a command: `emit`. A closed pipe (`biodyn
//! response | head -1`) ends the command quietly with status 0, as git and
//! ripgrep do; any other write error is an error that names standard output.

use std::io::Write;

/// Writing to standard output failed (a full disk, a closed terminal).
#[derive(Debug)]
pub struct StdoutError(pub std::io::Error);

impl std::fmt::Display for StdoutError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "cannot write to standard output: {}", self.0)
    }
}

impl std::error::Error for StdoutError {}

/// A status line ("saved …", a closing summary): `note!`, unless `--quiet`.
macro_rules! status {
    ($($t:tt)*) => {{
        if !$crate::cli::progress::quiet() {
            $crate::cli::out::note!($($t)*);
        }
    }};
}
pub(crate) use status;

/// How far a result reached its reader.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Delivered {
    /// All of it was written and flushed.
    All,
    /// The reader closed the pipe first (`| head -1`): a quiet success, and
    /// nothing more is said (no closing summary on stderr).
    ReaderGone,
}

/// Writes all of `text` to stdout and flushes; says whether the reader
/// took it all.
pub fn emit(text: &str) -> anyhow::Result<Delivered> {
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|_| out.flush()) {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(Delivered::ReaderGone),
        Err(e) => Err(StdoutError(e).into()),
        Ok(()) => Ok(Delivered::All),
    }
}

/// `emit`, then the closing `summary` lines on stderr, after the result
/// (a summary printed before it would be the last thing on a terminal
/// scrolled by the table) and only if the reader took it all and
/// `--quiet` was not given.
pub fn emit_then(text: &str, summary: &[String]) -> anyhow::Result<()> {
    if emit(text)? == Delivered::All {
        for line in summary {
            status!("{line}");
        }
    }
    Ok(())
}

/// The end of a command that streamed to stdout itself (`simulate`: rows as
/// they are computed, in bounded memory): the same rules as `emit`. A closed
/// pipe is a quiet success; any other write error names standard output.
pub fn stream_result(r: anyhow::Result<()>) -> anyhow::Result<()> {
    match r {
        Err(e) => match e.downcast::<std::io::Error>() {
            Ok(io) if io.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
            Ok(io) => Err(StdoutError(io).into()),
            Err(e) => Err(e),
        },
        ok => ok,
    }
}

/// A line to standard error (a warning, a note, "saved …") that never panics:
/// `eprintln!` would, with stderr closed or full, turning a finished command
/// into exit status 101.
macro_rules! note {
    ($($t:tt)*) => {{
        use std::io::Write as _;
        // A name in the note (a file's) is escaped as the results are.
        let line = $crate::view::report::terminal_safe(&format!($($t)*));
        let _ = writeln!(std::io::stderr(), "{line}");
    }};
}
pub(crate) use note;
