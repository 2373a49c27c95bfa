//! Tab Seat: the seat between floor and body (SPEC §11, ISO 10326-1). The
//! seat's transmissibility (pan over floor, and floor to head beside it),
//! SEAT % under each input spectral class (ISO 7096, EN 13490, ISO 5007),
//! the selected class's r.m.s. travel against the seat's, and the design
//! map: SEAT over the suspension's k and c with the travel limit, the best
//! point (`biodyn::seat::design`) and the model's own. Recomputed on every
//! model edit, so editing the suspension on the Model tab moves it live.
//! A model without a seat gets a line saying how to load one.

mod bindings;
pub mod compute;
mod export;
mod heat;
#[cfg(test)]
mod tests;
mod view;

use crate::tui::component::{Change, Cx, Tab};
use crate::tui::effect::Effect;
use crate::tui::keys::{self, Doc};
use crate::tui::popups::field::{Field, Purpose};
use crate::tui::shared::Shared;
use crate::view::format::num;
use bindings::{Action, KEYS};
use biodyn::Body;
use biodyn::seat::SeatGrid;
use biodyn::time::CLASSES;
use compute::SeatData;
use ratatui::buffer::Buffer;
use ratatui::crossterm::event::KeyEvent;
use ratatui::layout::Rect;

/// The field tag of the stroke limit.
const LIMIT: usize = 0;

/// The class selected when the tab opens: EM6 (the docs' example, a
/// wheel loader's floor), else the first.
const FIRST_CLASS: &str = "EM6";

pub struct SeatTab {
    /// Index in `biodyn::time::CLASSES`.
    pub class: usize,
    /// The r.m.s. stroke limit typed with `s`, m; None: stroke/6.
    pub limit_m: Option<f64>,
    grids: Vec<Result<SeatGrid, String>>,
    /// None for a model without a seat.
    pub data: Option<SeatData>,
}

impl SeatTab {
    /// The limit the map keeps, m: the typed one, else stroke/6.
    pub fn limit_for(&self, body: &Body) -> Option<f64> {
        self.limit_m.or_else(|| compute::default_limit(body))
    }

    /// Everything again for `body`; `recentre` lays the map around the
    /// suspension's values now (else around the old centre while they
    /// stay inside its box).
    fn recompute(&mut self, body: &Body, recentre: bool) {
        let (Some((_, k, c)), Some(limit_m)) = (compute::suspension(body), self.limit_for(body))
        else {
            self.data = None;
            return;
        };
        let now = [k, c];
        let centre = match &self.data {
            Some(d) if !recentre && compute::inside(d.centre, now) => d.centre,
            _ => now,
        };
        let classes = compute::classes(&self.grids, body);
        let design = compute::design_of(body, &self.grids[self.class], centre, limit_m);
        self.data = Some(SeatData {
            classes,
            design,
            centre,
            now,
            limit_m,
        });
    }

    /// The design map only (a new class or limit; the model is the same).
    fn redesign(&mut self, body: &Body) {
        let limit = self.limit_for(body);
        if let (Some(d), Some(limit_m)) = (self.data.as_mut(), limit) {
            d.limit_m = limit_m;
            d.design = compute::design_of(body, &self.grids[self.class], d.centre, limit_m);
        }
    }

    fn select(&mut self, class: usize, body: &Body) -> Vec<Effect> {
        let class = class.min(CLASSES.len() - 1);
        if class != self.class {
            self.class = class;
            self.redesign(body);
        }
        Vec::new()
    }

