//! The Vibration tab's key table: the `?` page, the hint bar and the
//! lookup all read it. ←→ and Enter stay out of the hint bar (the settings
//! panel's title names them) so that `q quit` and `? help` fit in 80 columns.

use crate::tui::keys::{Binding, b, code, k};
use ratatui::crossterm::event::KeyCode as KC;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Action {
    Up,
    Down,
    PrevKind,
    NextKind,
    Edit,
    Weighted,
    ZoomIn,
    ZoomOut,
    Earlier,
    Later,
    Whole,
    Chart,
    Export,
    Spine,
}

pub static KEYS: &[Binding<Action>] = &[
    b(
        &[code(KC::Up)],
        Action::Up,
        "previous setting (mouse: click a row, double-click edits)",
        None,
    ),
    b(&[code(KC::Down)], Action::Down, "next setting", None),
    b(
        &[code(KC::Left)],
        Action::PrevKind,
        "previous signal kind: sine, sweep, random, shock, file (on the unit row: the unit)",
        None,
    ),
    b(
        &[code(KC::Right)],
        Action::NextKind,
        "next signal kind (on the unit row: the next unit)",
        None,
    ),
    b(
        &[code(KC::Enter), k('e')],
        Action::Edit,
        "edit the setting (spec takes sums: random:…+shock:…)",
        None,
    ),
    b(
        &[k('x')],
        Action::Export,
        "export: a .csv path gets what `biodyn simulate --format csv` prints, a .json path the assessment as `biodyn assess --format json`, a .txt path as `biodyn assess`, a .svg path the figure of `biodyn assess --plot`",
        Some("x export"),
    ),
    b(
        &[k('w')],
        Action::Weighted,
        "traces weighted (z and head Wk, x and y Wd) / unweighted",
        Some("w Wk"),
    ),
    b(
        &[k('p')],
        Action::Spine,
        "ISO 2631-5 spinal dose and risk on / off (the person: the spine row), its peaks marked on the seat trace",
        Some("p spine"),
    ),
    b(
        &[k('+'), k('=')],
        Action::ZoomIn,
        "zoom in on the time axis (×2; mouse: wheel over the traces)",
        Some("+- zoom"),
    ),
    b(
        &[k('-')],
        Action::ZoomOut,
        "zoom out on the time axis",
        None,
    ),
    b(
        &[k('<'), k(',')],
        Action::Earlier,
        "scroll to earlier times (mouse: click a time to centre it)",
        Some("<> scroll"),
    ),
    b(
        &[k('>'), k('.')],
        Action::Later,
        "scroll to later times",
        None,
    ),
    b(
        &[k('0')],
        Action::Whole,
        "the whole record (zoom out fully)",
        None,
    ),
    b(
        &[k('s')],
        Action::Chart,
        "traces / spectra / notes (narrow: one; at 60×16 notes + table)",
        Some("s panel"),
    ),
];
