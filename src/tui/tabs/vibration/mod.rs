//! Tab Vibration: the body under a seat-acceleration record (a generated
//! signal or a CSV file), judged by ISO 2631-1 and the EU Directive. The
//! settings, the seat and head traces (raw or Wk-weighted, zoom and scroll
//! in time), their one-third-octave spectra and the assessment table. It
//! reruns on every edit, on a worker thread when the app has a channel; a
//! newer edit cancels the older run. `x` exports what `biodyn simulate
//! --format csv` prints.

mod bindings;
pub mod compute;
pub mod export;
mod glyphs;
mod layout;
mod mouse;
mod record;
pub mod settings;
mod spectra;
mod table;
#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_axes;
#[cfg(test)]
mod tests_class;
#[cfg(test)]
mod tests_limits;
#[cfg(test)]
mod tests_spine;
mod traces;
mod view;
mod window;

use crate::tui::component::{Change, Cx, Mouse, Tab};
use crate::tui::effect::Effect;
use crate::tui::popups::field::{Field, Purpose};
use crate::tui::keys::{self, Doc};
use crate::tui::shared::Shared;
use bindings::{Action, KEYS};
use compute::{Exported, Input, Outcome, Report};
use ratatui::buffer::Buffer;
use ratatui::crossterm::event::KeyEvent;
use ratatui::layout::Rect;
use settings::{Row, Settings};
use std::any::Any;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

/// The field tag of the export path; settings rows use their index.
const EXPORT: usize = 1000;

/// Deepest zoom: 2^16 times the record.
const MAX_ZOOM: u32 = 16;

pub struct VibrationTab {
    pub settings: Settings,
    /// Selected settings row.
    pub sel: usize,
    /// The first settings line shown, as the mouse last left it (drawing
    /// moves it the least that keeps the selected row in view).
    pub settings_top: usize,
    /// Traces Wk-weighted.
    pub weighted: bool,
    /// What the big panel shows when only one fits: 0 traces, 1 spectra,
    /// 2 every verdict, comfort word and warning.
    pub panel: u8,
    /// The window is the record / 2^zoom long, starting `offset` of the
    /// record in (0..1).
    pub zoom: u32,
    pub offset: f64,
    /// The last finished run; kept on screen (marked) while a newer runs.
    pub result: Option<Result<Arc<Outcome>, String>>,
    /// A run is on its way.
    pub running: bool,
    /// Samples the run has done, of how many (None: a file).
    pub progress: Option<(u64, Option<u64>)>,
    /// An export is on its way.
    pub exporting: Option<PathBuf>,
    /// The existing file the last export commit warned about: a second
    /// Enter on the same path replaces it.
    replace: Option<PathBuf>,
    generation: u64,
    cancel: Option<Arc<AtomicBool>>,
}

impl VibrationTab {
    fn fresh() -> VibrationTab {
        VibrationTab {
            settings: Settings::default(),
            sel: 0,
            settings_top: 0,
            weighted: false,
            panel: 0,
            zoom: 0,
            offset: 0.0,
            result: None,
            running: false,
            progress: None,
            exporting: None,
            replace: None,
            generation: 0,
            cancel: None,
        }
    }

    pub fn rows(&self) -> Vec<Row> {
        self.settings.rows()
    }

    fn row(&self) -> Row {
        let rows = self.rows();
        rows.get(self.sel.min(rows.len().saturating_sub(1)))
            .copied()
            .unwrap_or(Row::Kind)
    }

    /// The run's outcome, if the last one succeeded.
    pub fn outcome(&self) -> Option<&Outcome> {
        match &self.result {
            Some(Ok(o)) => Some(o),
            _ => None,
        }
    }

