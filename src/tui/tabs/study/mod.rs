//! Tab Study: one parameter varied over a list of values, the curves
//! overlaid with a legend (the paper's Figures 2–4), the peak table, and the
//! direction of change of each function spelled out from `Study::trends`.
//! A frequency cursor (`cursor.rs`) reads every variant's magnitude in the
//! legend; `view.rs` draws the tab, `layout.rs` places it and takes clicks.

mod cursor;
mod export;
mod layout;
mod mouse;
mod table;
mod view;

#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_lines;

pub use cursor::Cursor;
use cursor::Move;

use crate::tui::component::{Change, Cx, Mouse, Tab};
use crate::tui::derived::in_background;
use crate::tui::effect::Effect;
use crate::tui::popups::field::{Field, Purpose};
use crate::tui::keys::{self, Binding, Doc, b, code, k};
use crate::tui::shared::Shared;
use crate::view::chart::Series;
use biodyn::{Band, Body, Function, Param};
use biodyn::freq::{self, Study};
use ratatui::buffer::Buffer;
use ratatui::crossterm::event::{KeyCode as KC, KeyEvent};
use ratatui::layout::Rect;
use std::any::Any;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Action {
    Left,
    Right,
    Paper(PaperStudy),
    Edit,
    Reset,
    NextFunction,
    ToggleLog,
    LegendUp,
    LegendDown,
    Export,
    Cursor(Move),
    GoTo,
}

/// The paper's three studies.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum PaperStudy {
    BodyMass,
    SeatK,
    SeatC,
}

static KEYS: &[Binding<Action>] = &[
    b(
        &[code(KC::Left), k('h')],
        Action::Left,
        "previous parameter",
        Some("←→ parameter"),
    ),
    b(
        &[code(KC::Right), k('l')],
        Action::Right,
        "next parameter",
        None,
    ),
    b(
        &[k('m')],
        Action::Paper(PaperStudy::BodyMass),
        "the paper's body-mass study: 65,75,85 kg",
        Some("m/k/c paper"),
    ),
    b(
        &[k('k')],
        Action::Paper(PaperStudy::SeatK),
        "the paper's k4 study (seat link): -40%,0%,+40%",
        None,
    ),
    b(
        &[k('c')],
        Action::Paper(PaperStudy::SeatC),
        "the paper's c4 study (seat link): -40%,0%,+40%",
        None,
    ),
    b(
        &[code(KC::Enter), k('e')],
        Action::Edit,
        "edit the values: 65,75,85 or -40%,0%,+40%",
        Some("Enter values"),
    ),
    b(
        &[k('r')],
        Action::Reset,
        "reset the value list to the paper's",
        Some("r reset"),
    ),
    b(
        &[k('f')],
        Action::NextFunction,
        "next function (when one chart is shown)",
        Some("f function"),
    ),
    b(
        &[k('a')],
        Action::ToggleLog,
        "linear / log axes",
        Some("a lin/log"),
    ),
    b(
        &[code(KC::Up)],
        Action::LegendUp,
        "scroll the legend (peaks, values at the cursor) up",
        Some("↑↓ legend"),
    ),
    b(
        &[code(KC::Down)],
        Action::LegendDown,
        "scroll the legend down",
        None,
    ),
    b(
        &[k('<'), k(',')],
        Action::Cursor(Move::Down),
        "frequency cursor down one grid step",
        Some("<> cursor"),
    ),
    b(
        &[k('>'), k('.')],
        Action::Cursor(Move::Up),
        "frequency cursor up one grid step",
        None,
    ),
    b(
        &[code(KC::PageUp)],
        Action::Cursor(Move::PageDown),
        "cursor down 1 Hz",
        None,
    ),
    b(
        &[code(KC::PageDown)],
        Action::Cursor(Move::PageUp),
        "cursor up 1 Hz",
        None,
    ),
    b(
        &[code(KC::Home)],
        Action::Cursor(Move::Start),
        "cursor to the band start",
        None,
    ),
    b(
        &[code(KC::End)],
        Action::Cursor(Move::End),
        "cursor to the band end",
        None,
    ),
    b(
        &[k('g')],
        Action::GoTo,
        "go to a frequency: each variant computed exactly there",
        Some("g go to"),
    ),
    b(
        &[k('x')],
        Action::Export,
        "export: .csv the curves (= biodyn study), .txt the chart (= biodyn plot)",
        Some("x export"),
    ),
];

/// The field tag of the value list.
const VALUES: usize = 0;

/// A study computed in the background, for model generation `generation`.
struct Done {
    generation: u64,
    result: Result<Study, String>,
}

