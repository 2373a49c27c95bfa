//! What the Vibration tab computes, off the main thread when it can: the
//! library's assessment of every axis of the seat record
//! (`iso2631::assess_axes`) and, in the same pass, the traces as min/max
//! envelopes: each seat axis raw and weighted with its own ISO 2631-1
//! weighting (x, y Wd; z Wk), the head raw and Wk-weighted; and the export
//! of what `biodyn simulate --format csv` prints (driven by z alone).

use crate::view::envelope::Envelope;
use biodyn::Body;
use biodyn::iso2631::spine::Person;
use biodyn::iso2631::{Assessment, Weighting, assess_with, rule};
use biodyn::time::{
    Axis, Generator, PerAxis, Record, RecordError, RecordOptions, Row, Signal, Simulator,
    TimeError, Unit, sample_count,
};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

pub use super::record::open_record;
use super::record::columns_words;

/// Where the seat acceleration comes from.
#[derive(Debug, Clone, PartialEq)]
pub enum Source {
    Signal(Signal),
    /// A CSV record; `axes` empty: the axes its header names; `unit`
    /// None: a column's suffix, else m/s².
    File {
        path: PathBuf,
        axes: PerAxis<String>,
        unit: Option<Unit>,
        /// Each channel's mean removed before judging (`--remove-mean`).
        remove_mean: bool,
    },
}

/// Everything a run depends on besides the body.
#[derive(Debug, Clone, PartialEq)]
pub struct Input {
    pub source: Source,
    /// Length of a generated signal, s.
    pub duration_s: f64,
    /// Rate of a generated signal; of a file only when it has no time column.
    pub fs_hz: f64,
    pub exposure_h: f64,
    /// ISO 2631-5 for this person, when asked.
    pub spine: Option<Person>,
}

/// The traces of a run: the seat's z (the body's input) and the head, and
/// the seat's x and y where the record has them (else empty).
#[derive(Debug, Clone, Default)]
pub struct Traces {
    pub fs: f64,
    pub t0: f64,
    /// The seat axes the record has.
    pub axes: PerAxis<()>,
    pub seat: Envelope,
    pub head: Envelope,
    pub seat_w: Envelope,
    pub head_w: Envelope,
    pub seat_x: Envelope,
    pub seat_y: Envelope,
    /// x and y weighted with Wd (ISO 2631-1 §7.2.2, seated, health).
    pub seat_x_w: Envelope,
    pub seat_y_w: Envelope,
    /// With a seat model: `seat` is the pan's motion (what is judged), the
    /// record being the floor.
    pub pan: bool,
}

impl Traces {
    /// The seat trace of `axis`, raw or weighted with its own weighting.
    pub fn seat_axis(&self, axis: Axis, weighted: bool) -> &Envelope {
        match (axis, weighted) {
            (Axis::X, false) => &self.seat_x,
            (Axis::X, true) => &self.seat_x_w,
            (Axis::Y, false) => &self.seat_y,
            (Axis::Y, true) => &self.seat_y_w,
            (Axis::Z, false) => &self.seat,
            (Axis::Z, true) => &self.seat_w,
        }
    }

    /// The head trace, raw or Wk-weighted.
    pub fn head(&self, weighted: bool) -> &Envelope {
        if weighted { &self.head_w } else { &self.head }
    }

    /// Samples in the record (every trace present holds them all).
    pub fn samples(&self) -> usize {
        self.seat.len
    }

    /// A record with more than the vertical axis.
    pub fn tri_axial(&self) -> bool {
        self.axes.has(Axis::X) || self.axes.has(Axis::Y)
    }

    /// Record length, s.
    pub fn duration(&self) -> f64 {
        if self.fs > 0.0 {
            self.samples() as f64 / self.fs
        } else {
            0.0
        }
    }
}

/// A finished run.
#[derive(Debug, Clone)]
pub struct Outcome {
    pub assessment: Assessment,
    pub traces: Traces,
    /// "sine:freq=5,amp=5" or "seat.csv (acc_m_s2)".
    pub label: String,
    /// The head segment's name.
    pub head: String,
    /// A record's columns per axis and their unit: "x ax, y ay, z az in m/s2".
    pub columns: Option<String>,
}

