//! `biodyn train`: headless training of one case or all six, reported beside
//! the paper's Table 5.

use anyhow::{Context, bail};
use biodyn::ann::metrics::worst;
use biodyn::ann::{Case, EpochStats, Flow, Outcome, Settings, Trainer, netfile, train};
use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum TrainFormat {
    Table,
    Json,
}

#[derive(clap::Args, Debug, Clone)]
pub struct TrainArgs {
    /// mass-stht, mass-dpmi, mass-apms, k4-stht, k4-dpmi, k4-apms, or all.
    #[arg(long)]
    pub case: String,
    /// backprop (the paper's) or lm (Levenberg–Marquardt, generalises).
    #[arg(long, default_value = "lm")]
    pub trainer: String,
    /// Epoch limit (LM: iterations per ensemble member); default: the paper's
    /// epoch count for backprop, 150 for LM.
    #[arg(long)]
    pub epochs: Option<u64>,
    /// Seed of the weight initialisation and the pattern order.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Back-propagation learning rate (paper: 1).
    #[arg(long)]
    pub lr: Option<f64>,
    /// Back-propagation momentum in [0, 1) (paper: 0.9).
    #[arg(long)]
    pub momentum: Option<f64>,
    /// Save the trained network here (with --case all: the case name is added).
    #[arg(long)]
    pub save: Option<PathBuf>,
    #[arg(long, value_enum, default_value_t = TrainFormat::Table)]
    pub format: TrainFormat,
    /// Architecture, e.g. 5-6-4-1 (default: the paper's for the case).
    #[arg(long)]
    pub layers: Option<String>,
    /// Training values: body masses in kg or k4 in N/m, comma-separated.
    #[arg(long, value_delimiter = ',')]
    pub train_values: Option<Vec<f64>>,
    /// Training grid in Hz as FROM:TO:STEP (default 0.5:20:0.5).
    #[arg(long, value_name = "FROM:TO:STEP")]
    pub grid: Option<String>,
    /// L2 weight decay λ (LM).
    #[arg(long)]
    pub weight_decay: Option<f64>,
    /// Networks averaged in the ensemble.
    #[arg(long)]
    pub ensemble: Option<usize>,
    /// Combine ensemble members by their median instead of their mean (true/false).
    #[arg(long)]
    pub median: Option<bool>,
    /// Train on ln|response| (true/false).
    #[arg(long)]
    pub log_target: Option<bool>,
    /// Feed ln f instead of f (true/false).
    #[arg(long)]
    pub log_freq: Option<bool>,
    /// Feed ln of m1..m4 or k4 (true/false).
    #[arg(long)]
    pub log_param: Option<bool>,
    /// Linear output neuron (true/false).
    #[arg(long)]
    pub linear_output: Option<bool>,
    /// Initial weights uniform in ±this.
    #[arg(long)]
    pub init_range: Option<f64>,
    /// Wall-time limit per case in seconds.
    #[arg(long)]
    pub time_limit: Option<f64>,
    /// Stop at this RMS (scaled).
    #[arg(long)]
    pub rms_target: Option<f64>,
    /// Stop at this MPRE in %.
    #[arg(long)]
    pub mpre_target: Option<f64>,
}

/// Settings for one case from the defaults of the trainer and the flags.
pub fn settings_for(case: Case, trainer: Trainer, a: &TrainArgs) -> anyhow::Result<Settings> {
    let mut s = Settings::for_trainer(case, trainer);
    s.seed = a.seed;
    if let Some(e) = a.epochs {
        s.epochs = e;
    }
    if let Some(v) = a.lr {
        s.learning_rate = v;
    }
    if let Some(v) = a.momentum {
        s.momentum = v;
    }
    if let Some(l) = &a.layers {
        s.layers = l
            .split(['-', ','])
            .map(|n| n.trim().parse::<usize>())
            .collect::<Result<_, _>>()
            .with_context(|| format!("--layers '{l}': give neuron counts like 5-6-4-1"))?;
    }
    if let Some(v) = &a.train_values {
        s.train_values = v.clone();
    }
    if let Some(g) = &a.grid {
        let parts: Vec<f64> = g
            .split(':')
            .map(|x| x.trim().parse::<f64>())
            .collect::<Result<_, _>>()
            .with_context(|| format!("--grid '{g}': write FROM:TO:STEP in Hz, e.g. 0.5:20:0.25"))?;
        let [from, to, step] = parts[..] else {
            bail!("--grid '{g}': write FROM:TO:STEP in Hz, e.g. 0.5:20:0.25");
        };
        s.grid = biodyn::Band::new(from, to, step).with_context(|| format!("--grid '{g}'"))?;
    }
    if let Some(v) = a.weight_decay {
        s.weight_decay = v;
    }
    if let Some(v) = a.ensemble {
        s.ensemble = v;
    }
    if let Some(v) = a.median {
        s.combine = if v {
            biodyn::ann::Combine::Median
        } else {
            biodyn::ann::Combine::Mean
        };
    }
    if let Some(v) = a.log_target {
        s.log_target = v;
    }
    if let Some(v) = a.log_freq {
        s.log_freq = v;
    }
    if let Some(v) = a.log_param {
        s.log_param = v;
    }
    if let Some(v) = a.linear_output {
        s.linear_output = v;
    }
    if let Some(v) = a.init_range {
        s.init_range = v;
    }
    s.time_limit_s = a.time_limit;
    s.rms_target = a.rms_target;
    s.mpre_target_pct = a.mpre_target;
    s.validate(case)
        .with_context(|| format!("settings for case {case}"))?;
    Ok(s)
}