#[derive(Debug, Clone)]
pub struct StudyTab {
    /// Body mass, then m1.., k1.., c1.. of the current model.
    pub params: Vec<Param>,
    pub sel: usize,
    /// The value list as typed: "65,75,85" or "-40%,0%,+40%".
    pub values: String,
    /// None while a large model's study runs in the background.
    pub result: Option<Result<Study, String>>,
    /// Curves per function (`Function::ALL` order), one series per variant.
    pub series: Vec<Vec<Series>>,
    /// The function shown when only one chart fits.
    pub func: usize,
    pub log: bool,
    /// First variant row shown in the peak table (it scrolls when long).
    pub legend_top: usize,
    /// Value lists the user typed, per parameter (index in `params`), kept
    /// while cycling.
    pub custom: std::collections::HashMap<usize, String>,
    /// The frequency cursor and each variant's response there.
    pub cursor: Cursor,
    /// Counts the runs, so a late background result for an older one is dropped.
    generation: u64,
}

/// The paper's lists: 65/75/85 kg, and base value ±40 % for k4 and c4
/// (the library's, as `biodyn study PARAM` without values takes them).
pub fn default_values(p: Param) -> &'static str {
    biodyn::freq::paper_steps(p)
}

impl StudyTab {
    pub fn for_body(body: &Body) -> StudyTab {
        let n = body.segments.len();
        let l = body.links.len();
        let mut params = vec![Param::BodyMass];
        params.extend((0..n).map(Param::Mass));
        params.extend((0..l).map(Param::Stiffness));
        params.extend((0..l).map(Param::Damping));
        // Body mass needs shares; without them start on the seat link's k
        // (k4 in the paper's chain), the paper's second study.
        let shares = body.segments.iter().all(|s| s.share.is_some());
        let sel = if shares || l == 0 { 0 } else { 1 + n + l - 1 };
        let values = params.get(sel).map_or("", |&p| default_values(p)).into();
        StudyTab {
            sel,
            values,
            params,
            result: Some(Err("not run yet".into())),
            series: Vec::new(),
            func: 0,
            log: false,
            legend_top: 0,
            custom: std::collections::HashMap::new(),
            cursor: Cursor::default(),
            generation: 0,
        }
    }

    pub fn param(&self) -> Param {
        self.params
            .get(self.sel)
            .copied()
            .unwrap_or(Param::BodyMass)
    }

    /// Runs the study on the current body: at once for a small model, on a
    /// thread for a large one (the result comes back through the mailbox).
    fn rerun(&mut self, cx: &Cx) {
        self.generation += 1;
        let s = cx.shared;
        let (body, p, values, band) = (s.body.clone(), self.param(), self.values.clone(), *s.band());
        if in_background(&body)
            && let Some((tx, wrap)) = cx.mailbox.wrap::<Done>()
        {
            self.result = None;
            self.series.clear();
            let generation = self.generation;
            let spawned = std::thread::Builder::new()
                .name("study".into())
                .spawn(move || {
                    let result = compute(&body, p, &values, &band);
                    let _ = tx.send(wrap(Done { generation, result }));
                });
            if let Err(e) = spawned {
                self.set_result(Err(format!("cannot start the study: {e}")), &band);
            }
            return;
        }
        self.set_result(compute(&body, p, &values, &band), &band);
    }

    /// Takes a study's result: its curves per function, and the cursor's
    /// values computed on its variants.
    fn set_result(&mut self, result: Result<Study, String>, band: &Band) {
        self.series = match &result {
            Ok(st) => Function::ALL
                .iter()
                .map(|&f| {
                    st.variants
                        .iter()
                        .map(|v| Series {
                            name: v.label.clone(),
                            points: v.curve.iter().map(|r| (r.f_hz, r.mag(f))).collect(),
                        })
                        .collect()
                })
                .collect(),
            Err(_) => Vec::new(),
        };
        self.cursor.follow(result.as_ref().ok(), band);
        self.result = Some(result);
    }

    fn select(&mut self, i: usize, cx: &Cx) {
        self.sel = i;
        let p = self.param();
        self.values = self
            .custom
            .get(&i)
            .cloned()
            .unwrap_or_else(|| default_values(p).into());
        self.legend_top = 0;
        self.rerun(cx);
    }

