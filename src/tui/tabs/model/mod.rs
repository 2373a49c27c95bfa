//! Tab Model: the body mass, the segment and link tables (editable values
//! and structure: add, remove, rename, head, shares, description), and
//! beside them the modes and peaks of the current model.

mod bindings;
mod confirm;
mod mouse;
mod panels;
pub mod structure;
mod table;
mod view;

use crate::tui::model_check::check_model;
use crate::tui::component::{Change, Cx, Mouse, Tab};
use crate::tui::effect::Effect;
use crate::tui::popups::field::{Field, Purpose};
use crate::tui::keys::{self, Doc};
use crate::tui::shared::Shared;
use crate::view::format::{for_edit, num};
use bindings::{Action, KEYS};
use biodyn::{Body, Param};
use confirm::Pending;
use ratatui::buffer::Buffer;
use ratatui::crossterm::event::KeyEvent;
use ratatui::layout::Rect;

/// The `+`/`-` factor: `+` multiplies by it, `-` divides, so they undo
/// each other exactly (×0.95 after ×1.05 would not).
pub const NUDGE: f64 = 1.05;

/// Fields the tab opens (`Purpose::Tab` tags).
const ADD_SEGMENT: usize = 0;
const ADD_LINK: usize = 1;
const RENAME: usize = 2;
const DESCRIPTION: usize = 3;
const SHARE: usize = 4;

/// The selected cell: row 0 is the body mass, then one row per segment,
/// then one per link (column 0 = mass / k, 1 = share / c).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct ModelTab {
    pub row: usize,
    pub col: usize,
    /// A delete waiting for its confirmation.
    pub pending: Option<Pending>,
    /// Why the confirmed delete was refused (shown, wrapped, in the question).
    pub refusal: Option<String>,
    /// The first table line shown, as the mouse last left it (drawing
    /// moves it the least that keeps the selection in view).
    pub top: usize,
}

impl ModelTab {
    fn rows(body: &Body) -> usize {
        1 + body.segments.len() + body.links.len()
    }

    fn clamp(&mut self, body: &Body) {
        self.row = self.row.min(Self::rows(body) - 1);
        self.fit_col(body);
    }

    /// The selected row has a second column (a link's c, a segment's share).
    fn two_cols(&self, body: &Body) -> bool {
        self.link(body).is_some() || (self.segment(body).is_some() && body.body_mass.is_some())
    }

    /// Back to the first column on a row without a second (the body mass,
    /// a segment of a model without shares), so Enter edits what is shown.
    fn fit_col(&mut self, body: &Body) {
        if !self.two_cols(body) {
            self.col = 0;
        }
    }

    fn link(&self, body: &Body) -> Option<usize> {
        self.row
            .checked_sub(1 + body.segments.len())
            .filter(|&i| i < body.links.len())
    }

    fn segment(&self, body: &Body) -> Option<usize> {
        self.row.checked_sub(1).filter(|&i| i < body.segments.len())
    }

    /// The parameter under the cursor (a share cell edits as its segment's mass would not).
    pub fn param(&self, body: &Body) -> Param {
        let n = body.segments.len();
        match self.row {
            0 => Param::BodyMass,
            r if r <= n => Param::Mass(r - 1),
            r if self.col == 0 => Param::Stiffness(r - 1 - n),
            r => Param::Damping(r - 1 - n),
        }
    }

    /// A share cell is selected.
    fn on_share(&self, body: &Body) -> bool {
        self.col == 1 && self.segment(body).is_some()
    }

    fn field(tag: usize, label: impl Into<String>, text: impl Into<String>) -> Vec<Effect> {
        vec![Effect::OpenField(Field::new(
            Purpose::Tab(tag),
            label,
            text,
        ))]
    }

    /// Moves the selection for a cursor key (as the wheel does); false
    /// for any other action.
    fn step(&mut self, a: Action, body: &Body) -> bool {
        let rows = Self::rows(body);
        self.row = match a {
            Action::Up => (self.row + rows - 1) % rows,
            Action::Down => (self.row + 1) % rows,
            Action::PageUp => self.row.saturating_sub(20),
            Action::PageDown => (self.row + 20).min(rows - 1),
            Action::Home => 0,
            Action::End => rows - 1,
            _ => return false,
        };
        self.fit_col(body);
        true
    }

