//! `biodyn weighting`: a frequency weighting's response (f, |W|, phase) and
//! its definition, what a meter is checked against; with no name, the list.

use super::args::{BandArgs, Format};
use crate::view::format::num;
use crate::view::report::table::{fx, table};
use crate::view::report::{Report, csv, json, render};
use anyhow::Result;
use biodyn::Band;
use biodyn::iso2631::{Quantity, WEIGHTINGS, Weighting, WeightingFilter};
use clap::Args;
use serde_json::{Value, json};

#[derive(Debug, Args)]
#[command(
    after_help = "Examples:\n  biodyn weighting\n  biodyn weighting Wk\n  biodyn weighting Wm --format csv\n  biodyn weighting Wd --from 1 --to 2 --step 0.25 --format json\n  biodyn weighting Wk --digital 1000\n\nWithout --step the rows are the exact one-third-octave centres 10^(n/10) Hz\nof the weighting's band (or of --from..--to). See docs/cli-weighting.md."
)]
pub struct WeightingArgs {
    /// The weighting: Wb, Wc, Wd, We, Wf, Wj, Wk or Wm. Without it, the list.
    #[arg(value_name = "NAME")]
    pub name: Option<String>,
    #[command(flatten)]
    pub band: BandArgs,
    /// Also the digital filter's response at this sampling rate, Hz.
    #[arg(long, value_name = "FS", allow_negative_numbers = true)]
    pub digital: Option<f64>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
}

/// A refused `weighting` command: the line, and what to try.
#[derive(Debug)]
pub struct Refused {
    text: String,
    hint: &'static str,
}

impl std::fmt::Display for Refused {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.text)
    }
}

impl std::error::Error for Refused {}

/// A refusal with the usual hint.
fn refused(text: String) -> anyhow::Error {
    Refused {
        text,
        hint: "e.g. biodyn weighting Wk --from 1 --to 80 --digital 1000 (see biodyn weighting --help)",
    }
    .into()
}

