//! The app's state: what the tabs share, the tabs, the open field or
//! dialog, the status line, the undo history. `apply` is the one place a
//! tab's effects land; `update.rs` routes messages and keys here. Derived
//! data are recomputed when the model changes, never per frame.

use super::component::{Change, Cx, Tab};
use super::derived::{self, Derived, Job, Part};
use super::dialog::Overlay;
use super::effect::{Effect, Export};
use super::event::{Mailbox, Msg};
use super::field::{Field, Purpose};
use super::shared::Shared;
use super::tabs;
use super::theme::Theme;
use crate::view::format::num;
use biodyn::body::preset::{self, Preset};
use biodyn::{Band, Body, Param};
use std::path::{Path, PathBuf};
use std::sync::mpsc::Sender;
use std::time::{Duration, Instant};

/// Undo depth: plenty for a session, bounded memory.
const UNDO_LIMIT: usize = 200;

/// How long a message stays on the status line (errors a little longer).
pub const STATUS_TTL: Duration = Duration::from_secs(8);
pub const ERROR_TTL: Duration = Duration::from_secs(15);

/// The last message, shown on the status line of the tab where it was
/// said until it expires, the next one comes or the user changes tab.
#[derive(Debug, Clone, PartialEq)]
pub struct Status {
    pub text: String,
    pub error: bool,
    pub at: Instant,
}

impl Default for Status {
    fn default() -> Status {
        Status {
            text: String::new(),
            error: false,
            at: Instant::now(),
        }
    }
}

/// What undo restores: the model and, for a load, the preset and file.
#[derive(Debug, Clone)]
pub struct Snapshot {
    pub body: Body,
    pub preset: Preset,
    pub path: Option<PathBuf>,
    pub saved: Body,
    /// The band as last loaded or saved.
    pub saved_band: Band,
}

/// One undoable change: the state before it and what it was
/// ("k4 54000 → 90000", "open paper-65kg (built-in)").
#[derive(Debug, Clone)]
pub struct Step {
    pub before: Snapshot,
    pub what: String,
}

pub struct App {
    pub shared: Shared,
    /// In tab-bar order (`tabs::all`).
    pub tabs: Vec<Box<dyn Tab>>,
    /// Index of the tab shown.
    pub current: usize,
    /// An open text field, owned by the current tab or the app.
    pub field: Option<Field>,
    pub overlay: Overlay,
    pub status: Status,
    pub quit: bool,
    pub undo: Vec<Step>,
    pub redo: Vec<Step>,
    /// The terminal's size, once known; keys do nothing while it is too small.
    pub size: Option<(u16, u16)>,
    /// A chart shown full-screen (`z`): the tab draws only it.
    pub zoom: bool,
    /// What the open export field writes (`Effect::Export`).
    pub export: Option<Export>,
    /// Mouse capture asked for (`M`); the event loop tells the terminal.
    pub mouse: bool,
    /// The band as last loaded or saved: a band edit is an unsaved edit.
    pub saved_band: Band,
    /// The last left click (time, column, row), to tell a double click.
    pub last_click: Option<(Instant, u16, u16)>,
    /// The main channel: background jobs and tab workers report on it.
    tx: Option<Sender<Msg>>,
    /// Counts model changes; background results of older ones are dropped.
    generation: u64,
    /// The background computation in flight, if any (at most one).
    job: Option<Job>,
}

impl App {
    /// An app on `preset` without a channel: everything is computed at
    /// once (tests, benches). `path` is the file it came from, if any.
    pub fn new(preset: Preset, path: Option<PathBuf>, theme: Theme) -> App {
        App::with_channel(preset, path, theme, None)
    }

    /// An app whose large-model work runs in the background, reporting on `tx`.
    pub fn with_channel(
        preset: Preset,
        path: Option<PathBuf>,
        theme: Theme,
        tx: Option<Sender<Msg>>,
    ) -> App {
        let shared = Shared {
            body: preset.body.clone(),
            saved: preset.body.clone(),
            preset,
            path,
            derived: None,
            modes: None,
            stale: false,
            theme,
        };
        let tabs = tabs::all(&shared);
        let mut app = App {
            shared,
            tabs,
            current: 0,
            field: None,
            overlay: Overlay::None,
            status: Status {
                text: "? lists every key; Enter edits the selected value".into(),
                error: false,
                at: Instant::now(),
            },
            quit: false,
            undo: Vec::new(),
            redo: Vec::new(),
            size: None,
            zoom: false,
            export: None,
            mouse: false,
            saved_band: Band::default(),
            last_click: None,
            tx,
            generation: 0,
            job: None,
        };
        app.saved_band = app.shared.preset.band;
        app.refresh(Change::Loaded);
        app
    }