/// An open input: rate, start time, label, the axes it has and its rows.
pub struct Opened {
    pub fs: f64,
    pub t0: f64,
    pub label: String,
    /// A record's axis columns in words (None for a signal).
    pub columns: Option<String>,
    /// A record's file, columns and time column as `biodyn simulate
    /// --format csv` comments them, and its refusal when it has no z.
    pub input_line: Option<String>,
    pub no_vertical: Option<String>,
    pub axes: PerAxis<()>,
    pub samples: Box<dyn Iterator<Item = Result<Row, TimeError>> + Send>,
}

/// Only the z axis: a generated signal is vertical.
pub(super) fn vertical() -> PerAxis<()> {
    let mut z = PerAxis::default();
    z.set(Axis::Z, ());
    z
}

/// Opens the input the way `biodyn simulate` does; a file without a time
/// column is read at the fs setting.
pub fn open(input: &Input) -> Result<Opened, String> {
    match &input.source {
        Source::Signal(sig) => {
            let g =
                Generator::new(sig, input.fs_hz, input.duration_s).map_err(|e| e.to_string())?;
            Ok(Opened {
                fs: input.fs_hz,
                t0: 0.0,
                label: sig.to_string(),
                columns: None,
                input_line: None,
                no_vertical: None,
                axes: vertical(),
                samples: Box::new(g.map(|a| Ok([0.0, 0.0, a]))),
            })
        }
        Source::File {
            path,
            axes,
            unit,
            remove_mean,
        } => {
            let rec = open_record(path, axes, *unit, *remove_mean, input.fs_hz)
                .map_err(|e| e.to_string())?;
            let columns = &rec.columns().axes;
            // As the command line words them (`biodyn simulate`'s "# input:").
            let source = crate::view::report::input::Source::Record {
                path: path.clone(),
                time: Some(rec.time_column().to_string()).filter(|t| !t.is_empty()),
                columns: Box::new(rec.columns().clone()),
            };
            let line = source.line();
            let no_vertical = RecordError::NoVertical {
                path: path.clone(),
                axes: crate::view::report::input::axes_words(rec.columns()),
            }
            .to_string();
            let listed: Vec<String> = columns
                .iter()
                .map(|(a, c)| format!("{a} {} {}", c.name, c.unit))
                .collect();
            Ok(Opened {
                fs: rec.fs(),
                t0: rec.t0(),
                label: format!("{} ({})", path.display(), listed.join(", ")),
                columns: Some(columns_words(columns)),
                input_line: Some(line),
                no_vertical: Some(no_vertical),
                axes: rec.axes(),
                samples: Box::new(rec.map(|r| r.map_err(TimeError::from))),
            })
        }
    }
}

/// Whether a file source is refused for its columns (no axis named, two
/// columns on one axis, a column not there, a unit clash): what the axes
/// and unit settings fix, so the path is kept and the run shows why.
pub fn refused_for_columns(input: &Input) -> bool {
    let Source::File {
        path, axes, unit, ..
    } = &input.source
    else {
        return false;
    };
    let opts = RecordOptions {
        axes: axes.clone(),
        unit: *unit,
        fs: Some(input.fs_hz),
        ..RecordOptions::default()
    };
    matches!(
        Record::open(path, &opts),
        Err(RecordError::Unnamed { .. }
            | RecordError::SameAxis { .. }
            | RecordError::SamePoint { .. }
            | RecordError::MissingColumn { .. }
            | RecordError::UnitClash { .. })
    )
}

/// Checks what can be checked without running: the signal against fs and
/// duration, the sample cap, the exposure. Files are checked by running.
pub fn check(input: &Input) -> Result<(), String> {
    if let Source::Signal(sig) = &input.source {
        sample_count(input.duration_s, input.fs_hz).map_err(|e| e.to_string())?;
        sig.check(input.fs_hz, input.duration_s)
            .map_err(|e| e.to_string())?;
    }
    let h = input.exposure_h;
    if !(h.is_finite() && h > 0.0 && h <= biodyn::iso2631::MAX_EXPOSURE_H) {
        return Err(biodyn::iso2631::AssessError::BadExposure(h).to_string());
    }
    Ok(())
}

