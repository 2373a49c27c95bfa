//! `biodyn simulate`: the body under a seat-acceleration record, every
//! output at every sample, streamed to stdout in bounded memory. The body
//! is vertical: it is driven by the record's z axis.

use super::args::{Format, ModelArgs};
pub use super::input::InputArgs;
use super::input::Source;
use super::progress::Counted;
use anyhow::Result;
use biodyn::time::{Simulator, TimeError};
use clap::Args;
use std::io::{IsTerminal, Write};

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
    let (fs, t0) = (input.fs, input.t0);
    let source = input.source.clone();
    let total = input.total;
    let samples = input.vertical()?;
    // Rows streamed to a terminal are their own progress: a line beside
    // them would be torn by them. Into a file or a pipe, the line shows.
    let samples: Box<dyn Iterator<Item = _>> = if std::io::stdout().is_terminal() {
        samples
    } else {
        Box::new(Counted::new(samples, "simulate", total))
    };
    let mut sim = Simulator::new(body, fs).map_err(TimeError::from)?;
    let layout = sim.layout();
    let names = biodyn::time::record_columns(body);
    let head = sim.head();
    let table = table_header(body);
    let stdout = std::io::stdout();
    let mut w = std::io::BufWriter::with_capacity(1 << 16, stdout.lock());
    let result = (|| -> Result<()> {
        let mut text = String::with_capacity(1 << 16);
        match a.format {
            Format::Csv => {
                // A record's columns and units, on a comment line before the header.
                if let Some(c) = source.csv_comment() {
                    text.push_str(&c);
                }
                text.push_str(&names.join(","))
            }
            Format::Json => {
                let head = serde_json::json!({
                    "model": preset.name,
                    "input": source.json(fs),
                    "fs_hz": fs,
                    "columns": names,
                });
                let s = serde_json::to_string(&head)?;
                // Open the object, then stream "rows".
                text.push_str(&s[..s.len() - 1]);
                text.push_str(",\"rows\":[");
            }
            Format::Table => {
                if let Source::Record { .. } = source {
                    text.push_str(&format!("input: {}\n", source.line()));
                }
                text.push_str(&table.0)
            }
        }
        if a.format != Format::Json {
            text.push('\n');
        }
        let streamed = sim.stream(
            samples.map(|s| s.map_err(anyhow::Error::from)),
            |k, seat, y| {
                let row = RowRef {
                    t: t0 + k as f64 / fs,
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
    // Under a seat the input is the floor (record_columns says the same).
    let first = if body.has_seat() {
        ["t s", "floor m/s²", "head m/s²", "floor force N"]
    } else {
        ["t s", "seat m/s²", "head m/s²", "force N"]
    };
    let mut labels: Vec<String> = first.map(String::from).to_vec();
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
