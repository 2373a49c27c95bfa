//! A record without a vertical axis (fore-and-aft and lateral only) is
//! still judged by the Directive: each axis weighted (Wd), with its k, the
//! day's exposure the highest axis's (Annex B), comfort the vector sum. The
//! body model is vertical and is not run: there is nothing to drive it.

use super::assess::{AssessError, MAX_EXPOSURE_H, MIN_RECORD_S};
use super::per_axis::{AxesAccumulator, AxisResult, Health, axes_warnings, vector_sum};
use super::verdict::comfort;
use crate::time::{PerAxis, Row, TimeError};

/// What the Directive and ISO 2631-1 say of the axes a record has, without
/// the body.
#[derive(Debug, Clone)]
pub struct AxesAssessment {
    pub fs: f64,
    pub duration_s: f64,
    pub exposure_h: f64,
    pub axes: PerAxis<AxisResult>,
    pub health: Health,
    /// √Σ(k_c·a_w)² over the axes, m/s², and its Annex C words.
    pub comfort_vector: f64,
    pub comfort_seat: Vec<&'static str>,
    pub warnings: Vec<String>,
}

/// Judges `rows` on the axes `present` (any subset; z among them or not)
/// at `fs` Hz over `exposure_h` hours, without the body.
pub fn assess_axes_only<I>(
    fs: f64,
    rows: I,
    present: &PerAxis<()>,
    exposure_h: f64,
) -> Result<AxesAssessment, AssessError>
where
    I: IntoIterator<Item = Result<Row, TimeError>>,
{
    if !(exposure_h.is_finite() && exposure_h > 0.0 && exposure_h <= MAX_EXPOSURE_H) {
        return Err(AssessError::BadExposure(exposure_h));
    }
    let mut acc = AxesAccumulator::new(present, fs);
    if acc.is_empty() {
        return Err(AssessError::NoVertical);
    }
    acc.check_rate()?;
    for row in rows {
        acc.push(&row?);
    }
    let axes = acc.results(exposure_h);
    let duration_s = axes
        .iter()
        .map(|(_, r)| r.metrics.duration_s)
        .fold(0.0, f64::max);
    if duration_s < MIN_RECORD_S {
        return Err(AssessError::TooShort {
            samples: (duration_s * fs).round(),
            seconds: duration_s,
        });
    }
    let mut warnings = acc.check_offsets()?;
    warnings.extend(axes_warnings(&axes));
    let health = Health::of(&axes).ok_or(AssessError::NoVertical)?;
    let comfort_vector = vector_sum(&axes);
    Ok(AxesAssessment {
        fs,
        duration_s,
        exposure_h,
        axes,
        health,
        comfort_vector,
        comfort_seat: comfort(comfort_vector),
        warnings,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::iso2631::assess_axes;
    use crate::time::Axis;
    use std::f64::consts::PI;

    fn rows(n: usize, fs: f64) -> impl Iterator<Item = Result<Row, TimeError>> {
        (0..n).map(move |k| {
            let t = k as f64 / fs;
            Ok([
                (2.0 * PI * 2.0 * t).sin(),
                0.5 * (2.0 * PI * 3.0 * t).sin(),
                (2.0 * PI * 5.0 * t).sin(),
            ])
        })
    }

    /// x and y alone are judged as they are beside z: the same numbers as
    /// the full assessment's x and y, the Directive on the highest of them.
    #[test]
    fn horizontal_axes_alone_are_judged_as_beside_z() {
        let fs = 500.0;
        let mut xy = PerAxis::default();
        xy.set(Axis::X, ());
        xy.set(Axis::Y, ());
        let only = assess_axes_only(fs, rows(5000, fs), &xy, 8.0).unwrap();
        let mut xyz = xy;
        xyz.set(Axis::Z, ());
        let body = crate::Preset::builtin_default().body;
        let full = assess_axes(&body, fs, rows(5000, fs), &xyz, 8.0).unwrap();
        for a in [Axis::X, Axis::Y] {
            assert_eq!(only.axes.get(a), full.axes.get(a), "{a}");
        }
        assert!(!only.axes.has(Axis::Z));
        assert_eq!(only.health.a8_axis, Axis::X);
        let want = 1.4 * only.axes.get(Axis::X).unwrap().metrics.aw;
        assert!((only.health.a8 - want).abs() < 1e-12);
        // The rate rule holds here too.
        assert!(matches!(
            assess_axes_only(100.0, rows(1000, 100.0), &xy, 8.0),
            Err(AssessError::Judge(_))
        ));
    }
}
