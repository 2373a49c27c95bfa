//! The Study tab's frequency cursor through the real `update`: keys that
//! step it along the grid, `g` to an exact frequency, a click on a chart,
//! and the readout in the legend, every value checked against the
//! library's Solver on a body built here (not the study's own variant),
//! at the cursor's exact frequency. Snapshots at 80×24 and 160×48.

use super::StudyTab;
use super::cursor::round4;
use super::layout::layout;
use super::view;
use crate::tui::app::App;
use crate::tui::event::Msg;
use crate::tui::tests::{app, key, screen, typ};
use crate::tui::update::update;
use crate::view::chart;
use crate::view::format::num;
use biodyn::{Body, Function, Param, Solver};
use ratatui::crossterm::event::{KeyCode, KeyModifiers, MouseButton, MouseEvent, MouseEventKind};
use ratatui::layout::Rect;

fn tab(a: &App) -> &StudyTab {
    a.tab_state().expect("study tab")
}

fn on_tab(w: u16, h: u16) -> App {
    let mut a = app();
    update(&mut a, Msg::Resize(w, h));
    key(&mut a, KeyCode::Char('3'));
    a
}

fn f_hz(a: &App) -> f64 {
    tab(a).cursor.f_hz.expect("a cursor")
}

fn ch(a: &mut App, c: char) {
    key(a, KeyCode::Char(c));
}

fn click(a: &mut App, column: u16, row: u16) {
    update(
        a,
        Msg::Mouse(MouseEvent {
            kind: MouseEventKind::Down(MouseButton::Left),
            column,
            row,
            modifiers: KeyModifiers::NONE,
        }),
    );
}

/// The body of the paper's study at `kg`, built here from the preset.
fn body_at(a: &App, kg: f64) -> Body {
    let mut b = a.shared.saved.clone();
    b.set(Param::BodyMass, kg).expect("a body mass");
    b
}

/// The cursor's values are the Solver's at its frequency on each
/// variant's body (65, 75, 85 kg), to the last bits.
fn check_values(a: &App, bodies: &[Body]) {
    let t = tab(a);
    let f = f_hz(a);
    assert_eq!(t.cursor.at.len(), bodies.len());
    for (got, body) in t.cursor.at.iter().zip(bodies) {
        let want = Solver::new(body).at(f);
        let got = got.expect("a value");
        assert_eq!(got.f_hz, f);
        for fun in Function::ALL {
            let (g, w) = (got.mag(fun), want.mag(fun));
            assert!((g - w).abs() <= 1e-12 * w.abs(), "{fun:?} at {f}: {g} vs {w}");
        }
    }
}

#[test]
fn keys_step_the_cursor_along_the_grid_and_g_goes_exactly() {
    let mut a = on_tab(80, 24);
    let bodies: Vec<Body> = [65.0, 75.0, 85.0].iter().map(|&m| body_at(&a, m)).collect();
    // It starts on the middle variant's STHT peak (75 kg: 4.561 Hz), on the grid.
    assert_eq!(f_hz(&a), 4.6);
    check_values(&a, &bodies);
    ch(&mut a, '>');
    assert_eq!(f_hz(&a), 4.7);
    ch(&mut a, '.');
    assert_eq!(f_hz(&a), 4.8);
    ch(&mut a, '<');
    ch(&mut a, ',');
    assert_eq!(f_hz(&a), 4.6);
    key(&mut a, KeyCode::PageDown);
    assert_eq!(f_hz(&a), 5.6);
    key(&mut a, KeyCode::PageUp);
    key(&mut a, KeyCode::PageUp);
    assert_eq!(f_hz(&a), 3.6);
    key(&mut a, KeyCode::Home);
    assert_eq!(f_hz(&a), 0.5);
    ch(&mut a, '<');
    assert_eq!(f_hz(&a), 0.5, "stays at the band start");
    key(&mut a, KeyCode::End);
    assert_eq!(f_hz(&a), 20.0);
    ch(&mut a, '>');
    assert_eq!(f_hz(&a), 20.0, "stays at the band end");
    check_values(&a, &bodies);

    // g: the exact frequency typed, every variant computed there.
    ch(&mut a, 'g');
    assert!(a.field.is_some());
    typ(&mut a, "7.123 Hz");
    key(&mut a, KeyCode::Enter);
    assert!(a.field.is_none(), "{:?}", a.field);
    assert_eq!(f_hz(&a), 7.123);
    check_values(&a, &bodies);
    let s = screen(&a, 80, 24);
    assert!(s.contains("STHT at 7.123 Hz"), "{s}");
    for (i, r) in tab(&a).cursor.at.iter().enumerate() {
        let v = num(r.expect("value").mag(Function::Stht), 4);
        let row = s
            .lines()
            .find(|l| l.contains(&format!("{} kg", 65 + 10 * i)))
            .unwrap_or_else(|| panic!("{s}"));
        assert!(row.contains(&v), "{v} in {row}");
    }
    // Off the grid, a step goes to the grid point beyond in that direction.
    ch(&mut a, '<');
    assert_eq!(f_hz(&a), 7.1);
    ch(&mut a, 'g');
    typ(&mut a, "7.123");
    key(&mut a, KeyCode::Enter);
    ch(&mut a, '>');
    assert_eq!(f_hz(&a), 7.2);

    // Outside the band or not a number: refused in the field, cursor kept.
    for bad in ["25", "abc"] {
        ch(&mut a, 'g');
        typ(&mut a, bad);
        key(&mut a, KeyCode::Enter);
        let err = a.field.as_ref().and_then(|f| f.error.clone());
        assert!(err.is_some(), "{bad}");
        key(&mut a, KeyCode::Esc);
        assert_eq!(f_hz(&a), 7.2);
    }
}

