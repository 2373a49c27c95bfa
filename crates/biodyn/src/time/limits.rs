//! The caps every signal and record is held to.

/// Most samples in one record, read or generated: 10^8 (27.8 h at 1 kHz,
/// 8 h at 3.4 kHz). Memory stays bounded either way; this caps the time a
/// typo (a duration of 3600000 s) can cost.
pub const MAX_SAMPLES: usize = 100_000_000;

/// Largest seat acceleration a signal or record may hold, m/s² (≈ 1000 g):
/// far beyond any seat vibration or shock a body survives, so a larger value
/// is a unit slip; it also keeps every sum and the simulator finite.
pub const MAX_ACC: f64 = 1e4;

/// Longest line a record may have, bytes: a row of a few numbers is under
/// 100 bytes; the cap keeps the reader's buffer (and memory) bounded when a
/// file has no newlines (1 GiB of NUL bytes).
pub const MAX_LINE: usize = 64 * 1024;
