//! One training run from settings to report: build the data from the
//! analytic engine, scale it, train each ensemble member with the chosen
//! trainer, then measure the result on the training set and the hold-outs.

use super::case::Case;
use super::dataset::{Dataset, holdouts};
use super::error::AnnError;
use super::exp::exp;
use super::metrics::{self, EpochStats, HoldoutResult};
use super::network::Network;
use super::rng::Rng;
use super::scaling::Scaling;
use super::settings::{Settings, Trainer};
use super::stop::{Flow, StopReason};
use super::trained::TrainedNet;
use super::{backprop, lm};
use crate::freq::band::Band;
use serde::Serialize;
use std::time::{Duration, Instant};

/// Training data on the network's scale.
#[derive(Debug, Clone)]
pub struct Encoded {
    pub scaling: Scaling,
    /// Scaled inputs, one row per pattern.
    pub x: Vec<Vec<f64>>,
    /// Scaled targets.
    pub d: Vec<f64>,
    /// Physical targets, for MPRE.
    pub actual: Vec<f64>,
    /// 100/|actual| per pattern, so that the per-pattern % error of the
    /// training loops needs no division.
    pct_scale: Vec<f64>,
    /// The output column's map back to physical units, folded to
    /// t = a + (y − lo)·c (then e^t for a log target).
    out_a: f64,
    out_lo: f64,
    out_c: f64,
    out_log: bool,
}

impl Encoded {
    pub fn new(data: &Dataset, settings: &Settings) -> Result<Encoded, AnnError> {
        let case = data.case;
        let raw = data.inputs();
        let actual = data.targets();
        let mut input_log = vec![settings.log_param; case.inputs()];
        input_log[case.freq_input()] = settings.log_freq;
        let range = settings.activation.range();
        let scaling = Scaling::fit(
            &raw,
            &actual,
            &input_log,
            settings.log_target,
            settings.scaling_margin,
            range,
        )?;
        let x = raw
            .iter()
            .map(|r| {
                let mut o = vec![0.0; r.len()];
                scaling.scale_inputs(r, &mut o);
                o
            })
            .collect();
        let d = actual.iter().map(|&v| scaling.scale_output(v)).collect();
        let pct_scale = actual.iter().map(|a| 100.0 / a.abs()).collect();
        let (out_a, out_lo, out_c, out_log) = scaling.output_affine();
        Ok(Encoded {
            scaling,
            x,
            d,
            actual,
            pct_scale,
            out_a,
            out_lo,
            out_c,
            out_log,
        })
    }

    /// Physical % error 100·|ŷ − y|/|y| of scaled output `y` for pattern
    /// `p`: the training loops' per-pattern MPRE term. The same quantity as
    /// `metrics::pct_error` of the unscaled output, with the constant parts
    /// precomputed (so it may differ from it in the last bits).
    #[inline(always)]
    pub fn pct_error(&self, y: f64, p: usize) -> f64 {
        let t = self.out_a + (y - self.out_lo) * self.out_c;
        let phys = if self.out_log { exp(t) } else { t };
        (phys - self.actual[p]).abs() * self.pct_scale[p]
    }

    /// The stop reason if an epoch's metrics reach a target.
    pub fn target_reached(&self, s: &Settings, stats: &EpochStats) -> Option<StopReason> {
        if s.stop_when_all_right && stats.share_right >= 1.0 {
            return Some(StopReason::AllRight);
        }
        if s.rms_target.is_some_and(|t| stats.rms <= t) {
            return Some(StopReason::RmsTarget);
        }
        if s.mpre_target_pct.is_some_and(|t| stats.mpre_pct <= t) {
            return Some(StopReason::MpreTarget);
        }
        None
    }
}

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
        }
    }
}

/// Trains one case. `observe` sees every epoch of every member and may cancel.
pub fn train(
    case: Case,
    settings: &Settings,
    observe: &mut dyn FnMut(&EpochStats) -> Flow,
) -> Result<Outcome, AnnError> {
    settings.validate(case)?;
    let start = Instant::now();
    let deadline = settings
        .time_limit_s
        .map(|s| start + Duration::from_secs_f64(s.min(1e9)));
    let data = Dataset::build(case, &settings.train_values, &settings.grid)?;
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
        let (why, epochs) = match settings.trainer {
            Trainer::Backprop => backprop::run(
                &mut net, &enc, settings, &mut rng, member, deadline, observe,
            ),
            Trainer::Lm => lm::run(&mut net, &enc, settings, member, deadline, observe),
        };
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
            out.holdout = evaluate_holdouts(&out.net, &case.holdout_values(), &Band::default())?;
        } else {
            out.stop =
                StopReason::Diverged("the final network gives NaN or infinite output".into());
        }
    }
    out.train_seconds = start.elapsed().as_secs_f64();
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
    let case = net.case;
    let sets = holdouts(case, values, &net.settings.train_values, band)?;
    let mut p = net.predictor();
    Ok(sets
        .iter()
        .map(|h| {
            let pred: Vec<f64> = h
                .curve
                .inputs
                .iter()
                .map(|x| net.predict_with(x, &mut p))
                .collect();
            let (max, mean) = metrics::curve_error(&pred, &h.curve.actual);
            let ys: Vec<f64> = pred.iter().map(|&y| net.scaling.scale_output(y)).collect();
            let ds: Vec<f64> = h
                .curve
                .actual
                .iter()
                .map(|&y| net.scaling.scale_output(y))
                .collect();
            HoldoutResult {
                param: case.param_name(),
                value: h.curve.value,
                max_err_pct: max,
                mean_err_pct: mean,
                extrapolation: h.extrapolation,
                share_right: metrics::share_right(&ys, &ds, net.settings.test_tolerance),
            }
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The training loops' precomputed % error is the MPRE term in
    /// physical units, for a plain and a log target.
    #[test]
    fn cheap_pct_error_is_the_physical_relative_error() {
        let case = Case::K4Dpmi;
        for log in [false, true] {
            let mut s = Settings::paper(case);
            s.log_target = log;
            let data = Dataset::build(case, &s.train_values, &s.grid).unwrap();
            let enc = Encoded::new(&data, &s).unwrap();
            let mut n = 0;
            for (p, &d) in enc.d.iter().enumerate() {
                for y in [d, d + 0.01, d - 0.2, 0.05, 0.97] {
                    let want = metrics::pct_error(enc.scaling.unscale_output(y), enc.actual[p]);
                    let got = enc.pct_error(y, p);
                    assert!(
                        (got - want).abs() <= 1e-9 * want.max(1.0),
                        "log {log}, pattern {p}, y {y}: {got} vs {want}"
                    );
                    n += 1;
                }
                assert!(enc.pct_error(d, p) < 1e-9);
            }
            assert_eq!(n, 5 * 120);
        }
    }
}
