//! Tab Day: the working day as the HSE whole-body vibration calculator
//! lays it out, with the records behind it. The operations are an
//! editable table (name, hours, a_w per axis before k, or a record); live
//! beside them, per operation and axis, k·a_w, the partial A(8), points
//! and the hours to the action and limit values; the day per axis and its
//! exposure, the highest axis (Directive 2002/44/EC Annex B), with the
//! verdict; and the points of each operation against 100 and 529.
//! Ctrl-S / Ctrl-O / u / Ctrl-R save, open, undo and redo the day here.

mod bars;
mod bindings;
mod edit;
mod export;
mod files;
mod history;
pub(super) mod records;
mod sheet;
mod view;

#[cfg(test)]
mod tests;

use crate::tui::component::{Cx, FileTitle, Tab};
use crate::tui::effect::Effect;
use crate::tui::keys::{self, Doc};
use crate::tui::popups::field::{Field, Purpose};
use crate::tui::shared::Shared;
use bindings::{Action, KEYS};
use biodyn::iso2631::spine::Person;
use biodyn::exposure::{DayFile, OperationSpec, Source};
use biodyn::time::{Axis, PerAxis};
use edit::Col;
use history::{History, Snapshot};
use ratatui::buffer::Buffer;
use ratatui::crossterm::event::KeyEvent;
use ratatui::layout::Rect;
use records::{Records, Report};
use sheet::Sheet;
use std::any::Any;
use std::path::PathBuf;

/// Fields the tab opens (`Purpose::Tab` tags).
const EDIT: usize = 0;
const ADD: usize = 1;
const SAVE: usize = 2;
const OPEN: usize = 3;

#[derive(Debug)]
pub struct DayTab {
    /// The operations as edited.
    pub ops: Vec<OperationSpec>,
    /// As last opened or saved: `ops != saved` is an unsaved edit.
    pub saved: Vec<OperationSpec>,
    /// The day file; None for a new day.
    pub path: Option<PathBuf>,
    /// The day file's ISO 2631-5 person: not edited here, kept and written
    /// back on save (`biodyn day` judges it).
    pub spine: Option<Person>,
    /// The day file's `[report]` table: kept and written back on save.
    pub report: biodyn::exposure::Meta,
    /// The selected operation and column.
    pub row: usize,
    pub col: Col,
    /// The day evaluated from `ops` and the records measured so far.
    pub sheet: Sheet,
    records: Records,
    history: History,
    /// A save path that exists, replaced on a second Enter.
    replace: Option<PathBuf>,
}

/// The day a fresh app starts with: one example operation (the issue's
/// haul road: x 0.36, y 0.21, z 0.52 m/s² for 3.25 h), to edit or delete.
fn example() -> Vec<OperationSpec> {
    let mut aw = PerAxis::default();
    aw.set(Axis::X, 0.36);
    aw.set(Axis::Y, 0.21);
    aw.set(Axis::Z, 0.52);
    vec![OperationSpec {
        name: "haul road".into(),
        hours: 3.25,
        source: Source::Measured {
            aw,
            vdv: PerAxis::default(),
            measured_s: None,
            dz: None,
        },
    }]
}

impl DayTab {
    pub fn modified(&self) -> bool {
        self.ops != self.saved
    }

    fn snapshot(&self) -> Snapshot {
        Snapshot {
            ops: self.ops.clone(),
            saved: self.saved.clone(),
            path: self.path.clone(),
            spine: self.spine,
            report: self.report.clone(),
        }
    }

    /// Puts a step's day back: for an open or save-as the whole document,
    /// for an edit the operations only (the file and what was last saved
    /// stay, so an undo after Ctrl-S is an unsaved edit).
    fn restore(&mut self, s: Snapshot, document: bool) {
        self.ops = s.ops;
        if document {
            self.saved = s.saved;
            self.path = s.path;
            self.spine = s.spine;
            self.report = s.report;
        }
    }

    /// After any change of the operations: the selection kept on the
    /// table, records not read yet asked for, the sheet again.
    fn refresh(&mut self, cx: &Cx) -> Vec<Effect> {
        self.row = self.row.min(self.ops.len().saturating_sub(1));
        let failed = self.records.request(&sheet::records_of(&self.ops), &cx.mailbox);
        self.sheet = Sheet::of(&self.ops, &self.records);
        failed.map(Effect::Error).into_iter().collect()
    }