    /// Reruns for the current body and settings: on a worker when there is
    /// a channel (cancelling an older run), else at once.
    fn rerun(&mut self, cx: &Cx) {
        self.generation += 1;
        if let Some(c) = self.cancel.take() {
            c.store(true, Ordering::Relaxed);
        }
        let (body, input) = (cx.shared.body.clone(), self.settings.input());
        self.progress = None;
        if let Some((tx, wrap)) = cx.mailbox.wrap::<Report>() {
            let send = move |r: Report| {
                let _ = tx.send(wrap(r));
            };
            match compute::spawn(body, input, self.generation, send) {
                Ok(c) => {
                    self.cancel = Some(c);
                    self.running = true;
                }
                Err(e) => self.result = Some(Err(format!("cannot start the run: {e}"))),
            }
            return;
        }
        let never = AtomicBool::new(false);
        self.set_result(compute::run(&body, &input, &never, &mut |_, _| {}));
    }

    fn set_result(&mut self, r: Result<Outcome, String>) {
        self.result = Some(r.map(Arc::new));
        self.running = false;
        self.progress = None;
        self.cancel = None;
    }

    fn act(&mut self, a: Action, cx: &Cx) -> Vec<Effect> {
        let n = self.rows().len().max(1);
        match a {
            Action::Up => self.sel = (self.sel + n - 1) % n,
            Action::Down => self.sel = (self.sel + 1) % n,
            Action::PrevKind | Action::NextKind => {
                let d = if a == Action::NextKind { 1 } else { -1 };
                if self.row() == Row::Unit {
                    // On the unit row ←→ step the unit; the record is
                    // reopened by the run, whose refusal shows in full.
                    self.settings.step_unit(d);
                } else if self.row() == Row::Mean {
                    self.settings.toggle_mean();
                } else {
                    self.settings.step_kind(d);
                    self.sel = 0;
                }
                self.whole();
                if self.settings.signal().is_none() && self.settings.path.trim().is_empty() {
                    self.result = Some(Err(keys::arrows(
                        "no file yet: ↓ to 'file', Enter, and give the path of a CSV record \
                         (a header, t_s and the acceleration columns: az, or ax,ay,az, \
                         or acc_z_g …)",
                        cx.shared.theme.ascii,
                    )));
                    self.running = false;
                    if let Some(c) = self.cancel.take() {
                        c.store(true, Ordering::Relaxed);
                    }
                    return Vec::new();
                }
                self.rerun(cx);
                if self.row() == Row::Unit {
                    let u = settings::unit_label(self.settings.unit);
                    return vec![Effect::Status(format!("unit = {u}"))];
                }
                if self.row() == Row::Mean {
                    let m = settings::mean_label(self.settings.remove_mean);
                    return vec![Effect::Status(format!("each channel's mean {m}"))];
                }
            }
            Action::Edit => {
                let row = self.row();
                if row == Row::Kind {
                    return vec![Effect::Status(keys::arrows(
                        "←→ pick the signal kind; Enter on a row below edits it",
                        cx.shared.theme.ascii,
                    ))];
                }
                if row == Row::Unit {
                    return vec![Effect::Status(keys::arrows(
                        "←→ pick the unit: from the header (a _g or _mm_s2 suffix, [g] …; else m/s², and said), m/s², g or mm/s²",
                        cx.shared.theme.ascii,
                    ))];
                }
                if row == Row::Mean {
                    return vec![Effect::Status(keys::arrows(
                        "←→ keep each channel's mean (a large one is refused: gravity, an offset) or remove it before judging",
                        cx.shared.theme.ascii,
                    ))];
                }
                let (label, unit, _) = self.settings.row_text(row);
                let label = if unit.is_empty() {
                    label
                } else {
                    format!("{label} ({unit})")
                };
                let f = Field::new(
                    Purpose::Tab(self.sel.min(n - 1)),
                    label,
                    self.settings.edit_text(row),
                );
                // The record's path: Tab completes it (issue 19 item 15).
                let f = if row == Row::Path { f.for_path() } else { f };
                return vec![Effect::OpenField(f)];
            }
            Action::Weighted => self.weighted = !self.weighted,
            Action::ZoomIn => self.zoom_by(1),
            Action::ZoomOut => self.zoom_by(-1),
            Action::Earlier => self.scroll(-1.0),
            Action::Later => self.scroll(1.0),
            Action::Whole => self.whole(),
            Action::Chart => self.panel = (self.panel + 1) % 3,
            Action::Spine => {
                self.settings.spine_on = !self.settings.spine_on;
                let runnable =
                    self.settings.signal().is_some() || !self.settings.path.trim().is_empty();
                if runnable {
                    self.rerun(cx);
                }
                let (_, _, v) = self.settings.row_text(Row::Spine);
                return vec![Effect::Status(format!("spine (ISO 2631-5) = {v}"))];
            }
            Action::Export => {
                if let Some(p) = &self.exporting {
                    return vec![Effect::Error(format!(
                        "an export to {} is still running",
                        p.display()
                    ))];
                }
                self.replace = None;
                let path = format!("{}-vibration.csv", cx.shared.preset.name);
                // The path's extension picks what is written (export.rs).
                return vec![Effect::OpenField(
                    Field::new(
                        Purpose::Tab(EXPORT),
                        "export (.csv simulation; .json/.txt assessment; .svg figure) to",
                        path,
                    )
                    .for_path(),
                )];
            }
        }
        Vec::new()
    }