    fn act(&mut self, a: Action, s: &Shared) -> Vec<Effect> {
        let body = &s.body;
        if self.step(a, body) {
            return Vec::new();
        }
        match a {
            // Moved by `step`.
            Action::Up
            | Action::Down
            | Action::PageUp
            | Action::PageDown
            | Action::Home
            | Action::End => {}
            Action::Left | Action::Right if self.two_cols(body) => self.col = 1 - self.col,
            Action::Left | Action::Right => {}
            Action::Edit if self.on_share(body) => {
                let i = self.row - 1;
                let share = body.segments[i]
                    .share
                    .map_or(String::new(), |sh| for_edit(sh * 100.0));
                return Self::field(
                    SHARE,
                    format!("share of body mass of '{}' (%)", body.segments[i].name),
                    share,
                );
            }
            Action::NudgeUp | Action::NudgeDown if self.on_share(body) => {
                return vec![Effect::Error(
                    "a share changes by Enter (type the %); +/- step masses, k and c".into(),
                )];
            }
            Action::Edit | Action::NudgeUp | Action::NudgeDown
                if self.param(body) == Param::BodyMass && !table::has_shares(body) =>
            {
                // The advice first, short: the status line is one row.
                return vec![Effect::Error(format!(
                    "no shares: edit m1…m{} (body mass = sum, {} kg)",
                    body.segments.len(),
                    num(body.seated_mass(), 4)
                ))];
            }
            Action::Edit => {
                let p = self.param(body);
                return vec![Effect::OpenField(Field::new(
                    Purpose::Param(p),
                    s.describe(p),
                    for_edit(body.get(p)),
                ))];
            }
            Action::NudgeUp | Action::NudgeDown => {
                let p = self.param(body);
                let v = body.get(p);
                if v == 0.0 {
                    return vec![Effect::Error(format!(
                        "{} is 0: a percentage step cannot move it; press Enter to type a value",
                        body.label(p)
                    ))];
                }
                let next = if a == Action::NudgeUp {
                    v * NUDGE
                } else {
                    v / NUDGE
                };
                return vec![Effect::SetParam(p, next)];
            }
            Action::AddSegment => {
                let on = self
                    .segment(body)
                    .map_or("seat".to_string(), |i| body.segments[i].name.clone());
                return Self::field(
                    ADD_SEGMENT,
                    "add segment: name mass_kg lower(segment|seat) [k_N/m c_N·s/m]",
                    structure::add_segment_template(body, &on),
                );
            }
            Action::AddLink => {
                let upper = self
                    .segment(body)
                    .or_else(|| self.link(body).map(|i| body.links[i].upper))
                    .and_then(|i| body.segments.get(i))
                    .map_or("segment", |s| s.name.as_str());
                return Self::field(
                    ADD_LINK,
                    "add link: upper lower(segment|seat) k_N/m c_N·s/m [name]",
                    format!("{upper} seat {} {}", structure::NEW_K, structure::NEW_C),
                );
            }
            Action::Delete => match (self.segment(body), self.link(body)) {
                (Some(i), _) => self.pending = Some(Pending::Segment(i)),
                (_, Some(i)) => self.pending = Some(Pending::Link(i)),
                _ => {
                    return vec![Effect::Error(
                        "select a segment or a link to delete (the body mass stays)".into(),
                    )];
                }
            },
            Action::Rename => {
                let name = match (self.segment(body), self.link(body)) {
                    (Some(i), _) => format!("segment m{}", i + 1),
                    (_, Some(i)) => format!("link {}", i + 1),
                    _ => return vec![Effect::Error("select a segment or a link to rename".into())],
                };
                let now = self
                    .segment(body)
                    .map(|i| body.segments[i].name.clone())
                    .or_else(|| self.link(body).map(|i| body.links[i].name.clone()))
                    .unwrap_or_default();
                return Self::field(RENAME, format!("rename {name}"), now);
            }
            Action::Head => {
                let Some(i) = self.segment(body) else {
                    return vec![Effect::Error(
                        "select a segment to make it the head (STHT is its motion)".into(),
                    )];
                };
                return self.structural(s, structure::set_head(body, i), None);
            }
            Action::Description => {
                return Self::field(
                    DESCRIPTION,
                    "description (saved with the preset)",
                    s.preset.description.clone(),
                );
            }
        }
        Vec::new()
    }

