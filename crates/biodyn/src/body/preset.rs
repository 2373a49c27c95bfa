//! Presets: a body, its band and a description, as TOML on disk.
//!
//! Loading names the file and the line (and column, for syntax) of every
//! problem; unknown fields are errors so a typo never silently falls back to
//! a default. Saving is atomic: a temp file in the same folder, then rename.

use crate::body::model::{Body, End, Link, MAX_C, MAX_K, MAX_MASS, ModelError, Segment};
use crate::freq::band::{Band, BandError};
use serde::{Deserialize, Serialize};
use std::fmt;
use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};
use toml::Spanned;

/// The preset format version this build reads and writes.
pub const SCHEMA: u32 = 1;

/// Shipped presets, compiled in so every command works with no files at all.
pub const SHIPPED: [(&str, &str); 4] = [
    (
        "paper-75kg",
        include_str!("../../../../presets/paper-75kg.toml"),
    ),
    (
        "paper-65kg",
        include_str!("../../../../presets/paper-65kg.toml"),
    ),
    (
        "paper-85kg",
        include_str!("../../../../presets/paper-85kg.toml"),
    ),
    (
        "boileau-rakheja-1998",
        include_str!("../../../../presets/boileau-rakheja-1998.toml"),
    ),
];

/// The built-in default model's name.
pub const DEFAULT_NAME: &str = "paper-75kg";

/// Where a preset came from, for error messages.
#[derive(Debug, Clone, PartialEq)]
pub enum Origin {
    File(PathBuf),
    Builtin(String),
}

impl fmt::Display for Origin {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Origin::File(p) => write!(f, "{}", p.display()),
            Origin::Builtin(n) => write!(f, "<built-in {n}>"),
        }
    }
}

#[derive(Debug, thiserror::Error)]
pub enum PresetError {
    #[error("{path}: cannot read: {source}")]
    Read {
        path: String,
        #[source]
        source: std::io::Error,
    },
    #[error("{path}: is a directory; give the path of a .toml preset file")]
    IsDir { path: String },
    #[error(
        "{path}: the file is empty; a preset needs [[segment]] and [[link]] tables (see `biodyn preset show`)"
    )]
    Empty { path: String },
    #[error("{path}: not a text file (binary data at byte {offset}); a preset is UTF-8 TOML")]
    Binary { path: String, offset: usize },
    #[error("{origin}:{line}:{col}: {message}")]
    Syntax {
        origin: String,
        line: usize,
        col: usize,
        message: String,
    },
    #[error("{origin}:{line}: {message}")]
    Field {
        origin: String,
        line: usize,
        message: String,
    },
    #[error("{origin}: {source}")]
    Model {
        origin: String,
        #[source]
        source: ModelError,
    },
    #[error("{origin}: [band]: {source}")]
    Band {
        origin: String,
        #[source]
        source: BandError,
    },
    #[error("{path}: cannot save: {source} (the existing file, if any, is unchanged)")]
    Save {
        path: String,
        #[source]
        source: std::io::Error,
    },
    #[error(
        "no preset file '{0}' and no built-in preset of that name; built-ins: paper-75kg, paper-65kg, paper-85kg, boileau-rakheja-1998"
    )]
    NotFound(String),
}

/// A loaded preset: the body plus what travels with it.
#[derive(Debug, Clone, PartialEq)]
pub struct Preset {
    pub name: String,
    pub description: String,
    pub source: String,
    pub body: Body,
    pub band: Band,
}

// ---- the file format -------------------------------------------------------

#[derive(Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct PresetFile {
    schema: Spanned<u32>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    name: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    description: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    source: Option<String>,
    /// Segment whose motion STHT reports; defaults to the first (top) one.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    head: Option<Spanned<String>>,
    /// Total body mass; segments with a share get share × this.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    body_mass_kg: Option<Spanned<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    band: Option<Spanned<BandFile>>,
    #[serde(rename = "segment", default)]
    segments: Vec<Spanned<SegmentFile>>,
    #[serde(rename = "link", default)]
    links: Vec<Spanned<LinkFile>>,
}

#[derive(Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct BandFile {
    from_hz: f64,
    to_hz: f64,
    step_hz: f64,
}

#[derive(Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct SegmentFile {
    name: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    mass_kg: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    share: Option<f64>,
}

#[derive(Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct LinkFile {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    name: Option<String>,
    upper: String,
    lower: String,
    k_n_per_m: f64,
    c_ns_per_m: f64,
}

// ---- loading ---------------------------------------------------------------

