//! One training run from settings to report: build the data from the
//! analytic engine, scale it, train each ensemble member with the chosen
//! trainer, then measure the result on the training set and the hold-outs.

use super::algorithm::{Algorithm, Member};
use super::backprop::Backprop;
use super::case::Case;
use super::dataset::Dataset;
use super::encoded::Encoded;
use super::error::AnnError;
use super::lm::Lm;
use super::metrics::{self, EpochStats, HoldoutResult};
use super::network::Network;
use super::settings::{Settings, Trainer};
use super::stop::{Flow, Halt, StopReason};
use super::trained::TrainedNet;
use crate::band::Band;
use crate::clock::Clock;
use crate::rng::Rng;
use serde::Serialize;
use std::time::Duration;

/// The report of a finished run. Error figures are `None` after divergence:
/// a diverged run has no meaningful number to show.
#[derive(Debug, Clone)]
pub struct Outcome {
    pub net: TrainedNet,
    pub stop: StopReason,
    /// Epochs (LM: iterations) of each ensemble member.
    pub member_epochs: Vec<u64>,
    pub rms: Option<f64>,
    pub mpre_pct: Option<f64>,
    pub share_right: Option<f64>,
    pub train_seconds: f64,
    pub holdout: Vec<HoldoutResult>,
}

/// The flat report the CLI prints as JSON.
#[derive(Debug, Clone, Serialize)]
pub struct Report {
    pub case: &'static str,
    pub trainer: &'static str,
    pub layers: Vec<usize>,
    pub epochs: u64,
    pub ensemble: usize,
    pub rms: Option<f64>,
    pub mpre_pct: Option<f64>,
    pub share_right: Option<f64>,
    pub stop_reason: &'static str,
    pub stop_detail: String,
    pub train_seconds: f64,
    pub paper_epochs: u64,
    pub paper_mpre_pct: f64,
    pub paper_rms: f64,
    pub holdout: Vec<HoldoutResult>,
    /// The base body's segment count and body mass, when the net was
    /// trained on one (absent: the paper's body).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub base_segments: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub base_body_mass_kg: Option<f64>,
}

impl Outcome {
    /// Epochs of the longest-running member.
    pub fn epochs(&self) -> u64 {
        self.member_epochs.iter().copied().max().unwrap_or(0)
    }

    pub fn report(&self) -> Report {
        let case = self.net.case;
        Report {
            case: case.key(),
            trainer: self.net.settings.trainer.key(),
            layers: self.net.settings.layers.clone(),
            epochs: self.epochs(),
            ensemble: self.net.members.len(),
            rms: self.rms,
            mpre_pct: self.mpre_pct,
            share_right: self.share_right,
            stop_reason: self.stop.key(),
            stop_detail: self.stop.to_string(),
            train_seconds: self.train_seconds,
            paper_epochs: case.paper().epochs,
            paper_mpre_pct: case.paper().mpre_pct,
            paper_rms: case.paper().rms,
            holdout: self.holdout.clone(),
            base_segments: self.net.base().map(|b| b.n()),
            base_body_mass_kg: self
                .net
                .base()
                .map(|b| b.get(crate::body::model::Param::BodyMass)),
        }
    }
}

/// The algorithm behind a trainer.
pub fn algorithm_for(trainer: Trainer) -> &'static dyn Algorithm {
    match trainer {
        Trainer::Backprop => &Backprop,
        Trainer::Lm => &Lm,
    }
}

/// Trains one case. `observe` sees every epoch of every member and may cancel.
pub fn train(
    case: Case,
    settings: &Settings,
    observe: &mut dyn FnMut(&EpochStats) -> Flow,
) -> Result<Outcome, AnnError> {
    train_with(case, settings, &Clock::Real, observe, None)
}