/// Samples between two progress calls.
const PROGRESS_EVERY: u64 = 1 << 16;

/// Assesses `input` for `body` and fills the traces, in one pass over the
/// samples. Stops early (Err) once `cancel` is set: a newer edit wants the
/// thread. `progress(done, total)` is called every 65536 samples (total is
/// None for a file: its length is known only at its end).
pub fn run(
    body: &Body,
    input: &Input,
    cancel: &AtomicBool,
    progress: &mut dyn FnMut(u64, Option<u64>),
) -> Result<Outcome, String> {
    check(input)?;
    let o = open(input)?;
    let total = match &input.source {
        Source::Signal(_) => sample_count(input.duration_s, input.fs_hz)
            .ok()
            .map(|n| n as u64),
        Source::File { .. } => None,
    };
    let mut done: u64 = 0;
    let mut sim = Simulator::new(body, o.fs).map_err(|e| TimeError::from(e).to_string())?;
    let head = sim.head();
    let mut y = vec![0.0; sim.layout().len()];
    let mut w_seat = Weighting::Wk.digital(o.fs);
    let mut w_head = w_seat.clone();
    let mut w_x = rule(Axis::X).weighting.digital(o.fs);
    let mut w_y = rule(Axis::Y).weighting.digital(o.fs);
    let (has_x, has_y) = (o.axes.has(Axis::X), o.axes.has(Axis::Y));
    let pan = body.pan();
    let mut tr = Traces {
        fs: o.fs,
        t0: o.t0,
        axes: o.axes,
        pan: pan.is_some(),
        ..Traces::default()
    };
    let tee = o
        .samples
        .take_while(|_| !cancel.load(Ordering::Relaxed))
        .inspect(|s| {
            if let Ok(row) = *s {
                let floor = row[Axis::Z.index()];
                sim.step(floor, &mut y);
                // Under a seat the seat trace is the pan's, as `assess` judges it.
                let a = pan.and_then(|p| y.get(p).copied()).unwrap_or(floor);
                let h = y.get(head).copied().unwrap_or(0.0);
                tr.seat.push(a);
                tr.head.push(h);
                tr.seat_w.push(w_seat.process(a));
                tr.head_w.push(w_head.process(h));
                if has_x {
                    tr.seat_x.push(row[Axis::X.index()]);
                    tr.seat_x_w.push(w_x.process(row[Axis::X.index()]));
                }
                if has_y {
                    tr.seat_y.push(row[Axis::Y.index()]);
                    tr.seat_y_w.push(w_y.process(row[Axis::Y.index()]));
                }
            }
            done += 1;
            if done % PROGRESS_EVERY == 0 {
                progress(done, total);
            }
        });
    let assessment = assess_with(
        body,
        o.fs,
        tee,
        &o.axes,
        input.exposure_h,
        input.spine.as_ref(),
    )
    // The tab's own words for the library's field.
    .map_err(|e| {
        e.to_string()
            .replace("(remove_mean)", "(set the mean row to removed)")
    })?;
    if cancel.load(Ordering::Relaxed) {
        return Err("superseded by a newer edit".into());
    }
    let head = body
        .segments
        .get(body.head)
        .map_or_else(|| "head".to_string(), |s| s.name.clone());
    Ok(Outcome {
        assessment,
        traces: tr,
        label: o.label,
        head,
        columns: o.columns,
    })
}

/// A run of model generation `generation`, as it comes back.
pub struct Done {
    pub generation: u64,
    pub result: Result<Outcome, String>,
}

/// How far a run of generation `generation` is: `done` samples of `total`.
pub struct Progress {
    pub generation: u64,
    pub done: u64,
    pub total: Option<u64>,
}

