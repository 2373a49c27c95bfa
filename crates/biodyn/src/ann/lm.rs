//! Levenberg–Marquardt on the same networks: the trainer that generalises.
//!
//! Minimises Σ(Y − d)² + λ·Σθ² (λ the weight decay) over all weights and
//! thresholds θ. Each iteration builds the Jacobian of the outputs by
//! back-propagation, then solves (JᵀJ + (λ + μ)I)·Δ = −(Jᵀr + λθ) by
//! Cholesky; μ falls tenfold after a step that lowers the loss and rises
//! tenfold after one that does not (the shared driver, [`crate::lm`]). When μ runs away no step helps any more:
//! the run has converged. One iteration counts as one epoch.

use super::algorithm::{Algorithm, Member};
use super::encoded::Encoded;
use super::metrics::EpochStats;
use super::network::Network;
use super::settings::{Settings, Trainer};
use super::stop::{Flow, Halt, POLL_WORK, StopReason, divergence};
use crate::lm::{Attempt, Model, Solve, Tenfold, attempt};
use nalgebra::{DMatrix, DVector};

const MU_START: f64 = 1e-3;
const MU_MAX: f64 = 1e10;
const MU_MIN: f64 = 1e-12;

/// Loss and metrics of the current weights.
struct Eval {
    loss: f64,
    stats: EpochStats,
}

fn evaluate(net: &Network, data: &Encoded, settings: &Settings, member: usize, epoch: u64) -> Eval {
    let mut s = net.scratch();
    let (mut se, mut mpre, mut right) = (0.0, 0.0f64, 0usize);
    for (p, x) in data.x.iter().enumerate() {
        let y = net.forward(x, &mut s)[0];
        let e = y - data.d[p];
        se += e * e;
        if e.abs() <= settings.train_tolerance {
            right += 1;
        }
        let rel = data.pct_error(y, p);
        if rel > mpre || rel.is_nan() {
            mpre = rel;
        }
    }
    let decay: f64 = net.params.iter().map(|w| w * w).sum::<f64>() * settings.weight_decay;
    let n = data.x.len() as f64;
    Eval {
        loss: se + decay,
        stats: EpochStats {
            member,
            epoch,
            rms: (se / n).sqrt(),
            mpre_pct: mpre,
            share_right: right as f64 / n,
        },
    }
}

/// JᵀJ from the columns of J, filling one triangle and mirroring it: half
/// the work of a general product, and the bulk of an iteration's cost.
/// `halt` is checked at every column; `Err` says why it stopped.
fn gram(jac: &DMatrix<f64>, halt: Halt<'_>) -> Result<DMatrix<f64>, StopReason> {
    let (n, np) = jac.shape();
    let data = jac.as_slice();
    let mut h = DMatrix::<f64>::zeros(np, np);
    for i in 0..np {
        if let Some(stop) = halt.check() {
            return Err(stop);
        }
        let ci = &data[i * n..(i + 1) * n];
        for j in i..np {
            let cj = &data[j * n..(j + 1) * n];
            let mut acc = [0.0f64; 4];
            let (a4, ar) = ci.split_at(n - n % 4);
            let (b4, br) = cj.split_at(n - n % 4);
            for (a, b) in a4.chunks_exact(4).zip(b4.chunks_exact(4)) {
                for k in 0..4 {
                    acc[k] += a[k] * b[k];
                }
            }
            let mut v = acc[0] + acc[1] + acc[2] + acc[3];
            for (a, b) in ar.iter().zip(br) {
                v += a * b;
            }
            h[(i, j)] = v;
            h[(j, i)] = v;
        }
    }
    Ok(h)
}

/// The network at one epoch, linearised, as the LM driver sees it: the
/// damped system is (JᵀJ + (λ + μ)I)·Δ = Jᵀr + λθ, solved by Cholesky.
struct Weights<'a> {
    h: DMatrix<f64>,
    g: DVector<f64>,
    lambda: f64,
    net: &'a mut Network,
    /// The trial network, then its evaluation.
    trial: Option<Network>,
    next: Option<Eval>,
    data: &'a Encoded,
    settings: &'a Settings,
    member: usize,
    epoch: u64,
    current: &'a mut Eval,
}