    /// An edit of the operations: undoable as `what`.
    fn apply(&mut self, ops: Vec<OperationSpec>, what: String, cx: &Cx) -> Vec<Effect> {
        if ops == self.ops {
            return vec![Effect::Status("unchanged".into())];
        }
        let before = self.snapshot();
        self.ops = ops;
        self.history.push(before, what.clone());
        let mut out = vec![Effect::Status(what)];
        out.extend(self.refresh(cx));
        out
    }

    fn field(tag: usize, label: impl Into<String>, text: impl Into<String>) -> Vec<Effect> {
        vec![Effect::OpenField(Field::new(Purpose::Tab(tag), label, text))]
    }

    fn folder(&self) -> PathBuf {
        files::folder_of(self.path.as_deref())
    }

    fn act(&mut self, a: Action, cx: &Cx) -> Vec<Effect> {
        let n = self.ops.len();
        let cols = Col::ALL.len();
        let c = self.col.index();
        match a {
            Action::Up if n > 0 => self.row = (self.row + n - 1) % n,
            Action::Down if n > 0 => self.row = (self.row + 1) % n,
            Action::Up | Action::Down => {}
            Action::Left => self.col = Col::ALL[(c + cols - 1) % cols],
            Action::Right => self.col = Col::ALL[(c + 1) % cols],
            Action::Home => self.row = 0,
            Action::End => self.row = n.saturating_sub(1),
            Action::Edit => return self.edit(),
            Action::Clear => {
                let mut ops = self.ops.clone();
                let measured = self
                    .ops
                    .get(self.row)
                    .and_then(|o| sheet::measured_of(o, &self.records))
                    .cloned();
                return match edit::clear(&mut ops, self.row, self.col, measured.as_ref()) {
                    Ok(what) => self.apply(ops, what, cx),
                    Err(why) => vec![Effect::Error(why)],
                };
            }
            Action::Add => {
                return Self::field(
                    ADD,
                    "add operation: its name (then Enter on hours and a_w)",
                    format!("operation {}", n + 1),
                );
            }
            Action::Delete => {
                let Some(o) = self.ops.get(self.row) else {
                    return vec![Effect::Error("no operation to delete: a adds one".into())];
                };
                let what = format!("delete operation '{}' (u brings it back)", o.name);
                let mut ops = self.ops.clone();
                ops.remove(self.row);
                return self.apply(ops, what, cx);
            }
            Action::Export => return export::effects(self),
            Action::Remeasure => {
                self.records.forget();
                let mut out = vec![Effect::Status("reading the records again".into())];
                out.extend(self.refresh(cx));
                return out;
            }
        }
        Vec::new()
    }

    fn edit(&self) -> Vec<Effect> {
        let Some(o) = self.ops.get(self.row) else {
            return vec![Effect::Error("no operations: a adds one".into())];
        };
        if let (Col::Aw(_), Source::Record(r)) = (self.col, &o.source) {
            return vec![Effect::Error(format!(
                "'{}' takes its a_w from {}; Backspace on the record types them in instead",
                o.name, r.path
            ))];
        }
        let label = format!("{} of '{}'", self.col.label(), o.name);
        let f = Field::new(Purpose::Tab(EDIT), label, edit::cell_text(o, self.col));
        let f = if self.col == Col::Record { f.for_path() } else { f };
        vec![Effect::OpenField(f)]
    }

    /// A day file loaded before the app started (`biodyn tui --day`).
    pub fn open_loaded(&mut self, path: PathBuf, file: DayFile, cx: &Cx) -> Vec<Effect> {
        let label = path.display().to_string();
        self.load(file.operations, file.spine, Some(path));
        self.report = file.report;
        let mut out = vec![Effect::Status(format!("opened {label}"))];
        out.extend(self.refresh(cx));
        out
    }

    fn undo_redo(&mut self, undo: bool, cx: &Cx) -> Vec<Effect> {
        let now = self.snapshot();
        let step = if undo {
            self.history.undo(now)
        } else {
            self.history.redo(now)
        };
        let Some(step) = step else {
            let what = if undo { "undo" } else { "redo" };
            return vec![Effect::Status(format!("nothing to {what} on the day"))];
        };
        self.restore(step.before, step.document);
        let verb = if undo { "undid" } else { "redid" };
        let mut out = vec![Effect::Status(format!("{verb} {}", step.what))];
        out.extend(self.refresh(cx));
        out
    }
}

