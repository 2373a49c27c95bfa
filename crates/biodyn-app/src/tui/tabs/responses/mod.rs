//! Tab Responses: STHT, DPMI and APMS over the band (magnitude or phase,
//! linear or log axes), a frequency cursor that reads the exact values of
//! all three, and the main peaks marked. Measured data can be laid over
//! the charts (`data.rs`) and the model fitted to them (`fit.rs` the
//! dialog's state and thread, `fit_keys.rs` its keys, `fit_view.rs` its
//! drawing); `view.rs` draws the tab.

mod data;
pub mod fit;
mod fit_keys;
mod fit_view;
mod view;

#[cfg(test)]
mod tests;

pub use data::DataOverlay;
pub use fit::{FitDialog, Stage};

use crate::tui::component::{Change, Cx, Tab};
use crate::tui::effect::Effect;
use crate::tui::field::{Field, Purpose};
use crate::tui::keys::{self, Binding, Doc, b, code, k};
use crate::tui::shared::Shared;
use crate::view::chart;
use ratatui::buffer::Buffer;
use ratatui::crossterm::event::{KeyCode as KC, KeyEvent};
use ratatui::layout::Rect;
use std::any::Any;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Action {
    Left,
    Right,
    PageUp,
    PageDown,
    Home,
    End,
    NextPeak,
    TogglePhase,
    ToggleLog,
    LoadData,
    ClearData,
    Fit,
}

static KEYS: &[Binding<Action>] = &[
    b(
        &[code(KC::Left), k('h')],
        Action::Left,
        "frequency cursor down one step",
        Some("←→ cursor"),
    ),
    b(
        &[code(KC::Right), k('l')],
        Action::Right,
        "frequency cursor up one step",
        None,
    ),
    b(
        &[code(KC::PageDown), k('L')],
        Action::PageDown,
        "cursor up 1 Hz",
        None,
    ),
    b(
        &[code(KC::PageUp), k('H')],
        Action::PageUp,
        "cursor down 1 Hz",
        None,
    ),
    b(
        &[code(KC::Home)],
        Action::Home,
        "cursor to the band start",
        None,
    ),
    b(&[code(KC::End)], Action::End, "cursor to the band end", None),
    b(
        &[k('n')],
        Action::NextPeak,
        "cursor to the next peak (any function)",
        Some("n peak"),
    ),
    b(
        &[k('p')],
        Action::TogglePhase,
        "magnitude / phase",
        Some("p mag/phase"),
    ),
    b(
        &[k('a')],
        Action::ToggleLog,
        "linear / log axes",
        Some("a lin/log"),
    ),
    b(
        &[k('D')],
        Action::LoadData,
        "load measured data (CSV, as for fit --data) over the charts",
        Some("D data"),
    ),
    b(
        &[k('X')],
        Action::ClearData,
        "clear the measured data from the charts",
        None,
    ),
    b(
        &[k('F')],
        Action::Fit,
        "fit the model to the loaded data: choose free parameters, run, apply",
        Some("F fit"),
    ),
];

/// Field tags of this tab's text fields.
const TAG_DATA: usize = 0;
pub(crate) const TAG_STARTS: usize = 1;
pub(crate) const TAG_SEED: usize = 2;

#[derive(Debug)]
pub struct ResponsesTab {
    pub phase: bool,
    pub log: bool,
    /// Index into the band's grid.
    pub cursor: usize,
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
            to_peak: true,
            data: None,
            data_path: if example { data::EXAMPLE.into() } else { String::new() },
            fit: None,
            overlaid: Vec::new(),
        }
    }
}

impl ResponsesTab {
    fn act(&mut self, a: Action, s: &Shared) -> Vec<Effect> {
        match a {
            Action::LoadData => {
                return vec![Effect::OpenField(Field::new(
                    Purpose::Tab(TAG_DATA),
                    "measured data, CSV",
                    self.data_path.clone(),
                ))];
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
                let here = d.curve.get(self.cursor).map_or(0.0, |r| r.f_hz);
                let mut fs: Vec<f64> = d
                    .functions
                    .iter()
                    .flat_map(|c| c.peaks.iter().map(|p| p.f_hz))
                    .collect();
                fs.sort_by(f64::total_cmp);
                let step = s.band().step;
                let next = fs
                    .iter()
                    .find(|&&f| f > here + step / 2.0)
                    .or(fs.first())
                    .copied();
                if let Some(f) = next {
                    self.cursor = s.index_of(f);
                }
            }
            Action::LoadData | Action::ClearData | Action::Fit => {}
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
        let a = keys::lookup(KEYS, ev)?;
        Some(self.act(a, cx.shared))
    }

    fn commit(&mut self, tag: usize, text: &str, cx: &Cx) -> Result<Vec<Effect>, String> {
        match tag {
            TAG_DATA => self.load_data(text, cx.shared),
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
        if let Some(d) = &s.derived
            && self.to_peak
        {
            self.cursor = s.index_of(d.first_main().map_or(5.0, |p| p.f_hz));
            self.to_peak = false;
        }
        self.cursor = self.cursor.min(s.curve_len().saturating_sub(1));
        self.overlaid = view::overlaid(self, s);
    }

    fn render(&self, s: &Shared, area: Rect, buf: &mut Buffer) {
        view::render(self, s, area, buf);
        if let (Some(d), Some(o)) = (&self.fit, &self.data) {
            fit_view::render(d, o, s, area, buf);
        }
    }
}