impl Model for Weights<'_> {
    fn solve(&mut self, mu: f64) -> Solve {
        let mut a = self.h.clone();
        for k in 0..a.nrows() {
            a[(k, k)] += self.lambda + mu;
        }
        let Some(chol) = a.cholesky() else {
            return Solve::Singular;
        };
        let step = chol.solve(&self.g);
        let mut trial = self.net.clone();
        for (w, d) in trial.params.iter_mut().zip(step.iter()) {
            *w -= d;
        }
        self.trial = Some(trial);
        Solve::Step
    }

    fn trial_cost(&mut self) -> f64 {
        let Some(trial) = &self.trial else {
            return f64::INFINITY;
        };
        let next = evaluate(trial, self.data, self.settings, self.member, self.epoch);
        let loss = next.loss;
        self.next = Some(next);
        loss
    }

    fn keep(&mut self, _before: f64, _after: f64) -> f64 {
        if let (Some(trial), Some(next)) = (self.trial.take(), self.next.take()) {
            *self.net = trial;
            *self.current = next;
        }
        0.0
    }
}

/// The `Algorithm` of this file.
pub struct Lm;

impl Algorithm for Lm {
    fn trainer(&self) -> Trainer {
        Trainer::Lm
    }

    fn run(
        &self,
        net: &mut Network,
        job: Member<'_>,
        observe: &mut dyn FnMut(&EpochStats) -> Flow,
    ) -> (StopReason, u64) {
        run_lm(net, job.data, job.settings, job.index, job.halt, observe)
    }
}

/// Trains `net` in place; returns why it stopped and the iterations done.
pub fn run_lm(
    net: &mut Network,
    data: &Encoded,
    settings: &Settings,
    member: usize,
    halt: Halt<'_>,
    observe: &mut dyn FnMut(&EpochStats) -> Flow,
) -> (StopReason, u64) {
    let n = data.x.len();
    let np = net.params.len();
    let lambda = settings.weight_decay;
    let mut jac = DMatrix::<f64>::zeros(n, np);
    let mut r = DVector::<f64>::zeros(n);
    let mut row = vec![0.0; np];
    let mut s = net.scratch();
    let mut current = evaluate(net, data, settings, member, 0);
    if let Some(d) = divergence(current.stats.rms, current.stats.mpre_pct, &net.params) {
        return (d, 0);
    }
    let mut damping = Tenfold {
        mu: MU_START,
        min: MU_MIN,
        max: MU_MAX,
    };
    // One iteration of a large network takes a while: the time limit and a
    // cancel are checked inside it, in the Jacobian every POLL_WORK
    // weights, at each column of JᵀJ and before each solve.
    let stride = (POLL_WORK / np.max(1)).max(1);
    for epoch in 1..=settings.epochs {
        for (p, x) in data.x.iter().enumerate() {
            if p % stride == stride - 1
                && let Some(stop) = halt.check()
            {
                return (stop, epoch - 1);
            }
            let y = net.forward(x, &mut s)[0];
            r[p] = y - data.d[p];
            net.backward(&mut s, &[1.0], &mut row);
            for (k, v) in row.iter().enumerate() {
                jac[(p, k)] = *v;
            }
        }
        let h = match gram(&jac, halt) {
            Ok(h) => h,
            Err(stop) => return (stop, epoch - 1),
        };
        let theta = DVector::from_column_slice(&net.params);
        let mut model = Weights {
            g: jac.tr_mul(&r) + &theta * lambda,
            h,
            lambda,
            net: &mut *net,
            trial: None,
            next: None,
            data,
            settings,
            member,
            epoch,
            current: &mut current,
        };
        let cost = model.current.loss;
        let accepted = loop {
            if let Some(stop) = halt.check() {
                return (stop, epoch - 1);
            }
            match attempt(&mut model, &mut damping, cost) {
                Attempt::Kept { .. } => break true,
                Attempt::Refused => {}
                Attempt::RanAway | Attempt::Stalled => break false,
            }
        };
        if !accepted {
            return (StopReason::Converged, epoch - 1);
        }
        let stats = current.stats;
        if let Some(d) = divergence(stats.rms, stats.mpre_pct, &net.params) {
            return (d, epoch);
        }
        match observe(&stats) {
            Flow::Continue => {}
            Flow::Cancel => return (StopReason::Cancelled, epoch),
            Flow::TimeUp => return (StopReason::TimeLimit, epoch),
        }
        if let Some(stop) = data.target_reached(settings, &stats) {
            return (stop, epoch);
        }
        if let Some(stop) = halt.check() {
            return (stop, epoch);
        }
    }
    (StopReason::EpochLimit, settings.epochs)
}
