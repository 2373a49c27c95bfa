//! The Responses tab's key table: the `?` page, the hint bar and the
//! lookup all read it (the fit dialog's own tables are in `fit_keys.rs`).

use crate::tui::keys::{Binding, b, code, k};
use ratatui::crossterm::event::KeyCode as KC;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Action {
    Left,
    Right,
    PageUp,
    PageDown,
    Home,
    End,
    NextPeak,
    TogglePhase,
    ToggleLog,
    NextFunction,
    GoTo,
    Copy,
    Export,
    Compare,
    ClearCompare,
    LoadData,
    ClearData,
    Fit,
}

pub static KEYS: &[Binding<Action>] = &[
    b(
        &[code(KC::Left), k('h')],
        Action::Left,
        "frequency cursor down one step",
        Some("←→ cursor"),
    ),
    b(
        &[code(KC::Right), k('l')],
        Action::Right,
        "frequency cursor up one step",
        None,
    ),
    b(
        &[code(KC::PageDown), k('L')],
        Action::PageDown,
        "cursor up 1 Hz",
        None,
    ),
    b(
        &[code(KC::PageUp), k('H')],
        Action::PageUp,
        "cursor down 1 Hz",
        None,
    ),
    b(
        &[code(KC::Home)],
        Action::Home,
        "cursor to the band start",
        None,
    ),
    b(
        &[code(KC::End)],
        Action::End,
        "cursor to the band end",
        None,
    ),
    b(
        &[k('n')],
        Action::NextPeak,
        "cursor to the next peak (any function)",
        Some("n peak"),
    ),
    b(
        &[k('f')],
        Action::NextFunction,
        "next function: the chart z zooms and x writes as text",
        None,
    ),
    b(
        &[k('g')],
        Action::GoTo,
        "go to a frequency, computed there (not on the grid)",
        Some("g go to"),
    ),
    b(
        &[k('y')],
        Action::Copy,
        "copy the readout as one CSV line to the status line",
        None,
    ),
    b(
        &[k('x')],
        Action::Export,
        "export the curves (.csv) or the chart (.txt)",
        Some("x export"),
    ),
    b(
        &[k('c')],
        Action::Compare,
        "compare with a preset file (empty: as last saved)",
        Some("c compare"),
    ),
    b(
        &[k('C')],
        Action::ClearCompare,
        "clear the compared model from the charts",
        None,
    ),
    b(
        &[k('p')],
        Action::TogglePhase,
        "magnitude / phase",
        Some("p mag/phase"),
    ),
    b(
        &[k('a')],
        Action::ToggleLog,
        "linear / log axes",
        Some("a lin/log"),
    ),
    b(
        &[k('D')],
        Action::LoadData,
        "load measured data (CSV, as for fit --data) over the charts",
        Some("D data"),
    ),
    b(
        &[k('X')],
        Action::ClearData,
        "clear the measured data from the charts",
        None,
    ),
    b(
        &[k('F')],
        Action::Fit,
        "fit the model to the loaded data: choose free parameters, run, apply",
        Some("F fit"),
    ),
];
