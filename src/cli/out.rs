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

/// Writes all of `text` to stdout and flushes.
pub fn emit(text: &str) -> anyhow::Result<()> {
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|_| out.flush()) {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        Err(e) => Err(StdoutError(e).into()),
        Ok(()) => Ok(()),
    }
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
        let _ = writeln!(std::io::stderr(), $($t)*);
    }};
}
pub(crate) use note;

/// `note!` without the newline (progress that rewrites its own line).
macro_rules! note_raw {
    ($($t:tt)*) => {{
        use std::io::Write as _;
        let _ = write!(std::io::stderr(), $($t)*);
    }};
}
pub(crate) use note_raw;
