//! The paper's trainer: online error back-propagation with momentum,
//! Δw(t) = LR·δ_j·X_i + M·Δw(t−1), one pattern at a time, in an order
//! shuffled each epoch from the seeded generator.
//!
//! The epoch's RMS, MPRE and share right are taken from each pattern's
//! output just before its own update, as online trainers traditionally
//! report them: it costs no extra pass. The final report recomputes them
//! with a clean pass over the finished network.

mod epoch;
mod fixed;
mod general;

use self::fixed::{Net3, Net4, run_fixed};
use self::general::run_general;
use crate::ann::algorithm::{Algorithm, Member};
use crate::ann::encoded::Encoded;
use crate::ann::metrics::EpochStats;
use crate::ann::network::Network;
use crate::ann::settings::{Settings, Trainer};
use crate::ann::stop::{Flow, Halt, StopReason};
use crate::rng::Rng;

/// The `Algorithm` of this file.
pub struct Backprop;

impl Algorithm for Backprop {
    fn trainer(&self) -> Trainer {
        Trainer::Backprop
    }

    fn run(
        &self,
        net: &mut Network,
        job: Member<'_>,
        observe: &mut dyn FnMut(&EpochStats) -> Flow,
    ) -> (StopReason, u64) {
        run_backprop(
            net,
            job.data,
            job.settings,
            job.rng,
            job.index,
            job.halt,
            observe,
        )
    }
}

/// Trains `net` in place; returns why it stopped and the epochs done.
///
/// The paper's three architectures get their own copies of the loop with
/// the layer sizes as constants (`Dense` layers of fixed-size arrays), so
/// the compiler unrolls the tiny inner loops and no index is checked; the
/// arithmetic, and so every bit of the result, is the same as for any other
/// architecture (a test checks it against the general loop and against
/// `Network::backprop_step`).
pub fn run_backprop(
    net: &mut Network,
    data: &Encoded,
    settings: &Settings,
    rng: &mut Rng,
    member: usize,
    halt: Halt<'_>,
    observe: &mut dyn FnMut(&EpochStats) -> Flow,
) -> (StopReason, u64) {
    let layers = net.layers.clone();
    let args = (data, settings, rng, member, halt, observe);
    match layers.as_slice() {
        [2, 5, 3, 1] => run_fixed::<2, Net3<2, 5, 3>>(net, args),
        [5, 6, 4, 1] => run_fixed::<5, Net3<5, 6, 4>>(net, args),
        [5, 6, 4, 2, 1] => run_fixed::<5, Net4<5, 6, 4, 2>>(net, args),
        other => run_general(other, net, args),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ann::case::Case;
    use crate::ann::dataset::Dataset;
    use crate::ann::network::Activation;

    fn general(net: &mut Network, enc: &Encoded, s: &Settings, seed: u64) -> (StopReason, u64) {
        let layers: Vec<usize> = std::hint::black_box(net.layers.clone());
        let mut rng = Rng::new(seed);
        let mut observe = |_: &EpochStats| Flow::Continue;
        run_general(
            &layers,
            net,
            (enc, s, &mut rng, 0, Halt::default(), &mut observe),
        )
    }

    /// The fixed-shape copies must give the very bits of the general loop
    /// and of `Network::backprop_step`, for each of the paper's shapes.
    #[test]
    fn fixed_loops_equal_general_loop_and_network_step() {
        for case in [Case::K4Stht, Case::MassDpmi, Case::MassStht] {
            let mut s = Settings::paper(case);
            s.epochs = 3;
            s.stop_when_all_right = false;
            let data = Dataset::build(case, &s.train_values, &s.grid).unwrap();
            let enc = Encoded::new(&data, &s).unwrap();
            let net0 = Network::new(&s.layers, s.activation, 1.0, 0.5, &mut Rng::new(9)).unwrap();
            let mut fast = net0.clone();
            run_backprop(
                &mut fast,
                &enc,
                &s,
                &mut Rng::new(4),
                0,
                Halt::default(),
                &mut |_| Flow::Continue,
            );
            let mut slow = net0.clone();
            general(&mut slow, &enc, &s, 4);
            assert_eq!(fast.params, slow.params, "{case}");
            // Against the Network methods, pattern by pattern.
            let mut reference = net0.clone();
            let mut rng = Rng::new(4);
            let mut order: Vec<usize> = (0..enc.x.len()).collect();
            let mut dprev = vec![0.0; reference.params.len()];
            let mut sc = reference.scratch();
            for _ in 0..3 {
                rng.shuffle(&mut order);
                for &p in &order {
                    let e = enc.d[p] - reference.forward(&enc.x[p], &mut sc)[0];
                    reference.backprop_step(&mut sc, e, 1.0, 0.9, &mut dprev);
                }
            }
            assert_eq!(fast.params, reference.params, "{case}");
        }
    }

    /// Input noise, tanh, a linear output and per-epoch statistics take the
    /// same course in both loops too.
    #[test]
    fn fixed_and_general_loops_agree_on_the_options() {
        let case = Case::MassStht;
        let s0 = Settings::paper(case);
        let data = Dataset::build(case, &s0.train_values, &s0.grid).unwrap();
        for (act, linear, noise) in [
            (Activation::Logistic, false, 0.02),
            (Activation::Tanh, true, 0.0),
            (Activation::Tanh, false, 0.01),
        ] {
            let mut s = Settings::paper(case);
            s.epochs = 4;
            s.stop_when_all_right = false;
            s.activation = act;
            s.input_noise = noise;
            s.linear_output = linear;
            let enc = Encoded::new(&data, &s).unwrap();
            let mut net0 = Network::new(&s.layers, act, 1.0, 0.5, &mut Rng::new(2)).unwrap();
            net0.linear_output = linear;
            let mut fast = net0.clone();
            let mut seen_fast = Vec::new();
            run_backprop(
                &mut fast,
                &enc,
                &s,
                &mut Rng::new(6),
                0,
                Halt::default(),
                &mut |e| {
                    seen_fast.push((e.rms.to_bits(), e.mpre_pct.to_bits(), e.share_right));
                    Flow::Continue
                },
            );
            let mut slow = net0.clone();
            let mut seen_slow = Vec::new();
            let layers: Vec<usize> = std::hint::black_box(slow.layers.clone());
            let mut observe = |e: &EpochStats| {
                seen_slow.push((e.rms.to_bits(), e.mpre_pct.to_bits(), e.share_right));
                Flow::Continue
            };
            let args = (
                &enc,
                &s,
                &mut Rng::new(6),
                0,
                Halt::default(),
                &mut observe as _,
            );
            run_general(&layers, &mut slow, args);
            assert_eq!(fast.params, slow.params, "{act:?} {linear} {noise}");
            assert_eq!(seen_fast, seen_slow);
            assert_ne!(fast.params, net0.params);
        }
    }
}
