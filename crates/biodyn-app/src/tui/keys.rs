//! The one key table. The `?` help screen and the bottom hint bar are both
//! drawn from it, so neither can drift from what the keys really do.

use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

/// Where a binding applies. Lookup goes from the most specific context
/// (an open dialog) to `Global`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ctx {
    Global,
    Model,
    Responses,
    Study,
    Training,
    /// A text field is open (cell edit, path prompt, study values).
    Field,
    /// The open-preset dialog (a list plus a path field).
    Open,
    /// The quit / discard confirmation.
    Confirm,
    Help,
}

impl Ctx {
    pub fn title(self) -> &'static str {
        match self {
            Ctx::Global => "Everywhere",
            Ctx::Model => "1 Model",
            Ctx::Responses => "2 Responses",
            Ctx::Study => "3 Study",
            Ctx::Training => "4 Training",
            Ctx::Field => "Text field",
            Ctx::Open => "Open preset (Ctrl-O)",
            Ctx::Confirm => "Confirmation",
            Ctx::Help => "This help",
        }
    }
}

/// What a key asks for; `update` interprets it in context.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Action {
    Quit,
    ForceQuit,
    Help,
    Tab(usize),
    NextTab,
    PrevTab,
    Save,
    Open,
    Undo,
    Redo,
    Up,
    Down,
    Left,
    Right,
    PageUp,
    PageDown,
    Home,
    End,
    Edit,
    NudgeUp,
    NudgeDown,
    TogglePhase,
    ToggleLog,
    NextFunction,
    ResetValues,
    NextPeak,
    /// The paper's three studies: 0 body mass, 1 seat-link k, 2 seat-link c.
    PaperStudy(usize),
    Start,
    PauseResume,
    Stop,
    SaveNet,
    ToggleView,
    Commit,
    Cancel,
    DeleteBack,
    DeleteFwd,
    Yes,
    No,
}

/// A key with the modifiers that matter (Ctrl, Alt). Shift is ignored for
/// characters, because terminals disagree on whether `+` or `?` carry it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Key {
    pub code: KeyCode,
    pub ctrl: bool,
}

const fn k(c: char) -> Key {
    Key {
        code: KeyCode::Char(c),
        ctrl: false,
    }
}
const fn ctrl(c: char) -> Key {
    Key {
        code: KeyCode::Char(c),
        ctrl: true,
    }
}
const fn code(code: KeyCode) -> Key {
    Key { code, ctrl: false }
}

/// One row of the table.
#[derive(Debug, Clone, Copy)]
pub struct Binding {
    pub ctx: Ctx,
    pub keys: &'static [Key],
    pub action: Action,
    /// What it does, for the help screen.
    pub help: &'static str,
    /// Short form for the hint bar (several bindings may share one entry,
    /// e.g. "↑↓←→ move"); None keeps it out of the bar.
    pub hint: Option<&'static str>,
}

const fn b(
    ctx: Ctx,
    keys: &'static [Key],
    action: Action,
    help: &'static str,
    hint: Option<&'static str>,
) -> Binding {
    Binding {
        ctx,
        keys,
        action,
        help,
        hint,
    }
}

use Action as A;
use Ctx as C;
use KeyCode as KC;

