//! The last runs, kept to compare: case, trainer, seed, epochs, working
//! time, RMS, MPRE and the held-out errors of each finished run.

use biodyn::ann::{Case, Outcome, Trainer};
use std::collections::VecDeque;

/// How many runs the table keeps (the oldest goes first).
pub const RUNS_KEPT: usize = 8;

#[derive(Debug, Clone, PartialEq)]
pub struct RunRecord {
    pub case: Case,
    pub trainer: Trainer,
    pub seed: u64,
    /// Epochs (LM: iterations) of each ensemble member.
    pub member_epochs: Vec<u64>,
    /// Working seconds (pauses left out).
    pub seconds: f64,
    pub rms: Option<f64>,
    pub mpre_pct: Option<f64>,
    /// Worst held-out max error and the mean of the held-out mean errors, %.
    pub holdout_max_pct: Option<f64>,
    pub holdout_mean_pct: Option<f64>,
    /// Why it stopped ("epoch limit", "diverged: …").
    pub stop: String,
    /// The body it trained on: "paper", or "N seg" for the model being edited.
    pub body: String,
}

impl RunRecord {
    pub fn of(out: &Outcome, seconds: f64) -> RunRecord {
        let h = &out.holdout;
        let max = h.iter().map(|r| r.max_err_pct).fold(None, |m: Option<f64>, v| {
            Some(m.map_or(v, |m| m.max(v)))
        });
        let mean = (!h.is_empty())
            .then(|| h.iter().map(|r| r.mean_err_pct).sum::<f64>() / h.len() as f64);
        RunRecord {
            case: out.net.case,
            trainer: out.net.settings.trainer,
            seed: out.net.settings.seed,
            member_epochs: out.member_epochs.clone(),
            seconds,
            rms: out.rms,
            mpre_pct: out.mpre_pct,
            holdout_max_pct: max,
            holdout_mean_pct: mean,
            stop: out.stop.to_string(),
            body: out
                .net
                .base()
                .map_or("paper".into(), |b| format!("{} seg", b.n())),
        }
    }
}

/// The epochs of a run, per member: `300`, `5×300` (5 members of 300
/// each) or `5×≤300` (5 members, the longest 300). The run panel and the
/// runs table both say it so.
pub fn epochs_text(member_epochs: &[u64]) -> String {
    let most = member_epochs.iter().copied().max().unwrap_or(0);
    match member_epochs {
        [] | [_] => most.to_string(),
        all if all.iter().all(|&e| e == most) => format!("{}×{most}", all.len()),
        all => format!("{}×≤{most}", all.len()),
    }
}

/// Newest last; at most `RUNS_KEPT`.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct History {
    pub runs: VecDeque<RunRecord>,
}

impl History {
    pub fn push(&mut self, r: RunRecord) {
        self.runs.push_back(r);
        while self.runs.len() > RUNS_KEPT {
            self.runs.pop_front();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::epochs_text;

    #[test]
    fn epochs_are_counted_per_member() {
        assert_eq!(epochs_text(&[300]), "300");
        assert_eq!(epochs_text(&[300; 5]), "5×300");
        assert_eq!(epochs_text(&[300, 120, 300]), "3×≤300");
        assert_eq!(epochs_text(&[]), "0");
    }
}
