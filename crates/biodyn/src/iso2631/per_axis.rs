//! The three axes judged together (ISO 2631-1 §7.2, §8.2; Directive
//! 2002/44/EC Annex B): each axis weighted and multiplied by its k, the
//! day's exposure the highest axis's, comfort the vector sum.
//!
//! Per axis, with a_w and VDV before k:
//! A(8) = k·a_w·√(T_exp / 8 h), VDV_exp = k·VDV·(T_exp / T)^¼;
//! health: A(8) = max over axes, VDV = max over axes, each named;
//! comfort: a_v = √Σ(k_c·a_w)².

use super::axes::{AxisRule, rule};
use super::judgeable::{JudgeError, Mean, check_band, check_offset, check_rate};
use super::metrics::{Accumulator, Metrics};
use super::verdict::{A8_ACTION, A8_LIMIT, Eu, VDV_ACTION, VDV_LIMIT, Verdict, additional_methods};
use super::weighting::WeightingFilter;
use crate::time::{Axis, PerAxis, Row};

/// One axis of an assessment.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AxisResult {
    pub rule: AxisRule,
    /// Of the weighted signal, before k.
    pub metrics: Metrics,
    /// k·a_w·√(T_exp / 8 h), m/s².
    pub a8: f64,
    /// k·VDV·(T_exp / T)^¼, m/s^1.75.
    pub vdv_exposure: f64,
}

impl AxisResult {
    pub fn new(axis: Axis, metrics: Metrics, exposure_h: f64) -> AxisResult {
        let rule = *rule(axis);
        let e = metrics.exposure(exposure_h);
        AxisResult {
            rule,
            metrics,
            a8: rule.k_health * e.a8,
            vdv_exposure: rule.k_health * e.vdv,
        }
    }
}

/// The Directive's daily values: the highest axis's, named.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Health {
    pub a8: f64,
    pub a8_axis: Axis,
    pub vdv_exposure: f64,
    pub vdv_axis: Axis,
    pub eu: Eu,
}

impl Health {
    /// None when no axis is present.
    pub fn of(axes: &PerAxis<AxisResult>) -> Option<Health> {
        let (a8_axis, a8) = axes.map(|_, r| r.a8).highest()?;
        let (vdv_axis, vdv) = axes.map(|_, r| r.vdv_exposure).highest()?;
        Some(Health {
            a8,
            a8_axis,
            vdv_exposure: vdv,
            vdv_axis,
            eu: Eu {
                a8: Verdict::judge(a8, A8_ACTION, A8_LIMIT),
                vdv: Verdict::judge(vdv, VDV_ACTION, VDV_LIMIT),
            },
        })
    }
}

/// The comfort vector sum a_v = √Σ(k_c·a_w)², m/s² (ISO 2631-1 §8.2.3).
pub fn vector_sum(axes: &PerAxis<AxisResult>) -> f64 {
    axes.iter()
        .map(|(_, r)| (r.rule.k_comfort * r.metrics.aw).powi(2))
        .sum::<f64>()
        .sqrt()
}

/// The checks that call for the additional methods, on each axis, named
/// ("seat" alone for one axis, else "seat x").
pub fn axes_warnings(axes: &PerAxis<AxisResult>) -> Vec<String> {
    let one = axes.iter().count() == 1;
    let mut out = Vec::new();
    for (a, r) in axes.iter() {
        let at = if one {
            "seat".to_string()
        } else {
            format!("seat {a}")
        };
        out.extend(
            additional_methods(&r.metrics)
                .into_iter()
                .map(|w| format!("{at}: {w}")),
        );
    }
    out
}

/// Weighted metrics of the axes of a stream of rows, without the body:
/// each present axis through its weighting into its accumulator, and its
/// raw mean beside (a mean far beyond vibration is not judged).
#[derive(Debug, Clone)]
pub struct AxesAccumulator {
    lanes: Vec<(Axis, WeightingFilter, Accumulator, Mean)>,
    fs: f64,
}

impl AxesAccumulator {
    /// For the axes `present` at `fs` Hz.
    pub fn new(present: &PerAxis<()>, fs: f64) -> AxesAccumulator {
        AxesAccumulator {
            lanes: present
                .axes()
                .map(|a| {
                    let w = rule(a).weighting.digital(fs);
                    (a, w, Accumulator::new(fs), Mean::new(fs))
                })
                .collect(),
            fs,
        }
    }

