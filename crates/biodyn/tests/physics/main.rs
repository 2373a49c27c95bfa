//! The library's physics and the standard's numbers against independent
//! computations: the frequency engine, big models, the time domain and
//! ISO 2631-1. One test binary.

/// Big and awkward models against a dense LU and polynomial roots.
mod big_models;
/// The frequency response against reference tables, a dense LU and limits.
mod frequency;
/// ISO 2631-1 weightings and metrics against Annex A and closed forms.
mod iso2631;
/// ISO 8041-1's meter conformance tests through the library's own meter.
mod meter;
/// The progress callbacks: counts to the total, the same bits as without.
mod progress_hooks;
/// A seat between floor and body: hand elimination, limits, SEAT, classes, design.
mod seat;
/// ISO 2631-5 against its frequency-domain form and Annex C.
mod spine;
/// The time domain against the frequency engine, RK4, linearity, records.
mod time;
/// The eight weightings against ISO 2631-1 Tables 3 and 4 and ISO 8041-1.
mod weightings;