/// Every binding of the app, in help-screen order.
pub static BINDINGS: &[Binding] = &[
    // dialogs first: they shadow everything below
    b(C::Confirm, &[k('y')], A::Yes, "yes", Some("y yes")),
    b(
        C::Confirm,
        &[k('n'), code(KC::Esc)],
        A::No,
        "no, go back",
        Some("n/Esc no"),
    ),
    b(
        C::Field,
        &[code(KC::Enter)],
        A::Commit,
        "commit (an invalid value is refused, with why)",
        Some("Enter commit"),
    ),
    b(
        C::Field,
        &[code(KC::Esc)],
        A::Cancel,
        "cancel, leave the value unchanged",
        Some("Esc cancel"),
    ),
    b(
        C::Field,
        &[code(KC::Left)],
        A::Left,
        "move the text cursor",
        None,
    ),
    b(
        C::Field,
        &[code(KC::Right)],
        A::Right,
        "move the text cursor",
        None,
    ),
    b(C::Field, &[code(KC::Home)], A::Home, "start of field", None),
    b(
        C::Field,
        &[code(KC::Backspace)],
        A::DeleteBack,
        "delete before the cursor (other keys type)",
        None,
    ),
    b(
        C::Field,
        &[code(KC::Delete)],
        A::DeleteFwd,
        "delete at the cursor",
        None,
    ),
    b(C::Field, &[code(KC::End)], A::End, "end of field", None),
    b(
        C::Open,
        &[code(KC::Up)],
        A::Up,
        "previous file (fills the path field)",
        Some("↑↓ pick"),
    ),
    b(C::Open, &[code(KC::Down)], A::Down, "next file", None),
    b(
        C::Open,
        &[code(KC::Enter)],
        A::Commit,
        "open the path in the field",
        Some("Enter open"),
    ),
    b(
        C::Open,
        &[code(KC::Esc)],
        A::Cancel,
        "close",
        Some("Esc close"),
    ),
    b(
        C::Help,
        &[code(KC::Up), k('k')],
        A::Up,
        "scroll up",
        Some("↑↓ scroll"),
    ),
    b(
        C::Help,
        &[code(KC::Down), k('j')],
        A::Down,
        "scroll down",
        None,
    ),
    b(
        C::Help,
        &[code(KC::Esc), k('?'), k('q')],
        A::Cancel,
        "close help",
        Some("Esc close"),
    ),
    // everywhere
    b(
        C::Global,
        &[ctrl('c')],
        A::ForceQuit,
        "quit at once, even with unsaved edits",
        None,
    ),
    b(
        C::Global,
        &[k('q')],
        A::Quit,
        "quit (asks first: unsaved edits, running training)",
        Some("q quit"),
    ),
    b(
        C::Global,
        &[k('?')],
        A::Help,
        "all key bindings",
        Some("? help"),
    ),
    b(C::Global, &[k('1')], A::Tab(0), "Model tab", None),
    b(C::Global, &[k('2')], A::Tab(1), "Responses tab", None),
    b(C::Global, &[k('3')], A::Tab(2), "Study tab", None),
    b(C::Global, &[k('4')], A::Tab(3), "Training tab", None),
    b(C::Global, &[code(KC::Tab)], A::NextTab, "next tab", None),
    b(
        C::Global,
        &[code(KC::BackTab)],
        A::PrevTab,
        "previous tab",
        None,
    ),
    b(
        C::Global,
        &[ctrl('s')],
        A::Save,
        "save the model as a preset (asks for a path)",
        Some("^S save"),
    ),
    b(
        C::Global,
        &[ctrl('o')],
        A::Open,
        "open a preset: presets/*.toml, built-ins, a path",
        Some("^O open"),
    ),
    b(
        C::Global,
        &[k('u')],
        A::Undo,
        "undo the last model edit",
        Some("u undo"),
    ),
    b(C::Global, &[ctrl('r')], A::Redo, "redo", Some("^R redo")),
    // 1 Model
    b(
        C::Model,
        &[code(KC::Up), k('k')],
        A::Up,
        "previous row",
        Some("↑↓←→ move"),
    ),
    b(
        C::Model,
        &[code(KC::Down), k('j')],
        A::Down,
        "next row",
        None,
    ),
    b(
        C::Model,
        &[code(KC::Left), k('h')],
        A::Left,
        "previous column (k / c of a link)",
        None,
    ),
    b(
        C::Model,
        &[code(KC::Right), k('l')],
        A::Right,
        "next column",
        None,
    ),
    b(
        C::Model,
        &[code(KC::Enter), k('e')],
        A::Edit,
        "edit the selected value",
        Some("Enter edit"),
    ),
    b(
        C::Model,
        &[k('+'), k('=')],
        A::NudgeUp,
        "raise the selected value by 5 %",
        Some("+/- 5%"),
    ),
    b(
        C::Model,
        &[k('-')],
        A::NudgeDown,
        "lower the selected value by 5 %",
        None,
    ),
    // 2 Responses
    b(
        C::Responses,
        &[code(KC::Left), k('h')],
        A::Left,
        "frequency cursor down one step",
        Some("←→ cursor"),
    ),
    b(
        C::Responses,
        &[code(KC::Right), k('l')],
        A::Right,
        "frequency cursor up one step",
        None,
    ),
    b(
        C::Responses,
        &[code(KC::PageDown), k('L')],
        A::PageDown,
        "cursor up 1 Hz",
        None,
    ),
    b(
        C::Responses,
        &[code(KC::PageUp), k('H')],
        A::PageUp,
        "cursor down 1 Hz",
        None,
    ),
    b(
        C::Responses,
        &[code(KC::Home)],
        A::Home,
        "cursor to the band start",
        None,
    ),
    b(
        C::Responses,
        &[code(KC::End)],
        A::End,
        "cursor to the band end",
        None,
    ),
    b(
        C::Responses,
        &[k('n')],
        A::NextPeak,
        "cursor to the next peak (any function)",
        Some("n peak"),
    ),
    b(
        C::Responses,
        &[k('p')],
        A::TogglePhase,
        "magnitude / phase",
        Some("p mag/phase"),
    ),
    b(
        C::Responses,
        &[k('a')],
        A::ToggleLog,
        "linear / log axes",
        Some("a lin/log"),
    ),
    // 3 Study
    b(
        C::Study,
        &[code(KC::Left), k('h')],
        A::Left,
        "previous parameter",
        Some("←→ parameter"),
    ),
    b(
        C::Study,
        &[code(KC::Right), k('l')],
        A::Right,
        "next parameter",
        None,
    ),
    b(
        C::Study,
        &[k('m')],
        A::PaperStudy(0),
        "the paper's body-mass study: 65,75,85 kg",
        Some("m/k/c paper"),
    ),
    b(
        C::Study,
        &[k('k')],
        A::PaperStudy(1),
        "the paper's k4 study (seat link): -40%,0%,+40%",
        None,
    ),
    b(
        C::Study,
        &[k('c')],
        A::PaperStudy(2),
        "the paper's c4 study (seat link): -40%,0%,+40%",
        None,
    ),
    b(
        C::Study,
        &[code(KC::Enter), k('e')],
        A::Edit,
        "edit the values: 65,75,85 or -40%,0%,+40%",
        Some("Enter values"),
    ),
    b(
        C::Study,
        &[k('r')],
        A::ResetValues,
        "reset the value list to the paper's",
        Some("r reset"),
    ),
    b(
        C::Study,
        &[k('f')],
        A::NextFunction,
        "next function (when one chart is shown)",
        Some("f function"),
    ),
    b(
        C::Study,
        &[k('a')],
        A::ToggleLog,
        "linear / log axes",
        Some("a lin/log"),
    ),
    // 4 Training
    b(
        C::Training,
        &[code(KC::Up), k('k')],
        A::Up,
        "previous setting",
        Some("↑↓ setting"),
    ),
    b(
        C::Training,
        &[code(KC::Down), k('j')],
        A::Down,
        "next setting",
        None,
    ),
    b(
        C::Training,
        &[code(KC::Left), k('h')],
        A::Left,
        "previous choice (case, trainer, held-out value)",
        Some("←→ choice"),
    ),
    b(
        C::Training,
        &[code(KC::Right), k('l')],
        A::Right,
        "next choice",
        None,
    ),
    b(
        C::Training,
        &[code(KC::Enter), k('e')],
        A::Edit,
        "edit the selected setting",
        Some("Enter edit"),
    ),
    b(
        C::Training,
        &[k('t')],
        A::Start,
        "start training",
        Some("t start"),
    ),
    b(
        C::Training,
        &[k(' ')],
        A::PauseResume,
        "pause / resume",
        Some("space pause"),
    ),
    b(C::Training, &[k('s')], A::Stop, "stop", Some("s stop")),
    b(
        C::Training,
        &[k('v')],
        A::ToggleView,
        "loss chart: whole run / recent window (narrow screens)",
        None,
    ),
    b(
        C::Training,
        &[k('w')],
        A::SaveNet,
        "save the trained network (asks for the path)",
        Some("w save net"),
    ),
];

