//! A whole assessment in one streaming pass: simulate the body under the
//! seat record, weight the seat and every segment, accumulate the metrics
//! and the one-third-octave bands of seat and head. Memory: the 1 s MTVV
//! windows and a few blocks of 4096 samples, whatever the record's length.
//! Two threads: the simulator and the bands on the caller's, the weighted
//! channels and their metrics on a second (the same bits as on one).

use super::bands::BandBank;
use super::judgeable::{JudgeError, Mean, check_band, check_offset, check_rate};
use super::metrics::{Accumulator, Exposure, Metrics};
use super::per_axis::{AxesAccumulator, AxisResult, Health, axes_warnings, vector_sum};
use super::points::{PointsAccumulator, PointsComfort, Sample};
use super::sickness::{Sickness, SicknessAccumulator};
use super::spine::{Person, Spine, SpineAccumulator, SpineError};
use super::verdict::{Eu, comfort};
use super::weighting::Weighting;
use crate::body::model::Body;
use crate::time::{Axis, PerAxis, PerPoint, Row, Simulator, TimeError};
use seat::StrokeAccumulator;
pub use seat::{SeatValue, Stroke};
use stream::{Channels, Spectra, stream};

/// Longest exposure a day can hold, h.
pub const MAX_EXPOSURE_H: f64 = 24.0;

/// Why an assessment stopped.
#[derive(Debug, thiserror::Error)]
pub enum AssessError {
    #[error(transparent)]
    Time(#[from] TimeError),
    #[error(transparent)]
    Judge(#[from] JudgeError),
    #[error("exposure {0:?} h: it must be > 0 and at most 24 h")]
    BadExposure(f64),
    #[error(
        "the record has no z (vertical) axis: the body model is driven vertically; name the z column"
    )]
    NoVertical,
    #[error(
        "the model has a seat, and the seat model is vertical: the pan's {0} is not computed, so the pan cannot be judged on every axis the record has; give the record's z axis alone"
    )]
    SeatNotVertical(&'static str),
    #[error(
        "the record is {samples} samples ({} s) long: too short to judge (a 1 s MTVV window and the weightings' settling need at least {MIN_RECORD_S} s); give a longer record",
        crate::io::excerpt::Short(*.seconds)
    )]
    TooShort { samples: f64, seconds: f64 },
}

/// Shortest record judged, s: the MTVV's 1 s window must run at least
/// once, with the weightings' 0.4 Hz band limit past its start.
pub const MIN_RECORD_S: f64 = 2.0;

/// One weighted signal: its metrics and their exposure values.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Channel {
    pub metrics: Metrics,
    pub exposure: Exposure,
}

/// One one-third-octave band: r.m.s. of the unweighted seat and head
/// accelerations (None where fs is too low for the band).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BandLevel {
    pub f_hz: f64,
    pub seat: Option<f64>,
    pub head: Option<f64>,
}

/// Everything `biodyn assess` reports.
#[derive(Debug, Clone)]
pub struct Assessment {
    /// The z axis's (the body's input).
    pub weighting: Weighting,
    pub fs: f64,
    pub duration_s: f64,
    pub exposure_h: f64,
    /// The z axis at the seat (Wk), the body's input.
    pub seat: Channel,
    pub head: Channel,
    /// Every segment, top to bottom, by name.
    pub segments: Vec<(String, Channel)>,
    /// Each axis of the record, z among them.
    pub axes: PerAxis<AxisResult>,
    /// The Directive's daily values: the highest axis (after k) at the seat.
    pub health: Health,
    /// The Directive judges the seat (the input), never the head: the
    /// verdicts of [`Assessment::health`].
    pub eu: Eu,
    /// The comfort vector sum √Σ(k·a_w)² at the seat, m/s².
    pub comfort_vector: f64,
    /// Annex C words of the vector sum (z alone for a vertical record).
    pub comfort_seat: Vec<&'static str>,
    pub comfort_head: Vec<&'static str>,
    /// Motion sickness (ISO 2631-1 Annex D) of the seat's z and of the head.
    pub sickness_seat: Sickness,
    pub sickness_head: Sickness,
    /// ISO 2631-5 of the seat's z, when a person was given.
    pub spine: Option<Result<Spine, SpineError>>,
    /// Comfort at the other points and overall, where the record has them.
    pub points: Option<PointsComfort>,
    pub bands: Vec<BandLevel>,
    pub warnings: Vec<String>,
    /// With a seat model: the floor (the record), while `seat` is the pan.
    pub floor: Option<Channel>,
    /// With a seat model: SEAT and the VDV ratio, pan over floor.
    pub seat_value: Option<SeatValue>,
    /// With a seat model: the suspension's travel.
    pub stroke: Option<Stroke>,
}

