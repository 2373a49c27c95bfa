//! What the library reads and writes: presets (round trips, errors with a
//! line, atomic saves) and the fuzz harnesses of every parser of user files
//! (`#[ignore]`d: run with `-- --ignored`, see each module). One test binary.

/// Day files: the format, round trips, every refusal, record operations.
mod day;
/// Day files as people write them: hours as text, caps, a record's fs, [report].
mod day_forms;
/// Day files with ISO 2631-5's person and doses: Formula 5, refusals, records.
mod day_spine;
/// Fuzzing the preset and network-file parsers.
mod fuzz;
/// Fuzzing the record, `--signal` and measured-data readers.
mod fuzz_records;
/// Shipped presets, round trips, errors naming file and line, saves.
mod presets;
/// Presets with a seat: the shipped two, round trips, the seat's refusals.
mod seat_presets;
