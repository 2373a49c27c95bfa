//! The delete question: what deleting the selected segment or link would
//! do, its keys (y, x, n/Esc), and the library's reason, wrapped in it,
//! when the delete is refused.

use super::ModelTab;
use super::structure::{self, Removal};
use crate::tui::effect::Effect;
use crate::tui::keys::{Binding, b, code, k};
use crate::tui::shared::Shared;
use crate::tui::widgets::block;
use biodyn::Body;
use ratatui::buffer::Buffer;
use ratatui::crossterm::event::KeyCode as KC;
use ratatui::layout::Rect;
use ratatui::text::Line;
use crate::view::format::wrapped_rows;
use ratatui::widgets::{Clear, Paragraph, Widget, Wrap};

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Answer {
    Yes,
    WithLinks,
    No,
}

/// The delete confirmation's keys (the tab answers nothing else meanwhile).
pub static CONFIRM_KEYS: &[Binding<Answer>] = &[
    b(
        &[k('y'), code(KC::Enter)],
        Answer::Yes,
        "delete; a segment's hanging links move to what it hung on",
        Some("y delete"),
    ),
    b(
        &[k('x')],
        Answer::WithLinks,
        "delete a segment with every link that touches it",
        Some("x with links"),
    ),
    b(
        &[k('n'), code(KC::Esc)],
        Answer::No,
        "keep it",
        Some("n/Esc keep"),
    ),
];

/// Deleting a link: no `x` (that is for a segment's links).
pub static LINK_CONFIRM_KEYS: &[Binding<Answer>] = &[
    b(
        &[k('y'), code(KC::Enter)],
        Answer::Yes,
        "delete the link",
        Some("y delete"),
    ),
    b(
        &[k('n'), code(KC::Esc)],
        Answer::No,
        "keep it",
        Some("n/Esc keep"),
    ),
];

/// The keys the question about `p` answers to (its hint and handling).
pub fn keys_for(p: Pending) -> &'static [Binding<Answer>] {
    match p {
        Pending::Segment(_) => CONFIRM_KEYS,
        Pending::Link(_) => LINK_CONFIRM_KEYS,
    }
}

/// What the delete confirmation is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Pending {
    Segment(usize),
    Link(usize),
}

impl ModelTab {
    pub(super) fn answer(&mut self, a: Answer, s: &Shared) -> Vec<Effect> {
        let Some(p) = self.pending.take() else {
            return Vec::new();
        };
        self.refusal = None;
        let edit = match (p, a) {
            (_, Answer::No) => return vec![Effect::Status("kept; nothing changed".into())],
            (Pending::Segment(i), Answer::Yes) => {
                structure::remove_segment(&s.body, i, Removal::Rejoin)
            }
            (Pending::Segment(i), Answer::WithLinks) => {
                structure::remove_segment(&s.body, i, Removal::WithLinks)
            }
            (Pending::Link(i), _) => structure::remove_link(&s.body, i),
        };
        let effects = self.structural(s, edit, None);
        // Refused: the question stays, with the library's reason in it.
        if let [Effect::Error(why)] = effects.as_slice() {
            self.pending = Some(p);
            self.refusal = Some(why.clone());
            return vec![Effect::Error(
                "refused: the model is unchanged (reason above)".into(),
            )];
        }
        effects
    }

    /// The question the delete confirmation asks.
    pub(super) fn question(&self, body: &Body) -> Option<String> {
        match self.pending? {
            Pending::Segment(i) => {
                let name = &body.segments.get(i)?.name;
                let hanging = body
                    .links
                    .iter()
                    .filter(|l| l.lower == biodyn::End::Segment(i))
                    .count();
                let rejoin = match structure::rejoin_target(body, i) {
                    Some(biodyn::End::Segment(j)) if hanging > 0 => format!(
                        "y deletes it and moves the {hanging} link(s) hanging on it to '{}'",
                        body.segments.get(j).map_or("?", |s| s.name.as_str())
                    ),
                    Some(biodyn::End::Seat) if hanging > 0 => {
                        format!(
                            "y deletes it and moves the {hanging} link(s) hanging on it to the seat"
                        )
                    }
                    _ => "y deletes it and its links".into(),
                };
                Some(format!(
                    "delete segment '{name}'? {rejoin}; x deletes it with every link that touches it; n/Esc keeps it. A model left with a segment not tied to the seat is refused."
                ))
            }
            Pending::Link(i) => Some(format!(
                "delete link '{}'? y deletes it, n/Esc keeps it. A segment left without a path to the seat is refused.",
                body.links.get(i)?.name
            )),
        }
    }
}

/// Draws the question over the bottom of the tab, if one is asked.
pub fn render_question(t: &ModelTab, s: &Shared, area: Rect, buf: &mut Buffer) {
    if let Some(q) = t.question(&s.body) {
        let th = s.theme;
        let w = area.width.min(76);
        let inner = usize::from(w.saturating_sub(2)).max(1);
        let mut lines = vec![Line::raw(q.clone())];
        let mut rows = wrapped_rows(&q, inner, true);
        if let Some(why) = &t.refusal {
            let text = format!("refused: {why}");
            rows += wrapped_rows(&text, inner, true);
            lines.push(Line::styled(text, th.error()));
        }
        let h = (u16::try_from(rows).unwrap_or(u16::MAX).saturating_add(2)).min(area.height);
        let r = Rect::new(area.x + (area.width - w) / 2, area.bottom() - h, w, h);
        let band = Rect::new(area.x, r.y, area.width, r.height);
        crate::view::probe::dialog(band, buf);
        Clear.render(band, buf);
        Paragraph::new(lines)
            .wrap(Wrap { trim: true })
            .block(block("delete", th))
            .render(r, buf);
    }
}