    /// A structural edit as an effect, or the refusal as an error.
    fn structural(
        &self,
        s: &Shared,
        edit: Result<(Body, String), String>,
        description: Option<String>,
    ) -> Vec<Effect> {
        match edit.and_then(|(body, what)| check_model(&s.preset, &body).map(|()| (body, what))) {
            Ok((body, what)) => vec![Effect::SetModel {
                body: Box::new(body),
                description,
                what,
            }],
            Err(why) => vec![Effect::Error(why)],
        }
    }
}

impl Tab for ModelTab {
    fn new(_shared: &Shared) -> Self {
        ModelTab::default()
    }

    fn title(&self) -> &'static str {
        "Model"
    }

    fn keys(&self) -> Vec<&'static Doc> {
        if let Some(p) = self.pending {
            keys::docs(confirm::keys_for(p))
        } else {
            keys::docs(KEYS)
        }
    }

    fn on_key(&mut self, ev: &KeyEvent, cx: &Cx) -> Option<Vec<Effect>> {
        if let Some(p) = self.pending {
            if let Some(a) = keys::lookup(confirm::keys_for(p), ev) {
                return Some(self.answer(a, cx.shared));
            }
            // Any other key drops the question and does what it does.
            self.pending = None;
            self.refusal = None;
        }
        keys::lookup(KEYS, ev).map(|a| self.act(a, cx.shared))
    }

    fn commit(&mut self, tag: usize, text: &str, cx: &Cx) -> Result<Vec<Effect>, String> {
        let s = cx.shared;
        let body = &s.body;
        let (edit, description) = match tag {
            ADD_SEGMENT => (structure::add_segment(body, text)?, None),
            ADD_LINK => (structure::add_link(body, text)?, None),
            RENAME => (
                structure::rename(body, self.segment(body), self.link(body), text)?,
                None,
            ),
            SHARE => {
                let i = self.segment(body).ok_or("select a segment")?;
                (structure::set_share(body, i, text)?, None)
            }
            DESCRIPTION => (
                (body.clone(), "edit the description".to_string()),
                Some(text.trim().to_string()),
            ),
            _ => return Ok(Vec::new()),
        };
        let (body, what) = edit;
        // Refused here, the field stays open with the library's reason.
        check_model(&s.preset, &body)?;
        if tag == ADD_SEGMENT || tag == ADD_LINK {
            // The new row is the last of its table: select it.
            let n = body.segments.len();
            self.row = if tag == ADD_SEGMENT {
                n
            } else {
                n + body.links.len()
            };
            self.col = 0;
        }
        Ok(vec![Effect::SetModel {
            body: Box::new(body),
            description,
            what,
        }])
    }

    fn on_change(&mut self, _change: Change, cx: &Cx) {
        self.clamp(&cx.shared.body);
        if let Some(Pending::Segment(i) | Pending::Link(i)) = self.pending
            && i >= cx
                .shared
                .body
                .segments
                .len()
                .max(cx.shared.body.links.len())
        {
            self.pending = None;
            self.refusal = None;
        }
    }

    fn on_mouse(&mut self, m: Mouse, area: Rect, cx: &Cx) -> Vec<Effect> {
        self.mouse(m, area, cx)
    }

    fn render(&self, s: &Shared, area: Rect, buf: &mut Buffer) {
        view::render(self, s, area, buf);
    }

    fn has_chart(&self, s: &Shared) -> bool {
        s.derived.is_some()
    }

    fn render_zoomed(&self, s: &Shared, area: Rect, buf: &mut Buffer) {
        view::stht_chart(s, area, buf);
    }
}
