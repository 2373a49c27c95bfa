//! The component structure: the key tables, the help page and the tab
//! bar all come from the tabs' own declarations.

use super::*;
use crate::tui::frame::help_lines;
use crate::tui::keys::{self, Doc, Key};
use crate::tui::popups::help::HelpLine;

/// Every table the app looks keys up in, with its name; the global table
/// includes one digit per registered tab.
fn tables(a: &App) -> Vec<(String, Vec<Key>, Vec<&'static Doc>)> {
    let digits: Vec<Key> = (0..a.tabs.len()).filter_map(keys::tab_key).collect();
    let mut out = vec![
        ("global".to_string(), digits, keys::docs(keys::GLOBAL)),
        (
            "field".into(),
            Vec::new(),
            keys::docs(crate::tui::popups::field::FIELD),
        ),
        (
            "open".into(),
            Vec::new(),
            keys::docs(crate::tui::popups::open::OPEN),
        ),
        (
            "confirm".into(),
            Vec::new(),
            keys::docs(crate::tui::popups::confirm::CONFIRM),
        ),
        (
            "help".into(),
            Vec::new(),
            keys::docs(crate::tui::popups::help::HELP),
        ),
    ];
    for t in &a.tabs {
        out.push((t.title().to_string(), Vec::new(), t.keys()));
    }
    out
}

#[test]
fn no_key_is_bound_twice_in_one_table() {
    let a = app();
    for (name, extra, docs) in tables(&a) {
        let mut seen = extra;
        for d in docs {
            for k in d.keys {
                assert!(!seen.contains(k), "{k:?} bound twice in {name}");
                seen.push(*k);
            }
        }
    }
}

#[test]
fn no_tab_hides_a_key_that_works_everywhere() {
    // A tab's keys are tried first: one of them on a global key (or a tab
    // digit) would make that key silently stop working on the tab.
    let a = app();
    let global = &tables(&a)[0];
    let mut everywhere: Vec<Key> = global.1.clone();
    everywhere.extend(global.2.iter().flat_map(|d| d.keys.iter().copied()));
    for t in &a.tabs {
        for d in t.keys() {
            for k in d.keys {
                assert!(
                    !everywhere.contains(k),
                    "{} binds {k:?}, a key that works everywhere",
                    t.title()
                );
            }
        }
    }
}

#[test]
fn help_lists_every_binding_and_every_tab() {
    let a = app();
    let lines = help_lines(&a);
    let rows = lines
        .iter()
        .filter(|l| matches!(l, HelpLine::Row { .. }))
        .count();
    let bindings: usize = tables(&a).iter().map(|t| t.2.len()).sum();
    assert_eq!(rows, bindings + a.tabs.len());
    for (i, t) in a.tabs.iter().enumerate() {
        let heading = format!("{} {}", i + 1, t.title());
        assert!(
            lines.contains(&HelpLine::Heading(heading.clone())),
            "{heading}"
        );
    }
    assert!(
        lines
            .iter()
            .any(|l| matches!(l, HelpLine::Row { keys, .. } if keys == "Ctrl-S"))
    );
}

#[test]
fn the_tab_bar_and_the_digits_follow_the_registry() {
    let mut a = app();
    let titles: Vec<&str> = a.tabs.iter().map(|t| t.title()).collect();
    assert_eq!(
        titles,
        [
            "Model",
            "Responses",
            "Study",
            "Training",
            "Vibration",
            "Day",
            "Seat"
        ]
    );
    let s = screen(&a, 160, 48);
    let bar = s.lines().next().unwrap_or_default().to_string();
    for (i, t) in titles.iter().enumerate() {
        assert!(bar.contains(&format!("{} {t}", i + 1)), "{bar}");
    }
    for i in (0..a.tabs.len()).rev() {
        key(&mut a, KeyCode::Char(char::from(b'1' + i as u8)));
        assert_eq!(a.current, i);
    }
    // Tab and Shift-Tab wrap around however many tabs there are
    key(&mut a, KeyCode::BackTab);
    assert_eq!(a.current, a.tabs.len() - 1);
    key(&mut a, KeyCode::Tab);
    assert_eq!(a.current, 0);
}

#[test]
fn the_hint_bar_shows_the_current_tabs_keys_first() {
    let mut a = app();
    let s = screen(&a, 160, 48);
    let hints = s.lines().last().unwrap_or_default().to_string();
    assert!(hints.trim_start().starts_with("↑↓←→ move"), "{hints}");
    key(&mut a, KeyCode::Char('2'));
    let s = screen(&a, 160, 48);
    let hints = s.lines().last().unwrap_or_default().to_string();
    assert!(hints.trim_start().starts_with("←→ cursor"), "{hints}");
    assert!(hints.contains("? help"), "{hints}");
}

