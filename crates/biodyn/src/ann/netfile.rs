//! Trained networks on disk, as JSON: architecture, weights, scaling,
//! training settings and case, under a format tag and a version. Saving goes
//! through [`crate::io::save_atomic`] (atomic, links followed, special files
//! refused, the old file's mode kept); loading through
//! [`crate::io::read_text`] (regular files of at most [`FileKind::Network`]'s
//! cap). Errors quote at most a short excerpt of the file.

use super::case::Case;
use super::error::AnnError;
use super::scaling::{Column, Scaling};
use super::trained::TrainedNet;
use crate::io::excerpt::{Short, message, num};
use crate::io::{FileKind, read_text};
use serde::{Deserialize, Serialize};
use std::path::Path;

/// Tag at the top of every network file.
pub const FORMAT: &str = "biodyn-network";
/// Newest version of the file layout this build reads and writes. A net
/// trained on the paper's body is written as version 1 (as before, so
/// older builds read it); one trained on another body (`Settings::base`)
/// as version 2, which adds that body under `network.settings.base`.
pub const VERSION: u32 = 2;
/// The version of a file without a base body.
pub const VERSION_PAPER: u32 = 1;
/// Most layers a network file may hold (the paper's have 3 or 4): a file of
/// thousands of one-neuron layers would load, but every message naming its
/// architecture would be as long as the file.
pub const MAX_LAYERS: usize = 64;

#[derive(Serialize)]
struct FileOut<'a> {
    format: &'static str,
    version: u32,
    network: &'a TrainedNet,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FileIn {
    format: String,
    version: u32,
    network: TrainedNet,
}

/// Just the header, read first so that a newer file gets a version error
/// rather than a confusing field error.
#[derive(Deserialize)]
struct Header {
    format: Option<String>,
    version: Option<u32>,
}

/// Writes `net` to `path` atomically.
pub fn save_network(path: &Path, net: &TrainedNet) -> Result<(), AnnError> {
    save_network_guarded(path, net, &crate::io::Guard::default())
}

/// [`save_network`] held to `guard`: not over the command's inputs, a
/// read-only file only when forced.
pub fn save_network_guarded(
    path: &Path,
    net: &TrainedNet,
    guard: &crate::io::Guard,
) -> Result<(), AnnError> {
    let io = |action, source| AnnError::Io {
        action,
        path: path.to_path_buf(),
        source,
    };
    let text = serde_json::to_string_pretty(&FileOut {
        format: FORMAT,
        version: version_of(net),
        network: net,
    })
    .map_err(|e| io("serialise", std::io::Error::other(e)))?;
    let text = format!("{text}\n");
    // Never write a file that `load` would refuse (a diverged net's NaN
    // weights become null in JSON; a net over the size cap).
    let cap = FileKind::Network.cap();
    if text.len() as u64 > cap {
        return Err(io(
            "save",
            std::io::Error::other(format!(
                "the network is {} bytes, over the {} MiB a network file may hold",
                text.len(),
                cap >> 20
            )),
        ));
    }
    if let Err(e) = parse_network(&text, path) {
        let why = match e {
            AnnError::Corrupted { message, .. } => message,
            other => other.to_string(),
        };
        return Err(io(
            "save",
            std::io::Error::other(format!("it would not load back: {why}")),
        ));
    }
    crate::io::save_guarded(path, guard, text.as_bytes()).map_err(|e| io("write", e.into_io()))
}

/// The version `save` writes for `net`: 2 with a base body, else 1.
pub fn version_of(net: &TrainedNet) -> u32 {
    if net.settings.base.is_some() {
        VERSION
    } else {
        VERSION_PAPER
    }
}

/// Reads and checks a network file.
pub fn load_network(path: &Path) -> Result<TrainedNet, AnnError> {
    let text = read_text(path, FileKind::Network).map_err(|e| AnnError::Io {
        action: "read",
        path: path.to_path_buf(),
        source: e.into_io(),
    })?;
    parse_network(&text, path)
}

