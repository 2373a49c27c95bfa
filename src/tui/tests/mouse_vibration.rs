//! The mouse on the Vibration tab through the real `update`: the settings
//! panel (select, edit, step the kind, the wheel, scrolling at 60×16) and
//! the traces (the wheel zooms about the pointer, a click centres), with
//! where to click read off the drawn screen.

use super::mouse_tables::{click, double, find, highlighted, lines, on, vibration, wheel};
use super::*;
use crate::tui::tabs::vibration::settings::Row;
use crate::view::format::num;

/// The settings row whose label starts the line, its screen (column, row).
fn setting(a: &App, label: &str) -> Option<(u16, u16)> {
    find(a, "│", &format!("{label} "), 40).map(|(x, y)| (x + 1, y))
}

#[test]
fn vibration_settings_select_edit_and_step_with_the_mouse() {
    for (w, h) in [(80, 24), (160, 48)] {
        let mut a = on('5', w, h);
        let rows = vibration(&a).rows();
        let amp = rows
            .iter()
            .position(|&r| r == Row::Param(0, "amp"))
            .expect("amp row");
        let (x, y) = setting(&a, "amp").expect("amp shown");
        click(&mut a, x, y);
        assert_eq!(vibration(&a).sel, amp);
        assert!(a.field.is_none());
        // Right of the text, on the same row, selects it too.
        let (fx, fy) = setting(&a, "fs").expect("fs shown");
        click(&mut a, fx + 25, fy);
        assert_eq!(rows.get(vibration(&a).sel), Some(&Row::Fs));
        // A double click opens the row's field, as Enter.
        double(&mut a, x + 10, y);
        let f = a.field.as_ref().expect("amp field");
        assert_eq!(f.text, "5");
        assert!(f.label.contains("amp"), "{}", f.label);
        // Nothing behind the field takes a click.
        click(&mut a, fx, fy);
        assert_eq!(vibration(&a).sel, amp);
        typ(&mut a, "2");
        key(&mut a, KeyCode::Enter);
        assert!(a.field.is_none(), "{:?}", a.field);
        let spec = vibration(&a).settings.signal().map(|s| s.to_string());
        assert_eq!(spec.as_deref(), Some("sine:freq=5,amp=2"));

        // ▶ and ◀ step the kind as → and ←; a double click on the
        // signal row steps it too.
        let l = lines(&a);
        let (y, line) = l
            .iter()
            .enumerate()
            .find(|(_, l)| l.contains('▶'))
            .expect("▶");
        let right = line[..line.find('▶').expect("▶")].chars().count() as u16;
        click(&mut a, right, y as u16);
        assert_eq!(vibration(&a).settings.kind_label(), "sweep");
        let l = lines(&a);
        let line = &l[y];
        let left = line[..line.find('◀').expect("◀")].chars().count() as u16;
        click(&mut a, left, y as u16);
        assert_eq!(vibration(&a).settings.kind_label(), "sine");
        let (sx, sy) = setting(&a, "signal").expect("signal row");
        double(&mut a, sx, sy);
        assert_eq!(vibration(&a).settings.kind_label(), "sweep");
        assert!(a.field.is_none());

        // The wheel over the settings moves the selection, no wrap.
        key(&mut a, KeyCode::Char('1'));
        key(&mut a, KeyCode::Char('5'));
        let n = vibration(&a).rows().len();
        let (sx, sy) = setting(&a, "signal").expect("signal row");
        click(&mut a, sx, sy);
        wheel(&mut a, false, sx, sy);
        assert_eq!(vibration(&a).sel, 0);
        for _ in 0..n + 2 {
            wheel(&mut a, true, sx, sy);
        }
        assert_eq!(vibration(&a).sel, n - 1);
    }
}

#[test]
fn vibration_settings_scroll_at_the_minimum_size_and_clicks_land() {
    let mut a = on('5', 60, 16);
    // "mouse on: …" takes two status rows at 60 columns (and one from the
    // panel) while it shows: this test is about the panel's own scrolling.
    a.hush();
    let n = vibration(&a).rows().len();
    assert!(
        setting(&a, "spine").is_none(),
        "the list is taller than the panel"
    );
    let (x, y) = setting(&a, "signal").expect("signal row");
    for _ in 0..n {
        wheel(&mut a, true, x, y);
    }
    assert_eq!(vibration(&a).sel, n - 1);
    // The selected row is drawn: the list scrolled.
    let (ex, ey) = setting(&a, "spine").expect("the last row, spine, scrolled into view");
    assert!(highlighted(&a).iter().any(|&(_, hy)| hy == ey));
    // A click on a row of the scrolled list selects it without scrolling;
    // a double click edits that row.
    let before = lines(&a);
    let (fx, fy) = setting(&a, "freq").expect("freq still shown");
    click(&mut a, fx, fy);
    assert_eq!(
        vibration(&a).rows()[vibration(&a).sel],
        Row::Param(0, "freq")
    );
    assert_eq!(lines(&a)[..14], before[..14]);
    double(&mut a, ex, ey);
    let f = a.field.as_ref().expect("spine field");
    assert_eq!(f.text, "age=25,years=10,days=240,sex=male");
    key(&mut a, KeyCode::Esc);
    // The traces take the right column (the table is on `s`'s third
    // panel), and the wheel zooms them here too.
    let (x0, pw, y) = seat_plot(&a);
    assert!(pw >= 16, "{pw}");
    wheel(&mut a, false, x0 + pw / 2, y);
    assert_eq!(vibration(&a).zoom, 1);
    assert!(!lines(&a).join("\n").contains("crest factor"));
    key(&mut a, KeyCode::Char('s'));
    key(&mut a, KeyCode::Char('s'));
    assert!(lines(&a).join("\n").contains("crest factor"));
}