#[test]
fn the_cursor_follows_edits_and_new_value_lists() {
    let mut a = on_tab(80, 24);
    ch(&mut a, 'g');
    typ(&mut a, "6.25");
    key(&mut a, KeyCode::Enter);
    // Another value list: the cursor stays, the values are the new variants'.
    key(&mut a, KeyCode::Enter);
    a.field.as_mut().expect("values field").set_text("60 90");
    key(&mut a, KeyCode::Enter);
    assert_eq!(f_hz(&a), 6.25);
    let bodies: Vec<Body> = [60.0, 90.0].iter().map(|&m| body_at(&a, m)).collect();
    check_values(&a, &bodies);
    // A model edit on tab 1 (k1 up): the variants are rebuilt, and so are
    // the values at the cursor.
    ch(&mut a, '1');
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Down);
    ch(&mut a, '+');
    assert!(a.modified());
    ch(&mut a, '3');
    assert_eq!(f_hz(&a), 6.25);
    let bodies: Vec<Body> = [60.0, 90.0]
        .iter()
        .map(|&m| {
            let mut b = a.shared.body.clone();
            b.set(Param::BodyMass, m).expect("mass");
            b
        })
        .collect();
    check_values(&a, &bodies);
}

#[test]
fn a_click_in_a_chart_moves_the_cursor_there_and_picks_the_function() {
    for (w, h, zoom) in [(160, 48, false), (80, 24, false), (80, 24, true)] {
        let mut a = on_tab(w, h);
        ch(&mut a, 'M');
        if zoom {
            ch(&mut a, 'z');
            assert!(a.zoom);
        }
        let body = Rect::new(0, 1, w, h - 3);
        let t = tab(&a);
        let Some(Ok(study)) = &t.result else {
            panic!("a study")
        };
        let l = layout(t, study, body, zoom);
        let &(fi, cell) = l.charts.last().expect("a chart");
        let (series, opts) =
            view::chart(t, &a.shared, study, fi, l.charts.len() == 1).expect("chart");
        let lay = chart::layout(cell, series, &opts).expect("layout");
        let col = lay.column(12.0, false).expect("12 Hz on the axis");
        let want = round4(lay.x_at(col, false).expect("x"));
        click(&mut a, col, lay.plot.y + 2);
        let f = f_hz(&a);
        assert_eq!(f, want, "{w}x{h}");
        assert!((f - 12.0).abs() < 0.5, "{w}x{h}: {f}");
        assert_eq!(lay.column(f, false), Some(col), "{w}x{h}: the clicked column");
        assert_eq!(tab(&a).func, fi);
        let bodies: Vec<Body> = [65.0, 75.0, 85.0].iter().map(|&m| body_at(&a, m)).collect();
        check_values(&a, &bodies);
        // The wheel still scrolls the legend, not the cursor.
        update(
            &mut a,
            Msg::Mouse(MouseEvent {
                kind: MouseEventKind::ScrollDown,
                column: col,
                row: lay.plot.y + 2,
                modifiers: KeyModifiers::NONE,
            }),
        );
        assert_eq!(tab(&a).legend_top, 1);
        assert_eq!(f_hz(&a), f);
        // The cursor line is drawn in that column (where no curve or
        // legend covers it).
        let s = screen(&a, w, h);
        let lines: Vec<Vec<char>> = s.lines().map(|l| l.chars().collect()).collect();
        let drawn = (lay.plot.y..lay.plot.bottom())
            .filter(|&r| {
                lines.get(usize::from(r)).and_then(|l| l.get(usize::from(col))) == Some(&'│')
            })
            .count();
        assert!(drawn * 2 >= usize::from(lay.plot.height), "{w}x{h} {drawn}\n{s}");
    }
}

