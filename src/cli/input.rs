//! The seat acceleration `simulate` and `assess` read: a generated signal
//! (vertical) or a CSV record on one to three axes, with the other
//! measuring points' channels where it has them, and how a report names it
//! (the file, each axis's column and unit).

pub use crate::view::report::input::Source;
use crate::view::report::input::axes_words;
use anyhow::{Context, Result, bail};
use biodyn::time::{
    Axis, Frame, Generator, PerAxis, PerPoint, Record, RecordError, RecordOptions, Row, Signal,
    TimeError, Unit, parse_channels, sample_count,
};
use clap::Args;
use std::path::PathBuf;

/// Defaults of the issue: 10 s at 1000 Hz for a generated signal.
pub const DEFAULT_DURATION_S: f64 = 10.0;
pub const DEFAULT_FS: f64 = 1000.0;

/// Where the seat acceleration comes from: one of --signal and --input,
/// and a missing one names both.
#[derive(Debug, Clone, Args)]
#[command(group(clap::ArgGroup::new("source").required(true).args(["signal", "input"])))]
pub struct InputArgs {
    /// Generated vertical seat acceleration (m/s²): sine:freq=HZ,amp=M_S2[,phase=DEG],
    /// sweep:from=HZ,to=HZ,amp=M_S2, random:rms=M_S2,band=LO-HI,seed=N,
    /// shock:peak=M_S2,width=S,at=S; join parts with + to add them.
    #[arg(long, value_name = "SPEC", allow_hyphen_values = true)]
    pub signal: Option<String>,
    /// A CSV record: a header, a time column (t_s, t, time or time_s) and one to
    /// three acceleration columns named by axis (ax, acc_z, z_m_s2, az_g …); other
    /// points beside them: backrest_x, feet_z, rx (rad/s²) …
    #[arg(long, value_name = "FILE")]
    pub input: Option<PathBuf>,
    /// Which column of --input is each axis (any subset); e.g. x=ax,y=ay,z=az; other
    /// points too: backrest_x=COL, feet_z=COL, rx=COL … (then only the columns named are read).
    #[arg(
        long,
        value_name = "x=COL,y=COL,z=COL",
        requires = "input",
        conflicts_with = "column"
    )]
    pub axes: Option<String>,
    /// The z (vertical) column of --input: the same as --axes z=NAME.
    #[arg(long, value_name = "NAME", requires = "input")]
    pub column: Option<String>,
    /// Unit of --input's columns whose name gives none (`az_g`, `Acc Z [g]` give
    /// theirs): m/s2, g or mm/s2; without it m/s2 is assumed, and the output says so.
    #[arg(long, value_name = "UNIT", requires = "input")]
    pub unit: Option<String>,
    /// Subtract each channel's mean over the whole --input before anything is
    /// judged: the 1 g of a DC-coupled accelerometer, or an offset (a mean whose
    /// start-up step could move a_w or VDV by over 5 % is refused without it).
    #[arg(long, requires = "input")]
    pub remove_mean: bool,
    /// Length in s of a generated signal (default 10); with --input, read at most this much.
    #[arg(long, value_name = "S", allow_negative_numbers = true)]
    pub duration: Option<f64>,
    /// Sampling rate in Hz (default 1000); with --input, for a file without a time column.
    #[arg(long, value_name = "HZ", allow_negative_numbers = true)]
    pub fs: Option<f64>,
}

type Rows = Box<dyn Iterator<Item = Result<Row, TimeError>>>;
type Frames = Box<dyn Iterator<Item = Result<Frame, TimeError>>>;

/// The samples of an input: the seat's rows alone, or, for a record with
/// other points, each row with those points' channels beside it.
pub enum Samples {
    Seat(Rows),
    Frames(Frames),
}

