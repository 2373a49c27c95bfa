//! The Vibration tab's text in ASCII mode: units and dashes spelled so
//! the frame's transliteration keeps them readable. Used by every part of
//! the tab that draws (view, spectra, traces).

use crate::tui::theme::Theme;
use ratatui::text::{Line, Span};

/// In ASCII mode, the glyphs the frame's transliteration would turn into
/// `?`: m/s² reads m/s^2.
pub fn fix(th: Theme, s: &str) -> String {
    if th.ascii {
        s.replace('²', "^2").replace('–', "-")
    } else {
        s.to_string()
    }
}

/// `fix` over every span.
pub fn fix_lines(th: Theme, lines: Vec<Line<'static>>) -> Vec<Line<'static>> {
    if !th.ascii {
        return lines;
    }
    lines
        .into_iter()
        .map(|l| {
            let spans: Vec<Span<'static>> = l
                .spans
                .into_iter()
                .map(|sp| Span::styled(fix(th, &sp.content), sp.style))
                .collect();
            Line::from(spans).style(l.style)
        })
        .collect()
}
