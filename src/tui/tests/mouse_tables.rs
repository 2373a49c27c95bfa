//! The mouse on the Model tab (and the helpers of mouse_vibration.rs),
//! through the real `update` with crossterm mouse events: where to click
//! is read off the drawn screen (not from the tabs' own geometry), and
//! what a click did is read off the tab's state, the open field and the
//! screen again.

use super::*;
use crate::tui::popups::field::Purpose;
use crate::tui::tabs::model::ModelTab;
use crate::tui::tabs::vibration::VibrationTab;
use crate::view::format::num;
use biodyn::Param;
use ratatui::crossterm::event::{MouseButton, MouseEventKind};
use ratatui::style::Modifier;

pub(super) fn click(a: &mut App, column: u16, row: u16) {
    mouse(a, MouseEventKind::Down(MouseButton::Left), column, row);
}

/// Two presses at one cell: the app reads the second as a double click.
pub(super) fn double(a: &mut App, column: u16, row: u16) {
    click(a, column, row);
    click(a, column, row);
}

pub(super) fn wheel(a: &mut App, down: bool, column: u16, row: u16) {
    let kind = if down {
        MouseEventKind::ScrollDown
    } else {
        MouseEventKind::ScrollUp
    };
    mouse(a, kind, column, row);
}

fn model(a: &App) -> &ModelTab {
    a.tab_state().expect("model tab")
}

pub(super) fn vibration(a: &App) -> &VibrationTab {
    a.tab_state().expect("vibration tab")
}

/// The app at `w`×`h` on tab `tab` with mouse capture on.
pub(super) fn on(tab: char, w: u16, h: u16) -> App {
    let mut a = app();
    update(&mut a, Msg::Resize(w, h));
    key(&mut a, KeyCode::Char(tab));
    key(&mut a, KeyCode::Char('M'));
    assert!(a.mouse);
    a
}

pub(super) fn lines(a: &App) -> Vec<String> {
    let (w, h) = a.size.expect("size");
    screen(a, w, h).lines().map(str::to_string).collect()
}

/// The cell (column, row) where `text` starts on the first screen line
/// that contains `on_line` and `text`, left of column `before`.
pub(super) fn find(a: &App, on_line: &str, text: &str, before: u16) -> Option<(u16, u16)> {
    lines(a).iter().enumerate().find_map(|(y, l)| {
        let cut: String = l.chars().take(usize::from(before)).collect();
        if !cut.contains(on_line) {
            return None;
        }
        // The value after the row's label, so "5.625" is not found in a name.
        let from = cut.find(on_line)? + on_line.len();
        let i = cut[from..].find(text)? + from;
        Some((cut[..i].chars().count() as u16, y as u16))
    })
}

/// The screen cells drawn in reverse video below the tab bar: the
/// selection (one cell, or a settings row's value).
pub(super) fn highlighted(a: &App) -> Vec<(u16, u16)> {
    let (w, h) = a.size.expect("size");
    let mut t = Terminal::new(TestBackend::new(w, h)).expect("backend");
    t.draw(|f| super::super::draw(f, a)).expect("draw");
    let buf = t.backend().buffer().clone();
    let mut out = Vec::new();
    for y in 1..h.saturating_sub(2) {
        for x in 0..w {
            if buf[(x, y)].modifier.contains(Modifier::REVERSED) {
                out.push((x, y));
            }
        }
    }
    out
}

fn param_field(a: &App) -> Option<(Param, String)> {
    a.field.as_ref().and_then(|f| match f.purpose {
        Purpose::Param(p) => Some((p, f.text.clone())),
        _ => None,
    })
}

/// Every value the Model tab shows in its tables, as (row, col, row's
/// label on screen, the value as drawn): what a click on it must select.
fn model_cells(a: &App) -> Vec<(usize, usize, String, String)> {
    let b = &a.shared.body;
    let n = b.segments.len();
    let mut out = vec![(
        0,
        0,
        "body mass".to_string(),
        num(b.get(Param::BodyMass), 5),
    )];
    // A name with the spaces around it: "segment " is not "segment2".
    for (i, s) in b.segments.iter().enumerate() {
        let label = format!(" {} ", s.name);
        out.push((i + 1, 0, label.clone(), num(s.mass, 5)));
        if let Some(sh) = s.share {
            out.push((i + 1, 1, label, format!("{}%", num(sh * 100.0, 3))));
        }
    }
    for (i, l) in b.links.iter().enumerate() {
        let label = format!(" {} ", l.name);
        out.push((1 + n + i, 0, label.clone(), num(l.k, 6)));
        out.push((1 + n + i, 1, label, num(l.c, 6)));
    }
    out
}

