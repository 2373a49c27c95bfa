//! Small pieces of drawing the tabs and dialogs share.

use super::theme::Theme;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Widget};

/// Width from which charts sit side by side instead of stacked.
pub const SIDE_BY_SIDE: u16 = 140;

/// A bordered panel with a heading-styled title.
pub fn block(title: &str, th: Theme) -> Block<'static> {
    Block::bordered()
        .border_set(th.border_set())
        .title(Span::styled(format!(" {title} "), th.heading()))
}

/// A bordered panel over `area`, its title cut to fit, drawn into `buf`:
/// the rect inside its border.
pub fn panel(title: &str, th: Theme, area: Rect, buf: &mut Buffer) -> Rect {
    let b = block(
        &crate::view::format::clip(title, area.width.saturating_sub(4) as usize),
        th,
    );
    let inner = b.inner(area);
    b.render(area, buf);
    inner
}

/// A right-aligned table cell, reverse video when selected.
pub fn cell(text: String, w: usize, selected: bool, th: Theme) -> Span<'static> {
    let s = format!("{text:>w$}");
    if selected {
        Span::styled(s, th.selected())
    } else {
        Span::raw(s)
    }
}

/// `lines` with each number glued to its unit (`format::glue_units`), for
/// a wrapping paragraph: it never breaks "1.213 %" across rows. `unglue`
/// puts plain spaces back once it is drawn.
pub fn glued(lines: Vec<Line<'static>>) -> Vec<Line<'static>> {
    lines
        .into_iter()
        .map(|mut l| {
            for sp in &mut l.spans {
                sp.content = crate::view::format::glue_units(&sp.content).into();
            }
            l
        })
        .collect()
}

/// The glue (`format::NBSP`) a `glued` paragraph drew in `area`, made
/// plain spaces.
pub fn unglue(area: Rect, buf: &mut Buffer) {
    let nbsp = crate::view::format::NBSP.to_string();
    let area = area.intersection(buf.area);
    for y in area.top()..area.bottom() {
        for x in area.left()..area.right() {
            if let Some(c) = buf.cell_mut((x, y))
                && c.symbol() == nbsp
            {
                c.set_symbol(" ");
            }
        }
    }
}
