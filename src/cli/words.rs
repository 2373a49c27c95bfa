//! The library's errors in the command line's words. The library names the
//! field and the value (`sampling rate 0 Hz: …`); here the flag and its
//! example are added back, so a user reads what to type (`…; e.g. --fs 1000`).
//! The TUI says the same in its own words.

use biodyn::ann::{AnnError, Setting, SettingKind};
use biodyn::body::PresetError;
use biodyn::fit::FitError;
use biodyn::io::num;
use biodyn::iso2631::AssessError;
use biodyn::seat::SeatError;
use biodyn::time::{RecordError, SignalError, SimError, TimeError};
use std::error::Error;
use std::fmt;

/// An error reworded for the command line: `text` is printed instead of
/// `source`'s own message, and `source` stays in the chain for the hint.
#[derive(Debug)]
pub struct Reworded {
    pub text: String,
    pub source: Box<dyn Error + Send + Sync>,
}

impl fmt::Display for Reworded {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text)
    }
}

impl Error for Reworded {
    fn source(&self) -> Option<&(dyn Error + 'static)> {
        Some(self.source.as_ref())
    }
}

/// The error chain as the command line prints it, cause by cause: a
/// reworded error replaces its source, a known library error gets its flag.
pub fn chain(e: &anyhow::Error) -> Vec<String> {
    let mut out = Vec::new();
    let mut skip = false;
    for cause in e.chain() {
        if std::mem::take(&mut skip) {
            continue;
        }
        if let Some(r) = cause.downcast_ref::<Reworded>() {
            out.push(rephrase(&r.text));
            skip = true;
            continue;
        }
        out.push(rephrase(
            &flagged(cause).unwrap_or_else(|| cause.to_string()),
        ));
    }
    out
}

/// Phrases inside messages the library builds from several parts (a body
/// name's problem inside a preset error, a signal's frequency limit): the
/// library's words and the command line's.
const PHRASES: [(&str, &str); 5] = [
    (
        "a setting NAME=VALUE could not reach it",
        "--set NAME=VALUE could not reach it",
    ),
    (
        "a setting by name could not reach it",
        "--set could not reach it",
    ),
    (
        "a setting by name would be ambiguous",
        "--set would be ambiguous",
    ),
    ("raise the sampling rate (now ", "raise --fs (now "),
    (
        "widen the band or lengthen the duration",
        "widen the band or lengthen --duration",
    ),
];

fn rephrase(text: &str) -> String {
    let mut s = text.to_string();
    for (lib, cli) in PHRASES {
        if s.contains(lib) {
            s = s.replace(lib, cli);
        }
    }
    s
}