/// Assesses `samples` (vertical seat acceleration, m/s², at `fs` Hz) for
/// `body` over an exposure of `exposure_h` hours; the first error of the
/// stream stops it.
pub fn assess<I>(
    body: &Body,
    fs: f64,
    samples: I,
    exposure_h: f64,
) -> Result<Assessment, AssessError>
where
    I: IntoIterator<Item = Result<f64, TimeError>>,
{
    let mut z = PerAxis::default();
    z.set(Axis::Z, ());
    let rows = samples.into_iter().map(|r| r.map(|a| [0.0, 0.0, a]));
    assess_axes(body, fs, rows, &z, exposure_h)
}

/// Assesses `rows` of seat acceleration on the axes `present` (z among
/// them: the body is driven by z), m/s², at `fs` Hz, for `body` over an
/// exposure of `exposure_h` hours; x and y are weighted beside the body's
/// run, on the simulator's thread.
pub fn assess_axes<I>(
    body: &Body,
    fs: f64,
    rows: I,
    present: &PerAxis<()>,
    exposure_h: f64,
) -> Result<Assessment, AssessError>
where
    I: IntoIterator<Item = Result<Row, TimeError>>,
{
    assess_with(body, fs, rows, present, exposure_h, None)
}

/// [`assess_axes`], and ISO 2631-5's spinal dose and risk for `spine`.
pub fn assess_with<I>(
    body: &Body,
    fs: f64,
    rows: I,
    present: &PerAxis<()>,
    exposure_h: f64,
    spine: Option<&Person>,
) -> Result<Assessment, AssessError>
where
    I: IntoIterator<Item = Result<Row, TimeError>>,
{
    assess_points(
        body,
        fs,
        rows,
        present,
        &PerPoint::default(),
        exposure_h,
        spine,
    )
}

