//! The Model tab's key table: the `?` page, the hint bar and the lookup
//! all read it.

use crate::tui::keys::{Binding, b, code, k};
use ratatui::crossterm::event::KeyCode as KC;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Action {
    Up,
    Down,
    Left,
    Right,
    Edit,
    NudgeUp,
    NudgeDown,
    AddSegment,
    AddLink,
    Delete,
    Rename,
    Head,
    Description,
    PageUp,
    PageDown,
    Home,
    End,
}

pub static KEYS: &[Binding<Action>] = &[
    b(
        &[code(KC::Up), k('k')],
        Action::Up,
        "previous row (mouse: click a value or a name; the wheel)",
        Some("↑↓←→ move"),
    ),
    b(&[code(KC::Down), k('j')], Action::Down, "next row", None),
    b(
        &[code(KC::Left), k('h')],
        Action::Left,
        "previous column (mass / share of a segment, k / c of a link)",
        None,
    ),
    b(
        &[code(KC::Right), k('l')],
        Action::Right,
        "next column",
        None,
    ),
    b(&[code(KC::PageUp)], Action::PageUp, "20 rows up", None),
    b(
        &[code(KC::PageDown)],
        Action::PageDown,
        "20 rows down",
        None,
    ),
    b(
        &[code(KC::Home)],
        Action::Home,
        "first row (body mass)",
        None,
    ),
    b(&[code(KC::End)], Action::End, "last row (last link)", None),
    b(
        &[code(KC::Enter), k('e')],
        Action::Edit,
        "edit the selected value (mouse: double-click it)",
        Some("Enter edit"),
    ),
    b(
        &[k('+'), k('=')],
        Action::NudgeUp,
        "raise the selected value by 5 % (×1.05)",
        Some("+/- 5%"),
    ),
    b(
        &[k('-')],
        Action::NudgeDown,
        "lower it (÷1.05, so + then - gives it back)",
        None,
    ),
    b(
        &[k('a')],
        Action::AddSegment,
        "add a segment tied by a new link: name kg lower [k c]",
        Some("a/A/d/r/H structure"),
    ),
    b(
        &[k('A')],
        Action::AddLink,
        "add a link: upper lower k c [name] (lower may be seat)",
        None,
    ),
    b(
        &[k('d'), code(KC::Delete)],
        Action::Delete,
        "delete the selected segment or link (asks first)",
        None,
    ),
    b(
        &[k('r')],
        Action::Rename,
        "rename the segment or link (mouse: double-click its name)",
        None,
    ),
    b(
        &[k('H')],
        Action::Head,
        "make the selected segment the head (STHT is measured there)",
        None,
    ),
    b(
        &[k('D')],
        Action::Description,
        "edit the model's description (saved with the preset)",
        None,
    ),
];
