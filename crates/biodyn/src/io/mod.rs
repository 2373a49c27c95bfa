//! Files in and out. Every file the program reads goes through [`read`]:
//! regular files only (after following links), with a size cap that fits its
//! kind, so a FIFO, a device or `/dev/zero` is refused instead of hanging or
//! eating memory. Every file it writes goes through [`save`]: atomic, links
//! followed, special files refused, permissions kept.

pub mod excerpt;
pub mod read;
pub mod save;
pub mod temp;

pub use read::{FileKind, ReadError, open_regular, read_bytes, read_text};
pub use save::{SaveError, save_atomic, save_atomic_with};
