//! The fit dialog's keys, one table per stage (setup, running, result), so
//! the hint bar and the `?` page show what works right now. Keys that work
//! everywhere (help, quit, save, undo, the tab keys) pass through to the
//! app; every other key is the dialog's, so a stray letter does not reach
//! the charts underneath.

use super::fit::{FitDialog, Row, Stage};
use super::ResponsesTab;
use super::tags::{TAG_SEED, TAG_STARTS};
use crate::tui::component::Cx;
use crate::tui::effect::Effect;
use crate::tui::popups::field::{Field, Purpose};
use crate::tui::keys::{self, Binding, Doc, b, code, k};
use crate::view::format::num;
use ratatui::crossterm::event::{KeyCode as KC, KeyEvent};

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Action {
    Up,
    Down,
    Toggle,
    All,
    Default,
    Less,
    More,
    Edit,
    Run,
    Close,
    Cancel,
    Apply,
    Discard,
}

pub static SETUP: &[Binding<Action>] = &[
    b(
        &[code(KC::Up), k('k')],
        Action::Up,
        "fit: previous row",
        Some("↑↓ row"),
    ),
    b(
        &[code(KC::Down), k('j')],
        Action::Down,
        "fit: next row",
        None,
    ),
    b(
        &[k(' ')],
        Action::Toggle,
        "fit: free / fix the selected parameter",
        Some("space free"),
    ),
    b(&[k('a')], Action::All, "fit: free every m, k and c", None),
    b(
        &[k('d')],
        Action::Default,
        "fit: back to the default free set (every k and c)",
        None,
    ),
    b(
        &[code(KC::Left), k('h')],
        Action::Less,
        "fit: one start fewer / seed down",
        Some("←→ starts/seed"),
    ),
    b(
        &[code(KC::Right), k('l')],
        Action::More,
        "fit: one start more / seed up",
        None,
    ),
    b(
        &[k('e')],
        Action::Edit,
        "fit: type the number of starts or the seed",
        None,
    ),
    b(
        &[code(KC::Enter)],
        Action::Run,
        "fit: run (in the background)",
        Some("Enter fit"),
    ),
    b(
        &[code(KC::Esc)],
        Action::Close,
        "fit: close, nothing changed",
        Some("Esc close"),
    ),
];

pub static RUNNING: &[Binding<Action>] = &[b(
    &[code(KC::Esc)],
    Action::Cancel,
    "fit: cancel (after the current start); the model is unchanged",
    Some("Esc cancel"),
)];

pub static RESULT: &[Binding<Action>] = &[
    b(
        &[code(KC::Up), k('k')],
        Action::Up,
        "fit result: scroll up",
        Some("↑↓ scroll"),
    ),
    b(
        &[code(KC::Down), k('j')],
        Action::Down,
        "fit result: scroll down",
        None,
    ),
    b(
        &[code(KC::Enter)],
        Action::Apply,
        "fit result: apply the fitted values as one edit (u undoes it)",
        Some("Enter apply"),
    ),
    b(
        &[code(KC::Esc)],
        Action::Discard,
        "fit result: discard, the model is unchanged",
        Some("Esc discard"),
    ),
];

/// The table of the dialog's current stage.
pub fn table(d: &FitDialog) -> &'static [Binding<Action>] {
    match d.stage {
        Stage::Setup => SETUP,
        Stage::Running(_) => RUNNING,
        Stage::Result { .. } => RESULT,
    }
}

pub fn docs(d: &FitDialog) -> Vec<&'static Doc> {
    keys::docs(table(d))
}