impl Preset {
    /// The built-in default model (the paper's 75 kg body).
    pub fn builtin_default() -> Preset {
        match Preset::builtin(DEFAULT_NAME) {
            Some(Ok(p)) => p,
            // The shipped text is tested (it must equal Body::paper(75.0));
            // this arm only keeps a broken build running on the same model,
            // built in code.
            _ => Preset {
                name: DEFAULT_NAME.into(),
                description: String::new(),
                source: String::new(),
                body: Body::paper(75.0).unwrap_or_else(|_| Body::chain(Vec::new(), &[], &[])),
                band: Band::default(),
            },
        }
    }

    /// A shipped preset by name, if there is one.
    pub fn builtin(name: &str) -> Option<Result<Preset, PresetError>> {
        SHIPPED
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(n, text)| Preset::parse(text, &Origin::Builtin((*n).to_string())))
    }

    /// Loads a file; when no such file exists, a built-in of that name.
    pub fn open(arg: &str) -> Result<Preset, PresetError> {
        let path = Path::new(arg);
        if !path.exists()
            && let Some(p) = Preset::builtin(arg.trim_end_matches(".toml"))
        {
            return p;
        }
        if !path.exists() && !arg.contains(['/', '\\']) && !arg.ends_with(".toml") {
            return Err(PresetError::NotFound(arg.to_string()));
        }
        Preset::load(path)
    }

    /// Reads and parses a preset file.
    pub fn load(path: &Path) -> Result<Preset, PresetError> {
        let shown = path.display().to_string();
        if path.is_dir() {
            return Err(PresetError::IsDir { path: shown });
        }
        let bytes = fs::read(path).map_err(|source| PresetError::Read {
            path: shown.clone(),
            source,
        })?;
        if bytes.iter().all(|b| b.is_ascii_whitespace()) {
            return Err(PresetError::Empty { path: shown });
        }
        if let Some(offset) = bytes.iter().position(|&b| b == 0) {
            return Err(PresetError::Binary {
                path: shown,
                offset,
            });
        }
        let text = String::from_utf8(bytes).map_err(|e| PresetError::Binary {
            path: shown.clone(),
            offset: e.utf8_error().valid_up_to(),
        })?;
        Preset::parse(&text, &Origin::File(path.to_path_buf()))
    }

    /// Parses preset text; `origin` only labels errors.
    pub fn parse(text: &str, origin: &Origin) -> Result<Preset, PresetError> {
        let o = origin.to_string();
        let file: PresetFile = toml::from_str(text).map_err(|e| {
            let (line, col) = e.span().map(|s| line_col(text, s.start)).unwrap_or((1, 1));
            let source_line = text.lines().nth(line - 1).unwrap_or("").trim();
            let mut message = e.message().trim().replace('\n', " ");
            if !source_line.is_empty() {
                message = format!("{message} (in `{source_line}`)");
            }
            PresetError::Syntax {
                origin: o.clone(),
                line,
                col,
                message,
            }
        })?;
        let field = |span: std::ops::Range<usize>, message: String| PresetError::Field {
            origin: o.clone(),
            line: line_col(text, span.start).0,
            message,
        };

        if *file.schema.get_ref() != SCHEMA {
            return Err(field(
                file.schema.span(),
                format!(
                    "schema = {}: this biodyn reads schema {SCHEMA}; convert the file or use a matching biodyn",
                    file.schema.get_ref()
                ),
            ));
        }
        let body_mass = match &file.body_mass_kg {
            Some(bm) => {
                let v = *bm.get_ref();
                if !(v.is_finite() && v > 0.0) {
                    return Err(field(
                        bm.span(),
                        format!("body_mass_kg = {v}: a body mass must be a finite number > 0 kg"),
                    ));
                }
                Some(v)
            }
            None => None,
        };
        if file.segments.is_empty() {
            return Err(field(
                0..0,
                "no [[segment]] tables: a preset needs at least one segment".into(),
            ));
        }

        let mut segments = Vec::with_capacity(file.segments.len());
        for (i, sp) in file.segments.iter().enumerate() {
            let s = sp.get_ref();
            let what = format!("segment {} ('{}')", i + 1, s.name);
            if s.name == "seat" {
                return Err(field(
                    sp.span(),
                    format!(
                        "{what}: \"seat\" is reserved for the seat in links; rename the segment"
                    ),
                ));
            }
            if let Some(share) = s.share
                && !(share.is_finite() && share > 0.0)
            {
                return Err(field(
                    sp.span(),
                    format!("{what}: share = {share}: a share of body mass must be finite and > 0"),
                ));
            }
            let mass = match (s.mass_kg, s.share, body_mass) {
                (Some(m), _, _) => m,
                (None, Some(share), Some(bm)) => share * bm,
                (None, Some(_), None) => {
                    return Err(field(
                        sp.span(),
                        format!(
                            "{what}: has a share but the preset has no body_mass_kg; add body_mass_kg = <kg> at the top, or give mass_kg"
                        ),
                    ));
                }
                (None, None, _) => {
                    return Err(field(
                        sp.span(),
                        format!(
                            "{what}: needs mass_kg = <kg>, or share = <fraction> with body_mass_kg"
                        ),
                    ));
                }
            };
            if !(mass.is_finite() && mass > 0.0 && mass <= MAX_MASS) {
                return Err(field(
                    sp.span(),
                    format!(
                        "{what}: mass_kg = {mass}: a mass must be a finite number > 0 and at most 1e6 kg"
                    ),
                ));
            }
            segments.push(Segment {
                name: s.name.clone(),
                mass,
                share: s.share,
            });
        }
        let index_of = |name: &str| segments.iter().position(|s| s.name == name);

        let mut links = Vec::with_capacity(file.links.len());
        for (i, lp) in file.links.iter().enumerate() {
            let l = lp.get_ref();
            let name = l
                .name
                .clone()
                .unwrap_or_else(|| format!("{}-{}", l.upper, l.lower));
            let what = format!("link {} ('{name}')", i + 1);
            let upper = index_of(&l.upper).ok_or_else(|| {
                field(
                    lp.span(),
                    format!("{what}: upper = \"{}\" is not a segment name", l.upper),
                )
            })?;
            let lower = if l.lower == "seat" {
                End::Seat
            } else {
                End::Segment(index_of(&l.lower).ok_or_else(|| {
                    field(
                        lp.span(),
                        format!(
                            "{what}: lower = \"{}\" is neither a segment name nor \"seat\"",
                            l.lower
                        ),
                    )
                })?)
            };
            for (key, v, max, unit) in [
                ("k_n_per_m", l.k_n_per_m, MAX_K, "N/m"),
                ("c_ns_per_m", l.c_ns_per_m, MAX_C, "N·s/m"),
            ] {
                if !(v.is_finite() && v >= 0.0 && v <= max) {
                    return Err(field(
                        lp.span(),
                        format!(
                            "{what}: {key} = {v:?}: must be a finite number from 0 to {max:e} {unit}"
                        ),
                    ));
                }
            }
            links.push(Link {
                name,
                upper,
                lower,
                k: l.k_n_per_m,
                c: l.c_ns_per_m,
            });
        }

        let head = match &file.head {
            Some(h) => index_of(h.get_ref()).ok_or_else(|| {
                field(
                    h.span(),
                    format!("head = \"{}\" is not a segment name", h.get_ref()),
                )
            })?,
            None => 0,
        };
        let body = Body {
            segments,
            links,
            head,
            body_mass,
        };
        body.validate().map_err(|source| PresetError::Model {
            origin: o.clone(),
            source,
        })?;

        let band = match &file.band {
            Some(b) => {
                let bf = b.get_ref();
                let band = Band {
                    from: bf.from_hz,
                    to: bf.to_hz,
                    step: bf.step_hz,
                };
                band.validate().map_err(|source| PresetError::Band {
                    origin: o.clone(),
                    source,
                })?;
                band
            }
            None => Band::default(),
        };

        Ok(Preset {
            name: file.name.unwrap_or_else(|| match origin {
                Origin::File(p) => p
                    .file_stem()
                    .map(|s| s.to_string_lossy().into_owned())
                    .unwrap_or_default(),
                Origin::Builtin(n) => n.clone(),
            }),
            description: file.description.unwrap_or_default(),
            source: file.source.unwrap_or_default(),
            body,
            band,
        })
    }

    // ---- saving ------------------------------------------------------------

    /// The preset as TOML. Masses that equal share × body mass bit for bit
    /// are written as shares alone, so a load/save/load round trip is exact.
    pub fn to_toml(&self) -> String {
        let b = &self.body;
        let file = PresetFile {
            schema: Spanned::new(0..0, SCHEMA),
            name: Some(self.name.clone()),
            description: non_empty(&self.description),
            source: non_empty(&self.source),
            head: b
                .segments
                .get(b.head)
                .map(|s| Spanned::new(0..0, s.name.clone())),
            body_mass_kg: b.body_mass.map(|v| Spanned::new(0..0, v)),
            band: Some(Spanned::new(
                0..0,
                BandFile {
                    from_hz: self.band.from,
                    to_hz: self.band.to,
                    step_hz: self.band.step,
                },
            )),
            segments: b
                .segments
                .iter()
                .map(|s| {
                    let derived = match (s.share, b.body_mass) {
                        (Some(sh), Some(bm)) => (sh * bm).to_bits() == s.mass.to_bits(),
                        _ => false,
                    };
                    Spanned::new(
                        0..0,
                        SegmentFile {
                            name: s.name.clone(),
                            mass_kg: (!derived).then_some(s.mass),
                            share: s.share,
                        },
                    )
                })
                .collect(),
            links: b
                .links
                .iter()
                .map(|l| {
                    Spanned::new(
                        0..0,
                        LinkFile {
                            name: Some(l.name.clone()),
                            upper: b.segments[l.upper].name.clone(),
                            lower: match l.lower {
                                End::Segment(j) => b.segments[j].name.clone(),
                                End::Seat => "seat".into(),
                            },
                            k_n_per_m: l.k,
                            c_ns_per_m: l.c,
                        },
                    )
                })
                .collect(),
        };
        let body = toml::to_string(&file).unwrap_or_default();
        format!(
            "# biodyn preset (schema {SCHEMA}). Units: kg, N/m, N·s/m, Hz.\n# Segments and links top to bottom: m1.., k1.., c1.. in that order.\n{body}"
        )
    }

    /// Writes the preset atomically: temp file beside the target, fsync, rename.
    pub fn save(&self, path: &Path) -> Result<(), PresetError> {
        save_atomic(path, self.to_toml().as_bytes()).map_err(|source| PresetError::Save {
            path: path.display().to_string(),
            source,
        })
    }
}