/// As [`assess_with`], and comfort at the other points `points` the
/// samples carry (the backrest, the feet, the seat's rotations), weighted
/// beside x and y.
pub fn assess_points<I, S>(
    body: &Body,
    fs: f64,
    rows: I,
    present: &PerAxis<()>,
    points: &PerPoint<()>,
    exposure_h: f64,
    spine: Option<&Person>,
) -> Result<Assessment, AssessError>
where
    I: IntoIterator<Item = Result<S, TimeError>>,
    S: Sample,
{
    if !(exposure_h.is_finite() && exposure_h > 0.0 && exposure_h <= MAX_EXPOSURE_H) {
        return Err(AssessError::BadExposure(exposure_h));
    }
    if !present.has(Axis::Z) {
        return Err(AssessError::NoVertical);
    }
    // A vertical seat model knows the pan's z only: x, y and the other
    // points at the pan are not the floor's, and guessing them is not judging.
    if body.has_seat() {
        if let Some(a) = present.axes().find(|&a| a != Axis::Z) {
            return Err(AssessError::SeatNotVertical(a.name()));
        }
        if !points.is_empty() {
            return Err(AssessError::SeatNotVertical("backrest, feet and rotations"));
        }
    }
    let weighting = super::axes::rule(Axis::Z).weighting;
    let mut horizontal = PerAxis::default();
    for a in present.axes().filter(|&a| a != Axis::Z) {
        horizontal.set(a, ());
    }
    // The band must fit under fs/2 before anything is judged.
    check_rate(weighting, fs)?;
    let mut sim = Simulator::new(body, fs).map_err(TimeError::from)?;
    let layout = sim.layout();
    let n = layout.segments;
    let head = sim.head();
    let filter = weighting.digital(fs);
    let mut channels = Channels {
        w_seat: filter.clone(),
        w_seg: vec![filter.clone(); n],
        acc_seat: Accumulator::new(fs),
        mean_z: Mean::new(fs),
        acc_seg: vec![Accumulator::new(fs); n],
        width: layout.len(),
        side: AxesAccumulator::new(&horizontal, fs),
        points: PointsAccumulator::new(points, fs),
        head,
        sick_seat: SicknessAccumulator::new(fs),
        sick_head: SicknessAccumulator::new(fs),
        spine: spine.map(|_| SpineAccumulator::new(fs)),
        pan: body.pan().map(|p| layout.acc(p)),
        floor: body
            .seat
            .as_ref()
            .map(|_| (filter.clone(), Accumulator::new(fs))),
        stroke: body
            .seat
            .as_ref()
            .map(|s| StrokeAccumulator::new(layout.deflection(s.suspension), s.stroke_m)),
    };
    let mut spectra = Spectra {
        bands: BandBank::<2>::new(fs),
        head,
        width: layout.len(),
    };
    let two = std::thread::available_parallelism().is_ok_and(|n| n.get() >= 2);
    stream(
        &mut rows.into_iter(),
        &mut sim,
        &mut spectra,
        &mut channels,
        two,
    )?;
    let Channels {
        acc_seat,
        mean_z,
        acc_seg,
        side,
        points,
        sick_seat,
        sick_head,
        spine: spine_acc,
        floor,
        stroke,
        ..
    } = channels;
    let spine = spine.zip(spine_acc).map(|(p, a)| a.finish(p, exposure_h));
    let bands = spectra.bands;

    let channel = |acc: &Accumulator| {
        let metrics = acc.metrics();
        Channel {
            metrics,
            exposure: metrics.exposure(exposure_h),
        }
    };
    let seat = channel(&acc_seat);
    let segments: Vec<(String, Channel)> = body
        .segments
        .iter()
        .zip(&acc_seg)
        .map(|(s, a)| (s.name.clone(), channel(a)))
        .collect();
    let head_ch = segments.get(head).map_or(seat, |s| s.1);
    let floor = floor.map(|(_, acc)| channel(&acc));
    // Too short means no verdict, not a verdict beside a warning.
    if seat.metrics.duration_s < MIN_RECORD_S {
        return Err(AssessError::TooShort {
            samples: (seat.metrics.duration_s * fs).round(),
            seconds: seat.metrics.duration_s,
        });
    }
    let mut warnings = Vec::new();
    // A mean far beyond vibration is refused; the floor is the record under a seat.
    let judged_z = floor.map_or(seat.metrics, |f| f.metrics);
    check_band(Axis::Z, weighting, fs, &mean_z, &judged_z)?;
    warnings.extend(check_offset(
        Axis::Z,
        weighting,
        fs,
        mean_z.offset(),
        &judged_z,
    )?);
    warnings.extend(side.check_offsets()?);
    warnings.extend(filter.warning());
    let levels = bands.levels();
    let missing: Vec<String> = levels
        .iter()
        .filter(|b| b.1.is_none())
        .map(|b| format!("{}", b.0))
        .collect();
    if !missing.is_empty() {
        warnings.push(format!(
            "bands {} Hz are not computed: they reach 0.45 fs at {fs} Hz",
            missing.join(", ")
        ));
    }
    let mut axes = side.results(exposure_h);
    axes.set(Axis::Z, AxisResult::new(Axis::Z, seat.metrics, exposure_h));
    warnings.extend(axes_warnings(&axes));
    let health = Health::of(&axes).ok_or(AssessError::NoVertical)?;
    let comfort_vector = vector_sum(&axes);
    let bands = levels
        .iter()
        .map(|&(f_hz, l)| BandLevel {
            f_hz,
            seat: l.map(|l| l[0]),
            head: l.map(|l| l[1]),
        })
        .collect();
    Ok(Assessment {
        weighting,
        fs,
        duration_s: seat.metrics.duration_s,
        exposure_h,
        eu: health.eu,
        axes,
        health,
        comfort_vector,
        comfort_seat: comfort(comfort_vector),
        comfort_head: comfort(head_ch.metrics.aw),
        sickness_seat: sick_seat.sickness(exposure_h),
        sickness_head: sick_head.sickness(exposure_h),
        spine,
        points: points.results(comfort_vector),
        seat,
        head: head_ch,
        segments,
        bands,
        warnings,
        seat_value: floor.map(|f| SeatValue::of(&seat.metrics, &f.metrics)),
        floor,
        stroke: stroke.map(|s| s.finish()),
    })
}

mod seat;
mod stream;
#[cfg(test)]
mod tests;
