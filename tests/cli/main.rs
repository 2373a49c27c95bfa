//! The command line as real processes of the `biodyn` binary, grouped by
//! behaviour in one test binary (one link of the app, not one per file).

#[path = "../common/mod.rs"]
mod common;

/// Tri-axial records: axes, units, the highest-axis rule, refusals.
mod axes;
/// Big models (chains of 400 and 1000 segments) through the binary.
mod big_models;
/// Sizes that cannot fit or finish, refused with the rule; time limits inside an epoch.
mod bounds;
/// `biodyn day`: the working day's sheet, JSON, week and refusals.
mod day;
/// Closed pipes, a full disk, help, refused combinations, no terminal.
mod edges;
/// `plot --format svg`: figures read back through their tick labels, rendered.
mod figures;
/// `seat --plot` and `day --plot`: bars and curves read back against the JSON.
mod figures_seat_day;
/// Saves that never clobber, reads that never hang, limits, names.
mod files;
/// `biodyn fit`.
mod fit;
/// `biodyn fit`'s intervals, data limits and a save from an odd name.
mod fit_intervals;
/// What a hostile pass found: outputs on one file, escapes in names.
mod hostile;
/// `assess`'s points and hours to the action and limit values per axis.
mod hours;
/// Records as instruments write them: gravity, a clock in ms, units, no header.
mod instruments;
/// `biodyn man` and `biodyn completions`.
mod man_and_completions;
/// Two values for one model parameter (--set twice, --body-mass with --set body_mass).
mod model_twice;
/// Papercuts of the command line: global --preset, --at, defaults, numbers.
mod papercuts;
/// Comfort at the backrest, the feet and the seat's rotations (ISO 2631-1 §8.2).
mod points;
/// The progress line on a terminal, none in a pipe, CI or --quiet; summaries after a closed pipe.
mod progress;
/// `assess --report` and `day --report`: the HTML page against the JSON, escaping, refusals.
mod report;
/// A report to hand over: --meta, [report], --no-model, hours as written, the day's caps and fs.
mod report_meta;
/// `response`, `modes`, `peaks`, `study`, `plot`, `preset` and bad input.
mod response;
/// Saves that lose nothing: not onto an input, checked first, read-only.
mod saves;
/// `biodyn seat`: SEAT %, stroke, the design search; `response` and `plot` with a seat.
mod seat;
/// `seat --psd FILE`: narrow peaks, a measured PSD, the lower limit, against a brute force.
mod seat_psd;
/// `assess` and `simulate` with a seat under the body.
mod seat_time;
/// `biodyn assess --spine`: ISO 2631-5, and motion sickness.
mod spine;
/// `biodyn simulate` and `biodyn assess`.
mod time;
/// `biodyn train` and `biodyn predict`.
mod train;
/// `train` and `predict` on models other than the paper's.
mod train_on_presets;
/// `biodyn weighting`: each format read back, the list, refusals.
mod weighting;