/// Atomic replace of `path` with `bytes`; the old file survives any failure.
pub fn save_atomic(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    save_atomic_with(path, |f| f.write_all(bytes))
}

/// `save_atomic` with the writing step supplied, so a failure midway can be tested.
fn save_atomic_with(
    path: &Path,
    write: impl FnOnce(&mut fs::File) -> std::io::Result<()>,
) -> std::io::Result<()> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let file_name = path
        .file_name()
        .ok_or_else(|| std::io::Error::other("the path names no file"))?;
    // Unique per process and per call, so concurrent saves never share it.
    static SEQ: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
    let seq = SEQ.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let tmp = dir.join(format!(
        ".{}.{}-{seq}.tmp",
        file_name.to_string_lossy(),
        std::process::id()
    ));
    let result = (|| {
        let mut f = fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&tmp)?;
        write(&mut f)?;
        f.sync_all()?;
        fs::rename(&tmp, path)
    })();
    if result.is_err() {
        let _ = fs::remove_file(&tmp);
    }
    result
}

fn non_empty(s: &str) -> Option<String> {
    (!s.is_empty()).then(|| s.to_string())
}

/// 1-based line and column of a byte offset.
fn line_col(text: &str, offset: usize) -> (usize, usize) {
    let offset = offset.min(text.len());
    let before = &text[..offset];
    let line = before.matches('\n').count() + 1;
    // Columns count characters, as an editor shows them, not bytes.
    let line_start = before.rfind('\n').map_or(0, |p| p + 1);
    let col = before[line_start..].chars().count() + 1;
    (line, col)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shipped_presets_parse() {
        for (name, text) in SHIPPED {
            let p = Preset::parse(text, &Origin::Builtin(name.into())).unwrap();
            assert_eq!(p.name, name);
            assert_eq!(p.body.n(), 4);
        }
        let d = Preset::builtin_default();
        assert_eq!(d.body, Body::paper(75.0).unwrap());
    }

    #[test]
    fn a_save_failing_midway_keeps_the_old_file_and_leaves_no_temp() {
        let dir = tempfile::tempdir().unwrap();
        let target = dir.path().join("keep.toml");
        fs::write(&target, b"old contents").unwrap();
        let err = save_atomic_with(&target, |f| {
            f.write_all(b"half of the new")?;
            Err(std::io::Error::other("disk full"))
        })
        .unwrap_err();
        assert_eq!(err.to_string(), "disk full");
        assert_eq!(fs::read(&target).unwrap(), b"old contents");
        let names: Vec<_> = fs::read_dir(dir.path())
            .unwrap()
            .flatten()
            .map(|e| e.file_name())
            .collect();
        assert_eq!(names, vec![std::ffi::OsString::from("keep.toml")]);
    }

    #[test]
    fn line_col_counts_from_one() {
        assert_eq!(line_col("ab\ncd", 0), (1, 1));
        assert_eq!(line_col("ab\ncd", 4), (2, 2));
        assert_eq!(line_col("x\néé z", 6), (2, 3));
    }
}
