//! `biodyn train`: headless training of one case or all six, reported beside
//! the paper's Table 5. The setting flags come from `settings_flags`.

use super::args::{BandArgs, Format, ModelArgs, table_or_json};
use super::progress::Progress;
use super::settings_flags::SettingFlags;
use crate::view::format::num;
use crate::view::report::{Report, json, render};
use anyhow::{Context, bail};
use biodyn::ann::{
    self, Case, EpochStats, Flow, Outcome, Settings, TRAIN_GRID, Trainer, train, worst_holdout,
};
use biodyn::{Body, Param};
use clap::builder::PossibleValue;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// `--case`: one of the paper's six networks, or all of them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CaseArg {
    One(Case),
    All,
}

impl clap::ValueEnum for CaseArg {
    fn value_variants<'a>() -> &'a [Self] {
        const ALL: [CaseArg; Case::ALL.len() + 1] = {
            let mut out = [CaseArg::All; Case::ALL.len() + 1];
            let mut i = 0;
            while i < Case::ALL.len() {
                out[i] = CaseArg::One(Case::ALL[i]);
                i += 1;
            }
            out
        };
        &ALL
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        Some(match self {
            CaseArg::One(c) => PossibleValue::new(c.key()),
            CaseArg::All => PossibleValue::new("all"),
        })
    }
}

/// `--trainer`: the values come from `Trainer::ALL`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TrainerArg(pub Trainer);

impl clap::ValueEnum for TrainerArg {
    fn value_variants<'a>() -> &'a [Self] {
        const ALL: [TrainerArg; Trainer::ALL.len()] = {
            let mut out = [TrainerArg(Trainer::ALL[0]); Trainer::ALL.len()];
            let mut i = 0;
            while i < out.len() {
                out[i] = TrainerArg(Trainer::ALL[i]);
                i += 1;
            }
            out
        };
        &ALL
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        Some(match self.0 {
            Trainer::Backprop => PossibleValue::new("backprop").alias("bp"),
            Trainer::Lm => PossibleValue::new("lm").alias("levenberg-marquardt"),
        })
    }
}

#[derive(clap::Args, Debug, Clone)]
#[command(
    after_help = "Examples:\n  biodyn train --case all --trainer backprop\n  biodyn train --case k4-dpmi --epochs 300 --save k4-dpmi.json\n  biodyn train --case mass-stht --from 0.5 --to 20 --step 0.25 --format json\n  biodyn train --case mass-apms --preset boileau-rakheja-1998 --save boileau-apms.json\n  biodyn train --case k4-stht --body-mass 85 --set c4=2500\n\nWithout --preset, --body-mass or --set the networks train on the paper's body\n(mass cases 65/75/85 kg, k4 cases at 75 kg). With any of them they train on that\nmodel: mass cases take every segment mass and f as inputs and train at its body\nmass x 65/75, 75/75, 85/75; k4 cases keep its masses and vary its 4th link's k\nat x 0.6, 1, 1.4. The saved file then holds the model (network file version 2)."
)]
pub struct TrainArgs {
    /// Which network to train (all: the six, one after another).
    #[arg(long, value_enum, ignore_case = true)]
    pub case: CaseArg,
    /// backprop (the paper's) or lm (Levenberg–Marquardt, generalises).
    #[arg(long, value_enum, ignore_case = true, default_value = "lm")]
    pub trainer: TrainerArg,
    /// Save the trained network here (with --case all: the case name is added).
    #[arg(long)]
    pub save: Option<PathBuf>,
    /// Replace a read-only --save file (its mode is kept).
    #[arg(long)]
    pub force: bool,
    #[arg(long, default_value = "table", value_parser = table_or_json())]
    pub format: Format,
    /// The training grid (default 0.5 to 20 Hz at 0.5 Hz, the paper's).
    #[command(flatten)]
    pub band: BandArgs,
    #[command(flatten)]
    pub settings: SettingFlags,
    /// The model to train on (default: the paper's body).
    #[command(flatten)]
    pub model: ModelArgs,
}

/// True when a model flag was given: then training uses that model.
fn model_given(m: &ModelArgs) -> bool {
    m.preset.is_some() || m.body_mass.is_some() || !m.set.is_empty()
}

/// Settings for one case on `base` (None: the paper's body) from the
/// defaults of the trainer and the flags.
pub fn settings_for(
    case: Case,
    trainer: Trainer,
    a: &TrainArgs,
    base: Option<&Body>,
) -> anyhow::Result<Settings> {
    let mut s = Settings::for_trainer_on(case, trainer, base.cloned())
        .with_context(|| format!("case {case} on this model"))?;
    a.settings.apply(&mut s)?;
    if a.band.is_set() {
        s.grid = a.band.band(TRAIN_GRID)?;
    }
    s.validate(case)
        .with_context(|| format!("settings for case {case}"))?;
    Ok(s)
}

/// "--lr and --momentum", "--a, --b and --c".
fn flag_list(flags: &[&str]) -> String {
    let f: Vec<String> = flags.iter().map(|f| format!("--{f}")).collect();
    match f.split_last() {
        Some((last, rest)) if !rest.is_empty() => format!("{} and {last}", rest.join(", ")),
        _ => f.concat(),
    }
}

