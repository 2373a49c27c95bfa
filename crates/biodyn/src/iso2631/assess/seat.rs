//! With a seat under the body (SPEC §11): the suspension's travel over the
//! record, and the seat's effective amplitude transmissibility (ISO 10326-1:
//! SEAT = a_w at the pan over a_w at the floor, and the VDV ratio beside it).

use super::super::metrics::Metrics;

/// The travel: the suspension link's deflection (upper minus lower end).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stroke {
    /// Largest |deflection|, m.
    pub peak_m: f64,
    /// r.m.s. of the deflection, m.
    pub rms_m: f64,
    /// Travel end-stop to end-stop, m.
    pub available_m: f64,
    /// Excursions beyond ±available/2 (each counted once, from its first
    /// sample past the stop until it comes back): the linear model has no
    /// end-stop, so past it the pan's figures are no longer the seat's.
    pub hits: u64,
}

/// SEAT from the record: 100 · a_w,pan / a_w,floor, and 100 · VDV,pan / VDV,floor.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SeatValue {
    pub seat_pct: f64,
    pub vdv_pct: f64,
}

impl SeatValue {
    pub fn of(pan: &Metrics, floor: &Metrics) -> SeatValue {
        SeatValue {
            seat_pct: 100.0 * pan.aw / floor.aw,
            vdv_pct: 100.0 * pan.vdv / floor.vdv,
        }
    }
}

/// Accumulates the travel from the simulator's rows.
#[derive(Debug, Clone)]
pub(crate) struct StrokeAccumulator {
    /// The deflection's column in a row.
    col: usize,
    available: f64,
    peak: f64,
    sum_sq: f64,
    n: u64,
    hits: u64,
    out: bool,
}

impl StrokeAccumulator {
    pub(crate) fn new(col: usize, available: f64) -> StrokeAccumulator {
        StrokeAccumulator {
            col,
            available,
            peak: 0.0,
            sum_sq: 0.0,
            n: 0,
            hits: 0,
            out: false,
        }
    }

    #[inline]
    pub(crate) fn push(&mut self, row: &[f64]) {
        let d = row.get(self.col).copied().unwrap_or(0.0);
        self.peak = self.peak.max(d.abs());
        self.sum_sq += d * d;
        self.n += 1;
        let past = d.abs() > self.available / 2.0;
        if past && !self.out {
            self.hits += 1;
        }
        self.out = past;
    }

    pub(crate) fn finish(&self) -> Stroke {
        Stroke {
            peak_m: self.peak,
            rms_m: (self.sum_sq / self.n.max(1) as f64).sqrt(),
            available_m: self.available,
            hits: self.hits,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hits_count_excursions_not_samples() {
        let mut s = StrokeAccumulator::new(0, 0.1);
        for d in [0.0, 0.06, 0.07, 0.02, -0.051, -0.06, 0.0, 0.049] {
            s.push(&[d]);
        }
        let r = s.finish();
        assert_eq!(r.hits, 2);
        assert_eq!(r.peak_m, 0.07);
        let ss: f64 = [0.0, 0.06, 0.07, 0.02, -0.051, -0.06, 0.0, 0.049f64]
            .iter()
            .map(|d| d * d)
            .sum();
        assert!((r.rms_m - (ss / 8.0).sqrt()).abs() < 1e-15);
    }
}
