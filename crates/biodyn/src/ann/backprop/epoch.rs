//! What both back-propagation loops share: the run's arguments, an
//! epoch's running metrics, the end-of-epoch checks and the neuron kind.

use crate::ann::encoded::Encoded;
use crate::ann::metrics::EpochStats;
use crate::ann::network::{Activation, Network};
use crate::ann::settings::Settings;
use crate::ann::stop::{Flow, Halt, StopReason, divergence};
use crate::rng::Rng;

pub(super) type Args<'a, 'b> = (
    &'a Encoded,
    &'a Settings,
    &'a mut Rng,
    usize,
    Halt<'a>,
    &'a mut (dyn FnMut(&EpochStats) -> Flow + 'b),
);

/// One epoch's running metrics: Σ(d − Y)², max % error, outputs right.
#[derive(Clone, Copy)]
pub(super) struct Running {
    pub(super) se: f64,
    pub(super) mpre: f64,
    pub(super) right: usize,
}

impl Running {
    pub(super) fn new() -> Running {
        Running {
            se: 0.0,
            mpre: 0.0,
            right: 0,
        }
    }

    #[inline(always)]
    pub(super) fn add(&mut self, data: &Encoded, p: usize, y: f64, e: f64, tol: f64) {
        self.se += e * e;
        if e.abs() <= tol {
            self.right += 1;
        }
        let rel = data.pct_error(y, p);
        // NaN-safe max: a NaN error must survive to the divergence check.
        if rel > self.mpre || rel.is_nan() {
            self.mpre = rel;
        }
    }
}

/// The end of an epoch, common to both loops: statistics, divergence,
/// observer, targets, deadline. `Some` stops the run.
#[allow(clippy::too_many_arguments)]
pub(super) fn end_epoch(
    run: Running,
    epoch: u64,
    params: &[f64],
    data: &Encoded,
    settings: &Settings,
    member: usize,
    halt: Halt<'_>,
    observe: &mut dyn FnMut(&EpochStats) -> Flow,
) -> Option<StopReason> {
    let n = data.x.len() as f64;
    let stats = EpochStats {
        member,
        epoch,
        rms: (run.se / n).sqrt(),
        mpre_pct: run.mpre,
        share_right: run.right as f64 / n,
    };
    if let Some(d) = divergence(stats.rms, stats.mpre_pct, params) {
        return Some(d);
    }
    match observe(&stats) {
        Flow::Continue => {}
        Flow::Cancel => return Some(StopReason::Cancelled),
        Flow::TimeUp => return Some(StopReason::TimeLimit),
    }
    if let Some(stop) = data.target_reached(settings, &stats) {
        return Some(stop);
    }
    if halt.past_deadline() {
        return Some(StopReason::TimeLimit);
    }
    None
}

#[derive(Clone, Copy)]
pub(super) struct Kind {
    pub(super) act: Activation,
    pub(super) gain: f64,
    pub(super) linear_output: bool,
}

impl Kind {
    pub(super) fn of(net: &Network) -> Kind {
        Kind {
            act: net.activation,
            gain: net.gain,
            linear_output: net.linear_output,
        }
    }
}

// ---------------------------------------------------------------------------
// The paper's architectures: layers with their sizes as constants.

/// δ of the single output neuron.
#[inline(always)]
pub(super) fn output_delta(k: Kind, y: f64, e: f64) -> [f64; 1] {
    let slope = if k.linear_output {
        1.0
    } else {
        k.act.slope(k.gain, y)
    };
    [slope * e]
}
