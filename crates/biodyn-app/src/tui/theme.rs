//! Every style in one place. Meaning never rides on colour alone: the
//! selection is reverse video and errors say "error" in words, so NO_COLOR
//! (https://no-color.org) loses nothing but the tint.

use ratatui::style::{Color, Modifier, Style};

#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Theme {
    /// No colours at all (NO_COLOR set and non-empty).
    pub mono: bool,
    /// ASCII glyphs only: chart markers and borders.
    pub ascii: bool,
}

impl Theme {
    /// Reads NO_COLOR from the environment.
    pub fn from_env(ascii: bool) -> Theme {
        let mono = std::env::var_os("NO_COLOR").is_some_and(|v| !v.is_empty());
        Theme { mono, ascii }
    }

    fn fg(self, c: Color) -> Style {
        if self.mono {
            Style::default()
        } else {
            Style::default().fg(c)
        }
    }

    pub fn base(self) -> Style {
        Style::default()
    }
    pub fn title(self) -> Style {
        self.fg(Color::Cyan).add_modifier(Modifier::BOLD)
    }
    pub fn heading(self) -> Style {
        self.fg(Color::Yellow).add_modifier(Modifier::BOLD)
    }
    pub fn dim(self) -> Style {
        if self.mono {
            Style::default()
        } else {
            Style::default().fg(Color::DarkGray)
        }
    }
    /// The selected cell or row: reverse video works on every terminal.
    pub fn selected(self) -> Style {
        Style::default().add_modifier(Modifier::REVERSED)
    }
    pub fn active_tab(self) -> Style {
        self.selected().add_modifier(Modifier::BOLD)
    }
    pub fn error(self) -> Style {
        self.fg(Color::Red).add_modifier(Modifier::BOLD)
    }
    pub fn ok(self) -> Style {
        self.fg(Color::Green)
    }
    pub fn key(self) -> Style {
        self.fg(Color::Cyan).add_modifier(Modifier::BOLD)
    }
    pub fn field(self) -> Style {
        self.fg(Color::White).add_modifier(Modifier::UNDERLINED)
    }
    pub fn border_set(self) -> ratatui::symbols::border::Set<'static> {
        if self.ascii {
            ascii_border()
        } else {
            ratatui::symbols::border::PLAIN
        }
    }
}

/// Plain ASCII box: + corners, - and | sides.
fn ascii_border() -> ratatui::symbols::border::Set<'static> {
    ratatui::symbols::border::Set {
        top_left: "+",
        top_right: "+",
        bottom_left: "+",
        bottom_right: "+",
        vertical_left: "|",
        vertical_right: "|",
        horizontal_top: "-",
        horizontal_bottom: "-",
    }
}
