//! `biodyn simulate`: the body under a seat-acceleration record, every
//! output at every sample, streamed to stdout in bounded memory. Also holds
//! the input options `assess` shares (a generated signal or a CSV record).

use super::args::{Format, ModelArgs};
use anyhow::{Context, Result};
use biodyn::time::{Generator, Record, RecordOptions, Signal, Simulator, TimeError, sample_count};
use clap::Args;
use std::io::Write;
use std::path::PathBuf;

/// Defaults of the issue: 10 s at 1000 Hz for a generated signal.
pub const DEFAULT_DURATION_S: f64 = 10.0;
pub const DEFAULT_FS: f64 = 1000.0;

/// Where the seat acceleration comes from.
#[derive(Debug, Clone, Args)]
pub struct InputArgs {
    /// Generated seat acceleration (m/s²): sine:freq=HZ,amp=M_S2[,phase=DEG],
    /// sweep:from=HZ,to=HZ,amp=M_S2, random:rms=M_S2,band=LO-HI,seed=N,
    /// shock:peak=M_S2,width=S,at=S; join parts with + to add them.
    #[arg(
        long,
        value_name = "SPEC",
        conflicts_with = "input",
        required_unless_present = "input",
        allow_hyphen_values = true
    )]
    pub signal: Option<String>,
    /// A CSV record: a header, a time column t_s (else the first column) and
    /// an acceleration column in m/s² (--column, else the first other column).
    #[arg(long, value_name = "FILE")]
    pub input: Option<PathBuf>,
    /// The acceleration column of --input, by header name.
    #[arg(long, value_name = "NAME", requires = "input")]
    pub column: Option<String>,
    /// Length in s of a generated signal (default 10); with --input, read at most this much.
    #[arg(long, value_name = "S", allow_negative_numbers = true)]
    pub duration: Option<f64>,
    /// Sampling rate in Hz (default 1000); with --input, for a file without a t_s column.
    #[arg(long, value_name = "HZ", allow_negative_numbers = true)]
    pub fs: Option<f64>,
}

/// An open input: its rate, start time and samples.
pub struct Input {
    pub fs: f64,
    pub t0: f64,
    /// What was read, for reports: the signal spec or "FILE (column)".
    pub label: String,
    pub samples: Box<dyn Iterator<Item = Result<f64, TimeError>>>,
}

impl InputArgs {
    pub fn open(&self) -> Result<Input> {
        if let Some(spec) = &self.signal {
            let sig = Signal::parse(spec).context("--signal")?;
            let fs = self.fs.unwrap_or(DEFAULT_FS);
            let duration = self.duration.unwrap_or(DEFAULT_DURATION_S);
            let g = Generator::new(&sig, fs, duration)?;
            return Ok(Input {
                fs,
                t0: 0.0,
                label: sig.to_string(),
                samples: Box::new(g.map(Ok)),
            });
        }
        let Some(path) = &self.input else {
            anyhow::bail!("give --signal SPEC or --input FILE");
        };
        let rec = Record::open(
            path,
            &RecordOptions {
                column: self.column.clone(),
                fs: self.fs,
            },
        )
        .map_err(TimeError::from)?;
        let fs = rec.fs();
        let limit = match self.duration {
            Some(d) => sample_count(d, fs)?,
            None => usize::MAX,
        };
        Ok(Input {
            fs,
            t0: rec.t0(),
            label: format!("{} ({})", path.display(), rec.column()),
            samples: Box::new(rec.take(limit).map(|r| r.map_err(TimeError::from))),
        })
    }
}

#[derive(Debug, Args)]
#[command(
    after_help = "Examples:\n  biodyn simulate --signal sine:freq=5,amp=5 --format csv\n  biodyn simulate --signal random:rms=0.8,band=1-20,seed=1+shock:peak=15,width=0.1,at=5 --format csv > run.csv\n  biodyn simulate --input seat.csv --column z_m_s2 --format csv"
)]
pub struct SimulateArgs {
    #[command(flatten)]
    pub model: ModelArgs,
    #[command(flatten)]
    pub input: InputArgs,
    /// Output format (every sample, streamed).
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
}