pub fn run(a: &TrainArgs) -> anyhow::Result<()> {
    let trainer = Trainer::parse(&a.trainer)?;
    let cases: Vec<Case> = if a.case.trim().eq_ignore_ascii_case("all") {
        Case::ALL.to_vec()
    } else {
        vec![Case::parse(&a.case)?]
    };
    if trainer == Trainer::Lm && (a.lr.is_some() || a.momentum.is_some()) {
        eprintln!("note: --lr and --momentum apply to --trainer backprop only; LM ignores them");
    }
    // Validate every case before the first one trains.
    let settings = cases
        .iter()
        .map(|&c| settings_for(c, trainer, a))
        .collect::<anyhow::Result<Vec<_>>>()?;
    let bar = std::io::stderr().is_terminal();
    let mut outcomes = Vec::new();
    for (&case, s) in cases.iter().zip(&settings) {
        let out = train_one(case, s, bar)?;
        if out.stop.is_diverged() {
            eprintln!("warning: {case} {}", out.stop);
        }
        if let Some(path) = &a.save {
            let path = if cases.len() > 1 {
                with_case(path, case)
            } else {
                path.clone()
            };
            if out.stop.is_diverged() {
                eprintln!(
                    "warning: {case} diverged; not saving it to {}",
                    path.display()
                );
            } else {
                netfile::save(&path, &out.net)?;
                eprintln!("saved {case} to {}", path.display());
            }
        }
        outcomes.push(out);
    }
    let mut stdout = std::io::stdout().lock();
    match a.format {
        TrainFormat::Json => {
            let reports: Vec<_> = outcomes.iter().map(Outcome::report).collect();
            serde_json::to_writer_pretty(&mut stdout, &reports)?;
            writeln!(stdout)?;
        }
        TrainFormat::Table => write_table(&mut stdout, &outcomes)?,
    }
    Ok(())
}

/// `dir/name.json` → `dir/name-mass-stht.json`.
fn with_case(path: &Path, case: Case) -> PathBuf {
    let stem = path
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "network".into());
    let ext = path
        .extension()
        .map(|e| format!(".{}", e.to_string_lossy()))
        .unwrap_or_default();
    path.with_file_name(format!("{stem}-{case}{ext}"))
}

fn train_one(case: Case, s: &Settings, bar: bool) -> anyhow::Result<Outcome> {
    let mut last = Instant::now();
    let start = last;
    let mut observe = |st: &EpochStats| {
        if bar && last.elapsed() >= Duration::from_millis(100) {
            last = Instant::now();
            let frac = st.epoch as f64 / s.epochs as f64;
            let filled = (frac * 30.0).round() as usize;
            eprint!(
                "\r{case:<9} [{}{}] member {}/{} epoch {:>7}/{} rms {:.5} mpre {:>7.3}% {:.1}s ",
                "#".repeat(filled.min(30)),
                " ".repeat(30 - filled.min(30)),
                st.member + 1,
                s.ensemble,
                st.epoch,
                s.epochs,
                st.rms,
                st.mpre_pct,
                start.elapsed().as_secs_f64()
            );
        }
        Flow::Continue
    };
    let out = train(case, s, &mut observe).with_context(|| format!("training {case}"))?;
    if bar {
        eprint!("\r{}\r", " ".repeat(110));
    }
    Ok(out)
}

fn opt(v: Option<f64>, prec: usize) -> String {
    match v {
        Some(x) => format!("{x:.prec$}"),
        None => "—".into(),
    }
}

fn write_table(w: &mut impl Write, outs: &[Outcome]) -> anyhow::Result<()> {
    writeln!(
        w,
        "{:<10} {:<8} {:>8} {:>9} {:>8} {:>7} {:<12} {:>7} | {:>8} {:>7} {:>7} | {:>9} {:>9}",
        "case",
        "trainer",
        "epochs",
        "RMS",
        "MPRE %",
        "right%",
        "stop",
        "time s",
        "paper ep",
        "MPRE %",
        "RMS",
        "interp %",
        "extrap %"
    )?;
    for o in outs {
        let r = o.report();
        writeln!(
            w,
            "{:<10} {:<8} {:>8} {:>9} {:>8} {:>7} {:<12} {:>7.2} | {:>8} {:>7.3} {:>7.4} | {:>9} {:>9}",
            r.case,
            r.trainer,
            r.epochs,
            opt(r.rms, 6),
            opt(r.mpre_pct, 3),
            opt(r.share_right.map(|x| 100.0 * x), 1),
            r.stop_reason,
            r.train_seconds,
            r.paper_epochs,
            r.paper_mpre_pct,
            r.paper_rms,
            opt(worst(&r.holdout, false), 3),
            opt(worst(&r.holdout, true), 3),
        )?;
    }
    writeln!(w)?;
    writeln!(
        w,
        "hold-out (0.5–20 Hz at 0.1 Hz): max / mean % error against the analytic response"
    )?;
    for o in outs {
        let cells: Vec<String> = o
            .holdout
            .iter()
            .map(|h| {
                format!(
                    "{}{} {:.3}/{:.3}",
                    h.value,
                    if h.extrapolation { "(ex)" } else { "(in)" },
                    h.max_err_pct,
                    h.mean_err_pct
                )
            })
            .collect();
        let text = if cells.is_empty() {
            format!("no figures: {}", o.stop)
        } else {
            cells.join("  ")
        };
        writeln!(w, "  {:<10} {text}", o.net.case.key())?;
    }
    if outs.iter().any(|o| o.stop.is_diverged()) {
        writeln!(
            w,
            "(—: the run diverged; it has no meaningful error figures)"
        )?;
    }
    if outs.is_empty() {
        bail!("no case was trained");
    }
    Ok(())
}
