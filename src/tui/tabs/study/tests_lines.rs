//! What the Study tab says must stay true and whole at 80×24: the status
//! after the cursor moves, the cursor column in the legend with long
//! labels, and the messages for a list with nothing to compare.

use super::StudyTab;
use crate::tui::app::App;
use crate::tui::event::Msg;
use crate::tui::tests::{app, key, screen};
use crate::tui::update::update;
use ratatui::crossterm::event::KeyCode;

fn tab(a: &App) -> &StudyTab {
    a.tab_state().expect("study tab")
}

fn on_tab(w: u16, h: u16) -> App {
    let mut a = app();
    update(&mut a, Msg::Resize(w, h));
    key(&mut a, KeyCode::Char('3'));
    a
}

fn ch(a: &mut App, c: char) {
    key(a, KeyCode::Char(c));
}

fn go_to(a: &mut App, f: &str) {
    ch(a, 'g');
    a.field.as_mut().expect("go-to field").set_text(f);
    key(a, KeyCode::Enter);
    assert!(a.field.is_none(), "go to {f} refused");
}

fn values(a: &mut App, v: &str) {
    key(a, KeyCode::Enter);
    a.field.as_mut().expect("values field").set_text(v);
    key(a, KeyCode::Enter);
}

#[test]
fn moving_the_cursor_replaces_the_go_to_message() {
    let mut a = on_tab(80, 24);
    ch(&mut a, 'k');
    go_to(&mut a, "5.8312");
    assert!(a.status.text.contains("5.8312"), "{}", a.status.text);
    ch(&mut a, '>');
    let f = tab(&a).cursor.f_hz.expect("a cursor");
    assert!((f - 5.9).abs() < 1e-9, "{f}");
    assert!(!a.status.text.contains("5.8312"), "stale: {}", a.status.text);
    assert!(a.status.text.contains("5.9 Hz"), "{}", a.status.text);
    let s = screen(&a, 80, 24);
    assert!(!s.contains("5.8312"), "{s}");
}

/// Each variant's magnitude of the current function at the cursor, as
/// the legend prints it.
fn at_cursor(a: &App) -> Vec<String> {
    let t = tab(a);
    let f = biodyn::Function::ALL[t.func];
    t.cursor
        .at
        .iter()
        .map(|r| crate::view::format::num(r.expect("a response").mag(f), 4))
        .collect()
}

#[test]
fn the_cursor_column_stays_in_the_legend_with_long_labels() {
    let mut a = on_tab(80, 24);
    ch(&mut a, 'k');
    ch(&mut a, 'f');
    go_to(&mut a, "5.8312");
    let s = screen(&a, 80, 24);
    assert!(s.contains("DPMI at 5.8312 Hz"), "{s}");
    assert!(!s.lines().any(|l| l.starts_with("f 5.8312 Hz")), "{s}");
    let rows: Vec<&str> = s.lines().filter(|l| l.contains("B.V.")).collect();
    assert_eq!(rows.len(), 3, "{s}");
    for (row, v) in rows.iter().zip(at_cursor(&a)) {
        assert!(row.contains(&format!(" {v} ")), "{v} not in {row}");
    }
}

#[test]
fn the_values_at_the_cursor_show_whole_in_the_legend_or_on_their_line() {
    for (w, h) in [(60u16, 16u16), (70, 20), (80, 24), (100, 30), (160, 48)] {
        for p in ['m', 'k', 'c'] {
            for fi in 0..3 {
                let mut a = on_tab(w, h);
                ch(&mut a, p);
                for _ in 0..fi {
                    ch(&mut a, 'f');
                }
                go_to(&mut a, "5.8312");
                let s = screen(&a, w, h);
                let line = s.lines().find(|l| l.starts_with("f 5.8312 Hz"));
                let in_legend = s.contains("at 5.8312 Hz");
                if w >= 80 {
                    assert!(in_legend && line.is_none(), "{w}x{h} {p} {fi}:\n{s}");
                }
                match line {
                    Some(l) => {
                        let all = at_cursor(&a).iter().all(|v| l.contains(&format!(" {v}")));
                        assert!(all || l.ends_with("↓ more"), "{w}x{h} {p} {fi}: {l}");
                    }
                    None => assert!(in_legend, "{w}x{h} {p} {fi}:\n{s}"),
                }
            }
        }
    }
}

#[test]
fn one_value_or_all_the_same_says_so_whole_under_aligned_headings() {
    for (list, what) in [("5%", "one value"), ("75,75", "the values are all the same")] {
        for (w, h) in [(80u16, 24u16), (60, 16), (160, 48)] {
            let mut a = on_tab(w, h);
            values(&mut a, list);
            let s = screen(&a, w, h);
            // The message whole, across its lines (frame bars taken off).
            let text: String = s
                .lines()
                .map(|l| l.trim_matches(|c| c == '│' || c == ' '))
                .collect::<Vec<_>>()
                .join(" ");
            let whole = format!(
                "{what}: nothing to compare. Enter gives two or more different values, e.g. 65,75,85 or -40%,0%,+40%."
            );
            assert!(text.contains(&whole), "{w}x{h} {list}:\n{s}");
            // The cursor heading ("STHT at 4.6 Hz", no unit) ends where
            // the first variant's value there ends.
            let lines: Vec<&str> = s.lines().collect();
            let at = lines.iter().position(|l| l.contains("STHT at "));
            // Too narrow for the cursor's column: its values on a line of
            // their own (the reviewer's case, 75,75 at 80x24, has room).
            let Some(i) = at else {
                assert!(w < 80 || list == "5%", "{w}x{h} {list}:\n{s}");
                continue;
            };
            let end = |l: &str, pat: &str| {
                let b = l.find(pat).expect("in the line");
                let b = b + l[b..].find(" Hz").expect("Hz") + 3;
                l[..b].chars().count()
            };
            let v = crate::view::format::num(
                tab(&a).cursor.at[0].expect("a response").mag(biodyn::Function::Stht),
                4,
            );
            let row = lines[i + 1];
            let b = row.find(&format!(" {v} ")).expect("the value");
            let row_end = row[..b + 1 + v.len()].chars().count();
            assert_eq!(end(lines[i], "STHT at "), row_end, "{w}x{h} {list}:\n{s}");
        }
    }
}