impl Tab for DayTab {
    fn new(_shared: &Shared) -> Self {
        let ops = example();
        let records = Records::default();
        let sheet = Sheet::of(&ops, &records);
        DayTab {
            saved: ops.clone(),
            ops,
            path: None,
            row: 0,
            col: Col::Name,
            sheet,
            records,
            history: History::default(),
            replace: None,
            spine: None,
            report: Default::default(),
        }
    }

    fn title(&self) -> &'static str {
        "Day"
    }

    fn keys(&self) -> Vec<&'static Doc> {
        keys::docs(KEYS)
    }

    fn on_key(&mut self, ev: &KeyEvent, cx: &Cx) -> Option<Vec<Effect>> {
        keys::lookup(KEYS, ev).map(|a| self.act(a, cx))
    }

    fn on_global(&mut self, a: keys::Action, cx: &Cx) -> Option<Vec<Effect>> {
        use keys::Action as G;
        Some(match a {
            G::Save => {
                self.replace = None;
                let path = self
                    .path
                    .as_ref()
                    .map_or("my-day.toml".to_string(), |p| p.display().to_string());
                let mut f = Field::new(Purpose::Tab(SAVE), "save the day to", path);
                f.path = true;
                vec![Effect::OpenField(f)]
            }
            G::Open => {
                let path = self
                    .path
                    .as_ref()
                    .map_or("examples/day.toml".to_string(), |p| p.display().to_string());
                let mut f = Field::new(Purpose::Tab(OPEN), "open a day file (TOML)", path);
                f.path = true;
                vec![Effect::OpenField(f)]
            }
            G::Undo => self.undo_redo(true, cx),
            G::Redo => self.undo_redo(false, cx),
            _ => return None,
        })
    }

    fn file(&self) -> Option<FileTitle> {
        Some(FileTitle {
            label: self
                .path
                .as_ref()
                .map_or("new day".into(), |p| p.display().to_string()),
            has_path: self.path.is_some(),
            modified: self.modified(),
        })
    }

    fn commit(&mut self, tag: usize, text: &str, cx: &Cx) -> Result<Vec<Effect>, String> {
        match tag {
            EDIT => {
                let mut ops = self.ops.clone();
                let what = edit::set(&mut ops, self.row, self.col, text, &self.folder())?;
                Ok(self.apply(ops, what, cx))
            }
            ADD => {
                let mut ops = self.ops.clone();
                let at = (!ops.is_empty()).then_some(self.row);
                let (i, what) = edit::add(&mut ops, at, text)?;
                let out = self.apply(ops, what, cx);
                self.row = i;
                self.col = Col::Hours;
                Ok(out)
            }
            SAVE => {
                let said = self.save_to(text, cx.shared)?;
                let mut out = vec![Effect::Status(said)];
                out.extend(self.refresh(cx));
                Ok(out)
            }
            OPEN => {
                let said = self.open(text)?;
                let mut out = vec![Effect::Status(said)];
                out.extend(self.refresh(cx));
                Ok(out)
            }
            _ => Ok(Vec::new()),
        }
    }

    fn on_msg(&mut self, msg: Box<dyn Any + Send>, cx: &Cx) -> Vec<Effect> {
        let Ok(report) = msg.downcast::<Report>() else {
            return Vec::new();
        };
        let failure = match report.as_ref() {
            // The reader's reason names the file already.
            Report::One(_, Err(why)) => Some(why.clone()),
            _ => None,
        };
        self.records.on_report(*report);
        let mut out: Vec<Effect> = failure.map(Effect::Error).into_iter().collect();
        out.extend(self.refresh(cx));
        out
    }

    fn render(&self, s: &Shared, area: Rect, buf: &mut Buffer) {
        view::render(self, s.theme, area, buf);
    }

    fn inputs(&self) -> Vec<PathBuf> {
        let records = self.ops.iter().filter_map(|o| match &o.source {
            biodyn::exposure::Source::Record(r) => Some(r.resolved.clone()),
            _ => None,
        });
        self.path.iter().cloned().chain(records).collect()
    }

    fn has_chart(&self, _s: &Shared) -> bool {
        true
    }

    fn render_zoomed(&self, s: &Shared, area: Rect, buf: &mut Buffer) {
        bars::render(&self.sheet, &self.ops, s.theme, area, buf);
    }

    fn busy(&self) -> Option<&'static str> {
        self.modified().then_some("the day has unsaved edits")
    }
}
