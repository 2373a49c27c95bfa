//! The headless command line (clap). Data go to stdout, diagnostics to stderr;
//! every error is one line plus a hint, with a non-zero exit.
//!
//! A command is a module with an args struct and `run(&Args) ->
//! anyhow::Result<String>`: it builds its result, wraps it in a
//! `view::report::Report` and returns `render(&report, args.format)`; `run`
//! below is the one place that writes the text to stdout (`out::emit`).
//! Adding one: the module, a `mod` line, a `Command` variant and its line in
//! `run`.

mod args;
mod assess;
mod command;
mod completions;
mod day;
mod figure_file;
mod fit;
mod free;
mod input;
mod man;
mod modes;
mod out;
mod plot;
mod predict;
mod preset;
mod progress;
mod refused;
mod report;
mod response;
mod seat;
mod seat_plot;
mod settings_flags;
mod simulate;
mod study;
mod train;
mod weighting;
mod words;

pub use command::{Cli, Command, TuiArgs};
pub use out::{Delivered, StdoutError, emit};

use crate::view::format::clip;
use std::io::{IsTerminal, Write as _};
use std::process::ExitCode;

/// Why the full-screen app cannot start here.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NoTerminal {
    /// stdin or stdout is not a terminal (a pipe, a file, a script, CI).
    NotATerminal,
    /// TERM=dumb: the terminal cannot position the cursor.
    Dumb,
}

/// Whether the full-screen app can draw here: stdin and stdout are
/// terminals, and the terminal is not a dumb one.
pub fn terminal_check() -> Result<(), NoTerminal> {
    if !(std::io::stdout().is_terminal() && std::io::stdin().is_terminal()) {
        return Err(NoTerminal::NotATerminal);
    }
    if std::env::var_os("TERM").is_some_and(|t| t == "dumb") {
        return Err(NoTerminal::Dumb);
    }
    Ok(())
}

/// Whether the full-screen app can draw here.
pub fn have_terminal() -> bool {
    terminal_check().is_ok()
}

/// The full-screen app's help when there is no terminal to draw on: say
/// what there is instead, exit status 2.
pub fn no_terminal(why: NoTerminal) -> ExitCode {
    use clap::CommandFactory;
    let mut err = std::io::stderr().lock();
    let _ = match why {
        NoTerminal::NotATerminal => writeln!(
            err,
            "biodyn: no terminal for the full-screen app; the headless commands:\n"
        ),
        NoTerminal::Dumb => writeln!(
            err,
            "biodyn: TERM=dumb cannot draw the full-screen app; the headless commands work anywhere:\n"
        ),
    };
    let _ = writeln!(err, "{}", Cli::command().render_help());
    ExitCode::from(2)
}

/// Runs one headless command and writes its output. `Tui` is the binary's
/// to dispatch.
pub fn run(command: &Command) -> anyhow::Result<()> {
    let text = match command {
        Command::Tui(_) => {
            anyhow::bail!("the terminal app is started by the binary, not the command line")
        }
        Command::Response(a) => response::run(a),
        Command::Modes(a) => modes::run_modes(a),
        Command::Peaks(a) => modes::run_peaks(a),
        Command::Study(a) => study::run(a),
        Command::Plot(a) => plot::run(a),
        Command::Train(a) => train::run(a),
        // Its summary follows the result on stderr, unless the reader left.
        Command::Predict(a) => {
            let (text, summary) = predict::run(a)?;
            return out::emit_then(&text, &summary);
        }
        Command::Preset(c) => preset::run(c),
        Command::Fit(a) => fit::run(a),
        Command::Assess(a) => assess::run(a),
        Command::Seat(a) => seat::run(a),
        Command::Day(a) => day::run(a),
        Command::Weighting(a) => weighting::run(a),
        Command::Man(a) => man::run(a),
        Command::Completions(a) => completions::run(a),
        // Streams its rows as it computes them (bounded memory), through
        // the same stdout rules as emit.
        Command::Simulate(a) => return simulate::run(a),
    }?;
    emit(&text).map(|_| ())
}

/// Parses the command line. Help and version text go through `emit`, so a
/// full disk or closed stdout is reported (clap alone exits 0 silently);
/// usage errors are clap's, status 2.
pub fn parse() -> Result<Cli, ExitCode> {
    use clap::{CommandFactory, FromArgMatches};
    let parsed = Cli::command().try_get_matches().and_then(|m| {
        let cli = Cli::from_arg_matches(&m)?;
        cli.hoist(m.subcommand_name().unwrap_or_default())
            .map_err(|why| Cli::command().error(clap::error::ErrorKind::ArgumentConflict, why))
    });
    match parsed {
        Ok(cli) => {
            progress::set_quiet(cli.quiet);
            Ok(cli)
        }
        Err(e) if e.use_stderr() || std::io::stdout().is_terminal() => {
            // Usage errors, and help on a terminal (clap colours it).
            let _ = e.print();
            Err(ExitCode::from(u8::try_from(e.exit_code()).unwrap_or(2)))
        }
        Err(e) => {
            let code = e.exit_code();
            match emit(&e.render().to_string()) {
                Ok(_) => Err(ExitCode::from(u8::try_from(code).unwrap_or(0))),
                Err(err) => Err(exit(Err(err))),
            }
        }
    }
}