    /// Refuses a rate that cannot carry an axis's weighting band.
    pub fn check_rate(&self) -> Result<(), JudgeError> {
        for (_, w, _, _) in &self.lanes {
            check_rate(w.weighting, self.fs)?;
        }
        Ok(())
    }

    /// Refuses an axis whose mean's start-up step could move its a_w or
    /// VDV by more than 5 %; the notes of those above 1 %.
    pub fn check_offsets(&self) -> Result<Vec<String>, JudgeError> {
        let mut notes = Vec::new();
        for (a, w, acc, mean) in &self.lanes {
            let m = acc.metrics();
            check_band(*a, w.weighting, self.fs, mean, &m)?;
            notes.extend(check_offset(*a, w.weighting, self.fs, mean.offset(), &m)?);
        }
        Ok(notes)
    }

    /// No axis to weigh.
    pub fn is_empty(&self) -> bool {
        self.lanes.is_empty()
    }

    #[inline(always)]
    pub fn push(&mut self, row: &Row) {
        for (a, f, acc, mean) in &mut self.lanes {
            let x = row[a.index()];
            mean.push(x);
            acc.push(f.process(x));
        }
    }

    /// Each axis's metrics (before k).
    pub fn metrics(&self) -> PerAxis<Metrics> {
        let mut out = PerAxis::default();
        for (a, _, acc, _) in &self.lanes {
            out.set(*a, acc.metrics());
        }
        out
    }

    /// Each axis judged over `exposure_h` hours.
    pub fn results(&self, exposure_h: f64) -> PerAxis<AxisResult> {
        self.metrics()
            .map(|a, m| AxisResult::new(a, *m, exposure_h))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn m(aw: f64, vdv: f64) -> Metrics {
        Metrics {
            aw,
            peak: 0.0,
            crest: 0.0,
            mtvv: 0.0,
            vdv,
            duration_s: 3600.0,
        }
    }

    /// The record: a_w x 0.08, y 0.05, z 0.745 over 8 h: z rules A(8)
    /// (1.4·0.08 = 0.112 < 0.745); x rules when 1.4·a_wx passes a_wz.
    #[test]
    fn the_highest_axis_after_k_is_the_days() {
        let mut axes = PerAxis::default();
        axes.set(Axis::X, AxisResult::new(Axis::X, m(0.08, 1.0), 8.0));
        axes.set(Axis::Y, AxisResult::new(Axis::Y, m(0.05, 0.5), 8.0));
        axes.set(Axis::Z, AxisResult::new(Axis::Z, m(0.745, 6.0), 8.0));
        let h = Health::of(&axes).unwrap();
        assert_eq!((h.a8_axis, h.a8), (Axis::Z, 0.745));
        assert_eq!(h.eu.a8, Verdict::AboveAction);
        // 1.4 · 0.55 = 0.77 > 0.745: x now rules, above the action value.
        axes.set(Axis::X, AxisResult::new(Axis::X, m(0.55, 5.0), 8.0));
        let h = Health::of(&axes).unwrap();
        assert_eq!(h.a8_axis, Axis::X);
        assert!((h.a8 - 0.77).abs() < 1e-12);
        // VDV over 8 h of a 1 h record: k·VDV·8^¼; x 1.4·5·1.6818 = 11.77 > z 6·1.6818 = 10.09.
        assert_eq!(h.vdv_axis, Axis::X);
        assert!((h.vdv_exposure - 1.4 * 5.0 * 8f64.powf(0.25)).abs() < 1e-12);
        assert_eq!(h.eu.vdv, Verdict::AboveAction);
        // Comfort: √(0.3025 + 0.0025 + 0.555025) = √0.860025 = 0.927375…, k_c = 1 on every axis.
        assert!(
            (vector_sum(&axes) - (0.55f64.powi(2) + 0.0025 + 0.745f64.powi(2)).sqrt()).abs()
                < 1e-12
        );
        assert!((vector_sum(&axes) - 0.927_375).abs() < 1e-6);
        assert!(Health::of(&PerAxis::default()).is_none());
    }

    /// A(8) scales with √(T/8 h): 2 h of a_w 1.0 on z is 0.5.
    #[test]
    fn a8_scales_with_the_square_root_of_the_exposure() {
        let r = AxisResult::new(Axis::Z, m(1.0, 1.0), 2.0);
        assert!((r.a8 - 0.5).abs() < 1e-15);
        let x = AxisResult::new(Axis::X, m(1.0, 1.0), 2.0);
        assert!((x.a8 - 0.7).abs() < 1e-15);
    }
}
