//! The app's state and `update`, the only place it changes. Rendering
//! (`frame.rs` and the tabs) borrows the state and never mutates it; derived
//! data (curves, peaks, modes, the study) is recomputed in `refresh` when the
//! model changes, never per frame.

use super::event::Msg;
use super::field::{Field, Purpose};
use super::keys::{self, Action, Ctx};
use super::theme::Theme;
use super::{model, responses, study, training};
use crate::view::chart::Series;
use biodyn::body::preset::{self, Preset};
use biodyn::freq::modes::{self, Modes};
use biodyn::freq::peaks::{self, Peak};
use biodyn::{Band, Body, Function, Param, Response, Solver};
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use std::path::{Path, PathBuf};
use std::sync::mpsc::Sender;

/// Undo depth: plenty for a session, bounded memory.
const UNDO_LIMIT: usize = 200;
/// The `+`/`-` step.
pub const NUDGE: f64 = 0.05;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Tab {
    Model,
    Responses,
    Study,
    Training,
}

impl Tab {
    pub const ALL: [Tab; 4] = [Tab::Model, Tab::Responses, Tab::Study, Tab::Training];

    pub fn index(self) -> usize {
        Tab::ALL.iter().position(|&t| t == self).unwrap_or(0)
    }

    fn ctx(self) -> Ctx {
        match self {
            Tab::Model => Ctx::Model,
            Tab::Responses => Ctx::Responses,
            Tab::Study => Ctx::Study,
            Tab::Training => Ctx::Training,
        }
    }
}

/// Everything computed from the current body.
#[derive(Debug, Clone)]
pub struct Derived {
    pub solver: Solver,
    pub curve: Vec<Response>,
    /// Magnitude and phase curves of STHT, DPMI, APMS, ready for the chart.
    pub mag: [Series; 3],
    pub phase: [Series; 3],
    /// Every interior peak per function, and the main one.
    pub peaks: [Vec<Peak>; 3],
    pub main: [Option<Peak>; 3],
    pub modes: Result<Modes, String>,
}

