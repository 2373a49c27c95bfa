//! ASCII mode names the keys a prompt means: an arrow there would become
//! `<` `>` `^` `v` (keys of their own, e.g. `<` `>` scroll the Vibration
//! traces), so every text that names arrow keys spells them out, one
//! function (`keys::arrows`) for all. Decorations that are no key (a
//! selector's `< value >`) stay.

use super::*;
use crate::tui::theme::Theme;

fn ascii_app() -> App {
    App::new(
        Preset::builtin_default(),
        None,
        Theme {
            mono: true,
            ascii: true,
        },
    )
}

#[test]
fn open_dialog_asks_to_pick_with_up_down() {
    let mut a = ascii_app();
    ctrl(&mut a, 'o');
    if let Some(f) = a.field.as_mut() {
        f.set_text(String::new());
    }
    key(&mut a, KeyCode::Enter);
    let s = screen(&a, 100, 30);
    assert!(s.contains("pick a preset with Up/Down"), "{s}");
    assert!(!s.contains("with ^v"), "{s}");
}

#[test]
fn training_rows_say_left_right_picks() {
    let mut a = ascii_app();
    key(&mut a, KeyCode::Char('4'));
    key(&mut a, KeyCode::Right); // case row: the next case
    assert!(
        a.status
            .text
            .contains("(Left/Right: the network the next run trains)"),
        "{}",
        a.status.text
    );
    key(&mut a, KeyCode::Down); // trainer row
    assert!(
        a.status.text.contains("(Left/Right: backprop"),
        "{}",
        a.status.text
    );
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.status.text, "Left/Right picks this one");
    let s = screen(&a, 100, 30);
    assert!(s.contains("Left/Right picks this one"), "{s}");
    assert!(!s.contains("</>"), "{s}");
}

#[test]
fn vibration_kind_is_left_right_not_the_scroll_keys() {
    let mut a = ascii_app();
    key(&mut a, KeyCode::Char('5'));
    let s = screen(&a, 100, 30);
    // Too long for the panel with its name: the keys stay, whole.
    assert!(s.contains(" Left/Right kind, Enter edit "), "{s}");
    assert!(!s.contains("<> kind"), "{s}");
    let s = screen(&a, 160, 48);
    assert!(s.contains(" signal (Left/Right kind, Enter edit) "), "{s}");
    // The selector's brackets are no key name: they stay.
    assert!(s.contains("< sine >"), "{s}");
    key(&mut a, KeyCode::Enter); // on the kind row
    assert_eq!(
        a.status.text,
        "Left/Right pick the signal kind; Enter on a row below edits it"
    );
    key(&mut a, KeyCode::Left); // sine → file, no path yet
    let s = screen(&a, 100, 30);
    let flat: String = s.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(flat.contains("no file yet: Down to 'file'"), "{s}");
    assert!(
        flat.contains("Up/Down pick a setting and Enter edits it; Left/Right picks"),
        "{s}"
    );
    assert!(!flat.contains("v to 'file'"), "{s}");
}

#[test]
fn training_chart_of_another_case_says_left_right() {
    let (tx, rx) = std::sync::mpsc::channel();
    let mut a = App::with_channel(
        Preset::builtin_default(),
        None,
        Theme {
            mono: true,
            ascii: true,
        },
        Some(tx),
    );
    key(&mut a, KeyCode::Char('4'));
    super::training_runs::set(&mut a, "epoch limit", "5");
    key(&mut a, KeyCode::Char('t'));
    super::training_runs::pump(&mut a, &rx, |a| !training(a).running());
    super::training_runs::go_to_named(&mut a, "case");
    key(&mut a, KeyCode::Right); // another case than the shown run's
    let s = screen(&a, 160, 48);
    let flat: String = s.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(flat.contains("Left/Right on the case row goes back"), "{s}");
    assert!(!flat.contains("</> on the case row"), "{s}");
}

/// Eleven variants: the legend scrolls with Up/Down, and the Study tab
/// says so without `^v` (its title), or not at all (a bare heading cell
/// of 9 columns); the readout line's "more" is a Down away.
#[test]
fn study_scroll_position_and_more_name_up_down() {
    let mut a = ascii_app();
    key(&mut a, KeyCode::Char('3'));
    key(&mut a, KeyCode::Enter);
    typ(&mut a, "50,55,60,65,70,75,80,85,90,95,100");
    key(&mut a, KeyCode::Enter);
    let s = screen(&a, 80, 24);
    assert!(s.contains("/11 Up/Down"), "{s}");
    let mut more = false;
    for (w, h) in [(60u16, 16u16), (70, 20), (80, 24), (100, 30)] {
        let s = screen(&a, w, h);
        assert!(!s.contains("^v") && !s.contains("v more"), "{w}x{h}\n{s}");
        more |= s.contains("Down more");
    }
    assert!(more, "no readout line cut with 'Down more'");
}