pub fn run(a: &SimulateArgs) -> Result<()> {
    let preset = a.model.load()?;
    let body = &preset.body;
    let input = a.input.open()?;
    let mut sim = Simulator::new(body, input.fs).map_err(TimeError::from)?;
    let layout = sim.layout();
    let names = biodyn::time::record_columns(body);
    let head = sim.head();
    let table = table_header(body);
    let stdout = std::io::stdout();
    let mut w = std::io::BufWriter::with_capacity(1 << 16, stdout.lock());
    let result = (|| -> Result<()> {
        let mut text = String::with_capacity(1 << 16);
        match a.format {
            Format::Csv => text.push_str(&names.join(",")),
            Format::Json => {
                let head = serde_json::json!({
                    "model": preset.name,
                    "input": input.label,
                    "fs_hz": input.fs,
                    "columns": names,
                });
                let s = serde_json::to_string(&head)?;
                // Open the object, then stream "rows".
                text.push_str(&s[..s.len() - 1]);
                text.push_str(",\"rows\":[");
            }
            Format::Table => text.push_str(&table.0),
        }
        if a.format != Format::Json {
            text.push('\n');
        }
        let streamed = sim.stream(
            input.samples.map(|s| s.map_err(anyhow::Error::from)),
            |k, seat, y| {
                let row = RowRef {
                    t: input.t0 + k as f64 / input.fs,
                    seat,
                    head: y[head],
                    force: y[layout.force()],
                    acc: &y[..layout.segments],
                    defl: &y[layout.segments + 1..],
                };
                match a.format {
                    Format::Csv => row.csv(&mut text),
                    Format::Json => row.json(&mut text, k == 0),
                    Format::Table => row.table(&mut text, &table.1),
                }
                if text.len() > (1 << 16) - 1024 {
                    w.write_all(text.as_bytes())?;
                    text.clear();
                }
                Ok(())
            },
        );
        if let Err(e) = streamed {
            // A bad row in the input: what came before it is written, then
            // the error. A failed write is returned as it is.
            if e.downcast_ref::<std::io::Error>().is_none() {
                w.write_all(text.as_bytes())?;
                w.flush()?;
            }
            return Err(e);
        }
        if a.format == Format::Json {
            text.push_str("]}\n");
        }
        w.write_all(text.as_bytes())?;
        w.flush()?;
        Ok(())
    })();
    super::out::stream_result(result)
}

struct RowRef<'a> {
    t: f64,
    seat: f64,
    head: f64,
    force: f64,
    acc: &'a [f64],
    defl: &'a [f64],
}

impl RowRef<'_> {
    fn values(&self) -> impl Iterator<Item = f64> + '_ {
        [self.t, self.seat, self.head, self.force]
            .into_iter()
            .chain(self.acc.iter().copied())
            .chain(self.defl.iter().copied())
    }

    fn csv(&self, s: &mut String) {
        use std::fmt::Write;
        for (i, v) in self.values().enumerate() {
            if i > 0 {
                s.push(',');
            }
            let _ = write!(s, "{v}");
        }
        s.push('\n');
    }

    fn json(&self, s: &mut String, first: bool) {
        use std::fmt::Write;
        if !first {
            s.push(',');
        }
        s.push_str("\n[");
        for (i, v) in self.values().enumerate() {
            if i > 0 {
                s.push(',');
            }
            if v.is_finite() {
                let _ = write!(s, "{v}");
            } else {
                s.push_str("null");
            }
        }
        s.push(']');
    }

    fn table(&self, s: &mut String, widths: &[usize]) {
        use std::fmt::Write;
        let n_acc = self.acc.len();
        for (i, (v, w)) in self.values().zip(widths).enumerate() {
            if i > 0 {
                s.push_str("  ");
            }
            // Force to 0.01 N, deflections in mm, the rest to 1e-4.
            let _ = match i {
                3 => write!(s, "{v:>w$.2}"),
                i if i >= 4 + n_acc => write!(s, "{:>w$.4}", v * 1000.0),
                _ => write!(s, "{v:>w$.4}"),
            };
        }
        s.push('\n');
    }
}

/// Column labels for eyes and their widths.
fn table_header(body: &biodyn::Body) -> (String, Vec<usize>) {
    use std::fmt::Write;
    let mut labels: Vec<String> = ["t s", "seat m/s²", "head m/s²", "force N"]
        .map(String::from)
        .to_vec();
    labels.extend(body.segments.iter().map(|s| format!("{} m/s²", s.name)));
    labels.extend(body.links.iter().map(|l| format!("{} mm", l.name)));
    let widths: Vec<usize> = labels.iter().map(|l| l.chars().count().max(10)).collect();
    let mut s = String::new();
    for (i, (l, w)) in labels.iter().zip(&widths).enumerate() {
        if i > 0 {
            s.push_str("  ");
        }
        let pad = w - l.chars().count();
        let _ = write!(s, "{}{l}", " ".repeat(pad));
    }
    (s, widths)
}
