//! Opening and reading user files safely: only regular files, never more than
//! the cap for their kind, never blocking on a FIFO.

use std::fs::File;
use std::io::Read;
use std::path::{Path, PathBuf};

/// What a file holds; each kind has its own size cap.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FileKind {
    /// A TOML body preset.
    Preset,
    /// A trained network (JSON).
    Network,
    /// A seat-acceleration record (CSV), read streaming.
    Record,
    /// Measured APMS/DPMI/STHT data (CSV).
    Measured,
    /// A working day's operations (TOML).
    Day,
    /// A floor vibration's power spectral density (CSV).
    Psd,
    /// A report's details: who, where, when, with what (TOML).
    Meta,
}

impl FileKind {
    /// The largest file of this kind we open, in bytes.
    pub fn cap(self) -> u64 {
        match self {
            // A preset of 10 000 segments and links is ~1 MB.
            FileKind::Preset => 4 << 20,
            // The largest network we train is a few kB; ensembles of big ones fit.
            FileKind::Network => 16 << 20,
            // Eight hours at 2 kHz with a time column is ~1.2 GB of CSV.
            FileKind::Record => 2 << 30,
            // Measured spectra are thousands of rows at most.
            FileKind::Measured => 16 << 20,
            // A day of a few dozen operations is a few kB; 1 MiB is thousands.
            FileKind::Day => 1 << 20,
            // A PSD of a million rows is ~40 MB; spectra have thousands.
            FileKind::Psd => 16 << 20,
            // Nine short texts and notes are a few kB.
            FileKind::Meta => 64 << 10,
        }
    }

    /// The word users know the file by.
    pub fn noun(self) -> &'static str {
        match self {
            FileKind::Preset => "preset",
            FileKind::Network => "network",
            FileKind::Record => "vibration record",
            FileKind::Measured => "measured data",
            FileKind::Day => "day",
            FileKind::Psd => "PSD",
            FileKind::Meta => "report details",
        }
    }
}

/// Why a file could not be read.
#[derive(Debug, thiserror::Error)]
pub enum ReadError {
    #[error("{path}: {source}")]
    Io {
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },
    #[error("{path}: is a {what}, not a regular file; give the path of a {noun} file")]
    NotRegular {
        path: PathBuf,
        what: &'static str,
        noun: &'static str,
    },
    #[error("{path}: {size} bytes is over the {} cap for a {noun} file", mib(*.cap))]
    TooLarge {
        path: PathBuf,
        size: u64,
        cap: u64,
        noun: &'static str,
    },
    #[error("{path}: not UTF-8 text (byte {offset}); save it as UTF-8")]
    NotText { path: PathBuf, offset: usize },
}

impl ReadError {
    /// The reason without the path, for callers that print the path themselves.
    pub fn reason(&self) -> String {
        match self {
            ReadError::Io { source, .. } => source.to_string(),
            ReadError::NotRegular { what, noun, .. } => {
                format!("is a {what}, not a regular file; give the path of a {noun} file")
            }
            ReadError::TooLarge {
                size, cap, noun, ..
            } => format!(
                "{size} bytes is over the {} cap for a {noun} file",
                mib(*cap)
            ),
            ReadError::NotText { offset, .. } => {
                format!("not UTF-8 text (byte {offset}); save it as UTF-8")
            }
        }
    }

    /// As an `io::Error` carrying [`reason`](Self::reason) (the original
    /// error for a failed open or read), for error types that hold one.
    pub fn into_io(self) -> std::io::Error {
        match self {
            ReadError::Io { source, .. } => source,
            other => std::io::Error::new(std::io::ErrorKind::InvalidData, other.reason()),
        }
    }
}

/// A cap in words: "4 MiB" (every cap is a whole number of MiB), else bytes.
fn mib(bytes: u64) -> String {
    if bytes % (1 << 20) == 0 {
        format!("{} MiB", bytes >> 20)
    } else {
        format!("{bytes} byte")
    }
}

/// What a non-regular file is, in words.
pub(crate) fn describe(t: std::fs::FileType) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if t.is_fifo() {
            return "FIFO (named pipe)";
        }
        if t.is_char_device() {
            return "character device";
        }
        if t.is_block_device() {
            return "block device";
        }
        if t.is_socket() {
            return "socket";
        }
    }
    if t.is_dir() {
        "directory"
    } else {
        "special file"
    }
}