/// A key while the dialog is open; None lets the app's own keys work.
pub fn on_key(t: &mut ResponsesTab, ev: &KeyEvent, cx: &Cx) -> Option<Vec<Effect>> {
    let d = t.fit.as_mut()?;
    let Some(a) = keys::lookup(table(d), ev) else {
        let app_key = keys::lookup(keys::GLOBAL, ev).is_some() || keys::tab_of(ev, 9).is_some();
        return if app_key { None } else { Some(Vec::new()) };
    };
    let s = cx.shared;
    let say = |t: &str| vec![Effect::Status(t.to_string())];
    if let Stage::Result { scroll, .. } = &mut d.stage
        && matches!(a, Action::Up | Action::Down)
    {
        *scroll = if a == Action::Up {
            scroll.saturating_sub(1)
        } else {
            scroll.saturating_add(1)
        };
        return Some(Vec::new());
    }
    Some(match (&mut d.stage, a) {
        (_, Action::Up) => {
            d.step(true);
            Vec::new()
        }
        (_, Action::Down) => {
            d.step(false);
            Vec::new()
        }
        (_, Action::Toggle) => {
            d.toggle();
            Vec::new()
        }
        (_, Action::All) => {
            d.select_all(&s.body, true);
            Vec::new()
        }
        (_, Action::Default) => {
            d.select_all(&s.body, false);
            Vec::new()
        }
        (_, Action::Less) => {
            d.nudge(false);
            Vec::new()
        }
        (_, Action::More) => {
            d.nudge(true);
            Vec::new()
        }
        (_, Action::Edit) => match d.row() {
            Some(Row::Starts) => vec![Effect::OpenField(Field::new(
                Purpose::Tab(TAG_STARTS),
                format!("fit starts (1–{})", biodyn::fit::MAX_STARTS),
                d.starts.to_string(),
            ))],
            Some(Row::Seed) => vec![Effect::OpenField(Field::new(
                Purpose::Tab(TAG_SEED),
                "fit seed (a whole number ≥ 0)",
                d.seed.to_string(),
            ))],
            _ => say("e types a number on the starts and seed rows"),
        },
        (_, Action::Run) => {
            let Some(o) = t.data.as_ref() else {
                return Some(vec![Effect::Error("no measured data".into())]);
            };
            d.start(&s.body, &o.data, &cx.mailbox);
            match &d.stage {
                Stage::Running(_) => say(&format!(
                    "fitting {} to {}: {} starts, seed {} (Esc cancels)",
                    d.free_list(&s.body),
                    o.data.path,
                    d.starts,
                    d.seed
                )),
                Stage::Result { fit, .. } => say(&format!(
                    "fit done: cost {}; Enter applies, Esc discards",
                    num(fit.cost, 4)
                )),
                Stage::Setup => match &d.note {
                    Some(n) => vec![Effect::Error(format!("fit {n}"))],
                    None => Vec::new(),
                },
            }
        }
        (Stage::Running(r), Action::Cancel) => {
            r.cancel();
            say("cancelling the fit after the current start…")
        }
        (_, Action::Close) | (_, Action::Discard) => {
            t.fit = None;
            say("fit closed; the model is unchanged")
        }
        (Stage::Result { fit, .. }, Action::Apply) => {
            let values: Vec<_> = fit.params.iter().map(|p| (p.param, p.value)).collect();
            let names: Vec<&str> = fit.params.iter().map(|p| p.name.as_str()).collect();
            let done = format!(
                "applied the fitted {} (u undoes them all; ^S saves the fitted preset)",
                names.join(", ")
            );
            t.fit = None;
            vec![Effect::SetParams(values, done)]
        }
        (_, Action::Cancel) | (_, Action::Apply) => Vec::new(),
    })
}

/// A typed number of starts or seed; the reason when it is not one.
pub fn commit(d: &mut FitDialog, tag: usize, text: &str) -> Result<Vec<Effect>, String> {
    let t = text.trim();
    let max = biodyn::fit::MAX_STARTS;
    match tag {
        TAG_STARTS => match t.parse::<usize>() {
            Ok(n) if (1..=max).contains(&n) => d.starts = n,
            _ => return Err(format!("'{t}' is not a whole number from 1 to {max}")),
        },
        TAG_SEED => match t.parse::<u64>() {
            Ok(n) => d.seed = n,
            _ => return Err(format!("'{t}' is not a whole number ≥ 0")),
        },
        _ => {}
    }
    Ok(Vec::new())
}