impl Key {
    /// The key as the help screen writes it.
    pub fn label(self) -> String {
        let base = match self.code {
            KeyCode::Char(' ') => "space".to_string(),
            KeyCode::Char(c) => c.to_string(),
            KeyCode::Enter => "Enter".into(),
            KeyCode::Esc => "Esc".into(),
            KeyCode::Tab => "Tab".into(),
            KeyCode::BackTab => "Shift-Tab".into(),
            KeyCode::Up => "↑".into(),
            KeyCode::Down => "↓".into(),
            KeyCode::Left => "←".into(),
            KeyCode::Right => "→".into(),
            KeyCode::PageUp => "PgUp".into(),
            KeyCode::PageDown => "PgDn".into(),
            KeyCode::Home => "Home".into(),
            KeyCode::End => "End".into(),
            KeyCode::Backspace => "Backspace".into(),
            KeyCode::Delete => "Delete".into(),
            other => format!("{other:?}"),
        };
        if self.ctrl {
            format!("Ctrl-{}", base.to_uppercase())
        } else {
            base
        }
    }

    fn matches(self, ev: &KeyEvent) -> bool {
        let ev_ctrl = ev.modifiers.contains(KeyModifiers::CONTROL);
        if ev_ctrl != self.ctrl || ev.modifiers.contains(KeyModifiers::ALT) {
            return false;
        }
        match (self.code, ev.code) {
            // Ctrl-letters arrive lower- or upper-case depending on the terminal.
            (KeyCode::Char(a), KeyCode::Char(b)) if self.ctrl => a.eq_ignore_ascii_case(&b),
            (a, b) => a == b,
        }
    }
}