/// What to try after a refused weighting command.
pub fn hint(cause: &(dyn std::error::Error + 'static)) -> Option<String> {
    cause.downcast_ref::<Refused>().map(|r| r.hint.into())
}

/// The frequencies asked for, Hz: a weighting is ~10⁻⁶ outside them, and
/// far past them s² overflows.
const RANGE_HZ: (f64, f64) = (1e-3, 1e5);

/// Highest sampling rate --digital takes, Hz.
const MAX_FS: f64 = 1e7;

pub fn run(a: &WeightingArgs) -> Result<String> {
    let Some(name) = &a.name else {
        if a.band.is_set() || a.digital.is_some() {
            return Err(refused(
                "--from, --to, --step and --digital need a weighting: e.g. biodyn weighting Wk --from 1 --to 10".into(),
            ));
        }
        return render(&List, a.format);
    };
    let w = Weighting::parse(name).ok_or_else(|| Refused {
        text: format!(
            "unknown weighting '{}': choose one of {}",
            super::args::quote(name),
            Weighting::ALL.map(Weighting::name).join(", ")
        ),
        hint: "`biodyn weighting` lists them, each with what it is for",
    })?;
    let freqs = frequencies(w, &a.band)?;
    let digital = match a.digital {
        None => None,
        Some(fs) => Some(filter(w, fs, &freqs)?),
    };
    let rows = freqs
        .iter()
        .map(|&f| {
            let z = w.analog(f);
            Row {
                f,
                w: (z.norm(), z.arg().to_degrees()),
                d: digital.as_ref().map(|d| {
                    let z = d.response(f);
                    (z.norm(), z.arg().to_degrees())
                }),
            }
        })
        .collect();
    render(
        &Sheet {
            w,
            fs: a.digital,
            rows,
        },
        a.format,
    )
}

/// The rows' frequencies: a linear grid with --step, else the exact
/// one-third-octave centres 10^(n/10) Hz of the band (the weighting's, or
/// --from..--to), as `Weighting::centres` takes them.
fn frequencies(w: Weighting, b: &BandArgs) -> Result<Vec<f64>> {
    let (lo, hi) = w.band();
    let (from, to) = (b.from.unwrap_or(lo), b.to.unwrap_or(hi));
    for (flag, v) in [("--from", from), ("--to", to)] {
        if v.is_finite() && v > 0.0 && !(RANGE_HZ.0..=RANGE_HZ.1).contains(&v) {
            return Err(refused(format!(
                "{flag} {}: weightings are printed from {} to {} Hz",
                num(v, 6),
                RANGE_HZ.0,
                RANGE_HZ.1
            )));
        }
    }
    if let Some(step) = b.step {
        return Ok(Band::new(from, to, step)?.freqs());
    }
    // The band's own checks: finite, positive, from below to.
    Band::new(from, to, to - from)?;
    // A centre within 2.5 % of an end counts (the nominal 0.5 Hz is 0.501 Hz,
    // 80 Hz is 79.43 Hz): 0.11 in 10·log10 f.
    let n = |f: f64, up: bool| {
        let x = 10.0 * f.log10();
        if up {
            (x - 0.11).ceil()
        } else {
            (x + 0.11).floor()
        }
    };
    let (n0, n1) = (n(from, true), n(to, false));
    if n1 < n0 {
        return Err(refused(format!(
            "no one-third-octave centre lies between {from} and {to} Hz: widen --from/--to, or give --step for a linear grid"
        )));
    }
    Ok((n0 as i32..=n1 as i32)
        .map(|i| 10f64.powf(f64::from(i) / 10.0))
        .collect())
}

/// The digital filter at `fs`, refused unless every row lies below fs/2.
fn filter(w: Weighting, fs: f64, freqs: &[f64]) -> Result<WeightingFilter> {
    if !(fs.is_finite() && fs > 0.0 && fs <= MAX_FS) {
        return Err(refused(format!(
            "--digital {}: the sampling rate must be a number in (0, {MAX_FS:e}] Hz; e.g. --digital 1000",
            num(fs, 6)
        )));
    }
    let top = freqs.iter().copied().fold(0.0, f64::max);
    if fs / 2.0 <= top {
        return Err(refused(format!(
            "--digital {}: fs/2 = {} Hz is not above the highest frequency asked, {} Hz; give --digital {} or more, or a lower --to",
            num(fs, 6),
            num(fs / 2.0, 6),
            num(top, 6),
            (2.0 * top).floor() + 1.0
        )));
    }
    Ok(w.digital(fs))
}

/// One frequency: the analog |W| and phase (degrees), and the digital's.
struct Row {
    f: f64,
    w: (f64, f64),
    d: Option<(f64, f64)>,
}

/// One weighting: its definition and its response.
struct Sheet {
    w: Weighting,
    fs: Option<f64>,
    rows: Vec<Row>,
}

fn quantity(q: Quantity) -> &'static str {
    match q {
        Quantity::Acceleration => "acceleration",
        Quantity::AngularAcceleration => "angular acceleration",
    }
}

/// ∞ for a stage the table leaves out.
fn hz(v: Option<f64>) -> String {
    v.map_or("∞".into(), |v| format!("{} Hz", num(v, 6)))
}

impl Sheet {
    /// The definition as `key value` lines (the table's header block and,
    /// with `# ` before each, the CSV's comments).
    fn definition(&self) -> Vec<String> {
        let d = self.w.definition();
        let p = d.params;
        let q = |v: f64| num(v, 6);
        let mut v = vec![
            format!("{}: {} ({})", self.w.name(), d.purpose, d.standard),
            format!("quantity   {}, {}", quantity(d.quantity), d.quantity.unit()),
            format!(
                "band       {}–{} Hz",
                num(d.band_hz.0, 6),
                num(d.band_hz.1, 6)
            ),
            format!(
                "band limit f1 {} Hz  Q1 {}  f2 {} Hz  Q2 {}",
                q(p.f1),
                q(p.q1),
                q(p.f2),
                q(p.q2)
            ),
            match (p.f4, p.q4) {
                (Some(_), Some(q4)) => {
                    format!("transition f3 {}  f4 {}  Q4 {}", hz(p.f3), hz(p.f4), q(q4))
                }
                _ => "transition none (f3 = f4 = ∞)".into(),
            },
            match p.step {
                Some(s) => format!(
                    "step       f5 {} Hz  Q5 {}  f6 {} Hz  Q6 {}",
                    q(s.f5),
                    q(s.q5),
                    q(s.f6),
                    q(s.q6)
                ),
                None => "step       none (f5 = f6 = ∞)".into(),
            },
            format!("gain       K {}", q(p.k)),
        ];
        if let Some(fs) = self.fs {
            v.push(format!(
                "digital    fs {} Hz: exact first-order hold, parallel biquads, droop FIR",
                num(fs, 9)
            ));
        }
        v
    }

