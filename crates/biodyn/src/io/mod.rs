//! Files in and out. Every file the program reads goes through [`read`]:
//! regular files only (after following links), with a size cap that fits its
//! kind, so a FIFO, a device or `/dev/zero` is refused instead of hanging or
//! eating memory.

pub mod read;

pub use read::{FileKind, ReadError, open_regular, read_text};
