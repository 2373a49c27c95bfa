//! Presets: a body, its band and a description, as TOML on disk.
//!
//! Loading names the file and the line (and column, for syntax) of every
//! problem; unknown fields are errors so a typo never silently falls back to
//! a default. Reading goes through [`crate::io::read_text`] (regular files
//! only, capped at [`FileKind::Preset`]'s size) and saving through
//! [`crate::io::save`] (atomic, links followed, special files refused).
//! Errors quote at most a short excerpt of the file.

pub use super::preset_error::PresetError;
use super::preset_error::{line_col, syntax_error};
use crate::body::model::{
    Body, End, Link, MAX_C, MAX_K, MAX_LINK_NAME, MAX_MASS, MAX_NAME, MIN_MASS, Segment,
    mass_in_range, name_problem,
};
use crate::freq::band::Band;
use crate::io::excerpt::{is_invisible, num, quote};
use crate::io::{FileKind, ReadError, read_bytes};
use serde::{Deserialize, Serialize};
use std::fmt;
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

/// Longest preset name in characters.
pub const MAX_PRESET_NAME: usize = 200;

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
    name: Option<Spanned<String>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    description: Option<Spanned<String>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    source: Option<Spanned<String>>,
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
    name: Spanned<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    mass_kg: Option<Spanned<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    share: Option<Spanned<f64>>,
}

