//! The status area never cuts a message (issue 19 item 17): a message
//! longer than the line wraps and the area grows (at least 2 rows, at most
//! a quarter of the screen), the tab's area shrinks by as much, and the
//! mouse hit tests use the same layout. The Vibration tab's "computing …
//! %" fits its panel.

use super::*;
use crate::tui::tabs::vibration::VibrationTab;

/// The screen's rows between the body and the hint bar, joined by spaces.
fn status_text(s: &str, rows: usize) -> String {
    let lines: Vec<&str> = s.lines().collect();
    let n = lines.len();
    lines[n - 1 - rows..n - 1]
        .iter()
        .map(|l| l.trim())
        .collect::<Vec<_>>()
        .join(" ")
}

const LONG: &str = "applied the fitted k2, k3, k4, c3 and c4 of pelvis-seat and chest-lower-torso (u undoes them all; ^S saves the fitted preset)";

#[test]
fn a_long_message_wraps_onto_a_second_line_whole() {
    let mut a = app();
    a.say(LONG);
    for (w, h) in [(80u16, 24u16), (60, 16), (100, 30)] {
        let s = screen(&a, w, h);
        let rows = a.status_rows(w, h).len();
        assert!(rows >= 2, "{w}x{h}: {rows} rows");
        assert_eq!(status_text(&s, rows), LONG, "{w}x{h}:\n{s}");
        // the hint bar is still the last line, whole
        assert!(
            s.lines().last().is_some_and(|l| l.contains("? help")),
            "{s}"
        );
        // the tab gives the status area its extra rows
        assert_eq!(a.body_area(w, h).height, h - 2 - rows as u16);
    }
    // an error alike, with its "error:" in front
    a.fail(LONG);
    let s = screen(&a, 80, 24);
    assert_eq!(status_text(&s, 2), format!("error: {LONG}"), "{s}");
    // a short one keeps one line and the tab its full height
    a.say("k4 = 94500 N/m");
    assert_eq!(a.status_rows(80, 24).len(), 1);
    assert_eq!(a.body_area(80, 24).height, 21);
}

#[test]
fn the_vibration_export_message_is_shown_whole() {
    let dir = tempfile::tempdir().expect("tempdir");
    let mut a = app();
    key(&mut a, KeyCode::Char('5'));
    key(&mut a, KeyCode::Char('x'));
    let path = dir
        .path()
        .join("paper-75kg-vibration-of-the-morning-shift.csv");
    if let Some(f) = a.field.as_mut() {
        f.set_text(path.display().to_string());
    }
    key(&mut a, KeyCode::Enter);
    assert!(a.status.text.starts_with("exported"), "{:?}", a.status);
    assert!(a.status.text.chars().count() > 80, "{}", a.status.text);
    let rows = a.status_rows(80, 24).len();
    let s = screen(&a, 80, 24);
    let shown = status_text(&s, rows);
    assert_eq!(shown, a.status.text, "{s}");
    assert!(
        shown.ends_with("(what biodyn simulate --format csv prints)"),
        "{s}"
    );
}

/// A click on the status area's second row (the body's last row while
/// the status takes one) moves no cursor: the mouse sees the frame's layout.
#[test]
fn a_click_on_the_grown_status_area_reaches_no_tab() {
    let mut a = app();
    update(&mut a, Msg::Resize(80, 24));
    key(&mut a, KeyCode::Char('2'));
    key(&mut a, KeyCode::Char('M'));
    let cursor = |a: &App| responses(a).cursor;
    let at = cursor(&a);
    a.say(LONG);
    let body = a.body_area(80, 24);
    assert_eq!(body.bottom(), 21, "{body:?}");
    for row in [21u16, 22] {
        for column in [10u16, 40, 70] {
            mouse(
                &mut a,
                ratatui::crossterm::event::MouseEventKind::Down(
                    ratatui::crossterm::event::MouseButton::Left,
                ),
                column,
                row,
            );
            assert_eq!(cursor(&a), at, "a click at {column},{row} moved the cursor");
        }
    }
    // the body's last row still takes clicks (the APMS chart's)
    mouse(
        &mut a,
        ratatui::crossterm::event::MouseEventKind::Down(
            ratatui::crossterm::event::MouseButton::Left,
        ),
        70,
        body.bottom() - 3,
    );
    assert_ne!(cursor(&a), at, "{}", screen(&a, 80, 24));
}

#[test]
fn computing_with_its_percentage_fits_the_settings_panel() {
    let mut a = app();
    key(&mut a, KeyCode::Char('5'));
    let t = a
        .tabs
        .iter_mut()
        .find_map(|t| (t.as_mut() as &mut dyn std::any::Any).downcast_mut::<VibrationTab>())
        .expect("vibration tab");
    t.running = true;
    t.progress = Some((42, Some(100)));
    let s = screen(&a, 80, 24);
    assert!(s.contains("computing… 42 %"), "{s}");
    let s = screen(&a, 160, 48);
    assert!(s.contains("computing in the background… 42 %"), "{s}");
}

/// A running training's summary follows a short message on its line, and
/// takes a row of its own under a message that fills the line.
#[test]
fn a_running_jobs_summary_follows_the_message() {
    let (mut a, _rx) = super::training_runs::channel_app();
    super::training_runs::backprop(&mut a);
    super::training_runs::set(&mut a, "epoch limit", "1000000");
    key(&mut a, KeyCode::Char('t'));
    assert!(training(&a).running(), "{}", a.status.text);
    a.say("k4 = 94500 N/m");
    let rows = a.status_rows(80, 24);
    assert_eq!(rows.len(), 1, "{rows:?}");
    assert!(rows[0].1.starts_with("  │ training"), "{rows:?}");
    let s = screen(&a, 80, 24);
    assert!(s.contains(" k4 = 94500 N/m  │ training"), "{s}");
    // a long message: whole, and the summary once, beside its last row
    // where that fits, else on a row of its own
    a.say(LONG);
    for (w, h) in [(80u16, 24u16), (60, 16), (100, 30)] {
        let rows = a.status_rows(w, h);
        let said: Vec<&str> = rows
            .iter()
            .map(|(m, _)| m.trim())
            .filter(|m| !m.is_empty())
            .collect();
        assert_eq!(said.join(" "), LONG, "{w}x{h}");
        let with: Vec<&(String, String)> = rows.iter().filter(|(_, s)| !s.is_empty()).collect();
        assert_eq!(with.len(), 1, "{w}x{h}: {rows:?}");
        let (m, sum) = with[0];
        assert!(
            std::ptr::eq(with[0], rows.last().expect("rows")),
            "{rows:?}"
        );
        if m.is_empty() {
            assert!(sum.starts_with(" training"), "{rows:?}");
        } else {
            assert!(sum.starts_with("  │ training"), "{rows:?}");
        }
        assert!(
            rows.iter()
                .all(|(m, s)| m.chars().count() + s.chars().count() <= usize::from(w))
        );
    }
    // at 60x8 rows' worth of cap (2): the summary row gives way first
    a.say(&LONG[..100]);
    let rows = a.status_rows(60, 8);
    assert_eq!(rows.len(), 2, "{rows:?}");
    assert!(rows.iter().all(|(m, _)| !m.is_empty()), "{rows:?}");
    a.shutdown();
}
