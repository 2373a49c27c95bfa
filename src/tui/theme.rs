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
    /// Reads the environment: see [`Theme::detect`].
    pub fn from_env(ascii: bool) -> Theme {
        Theme::detect(ascii, |k| std::env::var(k).ok())
    }

    /// Glyphs and colours from what the terminal can show:
    /// - ASCII when `--ascii` is given, the locale is not UTF-8 (`LC_ALL`,
    ///   else `LC_CTYPE`, else `LANG`; unset counts as `C`), or `TERM` is a
    ///   console without box drawing or braille (`vt100`, `vt102`, `vt220`,
    ///   `linux`, `dumb`);
    /// - no colour when `NO_COLOR` is set (https://no-color.org) or `TERM`
    ///   is a monochrome terminal (`vt100`, `vt102`, `vt220`, `dumb`).
    ///
    /// `BIODYN_GLYPHS=unicode|ascii` and `BIODYN_COLOR=always|never`
    /// override the guess (`--ascii` always wins).
    pub fn detect(ascii_flag: bool, env: impl Fn(&str) -> Option<String>) -> Theme {
        let set = |k: &str| env(k).filter(|v| !v.is_empty());
        let term = set("TERM").unwrap_or_default().to_ascii_lowercase();
        let term_base = term.split('-').next().unwrap_or("");
        let mono_term = matches!(term_base, "vt100" | "vt102" | "vt220" | "dumb");
        let no_box = mono_term || term_base == "linux";
        let locale = set("LC_ALL")
            .or_else(|| set("LC_CTYPE"))
            .or_else(|| set("LANG"))
            .unwrap_or_else(|| "C".into())
            .to_ascii_lowercase();
        let utf8 = locale.contains("utf-8") || locale.contains("utf8");
        let ascii = match set("BIODYN_GLYPHS").as_deref() {
            _ if ascii_flag => true,
            Some("ascii") => true,
            Some("unicode") => false,
            _ => no_box || !utf8,
        };
        let mono = match set("BIODYN_COLOR").as_deref() {
            Some("always") => false,
            Some("never") => true,
            _ => set("NO_COLOR").is_some() || mono_term,
        };
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

#[cfg(test)]
mod tests {
    use super::*;

    fn with(vars: &[(&str, &str)]) -> impl Fn(&str) -> Option<String> {
        let vars: Vec<(String, String)> = vars
            .iter()
            .map(|(k, v)| (k.to_string(), v.to_string()))
            .collect();
        move |k: &str| vars.iter().find(|(n, _)| n == k).map(|(_, v)| v.clone())
    }

    #[test]
    fn the_terminal_and_locale_pick_glyphs_and_colours() {
        let utf = ("LANG", "en_GB.UTF-8");
        let t = |vars: &[(&str, &str)]| Theme::detect(false, with(vars));
        assert_eq!(
            t(&[utf, ("TERM", "xterm-256color")]),
            Theme {
                mono: false,
                ascii: false
            }
        );
        assert_eq!(
            t(&[utf, ("TERM", "vt100")]),
            Theme {
                mono: true,
                ascii: true
            }
        );
        assert_eq!(
            t(&[utf, ("TERM", "linux")]),
            Theme {
                mono: false,
                ascii: true
            }
        );
        assert_eq!(
            t(&[("LANG", "C"), ("TERM", "xterm")]),
            Theme {
                mono: false,
                ascii: true
            }
        );
        // LC_ALL wins over LANG
        assert!(t(&[utf, ("LC_ALL", "C"), ("TERM", "xterm")]).ascii);
        assert!(t(&[utf, ("NO_COLOR", "1"), ("TERM", "xterm")]).mono);
        // overrides
        let forced = [
            utf,
            ("TERM", "vt100"),
            ("BIODYN_GLYPHS", "unicode"),
            ("BIODYN_COLOR", "always"),
        ];
        assert_eq!(
            t(&forced),
            Theme {
                mono: false,
                ascii: false
            }
        );
        assert!(Theme::detect(true, with(&forced)).ascii);
    }
}
