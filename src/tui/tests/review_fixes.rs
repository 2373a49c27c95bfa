//! Defects a reviewer found walking the TUI: numbers cut in tables and
//! edit fields, cut reasons, hints offering keys that do nothing.

use super::super::theme::Theme;
use super::*;
use biodyn::Param;

/// The last row (k of the last link), its value typed in, then Enter.
fn set_last_stiffness(a: &mut App, text: &str) {
    key(a, KeyCode::End);
    key(a, KeyCode::Enter);
    typ(a, text);
    key(a, KeyCode::Enter);
}

#[test]
fn a_tiny_value_shows_whole_in_the_table_and_compact_in_the_field() {
    let mut a = app();
    set_last_stiffness(&mut a, "1e-320");
    assert!(a.field.is_none(), "{:?}", a.field);
    let s = screen(&a, 80, 24);
    assert!(s.contains("pelvis-seat            1e-320      2064"), "{s}");
    key(&mut a, KeyCode::Enter);
    let f = a.field.as_ref().expect("field");
    assert_eq!(f.text, "1e-320");
    // A huge value too: never 31 digits in the field.
    key(&mut a, KeyCode::Esc);
    set_last_stiffness(&mut a, "1e30");
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.field.as_ref().map(|f| f.text.as_str()), Some("1e30"));
}

#[test]
fn committing_the_prefilled_text_unchanged_keeps_the_exact_value() {
    let mut a = app();
    key(&mut a, KeyCode::Char('-'));
    let exact = a.shared.body.get(Param::BodyMass);
    assert_eq!(exact, 75.0 / 1.05);
    key(&mut a, KeyCode::Enter);
    assert_eq!(
        a.field.as_ref().map(|f| f.text.as_str()),
        Some("71.4285714286")
    );
    key(&mut a, KeyCode::Enter);
    assert!(a.field.is_none());
    assert_eq!(
        a.shared.body.get(Param::BodyMass).to_bits(),
        exact.to_bits()
    );
    assert_eq!(a.status.text, "unchanged");
}

/// The right-hand panels' text, one line per screen row (joined so a
/// wrapped message reads whole).
fn panel_text(s: &str, from_col: usize) -> String {
    s.lines()
        .map(|l| {
            let t: String = l.chars().skip(from_col).collect();
            t.trim_matches(|c| c == '│' || c == ' ').to_string()
        })
        .collect::<Vec<_>>()
        .join(" ")
}

#[test]
fn a_modes_error_wraps_whole_in_its_panel() {
    let mut a = app();
    key(&mut a, KeyCode::End);
    key(&mut a, KeyCode::Right);
    key(&mut a, KeyCode::Enter);
    typ(&mut a, "1e7");
    key(&mut a, KeyCode::Enter);
    for (w, h) in [(80, 24), (200, 60)] {
        let s = screen(&a, w, h);
        let right = panel_text(&s, if w >= 120 { 72 } else { usize::from(w) - 34 });
        for want in [
            "cannot be trusted",
            "span too many orders of magnitude",
            "1e9 N/m)",
        ] {
            assert!(right.contains(want), "{w}x{h} lacks {want:?}:\n{s}");
        }
        assert!(s.contains("(band edge)"), "{w}x{h}:\n{s}");
    }
}

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
        // last screen the last rows.
        let mut seen = String::new();
        for _ in 0..200 {
            let s = screen(&a, w, h);
            let body: Vec<&str> = s.lines().skip(2).take(usize::from(h) - 5).collect();
            seen.push(' ');
            seen.push_str(&words(&body.join("\n")));
            let Overlay::Help(v) = &a.overlay else {
                panic!("help closed")
            };
            let at = v.scroll;
            key(&mut a, KeyCode::PageDown);
            let Overlay::Help(v) = &a.overlay else {
                panic!("help closed")
            };
            if v.scroll == at {
                break;
            }
        }
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

