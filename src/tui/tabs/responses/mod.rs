//! Tab Responses: STHT, DPMI and APMS over the band (magnitude or phase,
//! linear or log axes), a frequency cursor that reads the exact values of
//! all three, and the main peaks marked. Measured data can be laid over
//! the charts (`data.rs`) and the model fitted to them (`fit.rs` the
//! dialog's state and thread, `fit_keys.rs` its keys, `fit_view.rs` its
//! drawing); `bindings.rs` is the tab's key table, `view.rs` draws the tab. `extras.rs` holds the export (`x`),
//! the readout copy (`y`), the go-to frequency (`g`) and the mouse;
//! `compare.rs` a second model laid over the charts (`c`).

mod bindings;
mod compare;
mod data;
mod extras;
pub mod fit;
mod fit_keys;
mod fit_view;
mod tags;
mod view;

#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_compare;
#[cfg(test)]
mod tests_cursor;
#[cfg(test)]
mod tests_narrow;

use bindings::{Action, KEYS};
use tags::{TAG_COMPARE, TAG_DATA, TAG_GOTO};
pub use compare::Compare;
pub use data::DataOverlay;
pub use fit::{FitDialog, Stage};

use crate::tui::component::{Change, Cx, Mouse, Tab};
use crate::tui::effect::Effect;
use crate::tui::popups::field::{Field, Purpose};
use crate::tui::keys::{self, Doc};
use crate::tui::shared::Shared;
use crate::view::chart;
use ratatui::buffer::Buffer;
use ratatui::crossterm::event::KeyEvent;
use ratatui::layout::Rect;
use std::any::Any;

#[derive(Debug)]
pub struct ResponsesTab {
    pub phase: bool,
    pub log: bool,
    /// Index into the band's grid.
    pub cursor: usize,
    /// The band `cursor` indexes: when the band changes, the cursor keeps
    /// its frequency (the new grid's nearest point), not its index.
    grid: Option<biodyn::Band>,
    /// The response at a frequency off the grid (`g`, `n`), shown by the
    /// readout and the cursor until the cursor moves.
    pub exact: Option<biodyn::Response>,
    /// The current function (index in `Function::ALL`).
    pub func: usize,
    /// A second model over the charts; kept while the model changes.
    pub compare: Option<Compare>,
    /// What the compare field offers next time (the last path typed).
    compare_path: String,
    /// The line `y` copied, shown whole above the charts (the status line
    /// cuts it at 80 columns) until the next key.
    pub copied: Option<String>,
    /// The width the tab was last drawn at: `y` puts the line on the
    /// status line only when it fits there.
    drawn_width: std::cell::Cell<u16>,
    /// Put the cursor on the STHT peak once the curves are there (a new model).
    to_peak: bool,
    /// Measured data over the charts; kept while the model changes.
    pub data: Option<DataOverlay>,
    /// What the data field offers next time (the last path typed).
    data_path: String,
    /// The fit dialog, while open (over the charts).
    pub fit: Option<FitDialog>,
    /// The charts' series with the data laid over (`view::overlaid`).
    overlaid: Vec<Vec<chart::Series>>,
}

impl Default for ResponsesTab {
    fn default() -> Self {
        let example = std::path::Path::new(data::EXAMPLE).is_file();
        ResponsesTab {
            phase: false,
            log: false,
            cursor: 0,
            grid: None,
            exact: None,
            func: 0,
            compare: None,
            compare_path: String::new(),
            copied: None,
            drawn_width: std::cell::Cell::new(0),
            to_peak: true,
            data: None,
            data_path: if example {
                data::EXAMPLE.into()
            } else {
                String::new()
            },
            fit: None,
            overlaid: Vec::new(),
        }
    }
}