/// Opens `path` for reading if, after following links, it is a regular file
/// within the cap for `kind`. Never blocks: the file is opened non-blocking
/// and checked again once open, so a FIFO swapped in after the first look is
/// refused too. Returns the file and its size.
pub fn open_regular(path: &Path, kind: FileKind) -> Result<(File, u64), ReadError> {
    let io = |source| ReadError::Io {
        path: path.to_path_buf(),
        source,
    };
    let check = |meta: &std::fs::Metadata| -> Result<u64, ReadError> {
        if !meta.is_file() {
            return Err(ReadError::NotRegular {
                path: path.to_path_buf(),
                what: describe(meta.file_type()),
                noun: kind.noun(),
            });
        }
        if meta.len() > kind.cap() {
            return Err(ReadError::TooLarge {
                path: path.to_path_buf(),
                size: meta.len(),
                cap: kind.cap(),
                noun: kind.noun(),
            });
        }
        Ok(meta.len())
    };
    check(&std::fs::metadata(path).map_err(io)?)?;
    let mut opts = std::fs::OpenOptions::new();
    opts.read(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        opts.custom_flags(libc::O_NONBLOCK);
    }
    let file = opts.open(path).map_err(io)?;
    let size = check(&file.metadata().map_err(io)?)?;
    Ok((file, size))
}

/// The whole of a small file (a preset, a network, measured data), read
/// through [`open_regular`] and never past the cap even if the file grows.
pub fn read_bytes(path: &Path, kind: FileKind) -> Result<Vec<u8>, ReadError> {
    let (file, size) = open_regular(path, kind)?;
    let mut bytes = Vec::with_capacity(size as usize);
    file.take(kind.cap() + 1)
        .read_to_end(&mut bytes)
        .map_err(|source| ReadError::Io {
            path: path.to_path_buf(),
            source,
        })?;
    if bytes.len() as u64 > kind.cap() {
        return Err(ReadError::TooLarge {
            path: path.to_path_buf(),
            size: bytes.len() as u64,
            cap: kind.cap(),
            noun: kind.noun(),
        });
    }
    Ok(bytes)
}

/// [`read_bytes`] for a file that must be UTF-8 text.
pub fn read_text(path: &Path, kind: FileKind) -> Result<String, ReadError> {
    String::from_utf8(read_bytes(path, kind)?).map_err(|e| ReadError::NotText {
        path: path.to_path_buf(),
        offset: e.utf8_error().valid_up_to(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_directory_is_refused_by_name() {
        let dir = tempfile::tempdir().unwrap();
        let e = read_text(dir.path(), FileKind::Preset).unwrap_err();
        assert!(
            matches!(
                e,
                ReadError::NotRegular {
                    what: "directory",
                    ..
                }
            ),
            "{e}"
        );
        assert!(e.to_string().contains("preset file"), "{e}");
    }

    #[cfg(unix)]
    #[test]
    fn a_fifo_is_refused_without_blocking() {
        let dir = tempfile::tempdir().unwrap();
        let fifo = dir.path().join("f");
        let c = std::ffi::CString::new(fifo.to_str().unwrap()).unwrap();
        assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o600) }, 0);
        let e = read_text(&fifo, FileKind::Record).unwrap_err();
        assert!(matches!(e, ReadError::NotRegular { .. }), "{e}");
        assert!(e.to_string().contains("FIFO"), "{e}");
    }

    #[cfg(unix)]
    #[test]
    fn dev_zero_is_refused() {
        let e = read_text(Path::new("/dev/zero"), FileKind::Network).unwrap_err();
        assert!(e.to_string().contains("character device"), "{e}");
    }

    #[test]
    fn a_file_over_the_cap_is_refused_before_reading() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("big.toml");
        let f = File::create(&p).unwrap();
        f.set_len(FileKind::Preset.cap() + 1).unwrap();
        let e = read_text(&p, FileKind::Preset).unwrap_err();
        assert!(matches!(e, ReadError::TooLarge { .. }), "{e}");
    }

    #[test]
    fn text_is_read_and_bad_utf8_named() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("a.toml");
        std::fs::write(&p, "x = 1\n").unwrap();
        assert_eq!(read_text(&p, FileKind::Preset).unwrap(), "x = 1\n");
        std::fs::write(&p, b"ab\xff").unwrap();
        let e = read_text(&p, FileKind::Preset).unwrap_err();
        assert!(matches!(e, ReadError::NotText { offset: 2, .. }), "{e}");
    }
}
