//! Reading a preset's TOML: every problem named by file, line and field.

use super::{MAX_PRESET_NAME, Origin, Preset, PresetError, PresetFile, SCHEMA};
use crate::band::Band;
use crate::body::limits::{
    MAX_C, MAX_K, MAX_LINK_NAME, MAX_MASS, MAX_NAME, MIN_MASS, mass_in_range, name_problem,
};
use crate::body::model::{Body, End, Link, Segment};
use crate::body::preset_error::{line_col, syntax_error};
use crate::io::excerpt::{is_invisible, num, quote};
use toml::Spanned;

impl Preset {
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
                            "body_mass_kg = {}: a body mass must be {}",
                            num(v),
                            crate::body::limits::mass_rule(v)
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
            if super::seat::is_base(name) {
                return Err(field(
                    s.name.span(),
                    format!(
                        "{what}: \"{name}\" is reserved for the base in links; rename the segment"
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
                                "{what}: mass_kg = {}: a mass must be {}",
                                num(v),
                                crate::body::limits::mass_rule(v)
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
                seat: s.seat.as_ref().is_some_and(|b| *b.get_ref()),
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
            let lower = if super::seat::is_base(lower_name) {
                // The base's name says what it is: "floor" under a seat, "seat" without one.
                let has_seat = file.seat.is_some();
                if let Some(fix) = super::seat::base_mismatch(lower_name, has_seat) {
                    return Err(field(l.lower.span(), format!("{what}: {fix}")));
                }
                End::Seat
            } else {
                End::Segment(index_of(lower_name).ok_or_else(|| {
                    field(
                        l.lower.span(),
                        format!(
                            "{what}: lower = \"{}\" is neither a segment name nor the base (\"seat\", or \"floor\" under a seat)",
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
        let mut body = Body {
            segments,
            links,
            head,
            body_mass,
            seat: None,
        };
        if let Some(sf) = &file.seat {
            let seat = super::seat::resolve(sf.get_ref(), &body)
                .map_err(|(span, message)| field(span, message))?;
            body.seat = Some(seat);
        }
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
}
