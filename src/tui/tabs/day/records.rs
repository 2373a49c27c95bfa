//! Record operations measured (`exposure::measure_record`: each axis
//! weighted, a_w and VDV over the record), off the main thread: a record
//! may be a few hundred MB of CSV (about a second at 300 MB/s), and the
//! keys must not wait for it. One worker at a time measures the records
//! still missing, in order, and reports each; a result is kept by what
//! it was read from (file, axes, unit, rate, mean), so an edit elsewhere never reads
//! a record again. `R` forgets them all. Without a channel (tests) the
//! records are measured at once.

use crate::tui::event::Mailbox;
use biodyn::exposure::{MeasureError, Measured, RecordSource, measure_record_noted};
use biodyn::time::{PerAxis, TimeError};
use std::collections::HashMap;
use std::path::PathBuf;

/// What a record is read from: the measurement stays valid while these do.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Key {
    pub path: PathBuf,
    pub axes: Option<String>,
    pub unit: Option<&'static str>,
    /// The rate given for a record without a time column, as bits (a key
    /// compares exactly what was typed).
    pub fs: Option<u64>,
    pub remove_mean: bool,
}

impl Key {
    pub fn of(r: &RecordSource) -> Key {
        Key {
            path: r.resolved.clone(),
            axes: r.axes_text(),
            unit: r.unit.map(|u| u.name()),
            fs: r.fs.map(f64::to_bits),
            remove_mean: r.remove_mean,
        }
    }
}

/// A record measured: a_w, VDV and duration per axis (before k), and the
/// notes every report of it carries (m/s² assumed, a mean removed, a mean
/// weighed and kept), as `biodyn day` prints them.
#[derive(Debug, Clone, PartialEq)]
pub struct Measure {
    pub axes: PerAxis<Measured>,
    pub notes: Vec<String>,
}

/// A record's state.
#[derive(Debug, Clone, PartialEq)]
pub enum State {
    Measuring,
    Done(Result<Measure, String>),
}

/// The worker's report: one record measured, or the batch over.
#[allow(clippy::large_enum_variant)] // one per record read: boxing buys nothing
pub enum Report {
    One(Key, Result<Measure, String>),
    Finished,
}

#[derive(Debug, Default)]
pub struct Records {
    pub states: HashMap<Key, State>,
    /// A worker is measuring.
    pub busy: bool,
}

/// A record's a_w, VDV and duration per axis (before k) with its notes,
/// or why not: the reader's reason, as `biodyn day` says it.
pub fn measure(r: &RecordSource) -> Result<Measure, String> {
    match measure_record_noted(r) {
        Ok((m, _)) if m.is_empty() => Err("the record has no axis to assess".into()),
        Ok((axes, notes)) => Ok(Measure { axes, notes }),
        Err(MeasureError::Record(e)) => Err(TimeError::from(e).to_string()),
        Err(e) => Err(e
            .to_string()
            .replace("(remove_mean)", "(remove_mean = true in the operation)")),
    }
}

impl Records {
    pub fn get(&self, r: &RecordSource) -> Option<&State> {
        self.states.get(&Key::of(r))
    }

    /// Starts measuring the records in `wanted` not known yet: at once
    /// without a channel, else on one worker (unless one runs: it asks
    /// again when it finishes). Returns why a worker could not start.
    pub fn request(&mut self, wanted: &[RecordSource], mailbox: &Mailbox) -> Option<String> {
        let mut todo: Vec<RecordSource> = Vec::new();
        for r in wanted {
            let key = Key::of(r);
            if !self.states.contains_key(&key) && !todo.iter().any(|t| Key::of(t) == key) {
                todo.push(r.clone());
            }
        }
        if todo.is_empty() || self.busy {
            return None;
        }
        let Some((tx, wrap)) = mailbox.wrap::<Report>() else {
            for r in todo {
                self.states.insert(Key::of(&r), State::Done(measure(&r)));
            }
            return None;
        };
        for r in &todo {
            self.states.insert(Key::of(r), State::Measuring);
        }
        let spawned = std::thread::Builder::new()
            .name("day-records".into())
            .spawn(move || {
                for r in todo {
                    let out = measure(&r);
                    if tx.send(wrap(Report::One(Key::of(&r), out))).is_err() {
                        return;
                    }
                }
                let _ = tx.send(wrap(Report::Finished));
            });
        match spawned {
            Ok(_) => {
                self.busy = true;
                None
            }
            Err(e) => {
                self.states.retain(|_, s| *s != State::Measuring);
                Some(format!("cannot start reading the records: {e}"))
            }
        }
    }

    /// A worker's report landed.
    pub fn on_report(&mut self, r: Report) {
        match r {
            Report::One(key, out) => {
                self.states.insert(key, State::Done(out));
            }
            Report::Finished => self.busy = false,
        }
    }

    /// Forgets every finished measurement (the files may have changed).
    pub fn forget(&mut self) {
        self.states.retain(|_, s| *s == State::Measuring);
    }
}