/// The exit status of a finished command: an error is one line plus a hint
/// on stderr (no hint for a failed write to stdout: nothing to change in the
/// command).
pub fn exit(result: anyhow::Result<()>) -> ExitCode {
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            let chain = words::chain(&e);
            // A failed write to stderr (closed pipe, full disk) must not
            // panic: the status stays 1. Control characters are escaped
            // again here, whatever error produced them.
            let line = biodyn::io::excerpt(&words::one_line(&chain), usize::MAX);
            let mut err = std::io::stderr().lock();
            let _ = writeln!(err, "biodyn: error: {}", clip(&line, MAX_ERROR_CHARS));
            if e.downcast_ref::<StdoutError>().is_none() {
                let _ = writeln!(err, "  hint: {}", hint(&e));
            }
            ExitCode::FAILURE
        }
    }
}

/// Longest error line printed: a library message that quotes too much
/// (a whole file) is cut here.
const MAX_ERROR_CHARS: usize = 600;

/// What to try next, by the kind of the root error.
fn hint(e: &anyhow::Error) -> String {
    use biodyn::BandError;
    use biodyn::ann::AnnError;
    use biodyn::body::{ModelError, PresetError};
    use biodyn::freq::StudyError;
    for cause in e.chain() {
        if let Some(r) = cause.downcast_ref::<refused::Refused>() {
            return r.hint.clone();
        }
        if let Some(h) = seat::hint(cause) {
            return h;
        }
        if let Some(s) = cause.downcast_ref::<biodyn::io::SaveError>() {
            use biodyn::io::SaveError;
            return match s {
                SaveError::OwnInput { .. } => {
                    "save under another file name; the input was not touched".into()
                }
                SaveError::ReadOnly { .. } => {
                    "add --force to replace it anyway (its mode is kept), or save under another name".into()
                }
                _ => "choose a file name in a folder you can write to (with room); that file was left as it was".into(),
            };
        }
        if let Some(h) = fit::hint(cause) {
            return h;
        }
        if let Some(h) = time_hint(cause) {
            return h;
        }
        if let Some(h) = report::hint(cause) {
            return h;
        }
        if let Some(h) = day::hint(cause) {
            return h;
        }
        if let Some(h) = weighting::hint(cause) {
            return h;
        }
        if let Some(a) = cause.downcast_ref::<AnnError>() {
            return match a {
                AnnError::Io { .. }
                | AnnError::Corrupted { .. }
                | AnnError::WrongCase { .. }
                | AnnError::WrongArchitecture { .. }
                | AnnError::WrongVersion { .. } => {
                    "make a network file with `biodyn train --case CASE --save FILE`".into()
                }
                AnnError::SegmentCount { .. } => {
                    "leave out --preset to predict on the network's own model, or give a model with that many segments".into()
                }
                AnnError::NoK4Link(_) => {
                    "pick a mass case, or a model with at least 4 links".into()
                }
                AnnError::TooManySegments { .. } => {
                    "pick a k4 case (k4 and f are its only inputs), or a model of fewer segments".into()
                }
                AnnError::Model(_) | AnnError::Band(_) => {
                    "masses in [1e-3, 1e6] kg, stiffness in [0, 1e12] N/m; e.g. --from 0.5 --to 20 --step 0.1".into()
                }
                _ => "`biodyn train --help` lists the cases, trainers and settings with their ranges".into(),
            };
        }
        if let Some(p) = cause.downcast_ref::<PresetError>() {
            return match p {
                PresetError::Save { .. } => {
                    "choose a writable folder; the old file was not touched".into()
                }
                PresetError::NotFound(_) | PresetError::Read { .. } | PresetError::IsDir { .. } => {
                    "`biodyn preset list` shows the built-ins; give a path to a .toml file".into()
                }
                PresetError::Field { message, .. } if message.starts_with("[seat]") => {
                    "`biodyn preset show paper-75kg-suspension-seat` prints a valid [seat] table to start from".into()
                }
                _ => {
                    "`biodyn preset show paper-75kg` prints a valid, commented preset to start from"
                        .into()
                }
            };
        }
        if let Some(m) = cause.downcast_ref::<ModelError>() {
            return match m {
                ModelError::UnknownParam(_) => {
                    "names: m1..m4, k1..k4, c1..c4, body_mass, segment names (head-neck, chest, lower-torso, pelvis) or LINK.k / LINK.c".into()
                }
                ModelError::NoShare(_) => {
                    "this model sets masses directly; use --set m1=.. instead of --body-mass".into()
                }
                _ => "masses in [1e-3, 1e6] kg; stiffness in [0, 1e12] N/m; damping in [0, 1e10] N·s/m; every segment tied to the seat".into(),
            };
        }
        if cause.downcast_ref::<BandError>().is_some() {
            return "e.g. --from 0.5 --to 20 --step 0.1 (0.001 Hz to 100 kHz, from < to, step > 0, at most 10^6 points)"
                .into();
        }
        if cause.downcast_ref::<StudyError>().is_some() {
            return "e.g. `biodyn study mass 65,75,85` or `biodyn study k4 -40%,0%,+40%`".into();
        }
    }
    let msg = e.to_string();
    if msg.starts_with("--set") {
        return "use --set NAME=VALUE, e.g. --set k4=54000 or --set pelvis=13.5".into();
    }
    "run the command with --help for its options and an example".into()
}

