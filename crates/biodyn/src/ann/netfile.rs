//! Trained networks on disk, as JSON: architecture, weights, scaling,
//! training settings and case, under a format tag and a version. Saving goes
//! through a temp file in the same folder and a rename, so a crash never
//! leaves half a file behind.

use super::case::Case;
use super::error::AnnError;
use super::trained::TrainedNet;
use serde::{Deserialize, Serialize};
use std::io::Write;
use std::path::Path;

/// Tag at the top of every network file.
pub const FORMAT: &str = "biodyn-network";
/// Version of the file layout this build reads and writes.
pub const VERSION: u32 = 1;

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
pub fn save(path: &Path, net: &TrainedNet) -> Result<(), AnnError> {
    let io = |action, source| AnnError::Io {
        action,
        path: path.to_path_buf(),
        source,
    };
    let text = serde_json::to_string_pretty(&FileOut {
        format: FORMAT,
        version: VERSION,
        network: net,
    })
    .map_err(|e| io("serialise", std::io::Error::other(e)))?;
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "network".into());
    let tmp = dir.join(format!(".{name}.{}.tmp", std::process::id()));
    let write = || -> std::io::Result<()> {
        let mut f = std::fs::File::create(&tmp)?;
        f.write_all(text.as_bytes())?;
        f.write_all(b"\n")?;
        f.sync_all()?;
        std::fs::rename(&tmp, path)
    };
    write().map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        io("write", e)
    })
}

/// Reads and checks a network file.
pub fn load(path: &Path) -> Result<TrainedNet, AnnError> {
    let text = std::fs::read_to_string(path).map_err(|source| AnnError::Io {
        action: "read",
        path: path.to_path_buf(),
        source,
    })?;
    parse(&text, path)
}

/// Parses the text of a network file; `path` only names it in errors.
pub fn parse(text: &str, path: &Path) -> Result<TrainedNet, AnnError> {
    let corrupted = |message: String| AnnError::Corrupted {
        path: path.to_path_buf(),
        message,
    };
    let header: Header = serde_json::from_str(text).map_err(|e| corrupted(e.to_string()))?;
    if header.format.as_deref() != Some(FORMAT) {
        return Err(corrupted(format!(
            "format is {:?}, expected \"{FORMAT}\"",
            header.format.unwrap_or_default()
        )));
    }
    match header.version {
        Some(VERSION) => {}
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
    debug_assert_eq!(file.version, VERSION);
    file.network
        .validate()
        .map_err(|e| corrupted(e.to_string()))?;
    Ok(file.network)
}

/// Loads a file and checks that it holds `case` (and `layers`, if given).
pub fn load_expect(
    path: &Path,
    case: Case,
    layers: Option<&[usize]>,
) -> Result<TrainedNet, AnnError> {
    let net = load(path)?;
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