/// The left edge of the side panels (the tables end before it).
fn tables_end(a: &App) -> u16 {
    let l = &lines(a)[1];
    l.find("┐┌").map_or(a.size.expect("size").0, |i| {
        l[..i].chars().count() as u16 + 1
    })
}

/// The paper's model with `more` segments added by `a` (each hung on the
/// last, with its link): a table taller than the screen.
fn grown(w: u16, h: u16, more: usize) -> App {
    let mut a = on('1', w, h);
    for _ in 0..more {
        key(&mut a, KeyCode::Char('a'));
        key(&mut a, KeyCode::Enter);
        assert!(a.field.is_none(), "{:?}", a.field);
    }
    key(&mut a, KeyCode::Home);
    a
}

#[test]
fn a_click_on_any_model_value_selects_it_under_the_pointer_at_every_size() {
    for (w, h, more) in [
        (60, 16, 0),
        (80, 24, 0),
        (100, 30, 0),
        (160, 48, 0),
        (200, 60, 0),
        (80, 24, 10),
        (60, 16, 10),
    ] {
        for start in [KeyCode::Home, KeyCode::End, KeyCode::PageDown] {
            let mut a = grown(w, h, more);
            key(&mut a, start);
            if start == KeyCode::PageDown {
                // Back up a little: the view was left scrolled, the selection mid-table.
                key(&mut a, KeyCode::Up);
                key(&mut a, KeyCode::Up);
                key(&mut a, KeyCode::Up);
            }
            let end = tables_end(&a);
            // The values on screen, where they are drawn.
            let shown: Vec<_> = model_cells(&a)
                .into_iter()
                .filter_map(|(row, col, label, value)| {
                    let at = find(&a, &label, &value, end)?;
                    Some((at, row, col, label, value))
                })
                .collect();
            let before = lines(&a);
            for (i, ((x, y), row, col, label, value)) in shown.iter().enumerate() {
                // Each glyph of the value, each time from another value
                // selected first, so a click beside a value cannot pass
                // for a click on it.
                let ((ax, ay), arow, acol, ..) = &shown[(i + 1) % shown.len()];
                for dx in 0..value.chars().count() as u16 {
                    click(&mut a, *ax, *ay);
                    assert_eq!((model(&a).row, model(&a).col), (*arow, *acol));
                    click(&mut a, x + dx, *y);
                    let t = model(&a);
                    assert_eq!(
                        (t.row, t.col),
                        (*row, *col),
                        "{w}x{h} {label} {value} +{dx}"
                    );
                    assert_eq!(lines(&a), before, "{w}x{h}: a click scrolled the table");
                    assert!(highlighted(&a).contains(&(x + dx, *y)), "{w}x{h} {label}");
                }
            }
            let clicked = shown.len();
            // Every value of the 4-segment model fits from 80×24 on; at
            // 60×16, or with 10 more segments, the table scrolls: what shows.
            let all = model_cells(&a).len();
            let rows_shown = usize::from(h) - 5 - 4;
            assert!(
                clicked == all || ((w == 60 || more > 0) && clicked >= rows_shown),
                "{w}x{h}+{more}: {clicked}/{all}"
            );
        }
    }
}

#[test]
fn clicks_on_the_model_tab_outside_values_change_nothing() {
    for (w, h) in [(80, 24), (160, 48)] {
        let mut a = on('1', w, h);
        key(&mut a, KeyCode::Down);
        key(&mut a, KeyCode::Down);
        let want = (model(&a).row, model(&a).col);
        let screen_before = lines(&a);
        let end = tables_end(&a);
        // The headings, blank lines, footnote, frame and the side panels.
        let l = &screen_before;
        let mut spots = Vec::new();
        for (y, line) in l.iter().enumerate().skip(1).take(usize::from(h) - 3) {
            let is_row = line.contains("m1 ")
                || line.contains("m2 ")
                || line.contains("m3 ")
                || line.contains("m4 ")
                || line.contains("body mass")
                || line.contains("-seat")
                || line.contains("-chest")
                || line.contains("-torso")
                || line.contains("-pelvis");
            if !is_row {
                spots.extend([(2, y as u16), (end / 2, y as u16)]);
            }
            // The side panels, on every line.
            if end + 3 < w {
                spots.push((end + 3, y as u16));
            }
        }
        spots.push((0, 5)); // the frame
        assert!(spots.len() > 20);
        for (x, y) in spots {
            double(&mut a, x, y);
            assert_eq!((model(&a).row, model(&a).col), want, "{w}x{h} at {x},{y}");
            assert!(a.field.is_none(), "{w}x{h} at {x},{y}: {:?}", a.field);
            assert_eq!(
                lines(&a)[1..usize::from(h) - 2],
                screen_before[1..usize::from(h) - 2]
            );
        }
    }
}