    /// Opens `arg` (a file or a built-in name) the way `--preset` does.
    pub fn open(arg: &str, theme: Theme) -> Result<App, preset::PresetError> {
        let (p, path) = open_preset(arg)?;
        Ok(App::new(p, path, theme))
    }

    /// Unsaved edits of the body or the band.
    pub fn modified(&self) -> bool {
        self.shared.modified() || self.shared.preset.band != self.saved_band
    }

    /// The tab shown.
    pub fn tab(&self) -> &dyn Tab {
        self.tabs[self.current.min(self.tabs.len() - 1)].as_ref()
    }

    /// The registered tab of type `T` (tests, benches).
    pub fn tab_state<T: Tab>(&self) -> Option<&T> {
        self.tabs
            .iter()
            .find_map(|t| (t.as_ref() as &dyn std::any::Any).downcast_ref::<T>())
    }

    pub fn mailbox(&self, tab: usize) -> Mailbox {
        Mailbox {
            tab,
            tx: self.tx.clone(),
        }
    }

    /// "k4 = 94500 N/m" on the status line.
    pub fn say_param(&mut self, p: Param) {
        let b = &self.shared.body;
        let text = format!("{} = {} {}", b.label(p), num(b.get(p), 6), p.unit());
        self.say(text);
    }

    pub fn say(&mut self, text: impl Into<String>) {
        self.status = Status {
            text: text.into(),
            error: false,
            at: Instant::now(),
        };
    }

    pub fn fail(&mut self, text: impl Into<String>) {
        self.status = Status {
            text: text.into(),
            error: true,
            at: Instant::now(),
        };
    }

    /// Clears the status line.
    pub fn hush(&mut self) {
        self.status.text.clear();
    }

    /// Drops a message older than its time; true if the screen changed.
    pub fn expire(&mut self, now: Instant) -> bool {
        let ttl = if self.status.error {
            ERROR_TTL
        } else {
            STATUS_TTL
        };
        let old = now.saturating_duration_since(self.status.at) >= ttl;
        if old && !self.status.text.is_empty() {
            self.hush();
            return true;
        }
        false
    }

    /// Opens tab `i`; the last tab's message stays behind.
    pub fn go_to_tab(&mut self, i: usize) {
        if i != self.current {
            self.current = i;
            self.zoom = false;
            self.hush();
        }
    }

    /// True while the terminal is below the size the layout needs.
    pub fn too_small(&self) -> bool {
        use super::terminal::{MIN_HEIGHT, MIN_WIDTH};
        self.size
            .is_some_and(|(w, h)| w < MIN_WIDTH || h < MIN_HEIGHT)
    }

    fn snapshot(&self) -> Snapshot {
        let s = &self.shared;
        Snapshot {
            body: s.body.clone(),
            preset: s.preset.clone(),
            path: s.path.clone(),
            saved: s.saved.clone(),
            saved_band: self.saved_band,
        }
    }

    /// Records the state before a change named `what`.
    fn push_undo(&mut self, before: Snapshot, what: String) {
        self.undo.push(Step { before, what });
        if self.undo.len() > UNDO_LIMIT {
            self.undo.remove(0);
        }
        self.redo.clear();
    }

    /// Puts `snap` in place; returns the state it replaced.
    fn restore(&mut self, snap: Snapshot) -> Snapshot {
        let now = self.snapshot();
        // A band edit is an edit, not another model: the tabs keep their state.
        let mut same = snap.preset.clone();
        same.band = now.preset.band;
        let loaded = now.path != snap.path || now.preset != same;
        self.saved_band = snap.saved_band;
        let s = &mut self.shared;
        s.body = snap.body;
        s.preset = snap.preset;
        s.path = snap.path;
        s.saved = snap.saved;
        self.refresh(if loaded {
            Change::Loaded
        } else {
            Change::Edited
        });
        now
    }

