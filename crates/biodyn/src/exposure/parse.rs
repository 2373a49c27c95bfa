//! Checking a day file's TOML: every problem named by file, line,
//! operation and field, with the fix.

use super::caps::{MAX_MEASURED_S, MAX_RECORD_FS, MIN_MEASURED_S, cap};
use super::error::{DayError, OperationError, syntax};
use super::file::{
    AxesToml, DayFile, DayToml, HoursToml, MAX_DAY_H, MAX_OPERATION_NAME, OperationSpec,
    OperationToml, RecordSource, SCHEMA, Source, parse_axes,
};
use super::hours::{HOURS_FORMS, HOURS_TOLERANCE, parse_hours};
use crate::io::excerpt::{is_invisible, line_col, num, quote};
use crate::iso2631::spine::Person;
use crate::time::{Axis, PerAxis, Unit};
use std::path::Path;
use toml::Spanned;

impl DayFile {
    /// Parses day-file text; `origin` labels errors and record paths are
    /// taken from `folder`.
    pub fn parse(text: &str, origin: &str, folder: &Path) -> Result<DayFile, DayError> {
        let file: DayToml = toml::from_str(text).map_err(|e| syntax(text, origin, &e))?;
        if let Some(s) = &file.schema
            && *s.get_ref() != i64::from(SCHEMA)
        {
            return Err(DayError::Schema {
                origin: origin.into(),
                line: line_col(text, s.span().start).0,
                found: *s.get_ref(),
                expected: SCHEMA,
            });
        }
        if file.operations.is_empty() {
            return Err(DayError::NoOperations {
                origin: origin.into(),
            });
        }
        let spine = match &file.spine {
            Some(p) => Some(Person::parse(p.get_ref()).map_err(|e| DayError::Spine {
                origin: origin.into(),
                line: line_col(text, p.span().start).0,
                reason: e.to_string(),
            })?),
            None => None,
        };
        let report = match &file.report {
            Some(r) => r.check(text, origin, "report.").map_err(DayError::Report)?,
            None => Default::default(),
        };
        let mut operations = Vec::with_capacity(file.operations.len());
        for (i, op) in file.operations.iter().enumerate() {
            let check = Check {
                text,
                origin,
                number: i + 1,
                table: op.span(),
                name: op.get_ref().name.as_ref().map_or("", |n| n.get_ref()),
            };
            operations.push(check.operation(op.get_ref(), folder)?);
        }
        // 0.1 + 16.1 + 7.8 is 24.000000000000004 in floats: a whole day.
        let total_h: f64 = operations.iter().map(|o| o.hours).sum();
        if total_h > MAX_DAY_H + HOURS_TOLERANCE {
            return Err(DayError::OverADay {
                origin: origin.into(),
                total_h,
            });
        }
        Ok(DayFile {
            origin: origin.into(),
            operations,
            spine,
            report,
        })
    }
}

/// One operation being checked, for its messages.
struct Check<'a> {
    text: &'a str,
    origin: &'a str,
    number: usize,
    table: std::ops::Range<usize>,
    name: &'a str,
}

