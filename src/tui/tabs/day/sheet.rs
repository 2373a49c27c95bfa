//! The day evaluated from the table, as `biodyn day` evaluates a day file
//! (`exposure::Operation`, `exposure::Day`): per operation and axis k·a_w,
//! partial A(8), points and hours to the action and limit values; per
//! axis the day's A(8) = √Σ partial², points Σ; the highest axis. A
//! record operation counts once measured; until then (or when it cannot
//! be read) the day is summed without it and not judged.

use super::records::{Records, State};
use biodyn::exposure::{Day, Measured, Operation, OperationSpec, RecordSource, Source};
use biodyn::time::{Axis, PerAxis};

/// One operation's row of the sheet.
#[derive(Debug, Clone, PartialEq)]
pub enum Row {
    /// Evaluated on the axes it has (none: no a_w typed yet); boxed, the
    /// other rows are small.
    Done(Box<Operation>),
    /// Its record is being read.
    Measuring,
    /// Its record could not be read: why.
    Failed(String),
}

#[derive(Debug, Clone, PartialEq, Default)]
pub struct Sheet {
    pub rows: Vec<Row>,
    /// The day of the evaluated operations; None when none has an axis.
    pub day: Option<Day>,
    /// Operations not in `day` (measuring, unreadable, or no a_w yet).
    pub left_out: Vec<usize>,
}

impl Sheet {
    /// Whether the day's verdict covers every operation.
    pub fn complete(&self) -> bool {
        self.left_out.is_empty()
    }

    pub fn of(ops: &[OperationSpec], records: &Records) -> Sheet {
        let mut rows = Vec::with_capacity(ops.len());
        let mut done = Vec::new();
        let mut left_out = Vec::new();
        for (i, o) in ops.iter().enumerate() {
            let row = match &o.source {
                Source::Measured { aw, vdv, measured_s, dz } => Row::Done(Box::new(Operation::new(
                    &o.name,
                    o.hours,
                    &aw.map(|a, &aw| Measured {
                        aw,
                        vdv: vdv.get(a).copied(),
                        measured_s: *measured_s,
                        dz: if a == Axis::Z { *dz } else { None },
                    }),
                ))),
                Source::Record(r) => match records.get(r) {
                    Some(State::Done(Ok(m))) => {
                        Row::Done(Box::new(Operation::new(&o.name, o.hours, &m.axes)))
                    }
                    Some(State::Done(Err(why))) => Row::Failed(why.clone()),
                    Some(State::Measuring) | None => Row::Measuring,
                },
            };
            match &row {
                Row::Done(op) if !op.axes.is_empty() => done.push(op.as_ref().clone()),
                _ => left_out.push(i),
            }
            rows.push(row);
        }
        Sheet {
            rows,
            day: Day::of(done),
            left_out,
        }
    }
}

/// The records the operations read.
pub fn records_of(ops: &[OperationSpec]) -> Vec<RecordSource> {
    ops.iter()
        .filter_map(|o| match &o.source {
            Source::Record(r) => Some(r.clone()),
            Source::Measured { .. } => None,
        })
        .collect()
}

/// What a record measured, when it has been.
pub fn measured_of<'a>(o: &OperationSpec, records: &'a Records) -> Option<&'a PerAxis<Measured>> {
    match &o.source {
        Source::Record(r) => match records.get(r) {
            Some(State::Done(Ok(m))) => Some(&m.axes),
            _ => None,
        },
        Source::Measured { .. } => None,
    }
}

/// A measured record's notes without the file's name (the operations
/// table names it): "m/s² assumed for 'az': …", "mean removed: z 9.8066 m/s²".
pub fn notes_of(o: &OperationSpec, records: &Records) -> Vec<String> {
    let Source::Record(r) = &o.source else {
        return Vec::new();
    };
    let Some(State::Done(Ok(m))) = records.get(r) else {
        return Vec::new();
    };
    let file = format!(
        "{}: ",
        biodyn::io::excerpt(&r.resolved.display().to_string(), 200)
    );
    m.notes
        .iter()
        .map(|n| n.strip_prefix(&file).unwrap_or(n).to_string())
        .collect()
}