    fn params_json(&self) -> Value {
        let p = self.w.params();
        let s = p.step;
        json!({
            "f1_hz": p.f1, "q1": p.q1, "f2_hz": p.f2, "q2": p.q2,
            "f3_hz": p.f3, "f4_hz": p.f4, "q4": p.q4,
            "f5_hz": s.map(|s| s.f5), "q5": s.map(|s| s.q5),
            "f6_hz": s.map(|s| s.f6), "q6": s.map(|s| s.q6),
            "k": p.k,
        })
    }
}

impl Report for Sheet {
    fn table(&self) -> String {
        let mut s = self.definition().join("\n");
        s.push_str("\n\n");
        let mut header = vec!["f Hz", "|W|", "phase deg"];
        if self.fs.is_some() {
            header.extend(["|W| digital", "phase digital deg"]);
        }
        let rows: Vec<Vec<String>> = self
            .rows
            .iter()
            .map(|r| {
                let mut row = vec![num(r.f, 4), num(r.w.0, 4), fx(r.w.1, 2)];
                if let Some((m, p)) = r.d {
                    row.extend([num(m, 4), fx(p, 2)]);
                }
                row
            })
            .collect();
        s.push_str(&table(&header, &rows));
        s
    }

    fn csv(&self) -> Option<String> {
        let mut s: String = self
            .definition()
            .iter()
            .map(|l| format!("# {l}\n"))
            .collect();
        let mut header = vec!["f_hz", "mag", "phase_deg"];
        if self.fs.is_some() {
            header.extend(["mag_digital", "phase_digital_deg"]);
        }
        s.push_str(&csv::numbers(
            &header,
            self.rows.iter().map(|r| {
                let mut v = vec![r.f, r.w.0, r.w.1];
                if let Some((m, p)) = r.d {
                    v.extend([m, p]);
                }
                v
            }),
        ));
        Some(s)
    }

    fn json(&self) -> Result<String, serde_json::Error> {
        let d = self.w.definition();
        let rows: Vec<Value> = self
            .rows
            .iter()
            .map(|r| {
                let mut o = json!({"f_hz": r.f, "mag": r.w.0, "phase_deg": r.w.1});
                if let Some((m, p)) = r.d {
                    o["mag_digital"] = json!(m);
                    o["phase_digital_deg"] = json!(p);
                }
                o
            })
            .collect();
        let mut v = json!({
            "name": self.w.name(),
            "purpose": d.purpose,
            "standard": d.standard,
            "quantity": quantity(d.quantity),
            "unit": d.quantity.unit(),
            "band_hz": [d.band_hz.0, d.band_hz.1],
            "params": self.params_json(),
            "rows": rows,
        });
        if let Some(fs) = self.fs {
            v["fs_hz"] = json!(fs);
        }
        json::pretty(&v)
    }
}

/// Every weighting, one line each.
struct List;

impl Report for List {
    /// Left-aligned: the last column is words.
    fn table(&self) -> String {
        let mut s = String::from("name  band        unit    what it is for\n");
        for d in &WEIGHTINGS {
            let band = format!("{}–{} Hz", num(d.band_hz.0, 6), num(d.band_hz.1, 6));
            s.push_str(&format!(
                "{:<4}  {band:<10}  {:<6}  {} ({})\n",
                d.name,
                d.quantity.unit(),
                d.purpose,
                d.standard
            ));
        }
        s.push_str("\n`biodyn weighting NAME` prints one's definition and response.\n");
        s
    }

    fn csv(&self) -> Option<String> {
        let mut s = String::from("name,band_from_hz,band_to_hz,unit,purpose,standard\n");
        for d in &WEIGHTINGS {
            s.push_str(&format!(
                "{},{},{},{},{},{}\n",
                d.name,
                d.band_hz.0,
                d.band_hz.1,
                d.quantity.unit(),
                csv::text_cell(d.purpose),
                csv::text_cell(d.standard)
            ));
        }
        Some(s)
    }

    fn json(&self) -> Result<String, serde_json::Error> {
        let v: Vec<Value> = WEIGHTINGS
            .iter()
            .map(|d| {
                json!({
                    "name": d.name,
                    "purpose": d.purpose,
                    "standard": d.standard,
                    "quantity": quantity(d.quantity),
                    "unit": d.quantity.unit(),
                    "band_hz": [d.band_hz.0, d.band_hz.1],
                })
            })
            .collect();
        json::pretty(&v)
    }
}