#[test]
fn the_readout_in_the_legend_at_both_sizes() {
    let mut a = on_tab(80, 24);
    ch(&mut a, 'g');
    typ(&mut a, "7.5");
    key(&mut a, KeyCode::Enter);
    let s = screen(&a, 80, 24);
    // 80 columns: one chart, one cursor column beside the variant names.
    assert!(s.contains("STHT at 7.5 Hz"), "{s}");
    assert!(!s.contains("DPMI at"), "{s}");
    assert!(s.contains("as body mass rises:"), "{s}");
    assert!(s.contains("band share up/down"), "{s}");
    for (w, h) in [(80, 24), (160, 48)] {
        update(&mut a, Msg::Resize(w, h));
        insta::assert_snapshot!(format!("study_cursor_{w}x{h}"), screen(&a, w, h));
    }
    // 160 columns: every chart shown, a column each.
    let s = screen(&a, 160, 48);
    for f in Function::ALL {
        assert!(s.contains(&format!("{} at 7.5 Hz", f.name())), "{s}");
    }
    let apms = num(
        tab(&a).cursor.at[2].expect("85 kg").mag(Function::Apms),
        4,
    );
    let row = s
        .lines()
        .find(|l| l.contains("body mass = 85 kg") && l.contains("Hz"))
        .expect("the 85 kg row");
    assert!(row.contains(&format!(" {apms} ")), "{row}");
    assert!(s.contains("APMS at 7.5 Hz, kg"), "{s}");
    // Zoomed: one readout line above the chart, scrolling with the legend.
    update(&mut a, Msg::Resize(80, 24));
    ch(&mut a, 'z');
    let s = screen(&a, 80, 24);
    let line = s.lines().nth(2).expect("readout line");
    assert!(line.starts_with("f 7.5 Hz  STHT  ⣿ 65 kg"), "{s}");
    insta::assert_snapshot!("study_cursor_zoom_80x24", s);
    key(&mut a, KeyCode::Down);
    let s = screen(&a, 80, 24);
    let line = s.lines().nth(2).expect("readout line");
    assert!(line.starts_with("f 7.5 Hz  STHT  • 75 kg"), "{s}");
}

#[test]
fn at_60x16_the_readout_takes_a_line_and_the_peaks_fit() {
    let mut a = on_tab(60, 16);
    ch(&mut a, 'g');
    typ(&mut a, "7.5");
    key(&mut a, KeyCode::Enter);
    let s = screen(&a, 60, 16);
    let line = s.lines().nth(2).expect("readout line");
    assert!(line.starts_with("f 7.5 Hz  STHT  ⣿ 65 kg 1.132"), "{s}");
    assert!(s.contains("4.74 Hz 81.25"), "the APMS peak whole\n{s}");
    // The chart's top rule (no room for a frame) starts with a rule cell
    // where the frame has its corner, not with its title (issue 21).
    let rule = s.lines().nth(3).expect("the chart's top rule");
    assert!(rule.starts_with("─STHT magnitude"), "{s}");
    insta::assert_snapshot!("study_cursor_60x16", s);
}

#[test]
fn the_help_page_opens_at_the_study_keys_with_the_cursor() {
    let mut a = on_tab(80, 24);
    ch(&mut a, '?');
    let s = screen(&a, 80, 24);
    for want in ["3 Study", "< / ,", "> / .", "PgUp", "Home", "g  ", "go to a frequency"] {
        assert!(s.contains(want), "{want}\n{s}");
    }
    insta::assert_snapshot!("study_help_80x24", s);
}