    fn act(&mut self, a: Action, cx: &Cx) -> Vec<Effect> {
        let n = self.params.len().max(1);
        match a {
            Action::Left => self.select((self.sel + n - 1) % n, cx),
            Action::Right => self.select((self.sel + 1) % n, cx),
            Action::Paper(which) => {
                let body = &cx.shared.body;
                let seat = body.links.iter().position(|l| l.lower == biodyn::End::Seat);
                let want = match (which, seat) {
                    (PaperStudy::BodyMass, _) => Some(Param::BodyMass),
                    (PaperStudy::SeatK, Some(i)) => Some(Param::Stiffness(i)),
                    (PaperStudy::SeatC, Some(i)) => Some(Param::Damping(i)),
                    _ => None,
                };
                if let Some(i) = want.and_then(|p| self.params.iter().position(|&q| q == p)) {
                    self.select(i, cx);
                }
            }
            Action::Reset => {
                self.custom.remove(&self.sel);
                self.values = default_values(self.param()).into();
                self.rerun(cx);
            }
            Action::LegendUp => self.legend_top = self.legend_top.saturating_sub(1),
            Action::LegendDown => {
                let n = self.result.as_ref().and_then(|r| r.as_ref().ok()).map_or(0, |s| s.variants.len());
                self.legend_top = (self.legend_top + 1).min(n.saturating_sub(1));
            }
            Action::Edit => {
                let label = format!("values of {}", cx.shared.body.label(self.param()));
                return vec![Effect::OpenField(Field::new(
                    Purpose::Tab(VALUES),
                    label,
                    self.values.clone(),
                ))];
            }
            Action::Export => return self.export(cx.shared),
            Action::Cursor(m) => {
                self.cursor.step(m, cx.shared.band());
                return self.cursor.said();
            }
            Action::GoTo => return self.go_to_field(cx.shared),
            Action::NextFunction => self.func = (self.func + 1) % Function::ALL.len(),
            Action::ToggleLog => self.log = !self.log,
        }
        Vec::new()
    }
}

/// The list as the library reads it: commas between entries. Tabs
/// (a pasted spreadsheet row), spaces and semicolons separate too, and a
/// lone `%` belongs to the number before it ("40 %").
pub fn normalize_values(text: &str) -> String {
    let mut out: Vec<String> = Vec::new();
    for tok in text.split(|c: char| c == ',' || c == ';' || c.is_whitespace()) {
        match (tok, out.last_mut()) {
            ("", _) => {}
            ("%", Some(prev)) => prev.push('%'),
            (t, _) => out.push(t.to_string()),
        }
    }
    out.join(",")
}

fn compute(body: &Body, p: Param, values: &str, band: &Band) -> Result<Study, String> {
    let steps = freq::parse_steps(&normalize_values(values)).map_err(|e| e.to_string())?;
    freq::run_study(body, p, &steps, band).map_err(|e| e.to_string())
}

impl Tab for StudyTab {
    fn new(shared: &Shared) -> Self {
        StudyTab::for_body(&shared.body)
    }

    fn title(&self) -> &'static str {
        "Study"
    }

    fn keys(&self) -> Vec<&'static Doc> {
        keys::docs(KEYS)
    }

    fn on_key(&mut self, ev: &KeyEvent, cx: &Cx) -> Option<Vec<Effect>> {
        keys::lookup(KEYS, ev).map(|a| self.act(a, cx))
    }

    /// Takes a new value list if it parses (and, for a small model, runs);
    /// otherwise says why and keeps the old one.
    fn commit(&mut self, tag: usize, text: &str, cx: &Cx) -> Result<Vec<Effect>, String> {
        let s = cx.shared;
        if tag == cursor::GOTO {
            return self.go_to(text, s);
        }
        let text = normalize_values(text);
        if in_background(&s.body) {
            freq::parse_steps(&text).map_err(|e| e.to_string())?;
        } else {
            compute(&s.body, self.param(), &text, s.band())?;
        }
        self.values = text;
        if self.values == default_values(self.param()) {
            self.custom.remove(&self.sel);
        } else {
            self.custom.insert(self.sel, self.values.clone());
        }
        self.legend_top = 0;
        self.rerun(cx);
        Ok(Vec::new())
    }

    fn on_mouse(&mut self, m: Mouse, area: Rect, cx: &Cx) -> Vec<Effect> {
        self.mouse(m, area, cx)
    }

    fn on_change(&mut self, change: Change, cx: &Cx) {
        match change {
            Change::Loaded => {
                *self = StudyTab::for_body(&cx.shared.body);
                self.rerun(cx);
            }
            Change::Edited => self.rerun(cx),
            Change::Derived => {}
        }
    }

    fn on_msg(&mut self, msg: Box<dyn Any + Send>, cx: &Cx) -> Vec<Effect> {
        if let Ok(done) = msg.downcast::<Done>()
            && done.generation == self.generation
        {
            self.set_result(done.result, cx.shared.band());
        }
        Vec::new()
    }

    fn render(&self, s: &Shared, area: Rect, buf: &mut Buffer) {
        view::render(self, s, area, buf, false);
    }

    fn has_chart(&self, _s: &Shared) -> bool {
        matches!(self.result, Some(Ok(_)))
    }

    /// The chart of the current function, with the header, over the whole tab.
    fn render_zoomed(&self, s: &Shared, area: Rect, buf: &mut Buffer) {
        view::render(self, s, area, buf, true);
    }
}

