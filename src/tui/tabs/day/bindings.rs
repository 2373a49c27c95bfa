//! The Day tab's key table: the `?` page, the hint bar and the lookup all
//! read it. Save, open, undo and redo are the app's own keys (Ctrl-S,
//! Ctrl-O, u, Ctrl-R): on this tab they act on the day (`Tab::on_global`).

use crate::tui::keys::{Binding, b, code, k};
use ratatui::crossterm::event::KeyCode as KC;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Action {
    Up,
    Down,
    Left,
    Right,
    Home,
    End,
    Edit,
    Clear,
    Add,
    Delete,
    Remeasure,
    Export,
}

pub static KEYS: &[Binding<Action>] = &[
    b(
        &[code(KC::Up), k('k')],
        Action::Up,
        "previous operation",
        Some("↑↓←→ move"),
    ),
    b(&[code(KC::Down), k('j')], Action::Down, "next operation", None),
    b(
        &[code(KC::Left), k('h')],
        Action::Left,
        "previous column (name, hours, a_w x, y, z, record)",
        None,
    ),
    b(&[code(KC::Right), k('l')], Action::Right, "next column", None),
    b(&[code(KC::Home)], Action::Home, "first operation", None),
    b(&[code(KC::End)], Action::End, "last operation", None),
    b(
        &[code(KC::Enter), k('e')],
        Action::Edit,
        "edit the cell: name, hours, a_w (m/s², before k) or record (PATH [axes=x=ax,..] [unit=g])",
        Some("Enter edit"),
    ),
    b(
        &[code(KC::Backspace)],
        Action::Clear,
        "clear an a_w cell (the axis not measured) or the record (its a_w stay, typed)",
        None,
    ),
    b(
        &[k('a')],
        Action::Add,
        "add an operation after the selected one (asks its name)",
        Some("a/d add/del"),
    ),
    b(
        &[k('d'), code(KC::Delete)],
        Action::Delete,
        "delete the selected operation (u brings it back)",
        None,
    ),
    b(
        &[k('R')],
        Action::Remeasure,
        "read the records again (after they changed on disk)",
        None,
    ),
    b(
        &[k('x')],
        Action::Export,
        "export the sheet (.csv) or the points figure (.svg); the day's every operation evaluated",
        None,
    ),
];
