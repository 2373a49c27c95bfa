//! The Study tab's frequency cursor: a line on the charts, and in the
//! legend (the peak table) each variant's magnitude there, computed by
//! that variant's own solver at exactly the cursor's frequency, never read
//! off the grid. `<`/`>` step along the band's grid, PgUp/PgDn by 1 Hz,
//! Home/End go to the band's ends, `g` to a typed frequency, a click to
//! the frequency under it.

use super::StudyTab;
use crate::tui::effect::Effect;
use crate::tui::popups::field::{Field, Purpose};
use crate::tui::shared::Shared;
use crate::tui::input::frequency_in_band;
use crate::view::format::num;
use biodyn::{Response, Band, Solver};
use biodyn::freq::Study;

/// The field tag of the go-to frequency (the value list is 0).
pub(super) const GOTO: usize = 1;

/// Where the cursor moves.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Move {
    /// One grid step down / up.
    Down,
    Up,
    /// 1 Hz (in grid steps) down / up.
    PageDown,
    PageUp,
    Start,
    End,
}

/// The frequency cursor and each variant's response there.
#[derive(Debug, Clone, Default)]
pub struct Cursor {
    /// Hz; None until a study is shown.
    pub f_hz: Option<f64>,
    /// Each variant's response at `f_hz`, in `Study::variants` order; None
    /// where the variant's solver could not be built.
    pub at: Vec<Option<Response>>,
    /// One solver per variant, built with the study's result.
    solvers: Vec<Option<Solver>>,
}

impl Cursor {
    /// A new study: its solvers, and the cursor kept where it was when it
    /// is still inside the band, else on the middle variant's STHT peak.
    pub(super) fn follow(&mut self, study: Option<&Study>, band: &Band) {
        let Some(st) = study else {
            *self = Cursor::default();
            return;
        };
        self.solvers = st
            .variants
            .iter()
            .map(|v| Solver::try_new(&v.body).ok())
            .collect();
        let inside = |f: f64| (band.from..=band.to).contains(&f);
        let f = match self.f_hz {
            Some(f) if inside(f) => f,
            _ => start(st, band),
        };
        self.set(f);
    }

    /// The cursor at `f_hz`, every variant computed there.
    pub(super) fn set(&mut self, f_hz: f64) {
        self.f_hz = Some(f_hz);
        self.at = self
            .solvers
            .iter()
            .map(|s| s.as_ref().map(|s| s.at(f_hz)))
            .collect();
    }

    /// The status line after a move: where the cursor is now, so an
    /// earlier "cursor at …" (from `g`) never stays behind, stale.
    pub(super) fn said(&self) -> Vec<Effect> {
        self.f_hz
            .map(|f| Effect::Status(format!("cursor at {} Hz", num(f, 8))))
            .into_iter()
            .collect()
    }

    /// Moves along the band's grid (from an off-grid frequency: to the
    /// grid point beyond it in that direction).
    pub(super) fn step(&mut self, m: Move, band: &Band) {
        let Some(f) = self.f_hz else {
            return;
        };
        let last = band.len().saturating_sub(1) as f64;
        let k = (f - band.from) / band.step;
        let per_hz = (1.0 / band.step).round().max(1.0);
        let i = match m {
            Move::Down => (k - 1e-6).ceil() - 1.0,
            Move::Up => (k + 1e-6).floor() + 1.0,
            Move::PageDown => (k - 1e-6).ceil() - per_hz,
            Move::PageUp => (k + 1e-6).floor() + per_hz,
            Move::Start => 0.0,
            Move::End => last,
        };
        self.set(band.freq(i.clamp(0.0, last) as usize));
    }
}

/// Where the cursor starts: the middle variant's main STHT peak, on the
/// grid (the band's middle when it has none).
fn start(st: &Study, band: &Band) -> f64 {
    let mid = st.variants.get(st.variants.len() / 2);
    let f = mid
        .and_then(|v| v.peaks.first().copied().flatten())
        .filter(|p| !p.at_edge)
        .map_or((band.from + band.to) / 2.0, |p| p.f_hz);
    let last = band.len().saturating_sub(1) as f64;
    let i = ((f - band.from) / band.step).round().clamp(0.0, last);
    band.freq(i as usize)
}

/// `f` to 4 significant digits: a click's frequency, as precise as a
/// column can tell and as the readout prints it.
pub(super) fn round4(f: f64) -> f64 {
    if !f.is_finite() || f <= 0.0 {
        return f;
    }
    let scale = 10f64.powi(3 - f.log10().floor() as i32);
    (f * scale).round() / scale
}

impl StudyTab {
    /// `g`: a field for the frequency, pre-filled with the cursor's.
    pub(super) fn go_to_field(&self, s: &Shared) -> Vec<Effect> {
        let b = s.band();
        let label = format!(
            "go to frequency, Hz ({}–{})",
            num(b.from, 6),
            num(b.to, 6)
        );
        vec![Effect::OpenField(Field::new(
            Purpose::Tab(GOTO),
            label,
            self.cursor.f_hz.map(|f| format!("{f}")).unwrap_or_default(),
        ))]
    }

    /// The `g` field was committed: the cursor at exactly that frequency,
    /// every variant computed there. Err keeps the field open.
    pub(super) fn go_to(&mut self, text: &str, s: &Shared) -> Result<Vec<Effect>, String> {
        if !matches!(self.result, Some(Ok(_))) {
            return Err("no study shown yet: Enter edits the values".into());
        }
        let f = frequency_in_band(text, s.band())?;
        self.cursor.set(f);
        Ok(vec![Effect::Status(format!(
            "cursor at {} Hz, every variant computed there",
            num(f, 8)
        ))])
    }
}
