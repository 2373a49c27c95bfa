use super::stream::BLOCK;
use super::*;

/// Two threads give the bits of one, and an error mid-stream stops both.
#[test]
fn two_threads_change_no_bit() {
    let body = Body::paper(75.0).unwrap();
    let fs = 500.0;
    let input: Vec<f64> = (0..3 * BLOCK + 77)
        .map(|k| (k as f64 * 0.21).sin() * 2.0 + (k as f64 * 0.013).cos())
        .collect();
    let mut xy = PerAxis::default();
    xy.set(Axis::X, ());
    xy.set(Axis::Y, ());
    let run = |two: bool, fail_at: Option<usize>| {
        let mut sim = Simulator::new(&body, fs).unwrap();
        let width = sim.layout().len();
        let filter = Weighting::Wk.digital(fs);
        let mut ch = Channels {
            w_seat: filter.clone(),
            w_seg: vec![filter.clone(); 4],
            acc_seat: Accumulator::new(fs),
            mean_z: Default::default(),
            acc_seg: vec![Accumulator::new(fs); 4],
            width,
            side: AxesAccumulator::new(&xy, fs),
            points: PointsAccumulator::new(&PerPoint::default(), fs),
            head: 0,
            sick_seat: SicknessAccumulator::new(fs),
            sick_head: SicknessAccumulator::new(fs),
            spine: Some(SpineAccumulator::new(fs)),
            pan: None,
            floor: None,
            stroke: None,
        };
        let mut sp = Spectra {
            bands: BandBank::<2>::new(fs),
            head: 0,
            width,
        };
        let mut it = input.iter().enumerate().map(|(k, &v)| {
            if Some(k) == fail_at {
                Err(TimeError::BadDuration(-1.0))
            } else {
                Ok([0.3 * v, (k as f64 * 0.05).sin(), v])
            }
        });
        let r = stream(&mut it, &mut sim, &mut sp, &mut ch, two);
        let mut bits: Vec<u64> = Vec::new();
        for a in std::iter::once(&ch.acc_seat).chain(&ch.acc_seg) {
            let m = a.metrics();
            bits.extend([m.aw, m.peak, m.mtvv, m.vdv].map(f64::to_bits));
        }
        for sick in [&ch.sick_seat, &ch.sick_head] {
            let m = sick.sickness(1.0);
            bits.extend([m.aw, m.msdv].map(f64::to_bits));
        }
        if let Some(sp) = ch.spine.clone() {
            let p = Person::new(30.0, 5, 200, crate::iso2631::spine::Sex::Male).unwrap();
            if let Ok(sp) = sp.finish(&p, 8.0) {
                bits.extend([sp.dose.dz, sp.risk.r].map(f64::to_bits));
                bits.push(sp.dose.count);
            }
        }
        for (_, m) in ch.side.metrics().iter() {
            bits.extend([m.aw, m.peak, m.mtvv, m.vdv].map(f64::to_bits));
        }
        for (_, l) in sp.bands.levels() {
            bits.extend(l.into_iter().flatten().map(f64::to_bits));
        }
        (r.is_ok(), bits)
    };
    let (ok1, one) = run(false, None);
    let (ok2, two) = run(true, None);
    assert!(ok1 && ok2);
    assert_eq!(one, two);
    assert!(!run(true, Some(2 * BLOCK + 5)).0);
}