#[test]
fn a_double_click_edits_the_model_value_as_enter_does() {
    for (w, h) in [(80, 24), (160, 48)] {
        let mut a = on('1', w, h);
        let end = tables_end(&a);
        // k4, the pelvis–seat stiffness: the same field Enter opens.
        let (x, y) = find(&a, "4  pelvis-seat", "90000", end).expect("k4 shown");
        double(&mut a, x + 2, y);
        assert_eq!(
            param_field(&a),
            Some((Param::Stiffness(3), "90000".to_string()))
        );
        let mut b = on('1', w, h);
        key(&mut b, KeyCode::End);
        key(&mut b, KeyCode::Enter);
        assert_eq!(a.field, b.field, "the field Enter opens");
        // Typing replaces the value; refused values keep the field open.
        typ(&mut a, "-5");
        key(&mut a, KeyCode::Enter);
        assert!(a.field.as_ref().and_then(|f| f.error.as_ref()).is_some());
        key(&mut a, KeyCode::Esc);
        double(&mut a, x + 2, y);
        typ(&mut a, "95000");
        key(&mut a, KeyCode::Enter);
        assert!(a.field.is_none(), "{:?}", a.field);
        assert_eq!(a.shared.body.links[3].k, 95000.0);
        // The same undo step as a typed edit.
        key(&mut a, KeyCode::Char('u'));
        assert_eq!(a.shared.body.links[3].k, 90000.0);
        assert!(a.status.text.contains("undid"), "{}", a.status.text);

        // The body mass, the share of m2 (its own field), c1.
        let (x, y) = find(&a, "body mass", "75", end).expect("body mass");
        double(&mut a, x, y);
        assert_eq!(param_field(&a), Some((Param::BodyMass, "75".to_string())));
        key(&mut a, KeyCode::Esc);
        let (x, y) = find(&a, "m2 chest", "40.2%", end).expect("share");
        double(&mut a, x, y);
        let f = a.field.as_ref().expect("share field");
        assert!(
            f.label.contains("share") && f.label.contains("chest"),
            "{}",
            f.label
        );
        key(&mut a, KeyCode::Esc);
        let (x, y) = find(&a, "1  head-neck-chest", "400", end).expect("c1");
        double(&mut a, x, y);
        assert_eq!(
            param_field(&a),
            Some((Param::Damping(0), "400".to_string()))
        );

        // While the field is open, clicks and the wheel act on nothing behind it.
        let (mx, my) = find(&a, "m3 lower-torso", "9.15", end).expect("m3");
        let sel = (model(&a).row, model(&a).col);
        double(&mut a, mx, my);
        wheel(&mut a, true, mx, my);
        assert_eq!((model(&a).row, model(&a).col), sel);
        assert_eq!(
            param_field(&a),
            Some((Param::Damping(0), "400".to_string()))
        );
        key(&mut a, KeyCode::Esc);

        // A double click on a name renames it (as r).
        let (x, y) = find(&a, "│", "m3 lower-torso", end).expect("m3 name");
        double(&mut a, x + 4, y);
        let f = a.field.as_ref().expect("rename field");
        assert_eq!(f.text, "lower-torso");
        assert!(f.label.contains("rename segment m3"), "{}", f.label);
        key(&mut a, KeyCode::Esc);
    }
}

