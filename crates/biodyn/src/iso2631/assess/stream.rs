//! The assessment's stream on two threads: the simulator and the
//! one-third-octave bands on the caller's, the weighted channels (seat,
//! segments, x and y, the other points, motion sickness, the spine) on a
//! second, blocks handed over in order; the same bits as on one thread.

use super::super::bands::BandBank;
use super::super::judgeable::Mean;
use super::super::metrics::Accumulator;
use super::super::per_axis::AxesAccumulator;
use super::super::points::{PointsAccumulator, Sample};
use super::super::sickness::SicknessAccumulator;
use super::super::spine::SpineAccumulator;
use super::super::weighting::WeightingFilter;
use super::seat::StrokeAccumulator;
use crate::simd::simd_fn;
use crate::time::{Axis, PointRow, Row, Simulator, TimeError};
use std::sync::mpsc;

pub(super) const BLOCK: usize = 4096;

/// Blocks in flight between the two threads: memory stays a few blocks.
const IN_FLIGHT: usize = 3;

/// The weighted channels, per sample: the seat and every segment weighted,
/// then their metrics, and the record's x and y axes. Runs on its own
/// thread beside the simulator.
pub(super) struct Channels {
    pub(super) w_seat: WeightingFilter,
    pub(super) w_seg: Vec<WeightingFilter>,
    pub(super) acc_seat: Accumulator,
    /// The record's z (the body's input, the floor under a seat): its mean.
    pub(super) mean_z: Mean,
    pub(super) acc_seg: Vec<Accumulator>,
    pub(super) width: usize,
    pub(super) side: AxesAccumulator,
    pub(super) points: PointsAccumulator,
    pub(super) head: usize,
    pub(super) sick_seat: SicknessAccumulator,
    pub(super) sick_head: SicknessAccumulator,
    pub(super) spine: Option<SpineAccumulator>,
    /// The pan's column in the simulator's rows, with a seat.
    pub(super) pan: Option<usize>,
    /// With a seat: the floor (the record) weighted, and the suspension's travel.
    pub(super) floor: Option<(WeightingFilter, Accumulator)>,
    pub(super) stroke: Option<StrokeAccumulator>,
}

impl Channels {
    /// One block: `blk.input` the seat samples, `blk.out` the simulator's
    /// rows, `blk.rows` the record's rows (x and y read from them).
    fn block(&mut self, blk: &Block) {
        channels_block(self, blk);
    }

    #[inline(always)]
    fn each_sample(&mut self, blk: &Block) {
        // The seat judged: the record itself, or with a seat the pan's motion.
        let judged = blk.judged();
        for (&a, y) in judged.iter().zip(blk.out.chunks_exact(self.width)) {
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
        for (&a, y) in judged.iter().zip(blk.out.chunks_exact(self.width)) {
            self.sick_seat.push(a);
            self.sick_head
                .push(y.get(self.head).copied().unwrap_or(0.0));
        }
        if let Some(sp) = &mut self.spine {
            for &a in judged {
                sp.push(a);
            }
        }
        for &a in &blk.input {
            self.mean_z.push(a);
        }
        if let Some((w, acc)) = &mut self.floor {
            for &a in &blk.input {
                acc.push(w.process(a));
            }
        }
        if let Some(st) = &mut self.stroke {
            // Only this block's rows: `out` is a reused buffer, and past the
            // last sample of a short block it holds an earlier block's rows.
            for y in blk.out.chunks_exact(self.width).take(blk.input.len()) {
                st.push(y);
            }
        }
    }
}

/// The one-third-octave bands of seat and head, on the simulator's thread.
pub(super) struct Spectra {
    pub(super) bands: BandBank<2>,
    pub(super) head: usize,
    pub(super) width: usize,
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
    /// With a seat: the pan's acceleration, read from `out`.
    pan: Vec<f64>,
}

impl Block {
    /// What the seat's channels judge: the pan's motion under a seat, else the input.
    fn judged(&self) -> &[f64] {
        if self.pan.is_empty() {
            &self.input
        } else {
            &self.pan
        }
    }
}

/// Reads the next block of `it` into `blk` and simulates it; false at the
/// end of the stream. The rows themselves are kept only where `rows` (a
/// record with x or y); the other points where the samples carry them.
fn fill<I, S>(
    it: &mut I,
    sim: &mut Simulator,
    blk: &mut Block,
    rows: bool,
    pan: Option<usize>,
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
    blk.pan.clear();
    if let Some(p) = pan {
        let width = sim.layout().len();
        let rows = blk.out.chunks_exact(width).take(blk.input.len());
        blk.pan.extend(rows.map(|y| y[p]));
    }
    Ok(true)
}

/// The stream through the simulator and the bands on this thread, the
/// weighted channels on a second one (blocks handed over through a bounded
/// channel, in order). Each channel sees the same samples in the same order
/// as on one thread, so the results are the same bits; where no second
/// thread can be had, everything runs here.
pub(super) fn stream<I, S>(
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
    let pan = channels.pan;
    let new_block = || Block {
        rows: Vec::with_capacity(BLOCK),
        points: Vec::new(),
        input: Vec::with_capacity(BLOCK),
        out: vec![0.0; BLOCK * width],
        pan: Vec::with_capacity(if pan.is_some() { BLOCK } else { 0 }),
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
                if !fill(it, sim, &mut blk, rows, pan)? {
                    break;
                }
                spectra.block(blk.judged(), &blk.out);
                // Fails only if the worker panicked, which the scope re-raises.
                if to_worker.send(blk).is_err() {
                    break;
                }
            }
            Ok(true)
        })?;
    if !threaded {
        let mut blk = new_block();
        while fill(it, sim, &mut blk, rows, pan)? {
            spectra.block(blk.judged(), &blk.out);
            channels.block(&blk);
        }
    }
    Ok(())
}
