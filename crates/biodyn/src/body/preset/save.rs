//! Writing a preset: the TOML (`to_toml`) and the atomic save.

use super::{BandFile, LinkFile, Origin, Preset, PresetError, PresetFile, SCHEMA, SegmentFile};
use crate::body::model::End;
use crate::io::FileKind;
use std::path::Path;
use toml::Spanned;

impl Preset {
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
            seat: super::seat::to_file(b).map(|s| Spanned::new(0..0, s)),
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
                            seat: s.seat.then_some(Spanned::new(0..0, true)),
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
                                    End::Seat => super::seat::base_name(b).into(),
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
        self.save_guarded(path, &crate::io::Guard::default())
    }

    /// [`save`](Self::save) held to `guard`: not over the command's inputs,
    /// a read-only file only when forced.
    pub fn save_guarded(&self, path: &Path, guard: &crate::io::Guard) -> Result<(), PresetError> {
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
        crate::io::save_guarded(path, guard, text.as_bytes()).map_err(|e| PresetError::Save {
            path: shown.clone(),
            source: e.into_io(),
        })
    }
}

fn non_empty(s: &str) -> Option<String> {
    (!s.is_empty()).then(|| s.to_string())
}