/// A library error in the command line's words, if its
/// library message leaves a flag (or a command) out.
fn flagged(cause: &(dyn Error + 'static)) -> Option<String> {
    if let Some(a) = cause.downcast_ref::<AssessError>() {
        return match a {
            AssessError::Time(t) => time(t),
            AssessError::Judge(j) => Some(
                j.to_string()
                    .replace("(remove_mean)", "(--remove-mean)")
                    .replace(
                        "name it so (t_ms, t_us)",
                        "name it so (t_ms, t_us), or give --fs",
                    ),
            ),
            AssessError::BadExposure(_) => Some(format!("{a}; e.g. --exposure 8")),
            AssessError::NoVertical => Some(format!("{a} with --axes z=COL")),
            AssessError::TooShort { .. } => None,
            AssessError::SeatNotVertical(_) => Some(format!(
                "{a} (--axes z=COL), or assess the pan's own record with a preset without [seat]"
            )),
        };
    }
    if let Some(t) = cause.downcast_ref::<TimeError>() {
        return time(t);
    }
    if let Some(s) = cause.downcast_ref::<SignalError>() {
        return signal(s);
    }
    if let Some(r) = cause.downcast_ref::<RecordError>() {
        return record(r);
    }
    if let Some(s) = cause.downcast_ref::<SimError>() {
        return sim(s);
    }
    if let Some(AnnError::TooBig {
        setting,
        value,
        why,
    }) = cause.downcast_ref::<AnnError>()
    {
        // The grid is set with --from/--to/--step; every other setting by its flag.
        let flag = match Setting::find(setting) {
            Some(s) if s.kind != SettingKind::Band => format!("--{}", s.flag),
            _ => "--from/--to/--step".into(),
        };
        return Some(format!("{flag} {value}: {why}"));
    }
    if let Some(e) = cause.downcast_ref::<SeatError>() {
        return seat(e);
    }
    if let Some(p @ PresetError::Empty { .. }) = cause.downcast_ref::<PresetError>() {
        return Some(format!("{p} (see `biodyn preset show`)"));
    }
    None
}

fn time(t: &TimeError) -> Option<String> {
    Some(match t {
        TimeError::Signal(s) => return signal(s),
        TimeError::Record(r) => return record(r),
        TimeError::Sim(s) => return sim(s),
        TimeError::BadDuration(_) => format!("{t}; e.g. --duration 10"),
        TimeError::BadFs(_) => format!("{t}; e.g. --fs 1000"),
        TimeError::TooLong { samples, cap } => format!(
            "{} samples (duration × fs) is over the cap of {cap}: shorten --duration or lower --fs",
            num(*samples)
        ),
        TimeError::TooShort { duration, fs } => format!(
            "{} s at {} Hz is fewer than two samples: lengthen --duration or raise --fs",
            num(*duration),
            num(*fs)
        ),
    })
}

fn seat(e: &SeatError) -> Option<String> {
    Some(match e {
        SeatError::BadLimit(m) => format!("--stroke-rms-max {}: {e}", num(*m)),
        SeatError::TooManyVaried { count } => format!(
            "--vary is given {count} times: the search and its map take one or two parameters"
        ),
        SeatError::NothingVaried | SeatError::VariedTwice(_) => format!("--vary: {e}"),
        // The reader's message names the path already.
        SeatError::Read { path, why } if why.starts_with(path.as_str()) => format!("--psd {why}"),
        SeatError::Read { .. } => format!("--psd {e}"),
        SeatError::Infeasible { limit, least, at } => format!(
            "no point of the --vary box keeps the r.m.s. stroke within {} m: the least is {} m, at {at}; widen the box or raise --stroke-rms-max",
            num(*limit),
            crate::view::format::num(*least, 4)
        ),
        _ => return None,
    })
}

fn signal(s: &SignalError) -> Option<String> {
    match s {
        SignalError::Empty => Some("signal spec is empty: e.g. --signal sine:freq=5,amp=5".into()),
        // A class's floor on the rate: the library says "raise the rate".
        SignalError::Bad { key: "class", .. } => Some(
            s.to_string()
                .replace("raise the rate", "raise --fs, e.g. --fs 200"),
        ),
        _ => None,
    }
}

fn record(r: &RecordError) -> Option<String> {
    Some(match r {
        RecordError::NeedFs { path } => format!(
            "{}: only one column and no time column: give its sampling rate with --fs HZ, or add a t_s column",
            path.display()
        ),
        RecordError::FsMismatch { path, file, given } => format!(
            "{}: the time column gives {} Hz but --fs says {} Hz: drop --fs or fix it",
            path.display(),
            num(*file),
            num(*given)
        ),
        RecordError::Unnamed { .. } => r.to_string().replace(
            "say which column is which axis (x=COL,y=COL,z=COL)",
            "say which column is which axis with --axes x=COL,y=COL,z=COL",
        ),
        RecordError::SameAxis { axis, .. } => r
            .to_string()
            .replace(&format!("({axis}=COL)"), &format!("with --axes {axis}=COL")),
        RecordError::SamePoint { channel, .. } => r.to_string().replace(
            &format!("({channel}=COL)"),
            &format!("with --axes {channel}=COL"),
        ),
        RecordError::NoVertical { .. } => r
            .to_string()
            .replace("name the z column (z=COL)", "name it with --axes z=COL"),
        RecordError::UnitClash { .. } => r
            .to_string()
            .replace("the unit given is", "--unit says")
            .replace("leave the unit out", "drop --unit"),
        RecordError::BadAxes { .. } => format!("--{r}"),
        RecordError::BadFs(fs) => format!(
            "--fs {}: the sampling rate must be a finite number > 0 and at most 1e6",
            num(*fs)
        ),
        _ => return None,
    })
}

fn sim(s: &SimError) -> Option<String> {
    match s {
        SimError::BadFs(_) => Some(format!("{s}; e.g. --fs 1000")),
        SimError::Overflow(_) => Some(
            s.to_string()
                .replace("raise the sampling rate", "raise --fs"),
        ),
        _ => None,
    }
}

/// A fit error in the command line's words; `bounds` are the `--bound`
/// texts, which a bound error points into by position.
pub fn fit(e: FitError, bounds: &[String]) -> anyhow::Error {
    let bound = |i: &usize| bounds.get(*i).map_or("", String::as_str).to_string();
    let text = match &e {
        FitError::EmptyFree => {
            "--free: the list is empty; name parameters, e.g. --free links or --free k1,c1".into()
        }
        FitError::NotInModel { .. }
        | FitError::NoSuchLink { .. }
        | FitError::MassTwice { .. } => format!("--free: {e}"),
        FitError::ZeroStart { name, .. } => format!("--free {e} (set one with --set {name}=VALUE)"),
        FitError::NoBodyMass => "--free body-mass: the model gives no body mass; set one with --body-mass KG, or free single masses".into(),
        FitError::NoShare { .. } | FitError::OffShare { .. } => format!("--free {e}"),
        FitError::BoundNotFree { bound: i, name } => format!(
            "--bound {}: {name} is not a free parameter; add it to --free",
            bound(i)
        ),
        FitError::BoundTwice { bound: i, name } => format!(
            "--bound {}: {name} is bounded twice; give one --bound per parameter",
            bound(i)
        ),
        FitError::BadBound { bound: i, value, .. } => format!(
            "--bound {}: {} is not a number > 0 (parameters are positive)",
            bound(i),
            num(*value)
        ),
        FitError::AboveLimit {
            bound: i,
            hi,
            max,
            unit,
            ..
        } => format!(
            "--bound {}: {} is above the model's limit {} {unit}",
            bound(i),
            num(*hi),
            num(*max)
        ),
        FitError::BelowLimit {
            bound: i,
            lo,
            min,
            unit,
            ..
        } => format!(
            "--bound {}: {} is below the model's floor {} {unit}",
            bound(i),
            biodyn::io::num(*lo),
            biodyn::io::num(*min)
        ),
        FitError::EmptyBox { bound: i, lo, hi, .. } => format!(
            "--bound {}: the box [{}, {}] is empty; give both ends",
            bound(i),
            num(*lo),
            num(*hi)
        ),
        FitError::BadStarts { starts, max } => format!("--starts {starts}: give between 1 and {max}"),
        _ => return e.into(),
    };
    Reworded {
        text,
        source: Box::new(e),
    }
    .into()
}

/// The error chain on one line, without repeating a cause a context already quotes.
pub(super) fn one_line(chain: &[String]) -> String {
    let mut parts: Vec<&str> = Vec::new();
    for c in chain {
        if !parts.iter().any(|p| p.contains(c.as_str())) {
            parts.push(c);
        }
    }
    parts.join(": ")
}

#[cfg(test)]
mod tests {
    use super::PHRASES;

    /// Every phrase the command line rewords still stands, word for word,
    /// in the library's source: a library rewording that the table missed
    /// would otherwise drop the flag from the message without a sound.
    #[test]
    fn every_reworded_phrase_is_still_the_librarys() {
        let mut text = String::new();
        let mut stack = vec![std::path::PathBuf::from(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/crates/biodyn/src"
        ))];
        while let Some(dir) = stack.pop() {
            for e in std::fs::read_dir(&dir).expect("library source").flatten() {
                let p = e.path();
                if p.is_dir() {
                    stack.push(p);
                } else if p.extension().is_some_and(|x| x == "rs") {
                    text += &std::fs::read_to_string(&p).expect("a source file");
                }
            }
        }
        for (lib, cli) in PHRASES {
            assert!(
                text.contains(lib),
                "no library message says {lib:?} (for {cli:?})"
            );
        }
    }
}
