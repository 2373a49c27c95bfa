//! The dialogs at work: the help page wraps long entries and pages through
//! them all, its search says what it did not find, and a confirmation
//! offers only the keys it answers to.

use super::*;

/// Words of `s` with the frame's borders dropped, one space apart.
fn words(s: &str) -> String {
    s.replace(['│', '┌', '┐', '└', '┘', '─'], " ")
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
}

#[test]
fn the_help_page_wraps_long_entries_and_pages_through_them_all() {
    use crate::tui::popups::Overlay;
    use crate::tui::popups::help::HelpLine;
    for (w, h) in [(80u16, 24u16), (60, 16)] {
        let mut a = app();
        update(&mut a, Msg::Resize(w, h));
        key(&mut a, KeyCode::Char('?'));
        // Page by page to the end: every entry's description whole, the
        // last screen the last rows. Each page's rows by their place in the
        // page, so the row a page repeats from the one before is read once.
        let mut rows = std::collections::BTreeMap::new();
        for _ in 0..200 {
            let s = screen(&a, w, h);
            let Overlay::Help(v) = &a.overlay else {
                panic!("help closed")
            };
            let at = v.scroll;
            for (j, line) in s.lines().skip(2).take(usize::from(h) - 5).enumerate() {
                rows.insert(at + j, line.to_string());
            }
            key(&mut a, KeyCode::PageDown);
            let Overlay::Help(v) = &a.overlay else {
                panic!("help closed")
            };
            if v.scroll == at {
                break;
            }
        }
        let seen = words(&rows.into_values().collect::<Vec<_>>().join("\n"));
        for l in crate::tui::frame::help_lines(&a) {
            if let HelpLine::Row { help, .. } = l {
                assert!(seen.contains(&words(&help)), "{w}x{h}: {help:?} cut");
            }
        }
    }
}

#[test]
fn help_search_says_not_found_and_m_works_there() {
    use crate::tui::popups::Overlay;
    let mut a = app();
    a.size = Some((80, 24));
    key(&mut a, KeyCode::Char('?'));
    typ(&mut a, "/zzqx");
    assert!(screen(&a, 80, 24).contains("not found"));
    key(&mut a, KeyCode::Enter);
    assert!(screen(&a, 80, 24).contains("'zzqx' not found"));
    key(&mut a, KeyCode::Char('n'));
    assert!(a.status.text.contains("not found"), "{}", a.status.text);
    key(&mut a, KeyCode::Esc);
    let was = a.mouse;
    key(&mut a, KeyCode::Char('M'));
    assert_eq!(a.mouse, !was);
    assert!(matches!(a.overlay, Overlay::Help(_)));
    // The message fits 80 columns.
    assert!(a.status.text.chars().count() <= 78, "{}", a.status.text);
    let s = screen(&a, 80, 24);
    assert!(s.contains("M turns it off"), "{s}");
}

/// The hint bar (the last screen row).
fn hint(a: &App) -> String {
    screen(a, 80, 24).lines().last().unwrap_or("").to_string()
}

#[test]
fn confirmations_offer_only_their_own_keys() {
    use crate::tui::popups::Overlay;
    use crate::tui::popups::confirm::{Confirm, ConfirmKind};
    // Opening a preset over unsaved edits: y / n, no s.
    let mut a = app();
    key(&mut a, KeyCode::Char('+'));
    ctrl(&mut a, 'o');
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Enter);
    assert!(matches!(
        a.overlay,
        Overlay::Confirm(Confirm {
            kind: ConfirmKind::Discard,
            ..
        })
    ));
    let h = hint(&a);
    assert!(h.contains("y yes") && h.contains("n/Esc no"), "{h}");
    assert!(!h.contains("save"), "{h}");
    // Quitting with unsaved edits: s is offered and acts.
    key(&mut a, KeyCode::Esc);
    key(&mut a, KeyCode::Esc);
    assert_eq!(a.overlay, Overlay::None);
    key(&mut a, KeyCode::Char('q'));
    assert!(hint(&a).contains("s save+quit"), "{}", hint(&a));
    key(&mut a, KeyCode::Char('s'));
    assert!(a.field.is_some());
    // A quit question whose reason went away (a run ended): whole text,
    // no s.
    let mut b = app();
    b.overlay = Overlay::Confirm(Confirm::new(ConfirmKind::Quit, None));
    let s = screen(&b, 80, 24);
    assert!(!s.contains("│ .") && s.contains("Quit now?"), "{s}");
    assert!(!hint(&b).contains("save"), "{}", hint(&b));
    key(&mut b, KeyCode::Char('s'));
    assert!(b.field.is_none());
    // Deleting a link: no x.
    let mut c = app();
    key(&mut c, KeyCode::End);
    key(&mut c, KeyCode::Char('d'));
    let h = hint(&c);
    assert!(h.contains("y delete") && !h.contains("x with links"), "{h}");
    let links = c.shared.body.links.len();
    key(&mut c, KeyCode::Char('x'));
    assert_eq!(c.shared.body.links.len(), links);
    // A segment's question still offers x.
    let mut d = app();
    key(&mut d, KeyCode::Down);
    key(&mut d, KeyCode::Char('d'));
    assert!(hint(&d).contains("x with links"), "{}", hint(&d));
}

#[test]
#[ignore = "prints screens for a look"]
fn show_review() {
    let mut a = app();
    update(&mut a, Msg::Resize(60, 16));
    key(&mut a, KeyCode::Char('?'));
    println!("{}", screen(&a, 60, 16));
    key(&mut a, KeyCode::PageDown);
    println!("{}", screen(&a, 60, 16));
}