/// Parses the text of a network file; `path` only names it in errors.
pub fn parse_network(text: &str, path: &Path) -> Result<TrainedNet, AnnError> {
    // Every message is bounded and on one line: serde quotes strings and
    // numbers from the file in full.
    let corrupted = |raw: String| AnnError::Corrupted {
        path: path.to_path_buf(),
        message: message(&raw),
    };
    // The top level must be an object before serde's own words (which
    // name our Rust types: "expected struct Header") could be printed.
    let top: serde_json::Value =
        serde_json::from_str(text).map_err(|e| corrupted(e.to_string()))?;
    if !top.is_object() {
        let kind = match top {
            serde_json::Value::Null => "null",
            serde_json::Value::Bool(_) => "a true/false value",
            serde_json::Value::Number(_) => "a number",
            serde_json::Value::String(_) => "a string",
            serde_json::Value::Array(_) => "a list",
            serde_json::Value::Object(_) => "an object",
        };
        return Err(corrupted(format!(
            "the file holds {kind}, not a network: a network file is a JSON object with \"format\": \"{FORMAT}\""
        )));
    }
    let header: Header = serde_json::from_str(text).map_err(|e| corrupted(e.to_string()))?;
    match header.format.as_deref() {
        Some(FORMAT) => {}
        None => {
            return Err(corrupted(format!(
                "no \"format\" field: a network file starts {{\"format\": \"{FORMAT}\", \"version\": …}}"
            )));
        }
        Some(other) => {
            return Err(corrupted(format!(
                "format is {other:?}, expected \"{FORMAT}\""
            )));
        }
    }
    match header.version {
        Some(VERSION_PAPER..=VERSION) => {}
        Some(v) => {
            return Err(AnnError::WrongVersion {
                path: path.to_path_buf(),
                expected: VERSION,
                found: v,
            });
        }
        None => return Err(corrupted("no version field".into())),
    }
    let file: FileIn = serde_json::from_str(text).map_err(|e| corrupted(e.to_string()))?;
    debug_assert_eq!(file.format, FORMAT);
    if file.version == VERSION_PAPER && file.network.settings.base.is_some() {
        return Err(corrupted(
            "version 1 holds no base model: a network with one is version 2".into(),
        ));
    }
    let layers = file.network.settings.layers.len();
    if layers > MAX_LAYERS {
        return Err(corrupted(format!(
            "{layers} layers: a network file holds at most {MAX_LAYERS}"
        )));
    }
    file.network
        .validate()
        .map_err(|e| corrupted(e.to_string()))?;
    check_scaling(&file.network.scaling).map_err(corrupted)?;
    Ok(file.network)
}

/// A scaling that maps values back and forth: finite, with a non-empty
/// activation range and (for the output) min < max. Without this a file
/// with `min = max` or a NaN loaded and predicted zeros or NaN.
fn check_scaling(s: &Scaling) -> Result<(), String> {
    if !(s.margin.is_finite() && s.margin >= 0.0) {
        return Err(format!(
            "scaling margin = {}: it must be a finite number >= 0",
            num(s.margin)
        ));
    }
    if !(s.lo.is_finite() && s.hi.is_finite() && s.lo < s.hi) {
        return Err(format!(
            "scaling range lo = {}, hi = {}: they must be finite with lo < hi",
            num(s.lo),
            num(s.hi)
        ));
    }
    for (i, c) in s.inputs.iter().enumerate() {
        column(c, s.margin, false).map_err(|why| format!("scaling of input {}: {why}", i + 1))?;
    }
    column(&s.output, s.margin, true).map_err(|why| format!("output scaling: {why}"))?;
    Ok(())
}

/// Largest |end| of a log column's widened interval: e^709.78 is the
/// largest finite f64, and 700 leaves the net's headroom beyond it.
const MAX_LOG_END: f64 = 700.0;

/// One column's problem in words, naming what overflows (min and max may
/// each be finite and in order while the margin or the exponential of a
/// log column is not).
fn column(c: &Column, margin: f64, output: bool) -> Result<(), String> {
    let (min, max) = (num(c.min), num(c.max));
    let fix = "retrain the network";
    if !(c.min.is_finite() && c.max.is_finite()) {
        return Err(format!(
            "min = {min}, max = {max}: both must be finite numbers; {fix}"
        ));
    }
    if output && c.min >= c.max {
        return Err(format!(
            "min = {min}, max = {max}: it needs min < max; {fix}"
        ));
    }
    if c.min > c.max {
        return Err(format!(
            "min = {min}, max = {max}: it needs min <= max; {fix}"
        ));
    }
    let (a, b) = c.widened(margin);
    if !(a.is_finite() && b.is_finite() && (b - a).is_finite()) {
        return Err(format!(
            "min = {min}, max = {max}: widened by the margin {}, the interval overflows f64; {fix}",
            num(margin)
        ));
    }
    if c.log && (a.abs() > MAX_LOG_END || b.abs() > MAX_LOG_END) {
        let end = if a.abs() > b.abs() { a } else { b };
        return Err(format!(
            "min = {min}, max = {max} are logarithms (log = true): widened by the margin they reach {}, and e^{} overflows f64 (a log end must lie within ±{MAX_LOG_END}); {fix}",
            Short(end),
            Short(end)
        ));
    }
    Ok(())
}