/// What a record must be, for every record error.
const RECORD_HINT: &str = "a CSV with a header, a uniform time column (t_s, t_ms, Time [s]) and acceleration columns named by axis (ax, acc_z, z_m_s2, az_g, Acc Z [g]; --axes x=COL,y=COL,z=COL names them), in the unit their name gives ([g], _g, [m/s²]) or --unit's (m/s² assumed, and said, without either); without a time column give --fs HZ";

/// What a class signal must be.
const CLASS_HINT: &str =
    "e.g. --signal class:EM6,seed=1 --fs 200 (a class record needs --fs of at least 100 Hz)";

/// Hints for the time-domain commands (`simulate`, `assess`).
fn time_hint(cause: &(dyn std::error::Error + 'static)) -> Option<String> {
    use biodyn::iso2631::{AssessError, JudgeError};
    use biodyn::time::{RecordError, SignalError, TimeError};
    if let Some(SignalError::Bad { key: "class", .. }) = cause.downcast_ref::<SignalError>() {
        return Some(CLASS_HINT.into());
    }
    if cause.downcast_ref::<SignalError>().is_some() {
        return Some("e.g. --signal sine:freq=5,amp=5 or random:rms=0.8,band=1-20,seed=1+shock:peak=15,width=0.1,at=30".into());
    }
    if cause.downcast_ref::<RecordError>().is_some() {
        return Some(RECORD_HINT.into());
    }
    // `assess` wraps a time error transparently, so look inside it too.
    let time = cause
        .downcast_ref::<TimeError>()
        .or(match cause.downcast_ref::<AssessError>() {
            Some(AssessError::Time(t)) => Some(t),
            _ => None,
        });
    if let Some(t) = time {
        return Some(match t {
            TimeError::Signal(SignalError::Bad { key: "class", .. }) => CLASS_HINT.into(),
            TimeError::Signal(_) => "e.g. --signal sine:freq=5,amp=5".into(),
            TimeError::Record(_) => RECORD_HINT.into(),
            _ => "e.g. --duration 10 --fs 1000 (at most 10^8 samples)".into(),
        });
    }
    if let Some(AssessError::NoVertical) = cause.downcast_ref::<AssessError>() {
        return Some(RECORD_HINT.into());
    }
    if let Some(AssessError::TooShort { .. }) = cause.downcast_ref::<AssessError>() {
        return Some(
            "give at least 2 s: a longer file for --input, e.g. --duration 60 for --signal".into(),
        );
    }
    match cause.downcast_ref::<AssessError>() {
        Some(AssessError::Judge(JudgeError::Rate { .. })) => {
            return Some("ISO 2631-1 records are sampled at 1000 Hz or more; a record's rate is read from its time column, in the unit its name gives (t_s, t_ms, t_us)".into());
        }
        Some(AssessError::Judge(JudgeError::Offset { .. })) => {
            return Some("--remove-mean subtracts each channel's mean over the whole record before judging; the output then says what was removed".into());
        }
        Some(AssessError::SeatNotVertical(_)) => {
            return Some(
                "e.g. --axes z=COL for the floor's z under the seat; a record taken on the pan itself is assessed with a preset without [seat] (paper-75kg)".into(),
            );
        }
        Some(AssessError::BadExposure(_)) => {
            return Some("e.g. --exposure 8 (hours a day, at most 24)".into());
        }
        _ => {}
    }
    None
}