/// What a worker sends: progress (at most every 100 ms), then the result.
pub enum Report {
    Progress(Progress),
    Done(Box<Done>),
}

/// Starts `run` on its own thread; `send` delivers the reports. A
/// cancelled run sends nothing more.
pub fn spawn(
    body: Body,
    input: Input,
    generation: u64,
    send: impl Fn(Report) + Send + 'static,
) -> std::io::Result<Arc<AtomicBool>> {
    let cancel = Arc::new(AtomicBool::new(false));
    let flag = Arc::clone(&cancel);
    std::thread::Builder::new()
        .name("vibration".into())
        .spawn(move || {
            let mut last = std::time::Instant::now();
            let mut progress = |done, total| {
                if last.elapsed() >= std::time::Duration::from_millis(100)
                    && !flag.load(Ordering::Relaxed)
                {
                    last = std::time::Instant::now();
                    send(Report::Progress(Progress {
                        generation,
                        done,
                        total,
                    }));
                }
            };
            let result = run(&body, &input, &flag, &mut progress);
            if !flag.load(Ordering::Relaxed) {
                send(Report::Done(Box::new(Done { generation, result })));
            }
        })?;
    Ok(cancel)
}


/// Writes what `biodyn simulate --format csv` prints for this body and
/// input to `out`; returns the number of rows.
pub fn write_csv(body: &Body, input: &Input, out: &mut dyn Write) -> Result<u64, String> {
    use std::fmt::Write as _;
    let o = open(input)?;
    let mut sim = Simulator::new(body, o.fs).map_err(|e| TimeError::from(e).to_string())?;
    let layout = sim.layout();
    let head = sim.head();
    let io = |e: std::io::Error| e.to_string();
    if !o.axes.has(Axis::Z) {
        return Err(o
            .no_vertical
            .unwrap_or_else(|| biodyn::iso2631::AssessError::NoVertical.to_string()));
    }
    let mut text = String::new();
    if let Some(line) = &o.input_line {
        let _ = writeln!(text, "# input: {line}");
    }
    text.push_str(&biodyn::time::record_columns(body).join(","));
    text.push('\n');
    let samples = o
        .samples
        .map(|s| s.map(|row| row[Axis::Z.index()]).map_err(|e| e.to_string()));
    let k = sim.stream(samples, |k, seat, r| {
        let t = o.t0 + k as f64 / o.fs;
        let values = [t, seat, r[head], r[layout.force()]]
            .into_iter()
            .chain(r[..layout.segments].iter().copied())
            .chain(r[layout.segments + 1..].iter().copied());
        for (i, v) in values.enumerate() {
            if i > 0 {
                text.push(',');
            }
            let _ = write!(text, "{v}");
        }
        text.push('\n');
        if text.len() > 1 << 16 {
            out.write_all(text.as_bytes()).map_err(io)?;
            text.clear();
        }
        Ok(())
    })?;
    out.write_all(text.as_bytes()).map_err(io)?;
    out.flush().map_err(io)?;
    Ok(k)
}

/// Exports to `path` through the library's atomic save (`io::save`): a
/// temporary file in the target's folder, renamed into place only when
/// complete, so a failed export leaves the old file (or none). The input's
/// own error (a bad row in a record) is reported as the library words it.
pub fn export(body: &Body, input: &Input, path: &Path) -> Result<u64, String> {
    let mut rows = 0;
    let mut failed: Option<String> = None;
    let saved = biodyn::io::save_atomic_with(path, |f| {
        let mut w = std::io::BufWriter::with_capacity(1 << 16, f);
        match write_csv(body, input, &mut w) {
            Ok(n) => rows = n,
            Err(e) => {
                failed = Some(e.clone());
                return Err(std::io::Error::other(e));
            }
        }
        w.flush()
    });
    match (saved, failed) {
        (Ok(()), _) => Ok(rows),
        (Err(_), Some(why)) => Err(why),
        (Err(e), None) => Err(e.to_string()),
    }
}

/// An export finished.
pub struct Exported {
    pub path: PathBuf,
    pub result: Result<u64, String>,
}
