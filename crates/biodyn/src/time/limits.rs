//! The caps every signal and record is held to.

/// Most samples in one record, read or generated: 10^8 (27.8 h at 1 kHz,
/// 8 h at 3.4 kHz). Memory stays bounded either way; this caps the time a
/// typo (a duration of 3600000 s) can cost.
pub const MAX_SAMPLES: usize = 100_000_000;

/// Largest seat acceleration a signal or record may hold, m/s² (≈ 1000 g):
/// far beyond any seat vibration or shock a body survives, so a larger value
/// is a unit slip; it also keeps every sum and the simulator finite.
pub const MAX_ACC: f64 = 1e4;

/// Most segments a model may have in the time domain. The exact step
/// q ← Φ q + Γ0 a0 + Γ1 a1 is dense whatever the links (Φ = e^(A h) couples
/// every state to every other): 6·n² multiply–adds a sample and 32·n² bytes
/// for Φ; discretising it is the exponential of a (2n + 2)² matrix, O(n³).
/// At 500 segments (measured, `docs/speed.md`): 0.8 s to discretise, 0.5 s
/// per second of signal at 1 kHz, 142 MB; at 1000 it was 12 s, 2.5 s per
/// second and 543 MB, and 28 000 ran out of memory.
pub const MAX_SEGMENTS: usize = 500;

/// Lowest sampling rate the simulator takes, Hz: a step of 1000 s, slower
/// than any vibration; A·h then stays far from overflow for every model
/// the body's limits allow (at 1e-300 Hz, a step of 1e300 s, it did not).
pub const MIN_FS: f64 = 1e-3;

/// Longest line a record may have, bytes: a row of a few numbers is under
/// 100 bytes; the cap keeps the reader's buffer (and memory) bounded when a
/// file has no newlines (1 GiB of NUL bytes).
pub const MAX_LINE: usize = 64 * 1024;
