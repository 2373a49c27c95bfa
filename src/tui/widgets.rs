//! Small pieces of drawing the tabs and dialogs share.

use super::theme::Theme;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::Span;
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