pub fn run(a: &TrainArgs) -> anyhow::Result<String> {
    let trainer = a.trainer.0;
    let cases: Vec<Case> = match a.case {
        CaseArg::All => Case::ALL.to_vec(),
        CaseArg::One(c) => vec![c],
    };
    let ignored = a.settings.ignored_by(trainer);
    if !ignored.is_empty() {
        let users: Vec<&str> = Trainer::ALL
            .iter()
            .filter(|t| **t != trainer)
            .map(|t| t.key())
            .collect();
        let (verb, them) = if ignored.len() == 1 {
            ("applies", "it")
        } else {
            ("apply", "them")
        };
        super::out::note!(
            "note: {} {verb} to --trainer {} only; {} ignores {them}",
            flag_list(&ignored),
            users.join(" or "),
            trainer.label()
        );
    }
    let preset = model_given(&a.model).then(|| a.model.load()).transpose()?;
    let base = preset.as_ref().map(|p| &p.body);
    // Validate every case before the first one trains.
    let settings = cases
        .iter()
        .map(|&c| settings_for(c, trainer, a, base))
        .collect::<anyhow::Result<Vec<_>>>()?;
    if let Some(p) = &preset {
        super::out::note!(
            "note: training on {} ({} segments, {} links, body mass {} kg), not the paper's body",
            p.name,
            p.body.n(),
            p.body.links.len(),
            num(p.body.get(Param::BodyMass), 5)
        );
    }
    // Every save is checked before the first case trains: not onto the
    // preset, not read-only, a folder that takes it.
    let guard = biodyn::io::Guard::reading(a.model.input_file(), a.force);
    let targets: Vec<Option<PathBuf>> = cases
        .iter()
        .map(|&case| {
            a.save.as_ref().map(|path| match cases.len() {
                1 => path.clone(),
                _ => with_case(path, case),
            })
        })
        .collect();
    for path in targets.iter().flatten() {
        guard.check(path)?;
    }
    let mut outcomes = Vec::new();
    let mut unsaved = Vec::new();
    for ((&case, s), target) in cases.iter().zip(&settings).zip(&targets) {
        let out = train_one(case, s)?;
        if out.stop.is_diverged() {
            super::out::note!("warning: {case} {}", out.stop);
        }
        if let Some(path) = target {
            if out.stop.is_diverged() {
                super::out::note!(
                    "warning: {case} diverged; not saving it to {}",
                    path.display()
                );
            } else if let Err(e) = ann::save_network_guarded(path, &out.net, &guard) {
                // The other cases still train and the table is printed.
                super::out::note!("warning: {case} not saved: {e}");
                unsaved.push(path.display().to_string());
            } else {
                super::out::status!("saved {case} to {}", path.display());
            }
        }
        outcomes.push(out);
    }
    if outcomes.is_empty() {
        bail!("no case was trained");
    }
    let report = render(&Trained(outcomes), a.format)?;
    if !unsaved.is_empty() {
        super::emit(&report)?;
        bail!(
            "the results are printed above; not written: {} (the warnings above say why)",
            unsaved.join(", ")
        );
    }
    Ok(report)
}

/// Finished runs beside the paper's Table 5.
struct Trained(Vec<Outcome>);

impl Report for Trained {
    fn table(&self) -> String {
        table(&self.0)
    }

    fn json(&self) -> Result<String, serde_json::Error> {
        let reports: Vec<_> = self.0.iter().map(Outcome::report).collect();
        json::pretty(&reports)
    }
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

/// One case, with its progress line: epochs of every member on one bar,
/// the RMS and MPRE of the epoch, the time left for the case.
fn train_one(case: Case, s: &Settings) -> anyhow::Result<Outcome> {
    let epochs = s.epochs;
    let first = format!("epoch 0/{epochs} member 1/{}", s.ensemble);
    let mut bar = Progress::bar(case.key(), epochs * s.ensemble as u64, first);
    let mut observe = |st: &EpochStats| {
        let done = st.member as u64 * epochs + st.epoch;
        bar.update(done, || {
            format!(
                "epoch {}/{epochs} member {}/{} rms {:.2e} mpre {:.2}%",
                st.epoch,
                st.member + 1,
                s.ensemble,
                st.rms,
                st.mpre_pct
            )
        });
        Flow::Continue
    };
    let out = train(case, s, &mut observe).with_context(|| format!("training {case}"));
    drop(bar);
    out
}

fn opt(v: Option<f64>, prec: usize) -> String {
    match v {
        Some(x) => format!("{x:.prec$}"),
        None => "—".into(),
    }
}

fn table(outs: &[Outcome]) -> String {
    let mut w = String::new();
    let _ = writeln!(
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
    );
    for o in outs {
        let r = o.report();
        let _ = writeln!(
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
            opt(worst_holdout(&r.holdout, false), 3),
            opt(worst_holdout(&r.holdout, true), 3),
        );
    }
    let _ = writeln!(w);
    let _ = writeln!(
        w,
        "hold-out (0.5–20 Hz at 0.1 Hz): max / mean % error against the analytic response"
    );
    for o in outs {
        let cells: Vec<String> = o
            .holdout
            .iter()
            .map(|h| {
                format!(
                    "{}{} {:.3}/{:.3}",
                    num(h.value, 6),
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
        let _ = writeln!(w, "  {:<10} {text}", o.net.case.key());
    }
    if let Some(b) = outs.iter().find_map(|o| o.net.base()) {
        let _ = writeln!(
            w,
            "trained on the model given: {} segments, {} links, body mass {} kg (not the paper's body)",
            b.n(),
            b.links.len(),
            num(b.get(Param::BodyMass), 5)
        );
    }
    if outs.iter().any(|o| o.stop.is_diverged()) {
        let _ = writeln!(
            w,
            "(—: the run diverged; it has no meaningful error figures)"
        );
    }
    w
}
