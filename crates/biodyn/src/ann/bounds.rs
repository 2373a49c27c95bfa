//! What a training run may ask for: sizes that fit in memory and runs that
//! can finish, checked before anything is allocated (`Settings::validate`
//! ends with [`check`]).
//!
//! The rule, with w the weights and thresholds of one network, n the
//! training samples (training values × grid points) and E the ensemble:
//!
//! - **n ≤ [`MAX_SAMPLES`]** (10⁶): the scaled data set, ≈ 100 bytes a sample.
//! - **E ≤ [`MAX_ENSEMBLE`]** (1000): members train one after another and all
//!   are kept; past a few dozen the mean and the median no longer move.
//! - **memory ≤ [`MEMORY_BUDGET`]** (1 GiB) for the run's large arrays:
//!   back-propagation holds 8·w·(2 + E) bytes (the weights and momentum
//!   of the member in training, and every member kept);
//!   Levenberg–Marquardt 8·(2·w² + n·w + E·w) bytes (the normal matrix JᵀJ
//!   and its damped copy that Cholesky factors in place, the n × w
//!   Jacobian, the members kept).
//! - **LM: w ≤ [`LM_MAX_WEIGHTS`]** (2000): one Cholesky solve is w³/3
//!   multiply–adds (≈ 2.7·10⁹ at the cap, about 2 s on one core), the
//!   longest step a time limit or a cancel cannot cut short; the
//!   Jacobian, the normal matrix and the steps between solves are checked
//!   as they go.

use super::case::Case;
use super::error::AnnError;
use super::network::param_count;
use super::settings::{Settings, Trainer};

/// Most training samples (training values × grid points).
pub const MAX_SAMPLES: usize = 1_000_000;
/// Most networks in an ensemble.
pub const MAX_ENSEMBLE: usize = 1000;
/// Bytes the large arrays of one run may take.
pub const MEMORY_BUDGET: f64 = 1024.0 * 1024.0 * 1024.0;
/// Most weights and thresholds of a network LM trains.
pub const LM_MAX_WEIGHTS: usize = 2000;

/// Bytes the large arrays of a run take (the rule above), as f64 so that
/// no product overflows.
pub fn memory_bytes(trainer: Trainer, weights: usize, samples: usize, ensemble: usize) -> f64 {
    let (w, n, e) = (weights as f64, samples as f64, ensemble as f64);
    match trainer {
        Trainer::Backprop => 8.0 * w * (2.0 + e),
        Trainer::Lm => 8.0 * (2.0 * w * w + n * w + e * w),
    }
}

/// "1.2 GB", "72 MB", "3 kB": decimal units, two significant digits.
fn bytes(b: f64) -> String {
    let (v, unit) = match b {
        b if b >= 1e9 => (b / 1e9, "GB"),
        b if b >= 1e6 => (b / 1e6, "MB"),
        b if b >= 1e3 => (b / 1e3, "kB"),
        b => (b, "B"),
    };
    if v >= 10.0 {
        format!("{v:.0} {unit}")
    } else {
        format!("{v:.1} {unit}")
    }
}

fn layers_text(layers: &[usize]) -> String {
    let v: Vec<String> = layers.iter().map(|l| l.to_string()).collect();
    v.join("-")
}