/// An open input: its rate, start time, axes and rows.
pub struct Input {
    pub fs: f64,
    pub t0: f64,
    pub source: Source,
    /// The axes the input has (a generated signal: z).
    pub axes: PerAxis<()>,
    /// The other points' channels it has (none: `rows` is `Samples::Seat`).
    pub points: PerPoint<()>,
    pub rows: Samples,
    /// How many samples `rows` holds, when that is known before reading
    /// them (a generated signal; a record's length is not: its progress
    /// counts the samples read).
    pub total: Option<u64>,
}

impl InputArgs {
    /// The record options the flags give.
    pub fn record_options(&self) -> Result<RecordOptions> {
        let mut o = RecordOptions {
            fs: self.fs,
            remove_mean: self.remove_mean,
            ..RecordOptions::default()
        };
        if let Some(spec) = &self.axes {
            (o.axes, o.points) =
                parse_channels(spec).map_err(|e| anyhow::Error::new(TimeError::from(e)))?;
        }
        if let Some(c) = &self.column {
            o.axes.set(Axis::Z, c.clone());
        }
        if let Some(u) = &self.unit {
            o.unit = Some(Unit::parse(u).with_context(|| {
                format!(
                    "--unit '{}': give m/s2, g (9.80665 m/s²) or mm/s2",
                    biodyn::io::short_quote(u)
                )
            })?);
        }
        Ok(o)
    }

    pub fn open(&self) -> Result<Input> {
        if let Some(spec) = &self.signal {
            let sig = Signal::parse(spec).context("--signal")?;
            let fs = self.fs.unwrap_or(DEFAULT_FS);
            let duration = self.duration.unwrap_or(DEFAULT_DURATION_S);
            let g = Generator::new(&sig, fs, duration)?;
            let total = sample_count(duration, fs).ok().map(|n| n as u64);
            let mut z = PerAxis::default();
            z.set(Axis::Z, ());
            return Ok(Input {
                fs,
                t0: 0.0,
                source: Source::Signal(sig.to_string()),
                axes: z,
                points: PerPoint::default(),
                rows: Samples::Seat(Box::new(g.map(|a| Ok([0.0, 0.0, a])))),
                total,
            });
        }
        let Some(path) = &self.input else {
            bail!("give --signal SPEC or --input FILE");
        };
        let rec = Record::open(path, &self.record_options()?).map_err(TimeError::from)?;
        let fs = rec.fs();
        let limit = match self.duration {
            Some(d) => sample_count(d, fs)?,
            None => usize::MAX,
        };
        let time = Some(rec.time_column().to_string()).filter(|t| !t.is_empty());
        let (axes, points) = (rec.axes(), rec.points());
        let (columns, t0) = (Box::new(rec.columns().clone()), rec.t0());
        let rows = if points.is_empty() {
            Samples::Seat(Box::new(
                rec.take(limit).map(|r| r.map_err(TimeError::from)),
            ))
        } else {
            Samples::Frames(Box::new(
                rec.frames().take(limit).map(|r| r.map_err(TimeError::from)),
            ))
        };
        Ok(Input {
            fs,
            t0,
            source: Source::Record {
                path: path.clone(),
                time,
                columns,
            },
            axes,
            points,
            rows,
            total: None,
        })
    }
}

impl Input {
    /// Refuses a record without a z column: the body is driven by z.
    pub fn require_vertical(&self) -> Result<()> {
        if let Source::Record { path, columns, .. } = &self.source
            && !self.axes.has(Axis::Z)
        {
            return Err(TimeError::from(RecordError::NoVertical {
                path: path.clone(),
                axes: axes_words(columns),
            })
            .into());
        }
        Ok(())
    }

    /// The z axis alone, the body's input; refused without one.
    pub fn vertical(self) -> Result<Box<dyn Iterator<Item = Result<f64, TimeError>>>> {
        self.require_vertical()?;
        let z = Axis::Z.index();
        Ok(match self.rows {
            Samples::Seat(rows) => Box::new(rows.map(move |r| r.map(|row| row[z]))),
            Samples::Frames(f) => Box::new(f.map(move |r| r.map(|(row, _)| row[z]))),
        })
    }
}