#[test]
fn fit_dialog_says_up_down_for_more() {
    let mut a = ascii_app();
    key(&mut a, KeyCode::Char('2'));
    key(&mut a, KeyCode::Char('D'));
    if let Some(f) = a.field.as_mut() {
        f.set_text("examples/synthetic-stht-apms-3pct-2deg.csv");
    }
    key(&mut a, KeyCode::Enter);
    key(&mut a, KeyCode::Char('F'));
    let s = screen(&a, 80, 20);
    assert!(s.contains("(Up/Down more)"), "{s}");
    assert!(!s.contains("(^v more)"), "{s}");
}

/// The frame before `asciify` maps its glyphs.
fn glyphs(a: &App, w: u16, h: u16) -> String {
    struct Raw<'a>(&'a App);
    impl ratatui::widgets::Widget for Raw<'_> {
        fn render(self, area: ratatui::layout::Rect, buf: &mut ratatui::buffer::Buffer) {
            self.0.render_glyphs(area, buf);
        }
    }
    let mut t = ratatui::Terminal::new(ratatui::backend::TestBackend::new(w, h)).expect("backend");
    t.draw(|f| f.render_widget(Raw(a), f.area())).expect("draw");
    buffer_text(t.backend().buffer()).join("\n")
}

/// An arrow key named by its glyph: ← ↑ ↓ anywhere, → unless it stands
/// between spaces as "becomes" ("k4 54000 → 90000", "band … → …").
fn arrow_keys_named(s: &str) -> Vec<String> {
    s.lines()
        .filter(|l| {
            l.contains(['←', '↑', '↓'])
                || l.match_indices('→').any(|(i, _)| {
                    !(l[..i].ends_with(' ') && l[i + '→'.len_utf8()..].starts_with(' '))
                })
        })
        .map(str::to_string)
        .collect()
}

/// Every screen reachable with a few keys on every tab, at the sizes people
/// use, its dialogs, fields and messages: in ASCII no text names an arrow
/// key by its glyph (issue 19 item 16's class, not only its examples).
#[test]
fn no_screen_in_ascii_names_an_arrow_key_by_its_glyph() {
    let sizes = [(60u16, 16u16), (80, 24), (100, 30), (160, 48)];
    let mut bad: Vec<String> = Vec::new();
    let mut check = |a: &App, what: &str| {
        for (w, h) in sizes {
            let text = glyphs(a, w, h);
            for l in arrow_keys_named(&text) {
                bad.push(format!("{what} {w}x{h}: {l}"));
            }
            // a glyph ASCII mode has no stand-in for would show as `?`
            // (± of the library's training table has none in one cell: left)
            for l in text.lines().map(|l| l.replace('±', "")) {
                let mut row =
                    ratatui::buffer::Buffer::empty(ratatui::layout::Rect::new(0, 0, w, 1));
                row.set_string(0, 0, &l, ratatui::style::Style::default());
                crate::view::chart::asciify(row.area, &mut row);
                let mapped = buffer_text(&row).join("");
                if mapped.matches('?').count() > l.matches('?').count() {
                    bad.push(format!("{what} {w}x{h}: unmapped glyph in {l}"));
                }
            }
        }
    };
    let mut a = ascii_app();
    for tab in '1'..='6' {
        key(&mut a, KeyCode::Char(tab));
        check(&a, &format!("tab {tab}"));
        // every row's Enter (a field, or a message), its Left and Right
        for _ in 0..14 {
            for k in [KeyCode::Enter, KeyCode::Esc, KeyCode::Right, KeyCode::Left] {
                key(&mut a, k);
                check(&a, &format!("tab {tab} after {k:?}"));
                key(&mut a, KeyCode::Esc);
            }
            key(&mut a, KeyCode::Down);
        }
        for c in ['z', 'x', 'b', 's', 'c', 'g', 'D'] {
            key(&mut a, KeyCode::Char(c));
            check(&a, &format!("tab {tab} after {c}"));
            key(&mut a, KeyCode::Esc);
            key(&mut a, KeyCode::Esc);
        }
        // the help page, every page of it
        key(&mut a, KeyCode::Char('?'));
        for _ in 0..12 {
            check(&a, &format!("tab {tab} help"));
            key(&mut a, KeyCode::PageDown);
        }
        key(&mut a, KeyCode::Esc);
        key(&mut a, KeyCode::Esc);
        // the open dialog, and its refusal of an empty path
        ctrl(&mut a, 'o');
        check(&a, &format!("tab {tab} open"));
        if let Some(f) = a.field.as_mut() {
            f.set_text(String::new());
        }
        key(&mut a, KeyCode::Enter);
        check(&a, &format!("tab {tab} open refused"));
        key(&mut a, KeyCode::Esc);
        key(&mut a, KeyCode::Esc);
    }
    assert!(bad.is_empty(), "{} lines:\n{}", bad.len(), bad.join("\n"));
}
