//! A whole assessment in one streaming pass: simulate the body under the
//! seat record, weight the seat and every segment, accumulate the metrics
//! and the one-third-octave bands of seat and head. Memory: the 1 s MTVV
//! windows and a block of 4096 samples, whatever the record's length.

use super::bands::BandBank;
use super::metrics::{Accumulator, Exposure, Metrics};
use super::verdict::{Eu, additional_methods, comfort};
use super::weighting::{Weighting, WeightingFilter};
use crate::body::model::Body;
use crate::time::{Simulator, TimeError};

/// Longest exposure a day can hold, h.
pub const MAX_EXPOSURE_H: f64 = 24.0;

/// Why an assessment stopped.
#[derive(Debug, thiserror::Error)]
pub enum AssessError {
    #[error(transparent)]
    Time(#[from] TimeError),
    #[error("exposure {0:?} h: it must be > 0 and at most 24 h; e.g. --exposure 8")]
    BadExposure(f64),
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
    pub weighting: Weighting,
    pub fs: f64,
    pub duration_s: f64,
    pub exposure_h: f64,
    pub seat: Channel,
    pub head: Channel,
    /// Every segment, top to bottom, by name.
    pub segments: Vec<(String, Channel)>,
    /// The Directive judges the seat (the input), never the head.
    pub eu: Eu,
    pub comfort_seat: Vec<&'static str>,
    pub comfort_head: Vec<&'static str>,
    pub bands: Vec<BandLevel>,
    pub warnings: Vec<String>,
}

const BLOCK: usize = 4096;

/// Everything after the simulator, per sample: the weighting of the seat and
/// of every segment, their metrics, the bands of seat and head.
struct Pipeline {
    w_seat: WeightingFilter,
    w_seg: Vec<WeightingFilter>,
    acc_seat: Accumulator,
    acc_seg: Vec<Accumulator>,
    bands: BandBank<2>,
    head: usize,
    width: usize,
}

impl Pipeline {
    /// One block: `input` the seat samples, `out` the simulator's rows.
    fn block(&mut self, input: &[f64], out: &[f64]) {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU has AVX2, checked just above.
            unsafe { self.block_avx2(input, out) };
            return;
        }
        self.block_plain(input, out);
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn block_avx2(&mut self, input: &[f64], out: &[f64]) {
        self.block_plain(input, out);
    }

    #[inline(always)]
    fn block_plain(&mut self, input: &[f64], out: &[f64]) {
        for (&a, y) in input.iter().zip(out.chunks_exact(self.width)) {
            self.acc_seat.push(self.w_seat.process(a));
            self.bands
                .push([a, y.get(self.head).copied().unwrap_or(0.0)]);
            for ((wf, acc), &v) in self.w_seg.iter_mut().zip(self.acc_seg.iter_mut()).zip(y) {
                acc.push(wf.process(v));
            }
        }
    }
}

/// Assesses `samples` (seat acceleration, m/s², at `fs` Hz) for `body` over
/// an exposure of `exposure_h` hours; the first error of the stream stops it.
pub fn assess<I>(
    body: &Body,
    fs: f64,
    samples: I,
    exposure_h: f64,
    weighting: Weighting,
) -> Result<Assessment, AssessError>
where
    I: IntoIterator<Item = Result<f64, TimeError>>,
{
    if !(exposure_h.is_finite() && exposure_h > 0.0 && exposure_h <= MAX_EXPOSURE_H) {
        return Err(AssessError::BadExposure(exposure_h));
    }
    let mut sim = Simulator::new(body, fs).map_err(TimeError::from)?;
    let layout = sim.layout();
    let n = layout.segments;
    let head = sim.head();
    let filter = weighting.digital(fs);
    let mut p = Pipeline {
        w_seat: filter.clone(),
        w_seg: vec![filter.clone(); n],
        acc_seat: Accumulator::new(fs),
        acc_seg: vec![Accumulator::new(fs); n],
        bands: BandBank::<2>::new(fs),
        head,
        width: layout.len(),
    };
    let mut input = Vec::with_capacity(BLOCK);
    let mut out = vec![0.0; BLOCK * p.width];
    let mut it = samples.into_iter();
    loop {
        input.clear();
        for s in it.by_ref() {
            input.push(s?);
            if input.len() == BLOCK {
                break;
            }
        }
        if input.is_empty() {
            break;
        }
        sim.run(&input, &mut out);
        p.block(&input, &out);
    }
    let Pipeline {
        acc_seat,
        acc_seg,
        bands,
        ..
    } = p;

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
    warnings.extend(
        additional_methods(&seat.metrics)
            .into_iter()
            .map(|w| format!("seat: {w}")),
    );
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
        eu: Eu::of(&seat.exposure),
        comfort_seat: comfort(seat.metrics.aw),
        comfort_head: comfort(head_ch.metrics.aw),
        seat,
        head: head_ch,
        segments,
        bands,
        warnings,
    })
}