impl Derived {
    pub fn compute(body: &Body, band: &Band) -> Derived {
        let solver = Solver::new(body);
        let curve = solver.sweep(band);
        let series = |f: Function, phase: bool| Series {
            name: f.name().to_string(),
            points: curve
                .iter()
                .map(|r| (r.f_hz, if phase { r.phase_deg(f) } else { r.mag(f) }))
                .collect(),
        };
        let mag = Function::ALL.map(|f| series(f, false));
        let phase = Function::ALL.map(|f| series(f, true));
        let peaks = Function::ALL.map(|f| peaks::find_in(&solver, &curve, f));
        let main = Function::ALL.map(|f| peaks::main_peak(&solver, &curve, f));
        let modes = modes::analyse(body).map_err(|e| e.to_string());
        Derived {
            solver,
            curve,
            mag,
            phase,
            peaks,
            main,
            modes,
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ConfirmKind {
    Quit,
    /// Open the preset named in the open dialog's field (kept beside the
    /// confirmation), discarding unsaved edits.
    Discard,
}

#[derive(Debug, Clone, PartialEq)]
pub struct OpenDialog {
    /// (what the list shows, what `Preset::open` gets)
    pub entries: Vec<(String, String)>,
    pub sel: Option<usize>,
    pub field: Field,
}

#[derive(Debug, Clone, PartialEq)]
pub enum Overlay {
    None,
    Help { scroll: u16 },
    Open(OpenDialog),
    Confirm(ConfirmKind, Option<OpenDialog>),
}

/// The last message, shown on the status line until the next one.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Status {
    pub text: String,
    pub error: bool,
}

pub struct App {
    pub tab: Tab,
    /// Name, description, source and band of the loaded preset.
    pub preset: Preset,
    /// The model being edited.
    pub body: Body,
    /// The model as last loaded or saved: `body != saved` means modified.
    pub saved: Body,
    /// The file the preset came from; None for a built-in.
    pub path: Option<PathBuf>,
    pub undo: Vec<Body>,
    pub redo: Vec<Body>,
    pub derived: Derived,
    pub model: model::ModelTab,
    pub responses: responses::ResponsesTab,
    pub study: study::StudyTab,
    pub training: training::TrainingTab,
    /// An open text field (cell edit, values, save path).
    pub field: Option<Field>,
    pub overlay: Overlay,
    pub status: Status,
    pub quit: bool,
    pub theme: Theme,
    /// Where the training worker sends its reports (the main channel).
    pub tx: Option<Sender<Msg>>,
}

impl App {
    /// An app on `preset`; `path` is the file it came from, if any.
    pub fn new(preset: Preset, path: Option<PathBuf>, theme: Theme) -> App {
        let derived = Derived::compute(&preset.body, &preset.band);
        let mut app = App {
            tab: Tab::Model,
            body: preset.body.clone(),
            saved: preset.body.clone(),
            path,
            undo: Vec::new(),
            redo: Vec::new(),
            model: model::ModelTab::default(),
            responses: responses::ResponsesTab::default(),
            study: study::StudyTab::new(&preset.body),
            training: training::TrainingTab::default(),
            derived,
            preset,
            field: None,
            overlay: Overlay::None,
            status: Status {
                text: "? lists every key; Enter edits the selected value".into(),
                error: false,
            },
            quit: false,
            theme,
            tx: None,
        };
        app.responses.cursor = app.peak_index(0);
        app.study.rerun(&app.body, &app.preset.band);
        app
    }

    /// Opens `arg` (a file or a built-in name) the way `--preset` does.
    pub fn open(arg: &str, theme: Theme) -> Result<App, preset::PresetError> {
        let p = Preset::open(arg)?;
        let path = Path::new(arg).exists().then(|| PathBuf::from(arg));
        Ok(App::new(p, path, theme))
    }

    pub fn modified(&self) -> bool {
        self.body != self.saved
    }

    /// "paper-75kg (built-in)" or the file path.
    pub fn file_label(&self) -> String {
        match &self.path {
            Some(p) => p.display().to_string(),
            None => format!("{} (built-in)", self.preset.name),
        }
    }

    fn say(&mut self, text: impl Into<String>) {
        self.status = Status {
            text: text.into(),
            error: false,
        };
    }

    fn fail(&mut self, text: impl Into<String>) {
        self.status = Status {
            text: text.into(),
            error: true,
        };
    }

    /// Grid index nearest the main peak of function `fi`.
    fn peak_index(&self, fi: usize) -> usize {
        let f = self.derived.main[fi].map_or(5.0, |p| p.f_hz);
        self.index_of(f)
    }

    fn index_of(&self, f: f64) -> usize {
        let b = &self.preset.band;
        let i = ((f - b.from) / b.step).round().max(0.0) as usize;
        i.min(self.derived.curve.len().saturating_sub(1))
    }

    /// Recomputes everything derived from the body.
    fn refresh(&mut self) {
        self.derived = Derived::compute(&self.body, &self.preset.band);
        let last = self.derived.curve.len().saturating_sub(1);
        self.responses.cursor = self.responses.cursor.min(last);
        self.model.clamp(&self.body);
        self.study.rerun(&self.body, &self.preset.band);
    }

    /// Sets a parameter through the library's validation; on success the
    /// old body goes on the undo stack. On error nothing changes.
    pub fn set_param(&mut self, p: Param, v: f64) -> Result<(), String> {
        let mut next = self.body.clone();
        next.set(p, v).map_err(|e| e.to_string())?;
        if next == self.body {
            return Ok(());
        }
        let old = std::mem::replace(&mut self.body, next);
        self.undo.push(old);
        if self.undo.len() > UNDO_LIMIT {
            self.undo.remove(0);
        }
        self.redo.clear();
        self.refresh();
        Ok(())
    }

    fn undo(&mut self) {
        match self.undo.pop() {
            Some(b) => {
                let cur = std::mem::replace(&mut self.body, b);
                self.redo.push(cur);
                self.refresh();
                self.say("undone");
            }
            None => self.fail("nothing to undo"),
        }
    }

    fn redo(&mut self) {
        match self.redo.pop() {
            Some(b) => {
                let cur = std::mem::replace(&mut self.body, b);
                self.undo.push(cur);
                self.refresh();
                self.say("redone");
            }
            None => self.fail("nothing to redo"),
        }
    }

    /// Replaces the model by a loaded preset (a fresh undo history).
    fn load(&mut self, p: Preset, path: Option<PathBuf>) {
        self.body = p.body.clone();
        self.saved = p.body.clone();
        self.preset = p;
        self.path = path;
        self.undo.clear();
        self.redo.clear();
        self.study = study::StudyTab::new(&self.body);
        self.refresh();
        self.responses.cursor = self.peak_index(0);
        let label = self.file_label();
        self.say(format!("opened {label}"));
    }

    /// Saves atomically; on success the file becomes the loaded one.
    pub fn save_to(&mut self, path: &Path) -> Result<(), String> {
        let mut p = self.preset.clone();
        p.body = self.body.clone();
        if let Some(stem) = path.file_stem().and_then(|s| s.to_str())
            && self.path.is_none()
        {
            p.name = stem.to_string();
        }
        p.save(path).map_err(|e| e.to_string())?;
        self.preset = p;
        self.saved = self.body.clone();
        self.path = Some(path.to_path_buf());
        self.say(format!("saved {}", path.display()));
        Ok(())
    }

    fn default_save_path(&self) -> String {
        match &self.path {
            Some(p) => p.display().to_string(),
            None => format!("{}.toml", self.preset.name),
        }
    }

    /// Contexts for key lookup, most specific first.
    pub fn contexts(&self) -> Vec<Ctx> {
        match &self.overlay {
            Overlay::Confirm(..) => vec![Ctx::Confirm],
            Overlay::Help { .. } => vec![Ctx::Help],
            Overlay::Open(_) => vec![Ctx::Open, Ctx::Field],
            Overlay::None if self.field.is_some() => vec![Ctx::Field],
            Overlay::None => vec![self.tab.ctx(), Ctx::Global],
        }
    }

    fn open_dialog(&self) -> OpenDialog {
        let mut entries = Vec::new();
        if let Ok(dir) = std::fs::read_dir("presets") {
            let mut files: Vec<String> = dir
                .filter_map(|e| e.ok())
                .map(|e| e.path())
                .filter(|p| p.extension().is_some_and(|x| x == "toml"))
                .map(|p| p.display().to_string())
                .collect();
            files.sort();
            entries.extend(files.into_iter().map(|f| (f.clone(), f)));
        }
        for (name, _) in preset::SHIPPED {
            entries.push((format!("{name} (built-in)"), name.to_string()));
        }
        let text = self
            .path
            .as_ref()
            .map(|p| p.display().to_string())
            .unwrap_or_default();
        OpenDialog {
            entries,
            sel: None,
            field: Field::new(Purpose::OpenPath, "path or built-in name", text),
        }
    }
}

/// The one place the state changes.
pub fn update(app: &mut App, msg: Msg) {
    match msg {
        Msg::Key(k) => on_key(app, k),
        Msg::Resize(..) => {}
        Msg::Signal(_) => app.quit = true,
        Msg::Train(m) => training::on_msg(app, m),
    }
}

fn on_key(app: &mut App, ev: KeyEvent) {
    // Ctrl-C quits from anywhere, whatever is open.
    if ev.modifiers.contains(KeyModifiers::CONTROL)
        && matches!(ev.code, KeyCode::Char('c') | KeyCode::Char('C'))
    {
        training::stop(app);
        app.quit = true;
        return;
    }
    let ctxs = app.contexts();
    let action = keys::lookup(&ctxs, &ev);
    match (&mut app.overlay, action) {
        (Overlay::Confirm(kind, dialog), Some(Action::Yes)) => {
            let kind = *kind;
            let dialog = dialog.take();
            app.overlay = Overlay::None;
            match kind {
                ConfirmKind::Quit => {
                    training::stop(app);
                    app.quit = true;
                }
                ConfirmKind::Discard => {
                    if let Some(d) = dialog {
                        open_from_dialog(app, d, true);
                    }
                }
            }
        }
        (Overlay::Confirm(_, dialog), Some(Action::No)) => {
            app.overlay = match dialog.take() {
                Some(d) => Overlay::Open(d),
                None => Overlay::None,
            };
        }
        (Overlay::Confirm(..), _) => {}
        (Overlay::Help { scroll }, a) => match a {
            Some(Action::Up) => *scroll = scroll.saturating_sub(1),
            Some(Action::Down) => *scroll = scroll.saturating_add(1),
            Some(Action::Cancel) => app.overlay = Overlay::None,
            _ => {}
        },
        (Overlay::Open(d), a) => match a {
            Some(Action::Cancel) => app.overlay = Overlay::None,
            Some(Action::Up) | Some(Action::Down) if !d.entries.is_empty() => {
                let n = d.entries.len();
                let i = match (d.sel, a) {
                    (None, Some(Action::Up)) => n - 1,
                    (None, _) => 0,
                    (Some(i), Some(Action::Up)) => (i + n - 1) % n,
                    (Some(i), _) => (i + 1) % n,
                };
                d.sel = Some(i);
                let arg = d.entries[i].1.clone();
                d.field.set_text(arg);
            }
            Some(Action::Commit) => {
                if let Overlay::Open(d) = std::mem::replace(&mut app.overlay, Overlay::None) {
                    open_from_dialog(app, d, false);
                }
            }
            Some(a) => edit_field(&mut d.field, a),
            None => type_into(&mut d.field, &ev),
        },
        (Overlay::None, a) if app.field.is_some() => match a {
            Some(Action::Commit) => commit_field(app),
            Some(Action::Cancel) => {
                app.field = None;
                app.say("cancelled; nothing changed");
            }
            Some(a) => {
                if let Some(f) = app.field.as_mut() {
                    edit_field(f, a);
                }
            }
            None => {
                if let Some(f) = app.field.as_mut() {
                    type_into(f, &ev);
                }
            }
        },
        (Overlay::None, Some(a)) => on_action(app, a),
        (Overlay::None, None) => {}
    }
}

fn edit_field(f: &mut Field, a: Action) {
    match a {
        Action::Left => f.left(),
        Action::Right => f.right(),
        Action::Home => f.home(),
        Action::End => f.end(),
        Action::DeleteBack => f.backspace(),
        Action::DeleteFwd => f.delete(),
        _ => {}
    }
}

fn type_into(f: &mut Field, ev: &KeyEvent) {
    if let KeyCode::Char(c) = ev.code
        && !ev
            .modifiers
            .intersects(KeyModifiers::CONTROL | KeyModifiers::ALT)
    {
        f.insert(c);
    }
}

fn open_from_dialog(app: &mut App, mut d: OpenDialog, confirmed: bool) {
    let arg = d.field.text.trim().to_string();
    if arg.is_empty() {
        d.field.error = Some("give a path or pick a preset with ↑↓".into());
        app.overlay = Overlay::Open(d);
        return;
    }
    match Preset::open(&arg) {
        Ok(p) => {
            if app.modified() && !confirmed {
                app.overlay = Overlay::Confirm(ConfirmKind::Discard, Some(d));
                return;
            }
            let path = Path::new(&arg).is_file().then(|| PathBuf::from(&arg));
            app.load(p, path);
        }
        Err(e) => {
            d.field.error = Some(e.to_string());
            app.overlay = Overlay::Open(d);
        }
    }
}

fn commit_field(app: &mut App) {
    let Some(mut f) = app.field.take() else {
        return;
    };
    let result = match f.purpose {
        Purpose::Param(_) if f.text.trim() == f.initial.trim() => {
            app.say("unchanged");
            Ok(())
        }
        Purpose::Param(p) => commit_param(app, p, &f.text),
        Purpose::StudyValues => app.study.set_values(&f.text, &app.body, &app.preset.band),
        Purpose::SavePath => {
            let t = f.text.trim();
            let path = Path::new(t);
            // Another file of that name is only replaced on a second Enter;
            // any edit of the path clears the error and asks again.
            let exists = format!("{t} exists: Enter again replaces it, or change the path");
            if t.is_empty() {
                Err("give a file path, e.g. presets/my-body.toml".into())
            } else if path.exists()
                && app.path.as_deref() != Some(path)
                && f.error.as_deref() != Some(exists.as_str())
            {
                Err(exists)
            } else {
                app.save_to(path)
            }
        }
        Purpose::TrainSetting(row) => training::commit_setting(app, row, &f.text),
        Purpose::SaveNet => training::save_net(app, f.text.trim()),
        Purpose::OpenPath => Ok(()),
    };
    if let Err(why) = result {
        f.error = Some(why);
        app.field = Some(f);
    }
}

/// Parses and sets a model value; the reason on refusal.
fn commit_param(app: &mut App, p: Param, text: &str) -> Result<(), String> {
    let t = text.trim();
    let v: f64 = t
        .parse()
        .map_err(|_| format!("'{t}' is not a number (write e.g. 75 or 1.5e5)"))?;
    let label = app.body.label(p);
    app.set_param(p, v)?;
    app.say(format!(
        "{label} = {} {}",
        crate::view::format::num(app.body.get(p), 6),
        p.unit()
    ));
    Ok(())
}

fn on_action(app: &mut App, a: Action) {
    match a {
        Action::Quit => {
            if app.modified() || app.training.running() {
                app.overlay = Overlay::Confirm(ConfirmKind::Quit, None);
            } else {
                app.quit = true;
            }
        }
        Action::ForceQuit => {
            training::stop(app);
            app.quit = true;
        }
        Action::Help => app.overlay = Overlay::Help { scroll: 0 },
        Action::Tab(i) => app.tab = Tab::ALL[i.min(3)],
        Action::NextTab => app.tab = Tab::ALL[(app.tab.index() + 1) % 4],
        Action::PrevTab => app.tab = Tab::ALL[(app.tab.index() + 3) % 4],
        Action::Open => app.overlay = Overlay::Open(app.open_dialog()),
        Action::Save => {
            let path = app.default_save_path();
            app.field = Some(Field::new(Purpose::SavePath, "save preset to", path));
        }
        Action::Undo => app.undo(),
        Action::Redo => app.redo(),
        _ => match app.tab {
            Tab::Model => model::on_action(app, a),
            Tab::Responses => responses::on_action(app, a),
            Tab::Study => study::on_action(app, a),
            Tab::Training => training::on_action(app, a),
        },
    }
}
