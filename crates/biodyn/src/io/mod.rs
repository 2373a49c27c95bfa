//! Files in and out, and quoting a value for a message. Every file the
//! program reads goes through [`read_text`], [`read_bytes`] or [`open_regular`]:
//! regular files only (after following links), with a size cap that fits its
//! [`FileKind`], so a FIFO, a device or `/dev/zero` is refused instead of
//! hanging or eating memory. Every file it writes goes through [`save_atomic`]:
//! atomic, links followed, special files refused, permissions kept; a
//! [`Guard`] keeps it off the command's own inputs and read-only files.
//! [`excerpt`], [`short_quote`], [`num`] and [`Short`] put a user's text or a
//! number into an error message, control characters escaped.

pub(crate) mod excerpt;
mod guard;
mod read;
pub(crate) mod save;
mod temp;

pub use excerpt::{Short, excerpt, num, short_quote};
pub use guard::{Guard, same_target, save_atomic, save_atomic_with, save_guarded};
pub use read::{FileKind, ReadError, open_regular, read_bytes, read_text};
pub use save::SaveError;