impl ResponsesTab {
    fn act(&mut self, a: Action, s: &Shared) -> Vec<Effect> {
        match a {
            Action::LoadData => {
                // A file path: Tab completes it (issue 19 item 15).
                return vec![Effect::OpenField(
                    Field::new(Purpose::Tab(TAG_DATA), "measured data, CSV", self.data_path.clone())
                        .for_path(),
                )];
            }
            Action::ClearData => {
                self.overlaid.clear();
                return match self.data.take() {
                    Some(_) => vec![Effect::Status("measured data cleared".into())],
                    None => vec![Effect::Error("no measured data to clear".into())],
                };
            }
            Action::Fit if self.data.is_none() => {
                return vec![Effect::Error(
                    "no measured data to fit: D loads a file first".into(),
                )];
            }
            Action::GoTo => {
                let now = view::at_cursor(self, s).map(|r| r.f_hz);
                let b = s.band();
                let label = format!(
                    "go to frequency, Hz ({}–{})",
                    crate::view::format::num(b.from, 6),
                    crate::view::format::num(b.to, 6)
                );
                return vec![Effect::OpenField(Field::new(
                    Purpose::Tab(TAG_GOTO),
                    label,
                    now.map(|f| format!("{f}")).unwrap_or_default(),
                ))];
            }
            Action::Copy => return self.copy_line(s),
            Action::Export => return self.export(s),
            Action::Compare => {
                return vec![Effect::OpenField(
                    Field::new(
                        Purpose::Tab(TAG_COMPARE),
                        "compare with: preset file or name (empty: as last saved)",
                        self.compare_path.clone(),
                    )
                    .for_path(),
                )];
            }
            Action::ClearCompare => {
                self.overlaid.clear();
                let had = self.compare.take();
                self.overlaid = view::overlaid(self, s);
                return match had {
                    Some(c) => vec![Effect::Status(format!("compared model {} cleared", c.name))],
                    None => vec![Effect::Error(
                        "no compared model to clear (c compares)".into(),
                    )],
                };
            }
            Action::NextFunction => {
                let n = s.derived.as_ref().map_or(3, |d| d.functions.len()).max(1);
                self.func = (self.func + 1) % n;
                return vec![Effect::Status(format!(
                    "{}: the chart z zooms and x writes as text",
                    self.function().name()
                ))];
            }
            Action::Fit => {
                self.fit = Some(FitDialog::new(&s.body));
                return vec![Effect::Status(
                    "choose the free parameters (space), starts and seed; Enter fits".into(),
                )];
            }
            _ => {}
        }
        let last = s.curve_len().saturating_sub(1);
        let per_hz = (1.0 / s.band().step).round().max(1.0) as usize;
        if matches!(
            a,
            Action::Left
                | Action::Right
                | Action::PageUp
                | Action::PageDown
                | Action::Home
                | Action::End
        ) {
            self.exact = None;
        }
        match a {
            Action::Left => self.cursor = self.cursor.saturating_sub(1),
            Action::Right => self.cursor = (self.cursor + 1).min(last),
            Action::PageUp => self.cursor = self.cursor.saturating_sub(per_hz),
            Action::PageDown => self.cursor = (self.cursor + per_hz).min(last),
            Action::Home => self.cursor = 0,
            Action::End => self.cursor = last,
            Action::TogglePhase => {
                self.phase = !self.phase;
                self.overlaid = view::overlaid(self, s);
            }
            Action::ToggleLog => self.log = !self.log,
            Action::NextPeak => {
                let Some(d) = &s.derived else {
                    return Vec::new();
                };
                let here = view::at_cursor(self, s).map_or(0.0, |r| r.f_hz);
                let mut ps: Vec<(usize, biodyn::freq::Peak)> = d
                    .functions
                    .iter()
                    .enumerate()
                    .flat_map(|(i, c)| c.peaks.iter().map(move |p| (i, *p)))
                    .collect();
                ps.sort_by(|a, b| a.1.f_hz.total_cmp(&b.1.f_hz).then(a.0.cmp(&b.0)));
                // The next peak up; at equal frequency, the next function.
                let next = ps
                    .iter()
                    .find(|(i, p)| {
                        p.f_hz > here + 1e-9 || (p.f_hz >= here - 1e-9 && *i > self.func)
                    })
                    .or(ps.first())
                    .copied();
                let Some((i, p)) = next else {
                    return vec![Effect::Error("no peak inside the band".into())];
                };
                self.func = i;
                self.cursor = s.index_of(p.f_hz);
                self.exact = Some(d.solver.at(p.f_hz));
                let u = crate::view::format::unit(p.function);
                return vec![Effect::Status(format!(
                    "peak {} {} Hz {}{}{}",
                    p.function.name(),
                    crate::view::format::num(p.f_hz, 4),
                    crate::view::format::num(p.mag, 4),
                    if u.is_empty() { "" } else { " " },
                    u
                ))];
            }
            _ => {}
        }
        Vec::new()
    }

    /// The D field was committed: read the file, or say why not.
    fn load_data(&mut self, text: &str, s: &Shared) -> Result<Vec<Effect>, String> {
        let o = DataOverlay::load(text)?;
        self.data_path = text.trim().to_string();
        let say = format!(
            "loaded {} ({} frequencies) as \"data\"; F fits, X clears",
            o.data.path,
            o.data.f_hz.len()
        );
        self.data = Some(o);
        self.overlaid = view::overlaid(self, s);
        Ok(vec![Effect::Status(say)])
    }
}

impl Tab for ResponsesTab {
    fn new(_shared: &Shared) -> Self {
        ResponsesTab::default()
    }

