//! A record's trace in bounded memory, drawn so that no peak disappears.
//!
//! Samples go into buckets of `per` samples, each keeping its min and max.
//! While the record fits in `MAX_BUCKETS`, a bucket is one sample; past it,
//! neighbouring buckets merge pairwise (`per` doubles), so an hour at 1 kHz
//! costs 4 MB a trace instead of 29. Drawing asks for one (min, max) per
//! screen column over any time window: every sample falls in exactly one
//! column, so the extremes of the record are always on screen.

/// Buckets kept per trace (each two f32).
pub const MAX_BUCKETS: usize = 1 << 18;

#[derive(Debug, Clone, PartialEq)]
pub struct Envelope {
    /// Samples per bucket (a power of two).
    pub per: usize,
    min: Vec<f32>,
    max: Vec<f32>,
    /// Samples in the last bucket (0: it is full, or there is none).
    fill: usize,
    /// Samples pushed.
    pub len: usize,
    /// Largest |sample|, for a y range that does not jump while scrolling.
    pub abs_max: f64,
}

impl Default for Envelope {
    fn default() -> Self {
        Envelope {
            per: 1,
            min: Vec::new(),
            max: Vec::new(),
            fill: 0,
            len: 0,
            abs_max: 0.0,
        }
    }
}

impl Envelope {
    pub fn push(&mut self, x: f64) {
        let v = x as f32;
        if self.fill == 0 {
            if self.min.len() == MAX_BUCKETS {
                self.halve();
            }
            self.min.push(v);
            self.max.push(v);
        } else if let (Some(lo), Some(hi)) = (self.min.last_mut(), self.max.last_mut()) {
            *lo = lo.min(v);
            *hi = hi.max(v);
        }
        self.fill = (self.fill + 1) % self.per;
        self.len += 1;
        if x.is_finite() {
            self.abs_max = self.abs_max.max(x.abs());
        }
    }

    /// Merges bucket pairs: half the buckets, each twice as long.
    fn halve(&mut self) {
        let merge = |v: &mut Vec<f32>, f: fn(f32, f32) -> f32| {
            let n = v.len() / 2;
            for i in 0..n {
                v[i] = f(v[2 * i], v[2 * i + 1]);
            }
            v.truncate(n);
        };
        merge(&mut self.min, f32::min);
        merge(&mut self.max, f32::max);
        self.per *= 2;
    }

    /// Number of buckets held (memory check in tests).
    pub fn buckets(&self) -> usize {
        self.min.len()
    }

    /// One (min, max) per column for samples `from..to` split evenly into
    /// `cols` columns; a column narrower than a bucket shows that bucket.
    /// Empty when there is nothing to show.
    pub fn columns(&self, from: usize, to: usize, cols: usize) -> Vec<(f64, f64)> {
        let to = to.min(self.len);
        if cols == 0 || from >= to || self.min.is_empty() {
            return Vec::new();
        }
        let span = (to - from) as f64;
        let last = self.min.len() - 1;
        (0..cols)
            .map(|c| {
                let a = from + (span * c as f64 / cols as f64).floor() as usize;
                let b = from + (span * (c + 1) as f64 / cols as f64).floor() as usize;
                let (b0, b1) = (a / self.per, (b.max(a + 1) - 1) / self.per);
                let (b0, b1) = (b0.min(last), b1.min(last));
                let lo = self.min[b0..=b1]
                    .iter()
                    .copied()
                    .fold(f32::INFINITY, f32::min);
                let hi = self.max[b0..=b1]
                    .iter()
                    .copied()
                    .fold(f32::NEG_INFINITY, f32::max);
                (f64::from(lo), f64::from(hi))
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_single_spike_survives_any_decimation_and_memory_stays_bounded() {
        let mut e = Envelope::default();
        let n = 3 * MAX_BUCKETS + 17;
        let spike = 500_001;
        for i in 0..n {
            e.push(if i == spike {
                50.0
            } else {
                (i as f64 * 0.01).sin()
            });
        }
        assert_eq!(e.len, n);
        assert!(e.buckets() <= MAX_BUCKETS, "{}", e.buckets());
        assert_eq!(e.per, 4);
        for cols in [1, 7, 80, 313, 1000] {
            let c = e.columns(0, n, cols);
            assert_eq!(c.len(), cols);
            let hi = c.iter().map(|p| p.1).fold(f64::MIN, f64::max);
            let lo = c.iter().map(|p| p.0).fold(f64::MAX, f64::min);
            assert_eq!(hi, 50.0, "{cols} columns");
            assert!(lo <= -0.999, "{cols} columns: {lo}");
        }
        // a window that holds the spike shows it, one that does not, not
        let c = e.columns(spike - 10, spike + 10, 5);
        assert!(c.iter().any(|p| p.1 == 50.0));
        let c = e.columns(spike + 100, spike + 1000, 5);
        assert!(c.iter().all(|p| p.1 < 2.0));
    }

    #[test]
    fn short_records_keep_every_sample() {
        let mut e = Envelope::default();
        for i in 0..10 {
            e.push(f64::from(i));
        }
        assert_eq!(e.per, 1);
        // more columns than samples: each column shows its sample
        let c = e.columns(0, 10, 20);
        assert_eq!(c[0], (0.0, 0.0));
        assert_eq!(c[19], (9.0, 9.0));
        assert_eq!(e.columns(0, 10, 2), vec![(0.0, 4.0), (5.0, 9.0)]);
        assert!(e.columns(5, 5, 3).is_empty());
    }
}