/// Ctrl-S, the path typed, Enter: the field's refusal, if any.
fn save_as(a: &mut App, path: &std::path::Path) -> Option<String> {
    ctrl(a, 's');
    if let Some(f) = a.field.as_mut() {
        f.set_text(path.display().to_string());
    }
    key(a, KeyCode::Enter);
    a.field.as_ref().and_then(|f| f.error.clone())
}

#[cfg(unix)]
#[test]
fn saving_over_a_fifo_or_a_device_is_refused_at_once() {
    use std::os::unix::fs::FileTypeExt;
    let dir = tempfile::tempdir().expect("tempdir");
    let fifo = dir.path().join("pipe.toml");
    let made = std::process::Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .expect("mkfifo runs");
    assert!(made.success());
    for target in [fifo.clone(), std::path::PathBuf::from("/dev/null")] {
        let mut a = app();
        key(&mut a, KeyCode::Char('+'));
        let e = save_as(&mut a, &target).unwrap_or_default();
        assert!(
            e.contains("not a regular file"),
            "{}: {e}",
            target.display()
        );
        assert!(!e.contains("exists"), "{e}");
        // A second Enter refuses again; nothing was written or replaced.
        key(&mut a, KeyCode::Enter);
        let e = field_error(&a);
        assert!(e.contains("not a regular file"), "{e}");
        assert!(a.modified());
    }
    let meta = std::fs::symlink_metadata(&fifo).expect("fifo stays");
    assert!(meta.file_type().is_fifo());
    // A regular file still asks first, then replaces.
    let file = dir.path().join("body.toml");
    std::fs::write(&file, "x").expect("write");
    let mut a = app();
    key(&mut a, KeyCode::Char('+'));
    let e = save_as(&mut a, &file).unwrap_or_default();
    assert!(e.contains("exists: Enter again replaces it"), "{e}");
    key(&mut a, KeyCode::Enter);
    assert!(a.field.is_none() && !a.modified());
}

#[test]
fn the_no_shares_advice_shows_whole() {
    let mut b = App::open("boileau-rakheja-1998", Theme::default()).expect("built-in");
    key(&mut b, KeyCode::Enter);
    let want = "no shares: edit m1…m4 (body mass = sum, 55.2 kg)";
    assert_eq!(b.status.text, want);
    for (w, h) in [(80, 24), (60, 16)] {
        let s = screen(&b, w, h);
        assert!(s.contains(want), "{w}x{h}:\n{s}");
    }
    let docs = super::docs_text();
    assert!(docs.contains(&format!("mass says `{want}`")));
}

#[test]
fn a_huge_body_mass_is_refused_without_a_contradiction() {
    let mut a = app();
    key(&mut a, KeyCode::Enter);
    typ(&mut a, "1e30");
    key(&mut a, KeyCode::Enter);
    let e = field_error(&a);
    assert_eq!(
        e,
        "body mass is 1e30 kg: it must be a number from 1e-3 to 1e6 kg"
    );
    assert!(screen(&a, 80, 24).contains("refused: body mass is 1e30 kg: it must be a number"));
}

#[test]
fn a_narrow_title_bar_drops_built_in_before_cutting_the_name() {
    let mut a = app();
    let top = |a: &App, w: u16| screen(a, w, 16).lines().next().unwrap_or("").to_string();
    assert!(
        top(&a, 60).ends_with("paper-75kg (built-in)"),
        "{}",
        top(&a, 60)
    );
    key(&mut a, KeyCode::Char('+'));
    let t = top(&a, 60);
    assert!(!t.contains('…') && t.contains("paper-75kg *"), "{t}");
    let mut b = App::open("boileau-rakheja-1998", Theme::default()).expect("built-in");
    assert!(
        top(&b, 60).ends_with(" boileau-rakheja-1998"),
        "{}",
        top(&b, 60)
    );
    key(&mut b, KeyCode::Down);
    key(&mut b, KeyCode::Char('+'));
    let t = top(&b, 60);
    assert!(t.ends_with(" boileau-rakheja-1998 *"), "{t}");
    assert!(
        top(&a, 80).ends_with("paper-75kg (built-in) *modified"),
        "{}",
        top(&a, 80)
    );
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