/// A fifth tab, as the Vibration tab will be: nothing but its own file.
mod fifth {
    use crate::tui::component::{Change, Cx, Tab};
    use crate::tui::effect::Effect;
    use crate::tui::keys::{self, Binding, Doc, b, k};
    use crate::tui::popups::field::{Field, Purpose};
    use crate::tui::shared::Shared;
    use ratatui::buffer::Buffer;
    use ratatui::crossterm::event::KeyEvent;
    use ratatui::layout::Rect;
    use ratatui::text::Line;
    use ratatui::widgets::Widget;
    use std::any::Any;

    #[derive(Clone, Copy)]
    enum Action {
        Run,
        Export,
    }

    static KEYS: &[Binding<Action>] = &[
        b(
            &[k('r')],
            Action::Run,
            "run in the background",
            Some("r run"),
        ),
        b(&[k('x')], Action::Export, "export", Some("x export")),
    ];

    #[derive(Default)]
    pub struct Fifth {
        pub edits: usize,
        pub result: Option<f64>,
    }

    impl Tab for Fifth {
        fn new(_: &Shared) -> Self {
            Fifth::default()
        }
        fn title(&self) -> &'static str {
            "Vibration"
        }
        fn keys(&self) -> Vec<&'static Doc> {
            keys::docs(KEYS)
        }
        fn on_key(&mut self, ev: &KeyEvent, cx: &Cx) -> Option<Vec<Effect>> {
            Some(match keys::lookup(KEYS, ev)? {
                Action::Run => {
                    let (tx, wrap) = cx.mailbox.wrap::<f64>()?;
                    let m = cx.shared.body.seated_mass();
                    std::thread::spawn(move || tx.send(wrap(2.0 * m)));
                    vec![Effect::Status("running".into())]
                }
                Action::Export => vec![Effect::OpenField(Field::new(
                    Purpose::Tab(7),
                    "export to",
                    "out.csv",
                ))],
            })
        }
        fn commit(&mut self, tag: usize, text: &str, _: &Cx) -> Result<Vec<Effect>, String> {
            Ok(vec![Effect::Status(format!("tag {tag}: {text}"))])
        }
        fn on_change(&mut self, change: Change, _: &Cx) {
            if change == Change::Edited {
                self.edits += 1;
            }
        }
        fn on_msg(&mut self, msg: Box<dyn Any + Send>, _: &Cx) -> Vec<Effect> {
            self.result = msg.downcast::<f64>().ok().map(|v| *v);
            vec![Effect::Status("done".into())]
        }
        fn render(&self, s: &Shared, area: Rect, buf: &mut Buffer) {
            Line::raw(format!("fifth tab on {}", s.preset.name)).render(area, buf);
        }
    }
}

#[test]
fn a_fifth_tab_needs_no_change_outside_its_own_file() {
    // what the one registration line does (in place of the real Vibration
    // tab). The channel comes after the swap: built with one, the real tab
    // starts its run on a worker, whose reports (~100 ms later) carry the
    // same tab index and could reach `rx` before the fifth tab's answer.
    let mut a = App::new(Preset::builtin_default(), None, Theme::default());
    a.tabs.truncate(4);
    a.tabs.push(Box::new(fifth::Fifth::default()));
    let (tx, rx) = std::sync::mpsc::channel();
    a.connect(tx);
    let s = screen(&a, 160, 48);
    assert!(
        s.lines().next().unwrap_or_default().contains("5 Vibration"),
        "{s}"
    );
    key(&mut a, KeyCode::Char('5'));
    assert_eq!(a.current, 4);
    let s = screen(&a, 80, 24);
    assert!(
        s.contains("fifth tab on paper-75kg") && s.contains("r run"),
        "{s}"
    );
    // its key starts background work; the result comes back through update
    key(&mut a, KeyCode::Char('r'));
    assert_eq!(a.status.text, "running");
    let msg = rx
        .recv_timeout(std::time::Duration::from_secs(10))
        .expect("the tab's message");
    update(&mut a, msg);
    let seated = a.shared.body.seated_mass();
    assert_eq!(
        a.tab_state::<fifth::Fifth>().and_then(|t| t.result),
        Some(2.0 * seated)
    );
    assert_eq!(a.status.text, "done");
    // its field is committed back to it
    key(&mut a, KeyCode::Char('x'));
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.status.text, "tag 7: out.csv");
    // it hears model edits made on another tab
    key(&mut a, KeyCode::Char('1'));
    key(&mut a, KeyCode::Char('+'));
    assert_eq!(a.tab_state::<fifth::Fifth>().map(|t| t.edits), Some(1));
    // the help page has its section and its digit
    key(&mut a, KeyCode::Char('?'));
    let help = crate::tui::frame::help_lines(&a);
    assert!(help.contains(&HelpLine::Heading("5 Vibration".into())));
    assert!(help.contains(&HelpLine::Row {
        keys: "5".into(),
        help: "Vibration tab".into()
    }));
}
