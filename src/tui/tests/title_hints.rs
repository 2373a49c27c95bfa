//! The frame's title and hint bar at the widths people use (issue 19
//! item 19): the tabs keep their full names whenever they fit beside the
//! file part at its shortest, and the hint bar always shows the quit key,
//! dropping the least important hints first.

use super::*;

/// The full names at 80 columns: seven tabs fit one space apart.
const FULL: &str = " 1 Model 2 Responses 3 Study 4 Training 5 Vibration 6 Day 7 Seat ";
/// The same where there is room: two spaces apart.
const WIDE: &str = " 1 Model  2 Responses  3 Study  4 Training  5 Vibration  6 Day  7 Seat ";

fn first_line(s: &str) -> &str {
    s.lines().next().unwrap_or("")
}

fn last_line(s: &str) -> &str {
    s.lines().last().unwrap_or("")
}

fn each_theme() -> [Theme; 3] {
    [
        Theme::default(),
        Theme {
            mono: true,
            ascii: false,
        },
        Theme {
            mono: false,
            ascii: true,
        },
    ]
}

#[test]
fn at_80_columns_every_tab_name_is_whole() {
    for th in each_theme() {
        let mut a = App::new(Preset::builtin_default(), None, th);
        for i in 0..a.tabs.len() {
            key(&mut a, KeyCode::Char(char::from(b'1' + i as u8)));
            let s = screen(&a, 80, 24);
            let title = first_line(&s);
            assert!(title.starts_with(FULL), "{th:?} tab {i}: {title:?}");
            // The file part gives way first: the name stays whole.
            assert!(
                title.trim_end().ends_with("paper-75kg") || title.trim_end().ends_with("new day"),
                "{title:?}"
            );
        }
        // An edit adds " *" where " *modified" does not fit; the tabs stay.
        key(&mut a, KeyCode::Char('1'));
        key(&mut a, KeyCode::Char('+'));
        let s = screen(&a, 80, 24);
        let title = first_line(&s);
        assert!(title.starts_with(FULL), "{title:?}");
        assert!(title.trim_end().ends_with("paper-75kg *"), "{title:?}");
    }
}

#[test]
fn names_shorten_only_where_the_full_ones_do_not_fit() {
    let mut a = app();
    // 60 columns: the full names (64 one space apart) cannot fit, so the
    // others shorten.
    let s = screen(&a, 60, 16);
    let title = first_line(&s);
    assert!(title.starts_with(" 1 Model 2 Res 3 Stu "), "{title:?}");
    assert!(title.trim_end().ends_with("paper-75kg"), "{title:?}");
    // 120 columns: the app's name and "(built-in)" as well.
    let s = screen(&a, 120, 30);
    assert!(first_line(&s).contains(WIDE.trim()), "{s}");
    assert!(first_line(&s).contains("paper-75kg (built-in)"), "{s}");
    // A click on a full name at 80 columns opens that tab.
    let x = FULL.find("5 Vibration").expect("in the title") as u16;
    a.size = Some((80, 24));
    assert_eq!(a.tab_at(80, x), Some(4));
    assert_eq!(a.tab_at(80, x + 10), Some(4));
    let x = FULL.find("7 Seat").expect("in the title") as u16;
    assert_eq!(a.tab_at(80, x + 5), Some(6));
}

#[test]
fn the_hint_bar_always_shows_the_quit_key() {
    for th in each_theme() {
        let mut a = App::new(Preset::builtin_default(), None, th);
        for (w, h) in [(60u16, 16u16), (70, 20), (80, 24), (100, 30), (160, 48)] {
            for i in 0..a.tabs.len() {
                key(&mut a, KeyCode::Char(char::from(b'1' + i as u8)));
                let s = screen(&a, w, h);
                let bar = last_line(&s);
                assert!(bar.contains(" q quit "), "{th:?} {w}x{h} tab {i}: {bar:?}");
                assert!(bar.contains("? help"), "{bar:?}");
                assert!(bar.contains("M mouse off"), "{bar:?}");
            }
        }
    }
}

#[test]
fn the_most_important_hints_stay_and_the_rest_go() {
    let mut a = app();
    key(&mut a, KeyCode::Char('2'));
    let s = screen(&a, 80, 24);
    let bar = last_line(&s);
    // The tab's own keys first, as its table orders them; quit kept.
    assert!(
        bar.starts_with(" ←→ cursor  n peak  g go to  x export"),
        "{bar:?}"
    );
    assert!(bar.contains("q quit"), "{bar:?}");
    // Nothing is cut in the middle of a word.
    for entry in ["c compare", "^S save", "u undo"] {
        let k = entry.split(' ').next().unwrap_or("");
        assert!(
            bar.contains(entry) || !bar.contains(&format!(" {k} ")),
            "{bar:?}"
        );
    }
}