#[derive(Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct LinkFile {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    name: Option<Spanned<String>>,
    upper: Spanned<String>,
    lower: Spanned<String>,
    k_n_per_m: Spanned<f64>,
    c_ns_per_m: Spanned<f64>,
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

    /// Reads and parses a preset file: a regular file of at most
    /// [`FileKind::Preset`]'s cap (a FIFO, device or `/dev/zero` is refused
    /// at once).
    pub fn load(path: &Path) -> Result<Preset, PresetError> {
        let shown = path.display().to_string();
        let bytes = read_bytes(path, FileKind::Preset).map_err(|e| match e {
            ReadError::NotRegular {
                what: "directory", ..
            } => PresetError::IsDir {
                path: shown.clone(),
            },
            other => PresetError::Read {
                path: shown.clone(),
                source: other.into_io(),
            },
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
        let file: PresetFile = toml::from_str(text).map_err(|e| syntax_error(text, &o, &e))?;
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
        for (key, value) in [
            ("name", &file.name),
            ("description", &file.description),
            ("source", &file.source),
        ] {
            let Some(v) = value else { continue };
            let bad_char = |c: char| (c.is_control() && c != '\n' && c != '\t') || is_invisible(c);
            if v.get_ref().chars().any(bad_char) {
                return Err(field(
                    v.span(),
                    format!(
                        "{key} = \"{}\": contains a control or invisible character; write plain text",
                        quote(v.get_ref())
                    ),
                ));
            }
        }
        if let Some(n) = &file.name
            && (n.get_ref().contains(['\n', '\t']) || n.get_ref().chars().count() > MAX_PRESET_NAME)
        {
            return Err(field(
                n.span(),
                format!(
                    "name = \"{}\": a preset name is one line of at most {MAX_PRESET_NAME} characters",
                    quote(n.get_ref())
                ),
            ));
        }
        let body_mass = match &file.body_mass_kg {
            Some(bm) => {
                let v = *bm.get_ref();
                if !mass_in_range(v) {
                    return Err(field(
                        bm.span(),
                        format!(
                            "body_mass_kg = {}: a body mass must be > 0: a number from {} to {} kg",
                            num(v),
                            num(MIN_MASS),
                            num(MAX_MASS)
                        ),
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
            let name = s.name.get_ref();
            let what = format!("segment {} ('{}')", i + 1, quote(name));
            if name == "seat" {
                return Err(field(
                    s.name.span(),
                    format!(
                        "{what}: \"seat\" is reserved for the seat in links; rename the segment"
                    ),
                ));
            }
            if let Some(why) = name_problem(name, MAX_NAME) {
                return Err(field(
                    s.name.span(),
                    format!("segment {}: name \"{}\" {why}", i + 1, quote(name)),
                ));
            }
            let share = s.share.as_ref().map(|sh| (*sh.get_ref(), sh.span()));
            if let Some((share, span)) = &share
                && !(share.is_finite() && *share > 0.0)
            {
                return Err(field(
                    span.clone(),
                    format!(
                        "{what}: share = {}: a share of body mass must be finite and > 0",
                        num(*share)
                    ),
                ));
            }
            let range = format!("from {} to {} kg", num(MIN_MASS), num(MAX_MASS));
            let mass = match (&s.mass_kg, &share, body_mass) {
                (Some(m), _, _) => {
                    let v = *m.get_ref();
                    if !mass_in_range(v) {
                        return Err(field(
                            m.span(),
                            format!(
                                "{what}: mass_kg = {}: a mass must be > 0: a number {range}",
                                num(v)
                            ),
                        ));
                    }
                    v
                }
                (None, Some((share, span)), Some(bm)) => {
                    let v = share * bm;
                    if !mass_in_range(v) {
                        return Err(field(
                            span.clone(),
                            format!(
                                "{what}: share {} × body_mass_kg {} = {} kg: a segment mass must be {range}",
                                num(*share),
                                num(bm),
                                num(v)
                            ),
                        ));
                    }
                    v
                }
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
            segments.push(Segment {
                name: name.clone(),
                mass,
                share: share.map(|(v, _)| v),
            });
        }
        // A map, not a search per link: a big preset must load in linear time.
        // The first segment of a name wins; validation refuses duplicates.
        let mut by_name = std::collections::HashMap::with_capacity(segments.len());
        for (i, s) in segments.iter().enumerate() {
            by_name.entry(s.name.as_str()).or_insert(i);
        }
        let index_of = |name: &str| by_name.get(name).copied();

        let mut links = Vec::with_capacity(file.links.len());
        for (i, lp) in file.links.iter().enumerate() {
            let l = lp.get_ref();
            let (upper_name, lower_name) = (l.upper.get_ref(), l.lower.get_ref());
            let (name, name_span) = match &l.name {
                Some(n) => (n.get_ref().clone(), n.span()),
                None => (format!("{upper_name}-{lower_name}"), lp.span()),
            };
            let what = format!("link {} ('{}')", i + 1, quote(&name));
            let upper = index_of(upper_name).ok_or_else(|| {
                field(
                    l.upper.span(),
                    format!(
                        "{what}: upper = \"{}\" is not a segment name",
                        quote(upper_name)
                    ),
                )
            })?;
            let lower = if lower_name == "seat" {
                End::Seat
            } else {
                End::Segment(index_of(lower_name).ok_or_else(|| {
                    field(
                        l.lower.span(),
                        format!(
                            "{what}: lower = \"{}\" is neither a segment name nor \"seat\"",
                            quote(lower_name)
                        ),
                    )
                })?)
            };
            if let Some(why) = name_problem(&name, MAX_LINK_NAME) {
                return Err(field(
                    name_span,
                    format!("link {}: name \"{}\" {why}", i + 1, quote(&name)),
                ));
            }
            for (key, v, max, unit) in [
                ("k_n_per_m", &l.k_n_per_m, MAX_K, "N/m"),
                ("c_ns_per_m", &l.c_ns_per_m, MAX_C, "N·s/m"),
            ] {
                let x = *v.get_ref();
                if !(x.is_finite() && (0.0..=max).contains(&x)) {
                    return Err(field(
                        v.span(),
                        format!(
                            "{what}: {key} = {}: must be a finite number from 0 to {max:e} {unit}",
                            num(x)
                        ),
                    ));
                }
            }
            links.push(Link {
                name,
                upper,
                lower,
                k: *l.k_n_per_m.get_ref(),
                c: *l.c_ns_per_m.get_ref(),
            });
        }

        let head = match &file.head {
            Some(h) => index_of(h.get_ref()).ok_or_else(|| {
                field(
                    h.span(),
                    format!("head = \"{}\" is not a segment name", quote(h.get_ref())),
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
                band.validate().map_err(|error| PresetError::Band {
                    origin: o.clone(),
                    error,
                })?;
                band
            }
            None => Band::default(),
        };

        Ok(Preset {
            name: file
                .name
                .map(Spanned::into_inner)
                .unwrap_or_else(|| match origin {
                    Origin::File(p) => p
                        .file_stem()
                        .map(|s| s.to_string_lossy().into_owned())
                        .unwrap_or_default(),
                    Origin::Builtin(n) => n.clone(),
                }),
            description: file
                .description
                .map(Spanned::into_inner)
                .unwrap_or_default(),
            source: file.source.map(Spanned::into_inner).unwrap_or_default(),
            body,
            band,
        })
    }

    // ---- saving ------------------------------------------------------------

    /// The preset as TOML. Masses that equal share × body mass bit for bit
    /// are written as shares alone, so a load/save/load round trip is exact.
    pub fn to_toml(&self) -> String {
        let b = &self.body;
        // A body that failed validation may hold an index past the end.
        let seg_name = |i: usize| {
            b.segments
                .get(i)
                .map(|s| s.name.clone())
                .unwrap_or_default()
        };
        let file = PresetFile {
            schema: Spanned::new(0..0, SCHEMA),
            name: Some(Spanned::new(0..0, self.name.clone())),
            description: non_empty(&self.description).map(|d| Spanned::new(0..0, d)),
            source: non_empty(&self.source).map(|d| Spanned::new(0..0, d)),
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
                            name: Spanned::new(0..0, s.name.clone()),
                            mass_kg: (!derived).then_some(Spanned::new(0..0, s.mass)),
                            share: s.share.map(|v| Spanned::new(0..0, v)),
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
                            name: Some(Spanned::new(0..0, l.name.clone())),
                            upper: Spanned::new(0..0, seg_name(l.upper)),
                            lower: Spanned::new(
                                0..0,
                                match l.lower {
                                    End::Segment(j) => seg_name(j),
                                    End::Seat => "seat".into(),
                                },
                            ),
                            k_n_per_m: Spanned::new(0..0, l.k),
                            c_ns_per_m: Spanned::new(0..0, l.c),
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

    /// Writes the preset through [`crate::io::save_atomic`]: a link is
    /// followed, a special file refused, the old file's mode kept, and a
    /// failure leaves the old file as it was. A preset that would not load
    /// back (over the size cap, or a name the loader refuses) is not written.
    pub fn save(&self, path: &Path) -> Result<(), PresetError> {
        let shown = path.display().to_string();
        let refuse = |why: String| PresetError::Save {
            path: shown.clone(),
            source: std::io::Error::new(std::io::ErrorKind::InvalidData, why),
        };
        let text = self.to_toml();
        let cap = FileKind::Preset.cap();
        if text.len() as u64 > cap {
            return Err(refuse(format!(
                "the preset is {} bytes, over the {} MiB a preset file may hold",
                text.len(),
                cap >> 20
            )));
        }
        if let Err(e) = Preset::parse(&text, &Origin::Builtin("preset to save".into())) {
            return Err(refuse(format!("it would not load back: {e}")));
        }
        crate::io::save_atomic(path, text.as_bytes()).map_err(|e| PresetError::Save {
            path: shown.clone(),
            source: e.into_io(),
        })
    }
}

fn non_empty(s: &str) -> Option<String> {
    (!s.is_empty()).then(|| s.to_string())
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
    fn line_col_counts_from_one() {
        assert_eq!(line_col("ab\ncd", 0), (1, 1));
        assert_eq!(line_col("ab\ncd", 4), (2, 2));
        assert_eq!(line_col("x\néé z", 6), (2, 3));
    }
}
