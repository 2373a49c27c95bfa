//! The Seat tab's key table: the `?` page, the hint bar and the lookup all
//! read it.

use crate::tui::keys::{Binding, b, code, k};
use ratatui::crossterm::event::KeyCode as KC;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Action {
    PrevClass,
    NextClass,
    FirstClass,
    LastClass,
    Limit,
    Centre,
    Export,
}

pub static KEYS: &[Binding<Action>] = &[
    b(
        &[code(KC::Left), k('h')],
        Action::PrevClass,
        "previous input class (its stroke and design map)",
        Some("←→ class"),
    ),
    b(
        &[code(KC::Right), k('l')],
        Action::NextClass,
        "next input class",
        None,
    ),
    b(&[code(KC::Home)], Action::FirstClass, "first input class (EM1)", None),
    b(&[code(KC::End)], Action::LastClass, "last input class (AG3)", None),
    b(
        &[k('s')],
        Action::Limit,
        "edit the design map's r.m.s. stroke limit, mm (empty: stroke/6, so 3 r.m.s. fit in half the travel)",
        Some("s stroke limit"),
    ),
    b(
        &[k('c')],
        Action::Centre,
        "centre the design map on the suspension's k and c now (×1/4 … ×4 each)",
        Some("c centre"),
    ),
    b(
        &[k('x')],
        Action::Export,
        "export the figures per class (.csv), the tab's charts as text (.txt) or the figure (.svg)",
        Some("x export"),
    ),
];