    /// True while a background computation of the model runs.
    pub fn computing(&self) -> bool {
        self.job.is_some()
    }

    /// Tells every tab what changed.
    fn notify(&mut self, change: Change) {
        for (i, t) in self.tabs.iter_mut().enumerate() {
            let cx = Cx {
                shared: &self.shared,
                mailbox: Mailbox {
                    tab: i,
                    tx: self.tx.clone(),
                },
            };
            t.on_change(change, &cx);
        }
    }

    /// Recomputes what is derived from the body: at once for a small
    /// model, in the background for a large one (the stale data stay on
    /// screen, marked, until the new arrive).
    fn refresh(&mut self, change: Change) {
        self.generation += 1;
        let s = &mut self.shared;
        if !derived::in_background(&s.body) || self.tx.is_none() {
            s.derived = Some(Derived::compute(&s.body, &s.preset.band));
            s.modes = Some(derived::modes_of(&s.body));
            s.stale = false;
            self.notify(change);
            self.notify(Change::Derived);
            return;
        }
        if change == Change::Loaded {
            s.derived = None;
            s.modes = None;
        }
        s.stale = s.derived.is_some();
        self.notify(change);
        self.kick();
    }

    /// Starts the background computation of the current body, unless one
    /// runs: that one is told to skip its modes and, when it ends, `kick`
    /// runs again for the newest body. At most one runs at a time.
    fn kick(&mut self) {
        if let Some(job) = &self.job {
            job.cancel();
            return;
        }
        let Some(tx) = self.tx.clone() else {
            return;
        };
        let g = self.generation;
        let (body, band) = (self.shared.body.clone(), self.shared.preset.band);
        match Job::start(g, body, band, move |p| tx.send(Msg::Derived(g, p)).is_ok()) {
            Ok(job) => self.job = Some(job),
            Err(e) => self.fail(format!("cannot start the computation: {e}")),
        }
    }

    pub fn on_derived(&mut self, generation: u64, part: Part) {
        let current = generation == self.generation;
        match part {
            Part::Curves(d) if current => {
                self.shared.derived = Some(*d);
                self.shared.stale = false;
                self.notify(Change::Derived);
            }
            Part::Curves(_) => {}
            Part::Modes(m) => {
                if current && let Some(m) = m {
                    self.shared.modes = Some(m);
                }
                if self
                    .job
                    .as_ref()
                    .is_some_and(|j| j.generation == generation)
                {
                    self.job = None;
                }
                // An older job ended: compute the newest body, if it still
                // waits for one (a small model loaded meanwhile does not).
                let s = &self.shared;
                let waiting = s.stale || s.derived.is_none() || s.modes.is_none();
                if !current && self.job.is_none() && derived::in_background(&s.body) && waiting {
                    self.kick();
                }
            }
        }
    }

    /// Sets a parameter through the library's validation; on success the
    /// old body goes on the undo stack. On error nothing changes.
    pub fn set_param(&mut self, p: Param, v: f64) -> Result<(), String> {
        let mut next = self.shared.body.clone();
        next.set(p, v).map_err(|e| refusal(&e, p))?;
        if next == self.shared.body {
            return Ok(());
        }
        let what = format!(
            "{} {} → {}",
            next.label(p),
            num(self.shared.body.get(p), 6),
            num(next.get(p), 6)
        );
        let before = self.snapshot();
        self.shared.body = next;
        self.push_undo(before, what);
        self.refresh(Change::Edited);
        Ok(())
    }

    /// Sets several parameters in order as one edit (one undo step, named
    /// by their labels); on the first refusal nothing changes.
    pub fn set_params(&mut self, values: &[(Param, f64)]) -> Result<(), String> {
        let mut next = self.shared.body.clone();
        for &(p, v) in values {
            next.set(p, v).map_err(|e| refusal(&e, p))?;
        }
        if next == self.shared.body {
            return Ok(());
        }
        let labels: Vec<String> = values.iter().map(|&(p, _)| next.label(p)).collect();
        let before = self.snapshot();
        self.shared.body = next;
        self.push_undo(before, format!("the edit of {}", labels.join(", ")));
        self.refresh(Change::Edited);
        Ok(())
    }

