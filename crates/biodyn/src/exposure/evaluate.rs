//! A day file to a [`Day`]: measured operations directly, record
//! operations through the caller's resolver (the library reads no record
//! here; the front end decides how).

use super::day::{Day, Operation};
use super::error::{DayError, EvalError, OperationError};
use super::file::{DayFile, OperationSpec, RecordSource, Source};
use super::operation::Measured;
use super::spine::DaySpine;
use crate::io::excerpt::{num, quote};
use crate::iso2631::MIN_RECORD_S;
use crate::time::{Axis, PerAxis};

impl DayFile {
    /// Every operation evaluated and the day summed. `resolve` gives a
    /// record's a_w per axis (before k), its VDVs and its duration.
    pub fn evaluate<E>(
        &self,
        mut resolve: impl FnMut(&RecordSource) -> Result<PerAxis<Measured>, E>,
    ) -> Result<Day, EvalError<E>> {
        let mut operations = Vec::with_capacity(self.operations.len());
        let mut doses = Vec::new();
        for (i, o) in self.operations.iter().enumerate() {
            let measured = match &o.source {
                Source::Measured {
                    aw,
                    vdv,
                    measured_s,
                    dz,
                } => aw.map(|a, &aw| Measured {
                    aw,
                    vdv: vdv.get(a).copied(),
                    measured_s: *measured_s,
                    dz: if a == Axis::Z { *dz } else { None },
                }),
                Source::Record(r) => {
                    let m = resolve(r).map_err(|reason| EvalError::Record {
                        origin: self.origin.clone(),
                        number: i + 1,
                        name: quote(&o.name),
                        record: quote(&r.path),
                        reason,
                    })?;
                    self.check_record(i, &o.name, r, &m)?;
                    m
                }
            };
            if self.spine.is_some() {
                doses.push(self.dose(i, o, &measured)?);
            }
            operations.push(Operation::new(&o.name, o.hours, &measured));
        }
        let mut day = Day::of(operations).ok_or_else(|| {
            EvalError::Day(DayError::NoOperations {
                origin: self.origin.clone(),
            })
        })?;
        if let Some(p) = self.spine {
            let spine = DaySpine::of(p, &doses).map_err(|e| {
                let o = &self.operations[e.operation];
                let record = matches!(o.source, Source::Record(_));
                DayError::Operation(Box::new(OperationError {
                    origin: self.origin.clone(),
                    line: None,
                    number: e.operation + 1,
                    name: quote(&o.name),
                    field: if record { "record" } else { "dz_m_s2" }.into(),
                    value: (!record).then(|| num(e.dz)),
                    fix: e.to_string(),
                }))
            })?;
            day.spine = Some(spine);
        }
        Ok(day)
    }

    /// Operation `i`'s z dose for the day's spine: (i, Dz, t_m, hours), or
    /// the field that is missing.
    fn dose(
        &self,
        i: usize,
        o: &OperationSpec,
        m: &PerAxis<Measured>,
    ) -> Result<(usize, f64, f64, f64), DayError> {
        if let Some(z) = m.get(Axis::Z)
            && let (Some(dz), Some(t)) = (z.dz, z.measured_s)
        {
            return Ok((i, dz, t, o.hours));
        }
        let (field, fix) = match &o.source {
            Source::Measured { .. } => (
                "dz_m_s2",
                "missing; the day's spine (ISO 2631-5) needs every operation's z dose: give dz_m_s2 = … (m/s², over measured_s) or a record",
            ),
            Source::Record(_) => (
                "record",
                "gives no ISO 2631-5 dose: it has no z, is under 1 s, or its mean is over 5 % of its largest spinal response peak (assess it with the spine to see which)",
            ),
        };
        Err(DayError::Operation(Box::new(OperationError {
            origin: self.origin.clone(),
            line: None,
            number: i + 1,
            name: quote(&o.name),
            field: field.into(),
            value: None,
            fix: fix.into(),
        })))
    }

    /// What a resolver gave must be numbers the day can use.
    fn check_record(
        &self,
        i: usize,
        name: &str,
        r: &RecordSource,
        m: &PerAxis<Measured>,
    ) -> Result<(), DayError> {
        let err = |value: Option<String>, fix: String| {
            DayError::Operation(Box::new(OperationError {
                origin: self.origin.clone(),
                line: None,
                number: i + 1,
                name: quote(name),
                field: "record".into(),
                value,
                fix,
            }))
        };
        let shown = || Some(format!("\"{}\"", quote(&r.path)));
        if m.is_empty() {
            return Err(err(shown(), "the record has no axis to assess".into()));
        }
        // Too short means no verdict, as for an assessment.
        if let Some(t) = m.iter().find_map(|(_, v)| v.measured_s)
            && t < MIN_RECORD_S
        {
            return Err(err(
                shown(),
                format!(
                    "the record is {} s long: too short to judge (at least {MIN_RECORD_S} s); give a longer record",
                    num(t)
                ),
            ));
        }
        for (a, v) in m.iter() {
            let bad = |x: f64| !(x.is_finite() && x >= 0.0);
            if bad(v.aw)
                || v.vdv.is_some_and(bad)
                || v.dz.is_some_and(bad)
                || v.measured_s.is_some_and(|t| !(t > 0.0 && t.is_finite()))
            {
                return Err(err(
                    shown(),
                    format!(
                        "axis {a} gave a_w {}, VDV {}, dose {}, duration {} s; each must be finite and ≥ 0 (the duration > 0)",
                        num(v.aw),
                        v.vdv.map_or("-".into(), num),
                        v.dz.map_or("-".into(), num),
                        v.measured_s.map_or("-".into(), num)
                    ),
                ));
            }
        }
        Ok(())
    }
}
