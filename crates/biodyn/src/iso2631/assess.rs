//! A whole assessment in one streaming pass: simulate the body under the
//! seat record, weight the seat and every segment, accumulate the metrics
//! and the one-third-octave bands of seat and head. Memory: the 1 s MTVV
//! windows and a few blocks of 4096 samples, whatever the record's length.
//! Two threads: the simulator and the bands on the caller's, the weighted
//! channels and their metrics on a second (the same bits as on one).

use super::bands::BandBank;
use super::metrics::{Accumulator, Exposure, Metrics};
use super::per_axis::{AxesAccumulator, AxisResult, Health, vector_sum};
use super::points::{PointsAccumulator, PointsComfort, Sample};
use super::verdict::{Eu, additional_methods, comfort};
use super::weighting::{Weighting, WeightingFilter};
use crate::body::model::Body;
use crate::simd::simd_fn;
use crate::time::{Axis, PerAxis, PerPoint, PointRow, Row, Simulator, TimeError};
use std::sync::mpsc;

/// Longest exposure a day can hold, h.
pub const MAX_EXPOSURE_H: f64 = 24.0;

/// Why an assessment stopped.
#[derive(Debug, thiserror::Error)]
pub enum AssessError {
    #[error(transparent)]
    Time(#[from] TimeError),
    #[error("exposure {0:?} h: it must be > 0 and at most 24 h")]
    BadExposure(f64),
    #[error(
        "the record has no z (vertical) axis: the body model is driven vertically; name the z column"
    )]
    NoVertical,
}

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
    /// Comfort at the other points and overall, where the record has them.
    pub points: Option<PointsComfort>,
    pub bands: Vec<BandLevel>,
    pub warnings: Vec<String>,
}

const BLOCK: usize = 4096;

/// Blocks in flight between the two threads: memory stays a few blocks.
const IN_FLIGHT: usize = 3;

/// The weighted channels, per sample: the seat and every segment weighted,
/// then their metrics, and the record's x and y axes. Runs on its own
/// thread beside the simulator.
struct Channels {
    w_seat: WeightingFilter,
    w_seg: Vec<WeightingFilter>,
    acc_seat: Accumulator,
    acc_seg: Vec<Accumulator>,
    width: usize,
    side: AxesAccumulator,
    points: PointsAccumulator,
}

impl Channels {
    /// One block: `blk.input` the seat samples, `blk.out` the simulator's
    /// rows, `blk.rows` the record's rows (x and y read from them).
    fn block(&mut self, blk: &Block) {
        channels_block(self, blk);
    }

    #[inline(always)]
    fn each_sample(&mut self, blk: &Block) {
        for (&a, y) in blk.input.iter().zip(blk.out.chunks_exact(self.width)) {
            self.acc_seat.push(self.w_seat.process(a));
            for ((wf, acc), &v) in self.w_seg.iter_mut().zip(self.acc_seg.iter_mut()).zip(y) {
                acc.push(wf.process(v));
            }
        }
        if !self.side.is_empty() {
            for r in &blk.rows {
                self.side.push(r);
            }
        }
        self.points.push_all(&blk.points);
    }
}

/// The one-third-octave bands of seat and head, on the simulator's thread.
struct Spectra {
    bands: BandBank<2>,
    head: usize,
    width: usize,
}

impl Spectra {
    fn block(&mut self, input: &[f64], out: &[f64]) {
        spectra_block(self, input, out);
    }

    #[inline(always)]
    fn each_sample(&mut self, input: &[f64], out: &[f64]) {
        for (&a, y) in input.iter().zip(out.chunks_exact(self.width)) {
            self.bands
                .push([a, y.get(self.head).copied().unwrap_or(0.0)]);
        }
    }
}

simd_fn! {
    /// [`Channels::block`], compiled for the crate's SIMD targets.
    fn channels_block(c: &mut Channels, blk: &Block) {
        c.each_sample(blk);
    }
}

simd_fn! {
    /// [`Spectra::block`], compiled for the crate's SIMD targets.
    fn spectra_block(s: &mut Spectra, input: &[f64], out: &[f64]) {
        s.each_sample(input, out);
    }
}

/// One block of the record's rows, their seat (z) samples and the
/// simulator's rows for them.
struct Block {
    rows: Vec<Row>,
    /// The other points' channels, kept only where the record has them.
    points: Vec<PointRow>,
    input: Vec<f64>,
    out: Vec<f64>,
}

