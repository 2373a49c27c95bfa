//! The app's state: what the tabs share, the tabs, the open field or
//! dialog, the status line, the undo history. `apply` is the one place a
//! tab's effects land; `update.rs` routes messages and keys here. Derived
//! data are recomputed when the model changes, never per frame.

mod commit;
mod effects;
mod files;
mod history;
mod structure;

pub use files::{band_text, fresh_description, open_preset};
pub use history::{Snapshot, Step};

use super::component::{Change, Cx, Tab};
use super::derived::{self, Derived, Job, Part};
use super::effect::Export;
use super::event::{Mailbox, Msg};
use super::popups::field::Field;
use super::popups::help::{self, HelpLine};
use super::popups::{Overlay, View};
use super::shared::Shared;
use super::tabs;
use super::theme::Theme;
use crate::view::format::num;
use biodyn::{Band, Clock, Param, Preset, body};
use std::path::PathBuf;
use std::sync::mpsc::Sender;
use std::time::{Duration, Instant};

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
    /// The signal that ended the app (SIGTERM, SIGHUP, SIGINT, SIGQUIT):
    /// the process then exits with 128 + its number, as a killed command would.
    pub signal: Option<i32>,
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
    /// The clock the tabs' workers and their paused time read: the real
    /// one, or a test's manual one (set before a worker starts).
    pub clock: Clock,
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
            saved_description: preset.description.clone(),
            preset,
            path,
            derived: None,
            modes: None,
            stale: false,
            theme,
            inputs: Vec::new(),
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
            signal: None,
            undo: Vec::new(),
            redo: Vec::new(),
            size: None,
            zoom: false,
            export: None,
            mouse: false,
            saved_band: Band::default(),
            last_click: None,
            tx,
            clock: Clock::Real,
            generation: 0,
            job: None,
        };
        app.saved_band = app.shared.preset.band;
        app.refresh(Change::Loaded);
        app.refresh_inputs();
        app
    }

    /// Gives an app built without a channel one, so a test can swap its
    /// tabs first: the replaced tabs never start a worker that reports on it.
    #[cfg(test)]
    pub fn connect(&mut self, tx: Sender<Msg>) {
        self.tx = Some(tx);
    }

    /// Opens `arg` (a file or a built-in name) the way `--preset` does.
    pub fn open(arg: &str, theme: Theme) -> Result<App, body::PresetError> {
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

    /// Opens a loaded day file on the Day tab (`biodyn tui --day`) and
    /// shows that tab.
    pub fn open_day(&mut self, path: PathBuf, file: biodyn::exposure::DayFile) {
        let Some(i) = self
            .tabs
            .iter()
            .position(|t| (t.as_ref() as &dyn std::any::Any).is::<tabs::day::DayTab>())
        else {
            return;
        };
        let cx = Cx {
            shared: &self.shared,
            mailbox: Mailbox {
                tab: i,
                tx: self.tx.clone(),
                clock: self.clock.clone(),
            },
        };
        let Some(day) =
            (self.tabs[i].as_mut() as &mut dyn std::any::Any).downcast_mut::<tabs::day::DayTab>()
        else {
            return;
        };
        let effects = day.open_loaded(path, file, &cx);
        self.current = i;
        self.apply(effects);
    }

    pub fn mailbox(&self, tab: usize) -> Mailbox {
        Mailbox {
            tab,
            tx: self.tx.clone(),
            clock: self.clock.clone(),
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

    /// Collects the files the app has open into `shared.inputs` (the
    /// preset's, then each tab's), which every save is held to.
    pub fn refresh_inputs(&mut self) {
        let mut inputs: Vec<PathBuf> = self.shared.path.iter().cloned().collect();
        for t in &self.tabs {
            inputs.extend(t.inputs());
        }
        self.shared.inputs = inputs;
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
                    clock: self.clock.clone(),
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

    /// Why quitting needs a yes: unsaved edits, busy tabs.
    pub fn quit_reasons(&self) -> Vec<&'static str> {
        let mut why = Vec::new();
        if self.modified() {
            why.push("the model has unsaved edits");
        }
        why.extend(self.tabs.iter().filter_map(|t| t.busy()));
        why
    }

    /// What the dialogs see of the app (read only); the `?` page's
    /// lines only while it is open.
    pub fn popup_view(&self) -> View {
        View {
            theme: self.shared.theme,
            size: self.size.unwrap_or((80, 24)),
            modified: self.modified(),
            quit_reasons: self.quit_reasons(),
            other_unsaved: self
                .tabs
                .iter()
                .any(|t| t.file().is_some_and(|f| f.modified)),
            help: match self.overlay {
                Overlay::Help(_) => self.help_lines(),
                _ => Vec::new(),
            },
        }
    }

    /// The `?` page's lines for the tab shown.
    pub fn help_lines(&self) -> Vec<HelpLine> {
        let tabs: Vec<(&str, Vec<_>)> = self.tabs.iter().map(|t| (t.title(), t.keys())).collect();
        help::lines(&tabs, self.current, self.shared.theme.ascii)
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
