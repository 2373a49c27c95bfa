//! The time window of the traces: the record / 2^zoom, moved by `<`/`>`,
//! zoomed by `+`/`-` about its middle or by the wheel about the pointer,
//! centred by a click.

use super::{MAX_ZOOM, VibrationTab};

impl VibrationTab {
    /// Window of the time axis as (start, length), s from the record start.
    pub fn window(&self, total: f64) -> (f64, f64) {
        let len = total / f64::from(1u32 << self.zoom.min(MAX_ZOOM));
        let start = (self.offset * total).clamp(0.0, (total - len).max(0.0));
        (start, len)
    }

    /// `+`/`-`: zooms about the window's middle.
    pub(super) fn zoom_by(&mut self, d: i32) {
        let Some(total) = self.outcome().map(|o| o.traces.duration()) else {
            return;
        };
        let (start, len) = self.window(total);
        self.zoom_about(d, start + len / 2.0, 0.5);
    }

    /// Zooms by 2^d keeping time `at` (s from the record's start) where it
    /// is, a fraction `frac` across the window (the wheel: under the pointer).
    pub(super) fn zoom_about(&mut self, d: i32, at: f64, frac: f64) {
        let Some(total) = self.outcome().map(|o| o.traces.duration()) else {
            return;
        };
        let min_len = self.outcome().map_or(0.0, |o| 8.0 / o.traces.fs.max(1e-9));
        let z = (self.zoom as i32 + d).clamp(0, MAX_ZOOM as i32) as u32;
        let new_len = total / f64::from(1u32 << z);
        if d > 0 && new_len < min_len {
            return;
        }
        self.zoom = z;
        self.offset = if total > 0.0 {
            ((at - frac * new_len) / total).clamp(0.0, 1.0 - new_len / total)
        } else {
            0.0
        };
    }

    /// Moves the window so that time `at` (s from the record's start) is
    /// in its middle, as far as the record allows.
    pub(super) fn centre_on(&mut self, at: f64) {
        let Some(total) = self.outcome().map(|o| o.traces.duration()) else {
            return;
        };
        let (_, len) = self.window(total);
        self.offset = if total > 0.0 {
            ((at - len / 2.0) / total).clamp(0.0, (1.0 - len / total).max(0.0))
        } else {
            0.0
        };
    }

    pub(super) fn scroll(&mut self, d: f64) {
        let step = 0.25 / f64::from(1u32 << self.zoom);
        let len = 1.0 / f64::from(1u32 << self.zoom);
        self.offset = (self.offset + d * step).clamp(0.0, (1.0 - len).max(0.0));
    }

    pub(super) fn whole(&mut self) {
        self.zoom = 0;
        self.offset = 0.0;
    }
}
