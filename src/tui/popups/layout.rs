//! The dialogs' shared frame: where a popup sits, what it clears, how
//! many rows its text takes and how its title fits. Its own file, so the
//! dialogs take it from a sibling, not from the `mod.rs` that uses them.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::Line;
use ratatui::widgets::{Clear, Widget};

/// A rectangle of `w`×`h` centred horizontally in `area`, vertically
/// centred or at its bottom.
pub fn popup(area: Rect, w: u16, h: u16, bottom: bool) -> Rect {
    let w = w.min(area.width);
    let h = h.min(area.height);
    let x = area.x + (area.width - w) / 2;
    let y = if bottom {
        area.bottom() - h
    } else {
        area.y + (area.height - h) / 2
    };
    Rect::new(x, y, w, h)
}

/// The rows popup `r` covers, across the whole of `area`: what it claims
/// (and clears), so no piece of a panel behind it (a corner, a letter)
/// shows beside it.
pub fn band(r: Rect, area: Rect) -> Rect {
    Rect::new(area.x, r.y, area.width, r.height)
}

/// Claims popup `r`'s band (`band`) for the layout check
/// (`view::probe::dialog`) and clears it.
pub fn clear_for(r: Rect, area: Rect, buf: &mut Buffer) {
    crate::view::probe::dialog(band(r, area), buf);
    Clear.render(band(r, area), buf);
}

/// Rows `lines` take in a popup's `Paragraph::wrap(Wrap { trim: false })`
/// `inner_w` columns wide (each line's text through `format::wrap`).
pub fn rows_of(lines: &[Line], inner_w: usize) -> usize {
    lines
        .iter()
        .map(|l| {
            let text: String = l.spans.iter().map(|s| s.content.as_ref()).collect();
            crate::view::format::wrapped_rows(&text, inner_w.max(1), false)
        })
        .sum()
}

/// A popup title cut to its frame (`w` columns) at the last ` — ` part
/// that fits (the key list the hint bar also shows), else clipped.
pub fn title_fit(title: &str, w: u16) -> String {
    // The block draws the title as " title " from the corner on.
    let room = usize::from(w).saturating_sub(4);
    let mut t = title.to_string();
    while t.chars().count() > room {
        match t.rfind(" — ") {
            Some(i) => t.truncate(i),
            None => return crate::view::format::clip(&t, room),
        }
    }
    t
}