    fn act(&mut self, a: Action, cx: &Cx) -> Vec<Effect> {
        let body = &cx.shared.body;
        let n = CLASSES.len();
        match a {
            Action::PrevClass => self.select((self.class + n - 1) % n, body),
            Action::NextClass => self.select((self.class + 1) % n, body),
            Action::FirstClass => self.select(0, body),
            Action::LastClass => self.select(n - 1, body),
            Action::Limit => {
                let Some(seat) = &body.seat else {
                    return vec![Effect::Error(view::NO_SEAT.into())];
                };
                let default = seat.stroke_m * compute::LIMIT_SHARE;
                let label = format!(
                    "r.m.s. stroke limit, mm (empty: stroke/6 = {} mm: 3 r.m.s. in half the travel)",
                    num(default * 1e3, 3)
                );
                let text = self.limit_m.map(|m| num(m * 1e3, 6)).unwrap_or_default();
                vec![Effect::OpenField(Field::new(Purpose::Tab(LIMIT), label, text))]
            }
            Action::Centre => {
                if body.seat.is_none() {
                    return vec![Effect::Error(view::NO_SEAT.into())];
                }
                self.recompute(body, true);
                vec![Effect::Status(
                    "design map centred on the suspension's k and c now".into(),
                )]
            }
            Action::Export => export::effects(self, cx.shared),
        }
    }
}

/// A typed limit in mm ("12", "12 mm", "0.012 m"); empty: None.
fn parse_limit(text: &str) -> Result<Option<f64>, String> {
    let t = text.trim();
    if t.is_empty() {
        return Ok(None);
    }
    let (number, scale) = if let Some(n) = t.strip_suffix("mm") {
        (n, 1e-3)
    } else if let Some(n) = t.strip_suffix('m') {
        (n, 1.0)
    } else {
        (t, 1e-3)
    };
    match number.trim().parse::<f64>() {
        Ok(v) if v.is_finite() && v > 0.0 => Ok(Some(v * scale)),
        _ => Err(format!(
            "stroke limit '{t}': write a number of mm > 0 (e.g. 16.7), or leave it empty for stroke/6"
        )),
    }
}

impl Tab for SeatTab {
    fn new(shared: &Shared) -> Self {
        let mut t = SeatTab {
            class: CLASSES
                .iter()
                .position(|c| c.name == FIRST_CLASS)
                .unwrap_or(0),
            limit_m: None,
            grids: compute::grids(),
            data: None,
        };
        t.recompute(&shared.body, true);
        t
    }

    fn title(&self) -> &'static str {
        "Seat"
    }

    fn keys(&self) -> Vec<&'static Doc> {
        keys::docs(KEYS)
    }

    fn on_key(&mut self, ev: &KeyEvent, cx: &Cx) -> Option<Vec<Effect>> {
        keys::lookup(KEYS, ev).map(|a| self.act(a, cx))
    }

    fn commit(&mut self, tag: usize, text: &str, cx: &Cx) -> Result<Vec<Effect>, String> {
        if tag != LIMIT {
            return Ok(Vec::new());
        }
        self.limit_m = parse_limit(text)?;
        let body = &cx.shared.body;
        self.redesign(body);
        let say = match (self.limit_m, self.limit_for(body)) {
            (Some(m), _) => format!("r.m.s. stroke limit {} mm", num(m * 1e3, 4)),
            (None, Some(m)) => format!("r.m.s. stroke limit stroke/6 = {} mm", num(m * 1e3, 4)),
            (None, None) => "r.m.s. stroke limit: stroke/6".into(),
        };
        Ok(vec![Effect::Status(say)])
    }

    fn on_change(&mut self, change: Change, cx: &Cx) {
        match change {
            Change::Loaded => {
                self.limit_m = None;
                self.recompute(&cx.shared.body, true);
            }
            Change::Edited => self.recompute(&cx.shared.body, false),
            Change::Derived => {}
        }
    }

    fn render(&self, shared: &Shared, area: Rect, buf: &mut Buffer) {
        view::render(self, shared, area, buf);
    }

    fn has_chart(&self, shared: &Shared) -> bool {
        shared.body.has_seat() && self.data.is_some()
    }

    fn render_zoomed(&self, shared: &Shared, area: Rect, buf: &mut Buffer) {
        view::render_map(self, shared, area, buf);
    }
}