    fn title(&self) -> &'static str {
        "Responses"
    }

    fn keys(&self) -> Vec<&'static Doc> {
        match &self.fit {
            Some(d) => fit_keys::docs(d),
            None => keys::docs(KEYS),
        }
    }

    fn on_key(&mut self, ev: &KeyEvent, cx: &Cx) -> Option<Vec<Effect>> {
        if self.fit.is_some() {
            return fit_keys::on_key(self, ev, cx);
        }
        self.copied = None;
        let a = keys::lookup(KEYS, ev)?;
        Some(self.act(a, cx.shared))
    }

    fn commit(&mut self, tag: usize, text: &str, cx: &Cx) -> Result<Vec<Effect>, String> {
        match tag {
            TAG_DATA => self.load_data(text, cx.shared),
            TAG_GOTO => self.go_to(text, cx.shared),
            TAG_COMPARE => {
                let c = Compare::load(text, cx.shared)?;
                self.compare_path = text.trim().to_string();
                // The saved model has no name of its own: say what it is.
                let what = if text.trim().is_empty() {
                    "the model as last saved".to_string()
                } else {
                    c.name.clone()
                };
                let how = compare::drawn_as(cx.shared.theme.mono);
                let say = format!("comparing with {what} ({how}, \"ref\" in the legend); C clears");
                self.compare = Some(c);
                self.overlaid = view::overlaid(self, cx.shared);
                Ok(vec![Effect::Status(say)])
            }
            _ => match self.fit.as_mut() {
                Some(d) => fit_keys::commit(d, tag, text),
                None => Ok(Vec::new()),
            },
        }
    }

    fn on_msg(&mut self, msg: Box<dyn Any + Send>, _cx: &Cx) -> Vec<Effect> {
        let (Ok(m), Some(d)) = (msg.downcast::<fit::FitMsg>(), self.fit.as_mut()) else {
            return Vec::new();
        };
        d.on_msg(*m)
            .map(|s| vec![Effect::Status(s)])
            .unwrap_or_default()
    }

    fn summary(&self) -> Option<String> {
        match &self.fit.as_ref()?.stage {
            Stage::Running(r) => Some(fit_view::progress_text(r)),
            _ => None,
        }
    }

    fn busy(&self) -> Option<&'static str> {
        self.fit
            .as_ref()
            .filter(|d| d.running())
            .map(|_| "a fit is running")
    }

    fn shutdown(&mut self) {
        if let Some(d) = self.fit.as_mut() {
            d.shutdown();
        }
    }

    fn on_change(&mut self, change: Change, cx: &Cx) {
        let s = cx.shared;
        if change == Change::Loaded {
            self.to_peak = true;
            // Another model: its parameters are not the dialog's. The data stay.
            if let Some(mut d) = self.fit.take() {
                d.shutdown();
            }
        }
        // Before a new model's peak is looked up: that index is the new band's.
        let band = *s.band();
        if let Some(old) = self.grid.filter(|b| *b != band) {
            // Another band: the same frequency, on the new grid.
            let f = self
                .exact
                .as_ref()
                .map_or(old.freq(self.cursor), |r| r.f_hz);
            self.cursor = nearest(&band, f);
        }
        self.grid = Some(band);
        if let Some(d) = &s.derived
            && self.to_peak
        {
            self.cursor = s.index_of(d.first_main().map_or(5.0, |p| p.f_hz));
            self.to_peak = false;
            self.exact = None;
        }
        if !s.stale {
            self.cursor = self.cursor.min(s.curve_len().saturating_sub(1));
        }
        // An exact point follows the model: computed again with its solver.
        if let (Some(r), Some(d)) = (self.exact.as_ref(), &s.derived) {
            self.exact = Some(d.solver.at(r.f_hz)).filter(|_| {
                let b = s.band();
                (b.from..=b.to).contains(&r.f_hz)
            });
        }
        if let Some(c) = self.compare.as_mut()
            && c.follow(s.band()).is_err()
        {
            self.compare = None;
        }
        self.overlaid = view::overlaid(self, s);
    }

    fn on_mouse(&mut self, m: Mouse, area: Rect, cx: &Cx) -> Vec<Effect> {
        if self.fit.is_some() {
            return Vec::new();
        }
        self.mouse(m, area, cx)
    }

    fn inputs(&self) -> Vec<std::path::PathBuf> {
        let data = self.data.as_ref().map(|d| d.data.path.clone().into());
        let compare = self.compare.as_ref().and_then(|c| c.path.clone());
        data.into_iter().chain(compare).collect()
    }

    fn has_chart(&self, s: &Shared) -> bool {
        s.derived.is_some() && self.fit.is_none()
    }

    /// The current function's chart (`f`, a click, `n`) over the whole tab,
    /// under the readout.
    fn render_zoomed(&self, s: &Shared, area: Rect, buf: &mut Buffer) {
        self.drawn_width.set(area.width);
        view::render(self, s, area, buf, true);
    }

    fn render(&self, s: &Shared, area: Rect, buf: &mut Buffer) {
        self.drawn_width.set(area.width);
        view::render(self, s, area, buf, false);
        if let (Some(d), Some(o)) = (&self.fit, &self.data) {
            fit_view::render(d, o, s, area, buf);
        }
    }
}

/// The grid index of `band` nearest `f_hz`, clamped into the band.
fn nearest(band: &biodyn::Band, f_hz: f64) -> usize {
    let last = band.len().saturating_sub(1);
    let k = ((f_hz - band.from) / band.step).round();
    if k.is_nan() || k <= 0.0 {
        0
    } else {
        (k as usize).min(last)
    }
}