    /// Undoes the last change and says which ("undid k4 54000 → 90000").
    pub fn undo(&mut self) {
        match self.undo.pop() {
            Some(step) => {
                let now = self.restore(step.before);
                self.say(format!("undid {} (^R redoes it)", step.what));
                self.redo.push(Step {
                    before: now,
                    what: step.what,
                });
            }
            None => self.fail("nothing to undo"),
        }
    }

    pub fn redo(&mut self) {
        match self.redo.pop() {
            Some(step) => {
                let now = self.restore(step.before);
                self.say(format!("redid {}", step.what));
                self.undo.push(Step {
                    before: now,
                    what: step.what,
                });
            }
            None => self.fail("nothing to redo"),
        }
    }

    /// Replaces the model by a loaded preset; undo brings the old one back.
    pub fn load(&mut self, p: Preset, path: Option<PathBuf>) {
        let before = self.snapshot();
        self.shared.body = p.body.clone();
        self.shared.saved = p.body.clone();
        self.shared.preset = p;
        self.shared.path = path;
        self.saved_band = self.shared.preset.band;
        let label = self.shared.file_label();
        self.push_undo(before, format!("open {label}"));
        self.refresh(Change::Loaded);
        self.say(format!("opened {label} (u brings the last model back)"));
    }

    /// Saves atomically; on success the file becomes the loaded one.
    pub fn save_to(&mut self, path: &Path) -> Result<(), String> {
        if path.is_dir() {
            return Err(format!("{} is a folder: add a file name", path.display()));
        }
        let s = &mut self.shared;
        let mut p = s.preset.clone();
        p.body = s.body.clone();
        p.description = fresh_description(&p.description, &s.saved, &s.body);
        p.save(path).map_err(|e| e.to_string())?;
        s.preset = p;
        s.saved = s.body.clone();
        s.path = Some(path.to_path_buf());
        self.saved_band = s.preset.band;
        self.say(format!("saved {}", path.display()));
        Ok(())
    }

    pub fn default_save_path(&self) -> String {
        match &self.shared.path {
            Some(p) => p.display().to_string(),
            None => format!("{}.toml", self.shared.preset.name),
        }
    }

    /// Sets the band (checked by the library: `Band::new`, and the sweep's
    /// work for this model); undoable; every tab recomputes.
    pub fn set_band(&mut self, from: f64, to: f64, step: f64) -> Result<(), String> {
        let band = Band::new(from, to, step).map_err(|e| e.to_string())?;
        band.check_work(self.shared.body.n())
            .map_err(|e| e.to_string())?;
        let old = self.shared.preset.band;
        if band == old {
            self.say("band unchanged");
            return Ok(());
        }
        let what = format!("band {} → {}", band_text(&old), band_text(&band));
        let before = self.snapshot();
        self.shared.preset.band = band;
        self.say(format!("{what} ({} points)", band.len()));
        self.push_undo(before, what);
        self.refresh(Change::Edited);
        Ok(())
    }

    /// Writes the pending export to `path` in the format its extension
    /// names, atomically (temp file in the same folder, then rename).
    pub fn write_export(&mut self, path: &Path) -> Result<(), String> {
        let Some(x) = &self.export else {
            return Err("nothing to export".into());
        };
        let f = x.pick(path)?;
        if path.is_dir() {
            return Err(format!("{} is a folder: add a file name", path.display()));
        }
        if path.exists() && !path.is_file() {
            return Err(format!(
                "{} is not a regular file (a device or pipe): choose another path",
                path.display()
            ));
        }
        biodyn::io::save_atomic(path, f.contents.as_bytes()).map_err(|e| e.to_string())?;
        let text = format!("exported {} ({}) to {}", x.what, f.what, path.display());
        self.export = None;
        self.say(text);
        Ok(())
    }