/// The plot's columns of the seat trace: right of its `│` axis line, as
/// wide as the braille it draws (read off the screen).
fn seat_plot(a: &App) -> (u16, u16, u16) {
    let l = lines(a);
    let (y, line) = l
        .iter()
        .enumerate()
        .find(|(_, l)| l.contains("seat, "))
        .expect("seat chart");
    // The y label and axis on the line below the title: "10┤".
    let below = &l[y + 1];
    let chart_x = line[..line.find("seat, ").expect("title")].chars().count();
    let axis = below
        .chars()
        .skip(chart_x)
        .position(|c| c == '│' || c == '┤')
        .expect("axis")
        + chart_x;
    // The x axis under the plot: └ below the │, then ─ as wide as the plot.
    let w = l[y + 1..]
        .iter()
        .map(|l| l.chars().skip(axis).collect::<String>())
        .find(|l| l.starts_with('└'))
        .expect("x axis")
        .chars()
        .skip(1)
        .take_while(|&c| c == '─' || c == '┬')
        .count();
    ((axis + 1) as u16, w as u16, (y + 2) as u16)
}

#[test]
fn the_wheel_zooms_the_traces_about_the_pointer_and_a_click_centres() {
    for (w, h) in [(80, 24), (160, 48)] {
        let mut a = on('5', w, h);
        let total = vibration(&a).outcome().expect("run").traces.duration();
        assert!((total - 10.0).abs() < 1e-9);
        let (x0, pw, y) = seat_plot(&a);
        // At the whole record a click says how to zoom; nothing moves.
        click(&mut a, x0 + pw / 2, y);
        assert_eq!(vibration(&a).zoom, 0);
        assert!(a.status.text.contains("wheel"), "{}", a.status.text);
        // The wheel at a quarter of the plot: 2.5 s stays under the pointer.
        let c = pw / 4;
        let t_at = (f64::from(c) + 0.5) / f64::from(pw) * total;
        wheel(&mut a, false, x0 + c, y);
        assert_eq!(vibration(&a).zoom, 1);
        let (start, len) = vibration(&a).window(total);
        assert!((len - total / 2.0).abs() < 1e-9);
        let under = start + (f64::from(c) + 0.5) / f64::from(pw) * len;
        assert!((under - t_at).abs() < 1e-9, "{under} vs {t_at}");
        // The x labels follow: the window's start is drawn at the left.
        let s = lines(&a).join("\n");
        assert!(s.contains(&num(start, 5)), "{s}");
        // A click at three quarters centres the window there (the plot
        // moved: the first time label is wider now).
        let (x0, pw, y) = seat_plot(&a);
        let c = 3 * pw / 4;
        let t_click = start + (f64::from(c) + 0.5) / f64::from(pw) * len;
        click(&mut a, x0 + c, y);
        let (start2, len2) = vibration(&a).window(total);
        assert!(
            (start2 + len2 / 2.0 - t_click).abs() < 1e-9,
            "{start}+{len} click at {t_click}: {start2}+{len2}, {}",
            lines(&a).join("\n")
        );
        assert!(a.status.text.contains("centred on"), "{}", a.status.text);
        // The wheel down zooms out; at the whole record it stays.
        wheel(&mut a, true, x0 + 1, y);
        wheel(&mut a, true, x0 + 1, y);
        assert_eq!(vibration(&a).zoom, 0);
        // Left of the plot (the y labels) is no time.
        wheel(&mut a, false, x0.saturating_sub(3), y);
        assert_eq!(vibration(&a).zoom, 0);
        // Zoomed (z), the traces fill the tab and the wheel zooms them.
        key(&mut a, KeyCode::Char('z'));
        let (zx, zw, zy) = seat_plot(&a);
        assert!(zw > pw, "{zw} vs {pw}");
        wheel(&mut a, false, zx + zw / 2, zy);
        assert_eq!(vibration(&a).zoom, 1);
        wheel(&mut a, true, zx + zw / 2, zy);
        key(&mut a, KeyCode::Char('z'));
        assert!(!a.zoom);
        // The assessment table takes nothing.
        let l = lines(&a);
        let ty = l
            .iter()
            .position(|l| l.contains("crest factor"))
            .expect("table") as u16;
        let sel = vibration(&a).sel;
        double(&mut a, w - 10, ty);
        wheel(&mut a, true, w - 10, ty);
        assert_eq!((vibration(&a).sel, vibration(&a).zoom), (sel, 0));
        assert!(a.field.is_none());
    }
}