impl Check<'_> {
    fn err(
        &self,
        at: std::ops::Range<usize>,
        field: &str,
        value: Option<String>,
        fix: &str,
    ) -> DayError {
        DayError::Operation(Box::new(OperationError {
            origin: self.origin.into(),
            line: Some(line_col(self.text, at.start).0),
            number: self.number,
            name: quote(self.name),
            field: field.into(),
            value,
            fix: fix.into(),
        }))
    }

    /// A field every operation has, or the error at its table.
    fn required<'v, T>(
        &self,
        v: &'v Option<Spanned<T>>,
        field: &str,
        fix: &str,
    ) -> Result<&'v Spanned<T>, DayError> {
        v.as_ref()
            .ok_or_else(|| self.err(self.table.clone(), field, None, fix))
    }

    fn operation(&self, o: &OperationToml, folder: &Path) -> Result<OperationSpec, DayError> {
        let name = self.required(
            &o.name,
            "name",
            "missing; give each operation a name, e.g. name = \"haul road\"",
        )?;
        let n = name.get_ref();
        let bad = |c: char| c.is_control() || is_invisible(c);
        if n.trim().is_empty() || n.chars().any(bad) || n.chars().count() > MAX_OPERATION_NAME {
            return Err(self.err(
                name.span(),
                "name",
                Some(format!("\"{}\"", quote(n))),
                &format!(
                    "a name is one line of 1 to {MAX_OPERATION_NAME} printable characters, e.g. name = \"haul road\""
                ),
            ));
        }
        let h = self.hours(o)?;
        let source = match (&o.aw_m_s2, &o.record) {
            (None, None) => {
                return Err(self.err(
                    self.table.clone(),
                    "aw_m_s2",
                    None,
                    "missing, and no record either; give aw_m_s2 = { z = … } (measured a_w, m/s², before k) or record = \"FILE.csv\"",
                ));
            }
            (Some(aw), Some(_)) => {
                return Err(self.err(
                    aw.span(),
                    "aw_m_s2",
                    None,
                    "given with record; an operation takes its a_w from one of them, so keep one",
                ));
            }
            (Some(aw), None) => self.measured(o, aw)?,
            (None, Some(r)) => self.record(o, r, folder)?,
        };
        Ok(OperationSpec {
            name: n.clone(),
            hours: h,
            source,
        })
    }

    /// The hours a day: `hours` as a number or a text (`"3:15"`), or
    /// `minutes`; over 0 and at most 24 h.
    fn hours(&self, o: &OperationToml) -> Result<f64, DayError> {
        const RANGE: &str =
            "the hours a day of an operation must be a number over 0 and at most 24";
        match (&o.hours, &o.minutes) {
            (None, None) => Err(self.err(
                self.table.clone(),
                "hours",
                None,
                "missing; give the hours a day of this operation, e.g. hours = 2.5, hours = \"2:30\" or minutes = 150",
            )),
            (Some(_), Some(m)) => Err(self.err(
                m.span(),
                "minutes",
                Some(num(*m.get_ref())),
                "given with hours; give the operation's time once, as hours or as minutes",
            )),
            (None, Some(m)) => {
                let v = *m.get_ref();
                if v.is_finite() && v > 0.0 && v <= MAX_DAY_H * 60.0 {
                    Ok(v / 60.0)
                } else {
                    Err(self.err(
                        m.span(),
                        "minutes",
                        Some(num(v)),
                        "the minutes a day of an operation must be over 0 and at most 1440 (24 h)",
                    ))
                }
            }
            (Some(h), None) => match h.get_ref() {
                HoursToml::Number(v) if v.is_finite() && *v > 0.0 && *v <= MAX_DAY_H => Ok(*v),
                HoursToml::Number(v) => Err(self.err(h.span(), "hours", Some(num(*v)), RANGE)),
                HoursToml::Text(t) => parse_hours(t).map_err(|e| {
                    self.err(
                        h.span(),
                        "hours",
                        Some(format!("\"{}\"", quote(t))),
                        &match e {
                            super::hours::HoursError::Range { .. } => RANGE.to_string(),
                            super::hours::HoursError::Minutes { example, .. } => {
                                format!("minutes past the hour are 0 to 59; write e.g. hours = \"{example}\"")
                            }
                            super::hours::HoursError::Form(_) => format!(
                                "not hours; write a number (hours = 3.25) or a text in one of the forms {HOURS_FORMS}"
                            ),
                        },
                    )
                }),
            },
        }
    }

    /// A value of `field` within its cap ([`super::caps`]), or the error.
    fn capped(
        &self,
        at: std::ops::Range<usize>,
        field: &str,
        shown: &str,
        x: f64,
    ) -> Result<f64, DayError> {
        let (max, unit) = cap(field);
        if x > max {
            return Err(self.err(
                at,
                shown,
                Some(num(x)),
                &format!(
                    "is over the cap of {} {unit} on a day's values, as records are capped: check the unit",
                    num(max)
                ),
            ));
        }
        Ok(x)
    }

    /// Every value of an axes table finite, ≥ 0 and within its cap; at
    /// least one axis.
    fn axes(
        &self,
        t: &Spanned<AxesToml>,
        field: &str,
        unit: &str,
    ) -> Result<PerAxis<f64>, DayError> {
        let mut out = PerAxis::default();
        for a in Axis::ALL {
            let Some(v) = t.get_ref().get(a) else {
                continue;
            };
            let x = *v.get_ref();
            if !(x.is_finite() && x >= 0.0) {
                return Err(self.err(
                    v.span(),
                    &format!("{field}.{a}"),
                    Some(num(x)),
                    &format!("must be a finite number ≥ 0 ({unit}, before k)"),
                ));
            }
            let x = self.capped(v.span(), field, &format!("{field}.{a}"), x)?;
            out.set(a, x);
        }
        if out.is_empty() {
            return Err(self.err(
                t.span(),
                field,
                Some("{}".into()),
                "names no axis; give at least one of x, y and z, e.g. { z = 0.5 }",
            ));
        }
        Ok(out)
    }

    fn measured(&self, o: &OperationToml, aw_t: &Spanned<AxesToml>) -> Result<Source, DayError> {
        for (key, v) in [("axes", &o.axes), ("unit", &o.unit)] {
            if let Some(v) = v {
                return Err(self.err(
                    v.span(),
                    key,
                    Some(format!("\"{}\"", quote(v.get_ref()))),
                    "reads a record's columns; an operation with aw_m_s2 has no record, so remove it",
                ));
            }
        }
        let record_only = [
            ("fs", o.fs.as_ref().map(|v| (v.span(), num(*v.get_ref())))),
            (
                "remove_mean",
                o.remove_mean
                    .as_ref()
                    .map(|v| (v.span(), v.get_ref().to_string())),
            ),
        ];
        for (key, v) in record_only {
            if let Some((span, value)) = v {
                return Err(self.err(
                    span,
                    key,
                    Some(value),
                    "reads a record; an operation with aw_m_s2 has no record, so remove it",
                ));
            }
        }
        let aw = self.axes(aw_t, "aw_m_s2", "m/s²")?;
        let vdv = match &o.vdv_m_s175 {
            Some(t) => self.axes(t, "vdv_m_s175", "m/s^1.75")?,
            None => PerAxis::default(),
        };
        for (a, _) in vdv.iter() {
            if !aw.has(a) {
                let at = o
                    .vdv_m_s175
                    .as_ref()
                    .map_or(self.table.clone(), |t| t.span());
                return Err(self.err(
                    at,
                    &format!("vdv_m_s175.{a}"),
                    None,
                    &format!("aw_m_s2 has no {a}; give the axis's a_w too, or remove its VDV"),
                ));
            }
        }
        let dz = match &o.dz_m_s2 {
            Some(d) => {
                let x = *d.get_ref();
                if !(x.is_finite() && x >= 0.0) {
                    return Err(self.err(
                        d.span(),
                        "dz_m_s2",
                        Some(num(x)),
                        "ISO 2631-5's acceleration dose of z must be a finite number ≥ 0 (m/s²)",
                    ));
                }
                let x = self.capped(d.span(), "dz_m_s2", "dz_m_s2", x)?;
                if !aw.has(Axis::Z) {
                    return Err(self.err(
                        d.span(),
                        "dz_m_s2",
                        Some(num(x)),
                        "is z's dose, and aw_m_s2 has no z; give z's a_w too",
                    ));
                }
                Some(x)
            }
            None => None,
        };
        let timed = !vdv.is_empty() || dz.is_some();
        let measured_s = match (&o.measured_s, timed) {
            (None, true) => {
                let (at, field) = match (&o.vdv_m_s175, &o.dz_m_s2) {
                    (Some(t), _) => (t.span(), "vdv_m_s175"),
                    (None, Some(d)) => (d.span(), "dz_m_s2"),
                    _ => (self.table.clone(), "vdv_m_s175"),
                };
                return Err(self.err(
                    at,
                    field,
                    None,
                    "needs measured_s, the seconds the VDVs and the dose were measured over, e.g. measured_s = 600",
                ));
            }
            (Some(t), false) => {
                return Err(self.err(
                    t.span(),
                    "measured_s",
                    Some(num(*t.get_ref())),
                    "is the duration of measured VDVs or dz_m_s2, and there is neither; add one or remove measured_s",
                ));
            }
            (Some(t), true) => {
                let s = *t.get_ref();
                if !(s.is_finite() && (MIN_MEASURED_S..=MAX_MEASURED_S).contains(&s)) {
                    return Err(self.err(
                        t.span(),
                        "measured_s",
                        Some(num(s)),
                        &format!(
                            "the seconds the VDVs and the dose were measured over must be from {} to {} s (a record's least length to 10^8 samples at 100 Hz)",
                            num(MIN_MEASURED_S),
                            num(MAX_MEASURED_S)
                        ),
                    ));
                }
                Some(s)
            }
            (None, false) => None,
        };
        Ok(Source::Measured {
            aw,
            vdv,
            measured_s,
            dz,
        })
    }

    fn record(
        &self,
        o: &OperationToml,
        r: &Spanned<String>,
        folder: &Path,
    ) -> Result<Source, DayError> {
        for (key, span) in [
            ("vdv_m_s175", o.vdv_m_s175.as_ref().map(|v| v.span())),
            ("measured_s", o.measured_s.as_ref().map(|v| v.span())),
            ("dz_m_s2", o.dz_m_s2.as_ref().map(|v| v.span())),
        ] {
            if let Some(span) = span {
                return Err(self.err(
                    span,
                    key,
                    None,
                    "given with record; the record's own VDV, dose and duration are used, so remove it",
                ));
            }
        }
        let path = r.get_ref();
        if path.trim().is_empty() || path.chars().any(char::is_control) {
            return Err(self.err(
                r.span(),
                "record",
                Some(format!("\"{}\"", quote(path))),
                "give the path of a CSV record, relative to the day file's folder",
            ));
        }
        let axes = match &o.axes {
            Some(a) => Some(parse_axes(a.get_ref()).map_err(|why| {
                self.err(
                    a.span(),
                    "axes",
                    Some(format!("\"{}\"", quote(a.get_ref()))),
                    &format!("{why}; write e.g. axes = \"x=ax,y=ay,z=az\" (any subset)"),
                )
            })?),
            None => None,
        };
        let unit = match &o.unit {
            Some(u) => Some(Unit::parse(u.get_ref()).ok_or_else(|| {
                self.err(
                    u.span(),
                    "unit",
                    Some(format!("\"{}\"", quote(u.get_ref()))),
                    "the units are m/s2, g and mm/s2",
                )
            })?),
            None => None,
        };
        let fs = match &o.fs {
            Some(f) => {
                let v = *f.get_ref();
                if !(v.is_finite() && v > 0.0 && v <= MAX_RECORD_FS) {
                    return Err(self.err(
                        f.span(),
                        "fs",
                        Some(num(v)),
                        &format!(
                            "the record's sampling rate must be a number over 0 and at most {} Hz, e.g. fs = 1000",
                            num(MAX_RECORD_FS)
                        ),
                    ));
                }
                Some(v)
            }
            None => None,
        };
        Ok(Source::Record(RecordSource {
            path: path.clone(),
            resolved: folder.join(path),
            axes,
            unit,
            fs,
            remove_mean: o.remove_mean.as_ref().is_some_and(|b| *b.get_ref()),
        }))
    }
}