    /// Carries out what a tab asked for: the one place effects land.
    pub fn apply(&mut self, effects: Vec<Effect>) {
        for e in effects {
            match e {
                Effect::Status(t) => self.say(t),
                Effect::Error(t) => self.fail(t),
                Effect::SetParam(p, v) => match self.set_param(p, v) {
                    Ok(()) => self.say_param(p),
                    Err(why) => self.fail(why),
                },
                Effect::SetParams(values, done) => match self.set_params(&values) {
                    Ok(()) => self.say(done),
                    Err(why) => self.fail(why),
                },
                Effect::OpenField(f) => self.field = Some(f),
                Effect::Export(x) => {
                    let label = match x.formats.as_slice() {
                        [one] => format!("export {} ({}) to", x.what, one.what),
                        many => {
                            let l: Vec<String> = many
                                .iter()
                                .map(|f| format!(".{} {}", f.ext, f.what))
                                .collect();
                            format!("export {} ({}) to", x.what, l.join(", "))
                        }
                    };
                    let f = Field::new(Purpose::Export, label, x.path_hint.clone());
                    self.field = Some(f.for_path());
                    self.export = Some(x);
                }
            }
        }
    }

    /// Why quitting needs a yes: unsaved edits, busy tabs.
    pub fn quit_reasons(&self) -> Vec<&'static str> {
        let mut why = Vec::new();
        if self.modified() {
            why.push("the model has unsaved edits");
        }
        why.extend(self.tabs.iter().filter_map(|t| t.busy()));
        why
    }

    /// Stops every tab's background work (on quit).
    pub fn shutdown(&mut self) {
        for t in &mut self.tabs {
            t.shutdown();
        }
        if let Some(job) = &self.job {
            job.cancel();
        }
    }
}

/// "0.5–20 Hz step 0.1", as the band field and undo name it.
pub fn band_text(b: &Band) -> String {
    format!("{}–{} Hz step {}", b.from, b.to, b.step)
}

/// Why a value was refused, about the value the user typed: a link's
/// stiffness or damping is told its own range only.
fn refusal(e: &biodyn::body::model::ModelError, p: Param) -> String {
    use biodyn::body::model::{MAX_C, MAX_K, ModelError};
    match (e, p) {
        (ModelError::BadLinkValue { link, value, .. }, Param::Stiffness(i)) => format!(
            "k{} of link '{link}' = {value:?} N/m: stiffness must be in [0, {MAX_K:e}] N/m",
            i + 1
        ),
        (ModelError::BadLinkValue { link, value, .. }, Param::Damping(i)) => format!(
            "c{} of link '{link}' = {value:?} N·s/m: damping must be in [0, {MAX_C:e}] N·s/m",
            i + 1
        ),
        _ => e.to_string(),
    }
}

/// The description as it reads for the edited body: a body mass it
/// quotes ("x 75 kg") follows the new one; other edits are noted once.
pub fn fresh_description(desc: &str, saved: &Body, body: &Body) -> String {
    if saved == body || desc.is_empty() {
        return desc.to_string();
    }
    let (old, new) = (saved.get(Param::BodyMass), body.get(Param::BodyMass));
    let mut out = desc.to_string();
    if old != new {
        for sig in (1..=6).rev() {
            let quoted = format!("{} kg", num(old, sig));
            if num(old, sig).parse::<f64>().ok() == Some(old) && out.contains(&quoted) {
                out = out.replace(&quoted, &format!("{} kg", num(new, 6)));
                break;
            }
        }
    }
    // An edit other than the body mass: the description no longer tells all.
    let mut rescaled = saved.clone();
    let only_mass = rescaled.set(Param::BodyMass, new).is_ok() && rescaled == *body;
    const NOTE: &str = " (edited in biodyn)";
    if !only_mass && !out.ends_with(NOTE) {
        out.push_str(NOTE);
    }
    out
}

/// Opens a preset file or built-in name; the path when it is a file.
pub fn open_preset(arg: &str) -> Result<(Preset, Option<PathBuf>), preset::PresetError> {
    let expanded = super::paths::expand(arg);
    let arg = if arg.trim_start().starts_with('~') {
        expanded.to_string_lossy().into_owned()
    } else {
        arg.to_string()
    };
    let p = Preset::open(&arg)?;
    let path = Path::new(&arg).is_file().then(|| PathBuf::from(&arg));
    Ok((p, path))
}