#[test]
fn the_wheel_moves_the_model_selection_and_scrolls_a_tall_table() {
    let mut a = on('1', 60, 16);
    let (x, y) = (20, 8);
    assert_eq!(model(&a).row, 0);
    wheel(&mut a, false, x, y);
    assert_eq!(model(&a).row, 0, "no wrap at the top");
    for want in 1..=8 {
        wheel(&mut a, true, x, y);
        assert_eq!(model(&a).row, want);
        // The selected cell is always drawn.
        assert!(highlighted(&a).len() > 1, "row {want}");
    }
    wheel(&mut a, true, x, y);
    assert_eq!(model(&a).row, 8, "no wrap at the bottom");
    // The last link shows; the body mass row scrolled away.
    let s = lines(&a).join("\n");
    assert!(s.contains("pelvis-seat") && !s.contains("body mass"), "{s}");
    // Click c4 on the scrolled table, then double-click m2: both land.
    let end = tables_end(&a);
    let (cx, cy) = find(&a, "4  pelvis-seat", "2064", end).expect("c4");
    click(&mut a, cx, cy);
    assert_eq!((model(&a).row, model(&a).col), (8, 1));
    let (mx, my) = find(&a, "m2 chest", "30.15", end).expect("m2 shown");
    double(&mut a, mx, my);
    assert_eq!(param_field(&a), Some((Param::Mass(1), "30.15".to_string())));
    key(&mut a, KeyCode::Esc);
    // Back up: the view follows to the body mass row.
    for _ in 0..10 {
        wheel(&mut a, false, x, y);
    }
    assert_eq!(model(&a).row, 0);
    assert!(lines(&a).join("\n").contains("body mass"));
    // The wheel over the side panels (80×24) does nothing.
    let mut b = on('1', 80, 24);
    wheel(&mut b, true, 60, 5);
    assert_eq!(model(&b).row, 0);
    wheel(&mut b, true, 10, 5);
    assert_eq!(model(&b).row, 1);
}

#[test]
fn the_delete_question_and_a_zoomed_chart_take_no_clicks() {
    let mut a = on('1', 80, 24);
    let end = tables_end(&a);
    let (x, y) = find(&a, "m2 chest", "30.15", end).expect("m2");
    click(&mut a, x, y);
    key(&mut a, KeyCode::Char('d'));
    assert!(model(&a).pending.is_some());
    let (kx, ky) = find(&a, "4  pelvis-seat", "90000", end).expect("k4");
    double(&mut a, kx, ky);
    assert!(model(&a).pending.is_some(), "the question stays");
    assert_eq!(model(&a).row, 2);
    assert!(a.field.is_none());
    assert!(
        a.status.text.contains("answer the delete question"),
        "{}",
        a.status.text
    );
    key(&mut a, KeyCode::Char('n'));
    assert!(model(&a).pending.is_none());
    // The help page over the tab: a click selects nothing behind it.
    key(&mut a, KeyCode::Char('?'));
    double(&mut a, kx, ky);
    assert_eq!(model(&a).row, 2);
    assert!(a.field.is_none());
    key(&mut a, KeyCode::Esc);
    // z: the STHT chart alone; a click there selects nothing.
    key(&mut a, KeyCode::Char('z'));
    assert!(a.zoom);
    double(&mut a, x, y);
    assert_eq!(model(&a).row, 2);
    assert!(a.field.is_none());
}

#[test]
fn on_a_model_of_plain_masses_the_selection_never_rests_on_a_missing_share() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/presets/boileau-rakheja-1998.toml"
    );
    let p = biodyn::Preset::open(path).expect("preset");
    let mut a = App::new(p, None, Theme::default());
    update(&mut a, Msg::Resize(80, 24));
    key(&mut a, KeyCode::Char('M'));
    assert!(a.shared.body.body_mass.is_none());
    let n = a.shared.body.segments.len();
    // c of the first link, then ↑ onto the last segment: its mass, not a
    // share it does not have (Enter used to open a share field there).
    key(&mut a, KeyCode::End);
    for _ in 1..a.shared.body.links.len() {
        key(&mut a, KeyCode::Up);
    }
    key(&mut a, KeyCode::Right);
    assert_eq!(model(&a).col, 1);
    key(&mut a, KeyCode::Up);
    assert_eq!((model(&a).row, model(&a).col), (n, 0));
    key(&mut a, KeyCode::Enter);
    assert_eq!(param_field(&a).map(|(p, _)| p), Some(Param::Mass(n - 1)));
    key(&mut a, KeyCode::Esc);
    assert!(highlighted(&a).len() > 1, "the selected mass is drawn");
    // The wheel does the same from a c cell; right of a mass (no share
    // column) a click selects nothing.
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Right);
    assert_eq!(model(&a).col, 1);
    wheel(&mut a, false, 10, 8);
    assert_eq!((model(&a).row, model(&a).col), (n, 0));
    let end = tables_end(&a);
    let name = a.shared.body.segments[0].name.clone();
    let mass = num(a.shared.body.segments[0].mass, 5);
    let (x, y) = find(&a, &format!(" {name} "), &mass, end).expect("m1 mass");
    let after = x + mass.chars().count() as u16;
    double(&mut a, after + 3, y);
    assert_eq!((model(&a).row, model(&a).col), (n, 0));
    assert!(a.field.is_none());
    double(&mut a, x, y);
    assert_eq!(param_field(&a).map(|(p, _)| p), Some(Param::Mass(0)));
}