/// Checks the sizes of a set of settings whose fields are each valid on
/// their own (the table's checks ran first).
pub fn check(s: &Settings, _case: Case) -> Result<(), AnnError> {
    if s.ensemble > MAX_ENSEMBLE {
        return Err(AnnError::TooBig {
            setting: "ensemble",
            value: s.ensemble.to_string(),
            why: format!(
                "at most {MAX_ENSEMBLE} networks (they train one after another and are all kept; past a few dozen the mean and median no longer move)"
            ),
        });
    }
    let samples = s.train_values.len().saturating_mul(s.grid.len());
    if samples > MAX_SAMPLES {
        return Err(AnnError::TooBig {
            setting: "grid",
            value: format!("{} points", s.grid.len()),
            why: format!(
                "{} training values × {} grid points = {samples} samples, over the cap of {MAX_SAMPLES}: a coarser grid or fewer training values",
                s.train_values.len(),
                s.grid.len()
            ),
        });
    }
    let w = param_count(&s.layers);
    let layers = layers_text(&s.layers);
    if s.trainer == Trainer::Lm && w > LM_MAX_WEIGHTS {
        return Err(AnnError::TooBig {
            setting: "layers",
            value: layers,
            why: format!(
                "{w} weights and thresholds; LM solves a {w} × {w} system each iteration ({} for the matrix and its factor, {:.1e} multiply-adds a solve), at most {LM_MAX_WEIGHTS} weights: fewer neurons, or trainer backprop",
                bytes(16.0 * w as f64 * w as f64),
                (w as f64).powi(3) / 3.0
            ),
        });
    }
    let need = memory_bytes(s.trainer, w, samples, s.ensemble);
    if need > MEMORY_BUDGET {
        let rule = match s.trainer {
            Trainer::Backprop => "8 bytes × weights × (2 + ensemble)",
            Trainer::Lm => "8 bytes × (2·weights² + samples·weights + ensemble·weights)",
        };
        return Err(AnnError::TooBig {
            setting: "layers",
            value: layers,
            why: format!(
                "{w} weights and thresholds, {samples} samples, ensemble {}: training needs {} ({rule}), over the 1 GiB budget: fewer neurons, a smaller ensemble or a coarser grid",
                s.ensemble,
                bytes(need)
            ),
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lm(layers: &[usize]) -> Settings {
        let mut s = Settings::lm(Case::K4Stht);
        s.layers = layers.to_vec();
        s
    }

    #[test]
    fn the_papers_settings_fit() {
        for c in Case::ALL {
            for t in Trainer::ALL {
                check(&Settings::for_trainer(c, t), c).unwrap();
            }
        }
    }

    #[test]
    fn lm_caps_the_weights_and_names_the_layers() {
        // 2-10000-1: 40001 weights, a normal matrix of 12.8 GB.
        let e = check(&lm(&[2, 10_000, 1]), Case::K4Stht).unwrap_err();
        let t = e.to_string();
        assert!(t.starts_with("layers = 2-10000-1: 40001 weights"), "{t}");
        assert!(t.contains("at most 2000"), "{t}");
        // Just under the cap: 2-499-1 has 4·499 + 1 = 1997.
        check(&lm(&[2, 499, 1]), Case::K4Stht).unwrap();
        assert!(check(&lm(&[2, 501, 1]), Case::K4Stht).is_err());
    }

    #[test]
    fn backprop_caps_the_memory_of_the_weights() {
        let mut s = Settings::paper(Case::K4Stht);
        s.layers = vec![2, 10_000, 10_000, 1];
        let t = check(&s, Case::K4Stht).unwrap_err().to_string();
        assert!(
            t.contains("100050001 weights") && t.contains("2.4 GB"),
            "{t}"
        );
        assert!(t.contains("1 GiB"), "{t}");
        s.layers = vec![2, 10_000, 1];
        check(&s, Case::K4Stht).unwrap();
        // The same net kept 5000 times does not fit: the ensemble cap first.
        s.ensemble = 5000;
        let t = check(&s, Case::K4Stht).unwrap_err().to_string();
        assert!(t.starts_with("ensemble = 5000: at most 1000"), "{t}");
        // 8 B × 40001 × 1002 = 321 MB fits; 230041 weights kept 1000 times do not.
        s.ensemble = 1000;
        check(&s, Case::K4Stht).unwrap();
        s.layers = vec![2, 10_000, 20, 1];
        let t = check(&s, Case::K4Stht).unwrap_err().to_string();
        assert!(t.contains("ensemble 1000: training needs 1.8 GB"), "{t}");
    }

    #[test]
    fn the_samples_are_capped() {
        let mut s = Settings::lm(Case::K4Stht);
        s.grid = crate::band::Band {
            from: 0.001,
            to: 1000.0,
            step: 0.001,
        };
        let t = check(&s, Case::K4Stht).unwrap_err().to_string();
        assert!(t.contains("3 training values × 1000000 grid points"), "{t}");
    }
}