/// [`train`] on `clock` (the time limit and `train_seconds` read it), with
/// a `poll` the trainers also call inside an epoch (or one LM iteration),
/// every few milliseconds of work: its `Cancel` or `TimeUp` stops the run
/// there, as `observe`'s does at an epoch's end.
pub fn train_with(
    case: Case,
    settings: &Settings,
    clock: &Clock,
    observe: &mut dyn FnMut(&EpochStats) -> Flow,
    poll: Option<&dyn Fn() -> Flow>,
) -> Result<Outcome, AnnError> {
    settings.validate(case)?;
    let start = clock.now();
    let deadline = settings
        .time_limit_s
        .map(|s| start + Duration::from_secs_f64(s.min(1e9)));
    let base = settings.base.as_ref();
    let data = Dataset::build_on(case, base, &settings.train_values, &settings.grid)?;
    let enc = Encoded::new(&data, settings)?;
    let mut members = Vec::with_capacity(settings.ensemble);
    let mut member_epochs = Vec::with_capacity(settings.ensemble);
    let mut stop = StopReason::EpochLimit;
    for member in 0..settings.ensemble {
        let mut rng = Rng::derived(settings.seed, member as u64);
        let mut net = Network::new(
            &settings.layers,
            settings.activation,
            settings.gain,
            settings.init_range,
            &mut rng,
        )?;
        net.linear_output = settings.linear_output;
        let job = Member {
            data: &enc,
            settings,
            rng: &mut rng,
            index: member,
            halt: Halt {
                deadline,
                poll,
                clock,
            },
        };
        let (why, epochs) = algorithm_for(settings.trainer).run(&mut net, job, observe);
        members.push(net);
        member_epochs.push(epochs);
        let last = matches!(
            why,
            StopReason::Cancelled | StopReason::TimeLimit | StopReason::Diverged(_)
        );
        stop = why;
        if last {
            break;
        }
    }
    let net = TrainedNet {
        case,
        settings: settings.clone(),
        scaling: enc.scaling.clone(),
        members,
    };
    let mut out = Outcome {
        net,
        stop,
        member_epochs,
        rms: None,
        mpre_pct: None,
        share_right: None,
        train_seconds: 0.0,
        holdout: Vec::new(),
    };
    if !out.stop.is_diverged() {
        let (rms, mpre, share) = training_metrics(&out.net, &data, settings.train_tolerance);
        if rms.is_finite() && mpre.is_finite() {
            out.rms = Some(rms);
            out.mpre_pct = Some(mpre);
            out.share_right = Some(share);
            let values = case.holdout_values_on(out.net.base());
            out.holdout = evaluate_holdouts(&out.net, &values, &Band::default())?;
        } else {
            out.stop =
                StopReason::Diverged("the final network gives NaN or infinite output".into());
        }
    }
    out.train_seconds = clock.since(start).as_secs_f64();
    Ok(out)
}

/// RMS (scaled), MPRE (%) and share right of a trained net on a data set.
pub fn training_metrics(net: &TrainedNet, data: &Dataset, tol: f64) -> (f64, f64, f64) {
    let mut p = net.predictor();
    let (mut ys, mut ds, mut phys) = (Vec::new(), Vec::new(), Vec::new());
    for c in &data.curves {
        for (x, &a) in c.inputs.iter().zip(&c.actual) {
            let y = net.predict_with(x, &mut p);
            phys.push(y);
            ys.push(net.scaling.scale_output(y));
            ds.push(net.scaling.scale_output(a));
        }
    }
    (
        metrics::rms(&ys, &ds),
        metrics::mpre_pct(&phys, &data.targets()),
        metrics::share_right(&ys, &ds, tol),
    )
}

/// Max and mean % error of the net on hold-out curves at `values` over `band`.
pub fn evaluate_holdouts(
    net: &TrainedNet,
    values: &[f64],
    band: &Band,
) -> Result<Vec<HoldoutResult>, AnnError> {
    values
        .iter()
        .map(|&v| {
            let c = net.compare(v, band)?;
            Ok(HoldoutResult {
                param: net.case.param_name(),
                value: v,
                max_err_pct: c.max_err_pct,
                mean_err_pct: c.mean_err_pct,
                extrapolation: c.extrapolation,
                share_right: c.share_right(net, net.settings.test_tolerance),
            })
        })
        .collect()
}
