//! The component structure: the key tables, the help page and the tab
//! bar all come from the tabs' own declarations.

use super::*;
use crate::tui::frame::help_lines;
use crate::tui::keys::{self, Doc, HelpLine, Key};

/// Every table the app looks keys up in, with its name; the global table
/// includes one digit per registered tab.
fn tables(a: &App) -> Vec<(String, Vec<Key>, Vec<&'static Doc>)> {
    let digits: Vec<Key> = (0..a.tabs.len()).filter_map(keys::tab_key).collect();
    let mut out = vec![
        ("global".to_string(), digits, keys::docs(keys::GLOBAL)),
        ("field".into(), Vec::new(), keys::docs(keys::FIELD)),
        ("open".into(), Vec::new(), keys::docs(keys::OPEN)),
        ("confirm".into(), Vec::new(), keys::docs(keys::CONFIRM)),
        ("help".into(), Vec::new(), keys::docs(keys::HELP)),
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
    assert_eq!(titles, ["Model", "Responses", "Study", "Training"]);
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