    /// Starts the export (on a worker when there is a channel): what the
    /// path's extension asks for (`export::Kind::of`).
    fn export(&mut self, path: &Path, cx: &Cx) -> Vec<Effect> {
        let (body, input) = (cx.shared.body.clone(), self.settings.input());
        let model = cx.shared.preset.name.clone();
        let kind = export::Kind::of(path);
        if let Some((tx, wrap)) = cx.mailbox.wrap::<Exported>() {
            let p = path.to_path_buf();
            let spawned = std::thread::Builder::new()
                .name("vibration-export".into())
                .spawn(move || {
                    let result = export::export(&body, &model, &input, kind, &p);
                    let _ = tx.send(wrap(Exported { path: p, result }));
                });
            return match spawned {
                Ok(_) => {
                    self.exporting = Some(path.to_path_buf());
                    vec![Effect::Status(format!("exporting to {}…", path.display()))]
                }
                Err(e) => vec![Effect::Error(format!("cannot start the export: {e}"))],
            };
        }
        let result = export::export(&body, &model, &input, kind, path);
        self.exported(Exported {
            path: path.to_path_buf(),
            result,
        })
    }

    fn exported(&mut self, e: Exported) -> Vec<Effect> {
        self.exporting = None;
        let kind = export::Kind::of(&e.path);
        match e.result {
            Ok(rows) if kind == export::Kind::Simulation => vec![Effect::Status(format!(
                "exported {rows} rows to {} (what {} prints)",
                e.path.display(),
                kind.command()
            ))],
            Ok(_) if kind == export::Kind::AssessFigure => vec![Effect::Status(format!(
                "exported the figure to {} (what {} FILE.svg writes)",
                e.path.display(),
                kind.command()
            ))],
            Ok(_) => vec![Effect::Status(format!(
                "exported the assessment to {} (what {} prints)",
                e.path.display(),
                kind.command()
            ))],
            Err(why) => vec![Effect::Error(format!("export failed: {why}"))],
        }
    }

    /// The input the shown result was computed from.
    pub fn input(&self) -> Input {
        self.settings.input()
    }
}

impl Tab for VibrationTab {
    fn new(_shared: &Shared) -> Self {
        VibrationTab::fresh()
    }