/// The action bound to `ev` in the first of `ctxs` (most specific first)
/// that binds it.
pub fn lookup(ctxs: &[Ctx], ev: &KeyEvent) -> Option<Action> {
    ctxs.iter().find_map(|&ctx| {
        BINDINGS
            .iter()
            .filter(|b| b.ctx == ctx)
            .find(|b| b.keys.iter().any(|k| k.matches(ev)))
            .map(|b| b.action)
    })
}

/// Hint-bar entries for the active contexts, most specific first, without
/// repeats.
pub fn hints(ctxs: &[Ctx]) -> Vec<&'static str> {
    let mut out: Vec<&'static str> = Vec::new();
    for &ctx in ctxs {
        for b in BINDINGS.iter().filter(|b| b.ctx == ctx) {
            if let Some(h) = b.hint
                && !out.contains(&h)
            {
                out.push(h);
            }
        }
    }
    out
}

/// The help screen's lines: one heading per context, then "keys  what".
pub fn help_lines() -> Vec<(Option<&'static str>, String, &'static str)> {
    let order = [
        C::Global,
        C::Model,
        C::Responses,
        C::Study,
        C::Training,
        C::Field,
        C::Open,
        C::Confirm,
        C::Help,
    ];
    let mut out = Vec::new();
    for ctx in order {
        out.push((Some(ctx.title()), String::new(), ""));
        for b in BINDINGS.iter().filter(|b| b.ctx == ctx) {
            let keys: Vec<String> = b.keys.iter().map(|k| k.label()).collect();
            out.push((None, keys.join(" / "), b.help));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use ratatui::crossterm::event::KeyEvent;

    fn ev(code: KeyCode, m: KeyModifiers) -> KeyEvent {
        KeyEvent::new(code, m)
    }

    #[test]
    fn dialogs_shadow_tabs_and_ctrl_is_told_apart() {
        let e = ev(KeyCode::Esc, KeyModifiers::NONE);
        assert_eq!(
            lookup(&[C::Field, C::Model, C::Global], &e),
            Some(A::Cancel)
        );
        let s = ev(KeyCode::Char('s'), KeyModifiers::CONTROL);
        assert_eq!(lookup(&[C::Training, C::Global], &s), Some(A::Save));
        let s = ev(KeyCode::Char('s'), KeyModifiers::NONE);
        assert_eq!(lookup(&[C::Training, C::Global], &s), Some(A::Stop));
        let plus = ev(KeyCode::Char('+'), KeyModifiers::SHIFT);
        assert_eq!(lookup(&[C::Model, C::Global], &plus), Some(A::NudgeUp));
    }

    #[test]
    fn no_key_is_bound_twice_in_one_context() {
        for (i, a) in BINDINGS.iter().enumerate() {
            for b2 in &BINDINGS[i + 1..] {
                if a.ctx == b2.ctx {
                    for k1 in a.keys {
                        assert!(!b2.keys.contains(k1), "{:?} bound twice in {:?}", k1, a.ctx);
                    }
                }
            }
        }
    }

    #[test]
    fn help_lists_every_binding() {
        let lines = help_lines();
        let rows = lines.iter().filter(|l| l.0.is_none()).count();
        assert_eq!(rows, BINDINGS.len());
        assert!(lines.iter().any(|l| l.1 == "Ctrl-S"));
    }
}