/// Loads a file and checks that it holds `case` (and `layers`, if given).
pub fn load_network_expect(
    path: &Path,
    case: Case,
    layers: Option<&[usize]>,
) -> Result<TrainedNet, AnnError> {
    let net = load_network(path)?;
    if net.case != case {
        return Err(AnnError::WrongCase {
            path: path.to_path_buf(),
            expected: case.key(),
            found: net.case.key(),
        });
    }
    if let Some(l) = layers
        && net.settings.layers != l
    {
        return Err(AnnError::WrongArchitecture {
            path: path.to_path_buf(),
            expected: l.to_vec(),
            found: net.settings.layers.clone(),
        });
    }
    Ok(net)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scaling(min: f64, max: f64) -> Scaling {
        let col = |min, max| Column {
            log: true,
            min,
            max,
        };
        Scaling {
            margin: 0.1,
            lo: 0.0,
            hi: 1.0,
            inputs: vec![col(10.0, 11.0), col(-0.7, 3.0)],
            output: col(min, max),
        }
    }

    /// The message names what the file holds, never our Rust types
    /// ("expected struct Header") nor an empty format (`format is ""`).
    #[test]
    fn a_file_that_is_not_a_network_says_what_it_holds() {
        let p = Path::new("n.json");
        let msg = |t: &str| parse_network(t, p).unwrap_err().to_string();
        let m = msg("\"hello\"");
        assert!(m.contains("holds a string, not a network"), "{m}");
        assert!(!m.contains("struct"), "{m}");
        assert!(msg("[1, 2]").contains("holds a list"), "{m}");
        assert!(msg("3").contains("holds a number"), "{m}");
        let m = msg("{\"version\": 1, \"network\": {}}");
        assert!(m.contains("no \"format\" field"), "{m}");
        assert!(!m.contains("format is \"\""), "{m}");
        let m = msg("{\"format\": \"x\", \"version\": 1}");
        assert!(m.contains("format is \"x\""), "{m}");
    }

    #[test]
    fn output_scaling_must_be_finite_and_increasing() {
        assert!(check_scaling(&scaling(-1.0, 0.5)).is_ok());
        for (min, max) in [
            (0.5, 0.5),
            (0.5, -1.0),
            (f64::NAN, 1.0),
            (0.0, f64::INFINITY),
            (-1e300, 1e300),
            (0.0, 800.0), // e^800 is not a number
        ] {
            let e = check_scaling(&scaling(min, max)).unwrap_err();
            assert!(e.contains("output scaling"), "{e}");
            assert!(e.len() < 200, "{e}");
        }
        let mut s = scaling(-1.0, 0.5);
        s.lo = 1.0;
        assert!(check_scaling(&s).unwrap_err().contains("lo < hi"));
        let mut s = scaling(-1.0, 0.5);
        s.inputs[1].max = f64::NAN;
        assert!(check_scaling(&s).unwrap_err().contains("input 2"));
    }

    /// Both ends finite and in order, yet unusable: the message says what
    /// overflows (the exponential of a log column, the widened span), not
    /// "must be finite with min <= max".
    #[test]
    fn a_scaling_that_overflows_says_what_overflows() {
        let mut s = scaling(-1.0, 0.5);
        s.inputs[0].max = 1e308; // a log k4 column: ln 54000 = 10.9, then 1e308
        s.inputs[0].min = 10.89;
        let e = check_scaling(&s).unwrap_err();
        assert!(
            e.starts_with("scaling of input 1: min = 10.89, max = 1e308 are logarithms"),
            "{e}"
        );
        assert!(
            e.contains("e^1.1e308 overflows") && e.contains("retrain"),
            "{e}"
        );
        assert!(!e.contains("must be finite"), "{e}");
        let mut s = scaling(-1.0, 0.5);
        s.inputs[0] = Column {
            log: false,
            min: -1e308,
            max: 1e308,
        };
        let e = check_scaling(&s).unwrap_err();
        assert!(e.contains("interval overflows f64"), "{e}");
        s.inputs[0] = Column {
            log: false,
            min: 10.89,
            max: 1e308,
        };
        assert!(
            check_scaling(&s).is_ok(),
            "a linear column maps 1e308 without overflow"
        );
    }

    #[test]
    fn a_network_that_would_not_load_back_is_not_saved() {
        use crate::ann::{Case, Flow, Settings, train};
        let case = Case::K4Stht;
        let mut s = Settings::lm(case);
        s.epochs = 1;
        s.ensemble = 1;
        let mut net = train(case, &s, &mut |_| Flow::Continue).unwrap().net;
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("n.json");
        save_network(&p, &net).unwrap();
        let before = std::fs::read(&p).unwrap();
        net.members[0].params[0] = f64::NAN; // written as null: unloadable
        let e = save_network(&p, &net).unwrap_err().to_string();
        assert!(e.contains("would not load back"), "{e}");
        net.members[0].params[0] = 0.5;
        net.scaling.output.max = net.scaling.output.min;
        let e = save_network(&p, &net).unwrap_err().to_string();
        assert!(e.contains("output scaling"), "{e}");
        assert_eq!(std::fs::read(&p).unwrap(), before);
    }
}