    fn title(&self) -> &'static str {
        "Vibration"
    }

    fn keys(&self) -> Vec<&'static Doc> {
        keys::docs(KEYS)
    }

    fn on_key(&mut self, ev: &KeyEvent, cx: &Cx) -> Option<Vec<Effect>> {
        keys::lookup(KEYS, ev).map(|a| self.act(a, cx))
    }

    fn commit(&mut self, tag: usize, text: &str, cx: &Cx) -> Result<Vec<Effect>, String> {
        if tag == EXPORT {
            let t = text.trim();
            if t.is_empty() {
                return Err("give a file path, e.g. paper-75kg-vibration.csv".into());
            }
            let expanded = crate::tui::paths::expand(t);
            let path = expanded.as_path();
            // A folder, pipe or device is refused before any "exists" question.
            if let Some(why) =
                crate::tui::paths::save_refusal(
                    t,
                    path,
                    "paper-75kg-vibration.csv",
                    &crate::tui::paths::guard(cx.shared, None),
                )
            {
                return Err(why);
            }
            if path.exists() && self.replace.as_deref() != Some(path) {
                self.replace = Some(path.to_path_buf());
                return Err(format!(
                    "{t} exists: Enter again replaces it, or change the path"
                ));
            }
            self.replace = None;
            return Ok(self.export(path, cx));
        }
        let row = self
            .rows()
            .get(tag)
            .copied()
            .ok_or("that setting is gone")?;
        // The spine row opens on the last person even while it is off:
        // Enter on it as it stands turns it on.
        let turns_on = row == Row::Spine && !self.settings.spine_on;
        if text.trim() == self.settings.edit_text(row).trim() && !turns_on {
            return Ok(vec![Effect::Status("unchanged".into())]);
        }
        self.settings.commit(row, text)?;
        let rows = self.rows();
        self.sel = rows.iter().position(|&r| r == row).unwrap_or(0);
        self.whole();
        self.rerun(cx);
        let (label, unit, value) = self.settings.row_text(row);
        Ok(vec![Effect::Status(format!("{label} = {value} {unit}"))])
    }

    fn on_change(&mut self, change: Change, cx: &Cx) {
        match change {
            Change::Loaded | Change::Edited => {
                if self.settings.signal().is_some() || !self.settings.path.trim().is_empty() {
                    self.rerun(cx);
                }
            }
            Change::Derived => {}
        }
    }

    fn on_msg(&mut self, msg: Box<dyn Any + Send>, _cx: &Cx) -> Vec<Effect> {
        let msg = match msg.downcast::<Report>() {
            Ok(r) => {
                match *r {
                    Report::Done(d) if d.generation == self.generation => self.set_result(d.result),
                    Report::Progress(p) if p.generation == self.generation => {
                        self.progress = Some((p.done, p.total));
                    }
                    _ => {}
                }
                return Vec::new();
            }
            Err(m) => m,
        };
        if let Ok(e) = msg.downcast::<Exported>() {
            return self.exported(*e);
        }
        Vec::new()
    }

    fn on_mouse(&mut self, m: Mouse, area: Rect, cx: &Cx) -> Vec<Effect> {
        self.mouse(m, area, cx)
    }

    fn render(&self, s: &Shared, area: Rect, buf: &mut Buffer) {
        view::render(self, s, area, buf);
    }

    fn inputs(&self) -> Vec<PathBuf> {
        let s = &self.settings;
        (s.kind == settings::Kind::File && !s.path.trim().is_empty())
            .then(|| crate::tui::paths::expand(&s.path))
            .into_iter()
            .collect()
    }

    fn has_chart(&self, _shared: &Shared) -> bool {
        self.outcome().is_some()
    }

    /// The traces, or the spectra when `s` shows them.
    fn render_zoomed(&self, s: &Shared, area: Rect, buf: &mut Buffer) {
        view::render_zoomed(self, s, area, buf);
    }

    fn busy(&self) -> Option<&'static str> {
        self.exporting
            .as_ref()
            .map(|_| "a vibration export is running")
    }

    fn shutdown(&mut self) {
        if let Some(c) = self.cancel.take() {
            c.store(true, Ordering::Relaxed);
        }
    }
}