/// Reads the next block of `it` into `blk` and simulates it; false at the
/// end of the stream. The rows themselves are kept only where `rows` (a
/// record with x or y); the other points where the samples carry them.
fn fill<I, S>(
    it: &mut I,
    sim: &mut Simulator,
    blk: &mut Block,
    rows: bool,
) -> Result<bool, TimeError>
where
    I: Iterator<Item = Result<S, TimeError>>,
    S: Sample,
{
    blk.input.clear();
    blk.rows.clear();
    blk.points.clear();
    for s in it.by_ref() {
        let s = s?;
        let row = s.seat();
        blk.input.push(row[Axis::Z.index()]);
        if rows {
            blk.rows.push(row);
        }
        s.keep_points(&mut blk.points);
        if blk.input.len() == BLOCK {
            break;
        }
    }
    if blk.input.is_empty() {
        return Ok(false);
    }
    sim.run(&blk.input, &mut blk.out);
    Ok(true)
}

/// The stream through the simulator and the bands on this thread, the
/// weighted channels on a second one (blocks handed over through a bounded
/// channel, in order). Each channel sees the same samples in the same order
/// as on one thread, so the results are the same bits; where no second
/// thread can be had, everything runs here.
fn stream<I, S>(
    it: &mut I,
    sim: &mut Simulator,
    spectra: &mut Spectra,
    channels: &mut Channels,
    two: bool,
) -> Result<(), TimeError>
where
    I: Iterator<Item = Result<S, TimeError>>,
    S: Sample,
{
    let width = sim.layout().len();
    let rows = !channels.side.is_empty();
    let new_block = || Block {
        rows: Vec::with_capacity(BLOCK),
        points: Vec::new(),
        input: Vec::with_capacity(BLOCK),
        out: vec![0.0; BLOCK * width],
    };
    let threaded = two
        && std::thread::scope(|scope| {
            let (to_worker, todo) = mpsc::sync_channel::<Block>(IN_FLIGHT);
            let (to_main, spare) = mpsc::channel::<Block>();
            let worker = std::thread::Builder::new().spawn_scoped(scope, || {
                let to_main = to_main;
                for blk in todo {
                    channels.block(&blk);
                    // The main thread may have stopped on an error: nothing to return to.
                    let _ = to_main.send(blk);
                }
            });
            if worker.is_err() {
                return Ok::<bool, TimeError>(false);
            }
            let mut made = 0;
            loop {
                let mut blk = match spare.try_recv() {
                    Ok(b) => b,
                    Err(_) if made <= IN_FLIGHT => {
                        made += 1;
                        new_block()
                    }
                    Err(_) => spare.recv().unwrap_or_else(|_| new_block()),
                };
                // An error drops `to_worker` on return: the worker finishes and the scope joins it.
                if !fill(it, sim, &mut blk, rows)? {
                    break;
                }
                spectra.block(&blk.input, &blk.out);
                // Fails only if the worker panicked, which the scope re-raises.
                if to_worker.send(blk).is_err() {
                    break;
                }
            }
            Ok(true)
        })?;
    if !threaded {
        let mut blk = new_block();
        while fill(it, sim, &mut blk, rows)? {
            spectra.block(&blk.input, &blk.out);
            channels.block(&blk);
        }
    }
    Ok(())
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
    assess_points(body, fs, rows, present, &PerPoint::default(), exposure_h)
}

/// As [`assess_axes`], and comfort at the other points `points` the
/// samples carry (the backrest, the feet, the seat's rotations), weighted
/// beside x and y.
pub fn assess_points<I, S>(
    body: &Body,
    fs: f64,
    rows: I,
    present: &PerAxis<()>,
    points: &PerPoint<()>,
    exposure_h: f64,
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
    let weighting = super::axes::rule(Axis::Z).weighting;
    let mut horizontal = PerAxis::default();
    for a in present.axes().filter(|&a| a != Axis::Z) {
        horizontal.set(a, ());
    }
    let mut sim = Simulator::new(body, fs).map_err(TimeError::from)?;
    let layout = sim.layout();
    let n = layout.segments;
    let head = sim.head();
    let filter = weighting.digital(fs);
    let mut channels = Channels {
        w_seat: filter.clone(),
        w_seg: vec![filter.clone(); n],
        acc_seat: Accumulator::new(fs),
        acc_seg: vec![Accumulator::new(fs); n],
        width: layout.len(),
        side: AxesAccumulator::new(&horizontal, fs),
        points: PointsAccumulator::new(points, fs),
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
        acc_seg,
        side,
        points,
        ..
    } = channels;
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
    let mut warnings = Vec::new();
    if seat.metrics.duration_s < 2.0 {
        warnings.push(format!(
            "the record is {} samples long: too short to judge",
            (seat.metrics.duration_s * fs).round()
        ));
    }
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
    let one = axes.iter().count() == 1;
    for (a, r) in axes.iter() {
        let at = if one {
            "seat".to_string()
        } else {
            format!("seat {a}")
        };
        warnings.extend(
            additional_methods(&r.metrics)
                .into_iter()
                .map(|w| format!("{at}: {w}")),
        );
    }
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
        points: points.results(comfort_vector),
        seat,
        head: head_ch,
        segments,
        bands,
        warnings,
    })
}

#[cfg(test)]
mod tests;
