//! The Responses tab's cursor through the real `update`: `y` copies the
//! readout, `g` goes to an exact frequency, `n` names the peak, a click
//! and the wheel move it, `z` shows one function; values are checked
//! against the library's own solver, not against what the tab printed.
//! Snapshots at 80×24 and 160×48 of the go-to field and the zoomed chart.
//! (The exports' bytes against the `biodyn` binary: tests/tui_responses_extras.rs.)

use super::{ResponsesTab, view};
use crate::tui::app::App;
use crate::tui::event::Msg;
use crate::tui::tests::{app, key, mouse, screen, typ};
use crate::tui::update::update;
use crate::view::chart;
use crate::view::report::csv;
use biodyn::{freq, Function, Solver};
use ratatui::crossterm::event::{KeyCode, MouseButton, MouseEventKind};
use ratatui::layout::Rect;

pub(super) fn tab(a: &App) -> &ResponsesTab {
    a.tab_state().expect("responses tab")
}

pub(super) fn on_tab(w: u16, h: u16) -> App {
    let mut a = app();
    update(&mut a, Msg::Resize(w, h));
    key(&mut a, KeyCode::Char('2'));
    a
}

pub(super) fn snap(name: &str, a: &mut App) {
    for (w, h) in [(80, 24), (160, 48)] {
        update(a, Msg::Resize(w, h));
        insta::assert_snapshot!(format!("{name}_{w}x{h}"), screen(a, w, h));
    }
}

#[test]
fn y_copies_the_readout_as_the_csv_row_of_the_cursor() {
    let mut a = on_tab(80, 24);
    key(&mut a, KeyCode::Char('y'));
    let i = tab(&a).cursor;
    let r = a.shared.derived.as_ref().expect("derived").curve[i];
    let mut want = String::new();
    csv::curve_rows(&mut want, "", &[r]);
    assert_eq!(a.status.text, want.trim_end());
    assert!(a.status.text.starts_with("4.6,"), "{}", a.status.text);
    assert_eq!(a.status.text.split(',').count(), 7);
    // At 80 columns the status line cuts it: the tab shows it whole.
    let screen = screen(&a, 80, 24);
    let joined: String = screen.lines().skip(2).take(2).collect();
    assert!(joined.starts_with(&a.status.text), "{screen}");
    key(&mut a, KeyCode::Right);
    assert!(tab(&a).copied.is_none());
}

#[test]
fn g_puts_the_cursor_on_the_exact_frequency_computed_there() {
    let mut a = on_tab(80, 24);
    key(&mut a, KeyCode::Char('g'));
    assert!(a.field.is_some());
    snap("goto_field", &mut a);
    // Typing replaces the pre-filled value.
    typ(&mut a, "4.5678");
    key(&mut a, KeyCode::Enter);
    assert!(a.field.is_none(), "{:?}", a.field);
    let exact = tab(&a).exact.expect("an exact point");
    let want = Solver::new(&a.shared.body).at(4.5678);
    assert_eq!(exact.f_hz, 4.5678);
    for f in Function::ALL {
        assert_eq!(exact.mag(f), want.mag(f));
    }
    let s = screen(&a, 80, 24);
    assert!(s.contains("f 4.5678 Hz"), "{s}");
    assert!(
        s.contains(&format!(
            "STHT {}",
            crate::view::format::num(want.mag(Function::Stht), 4)
        )),
        "{s}"
    );
    // y copies the exact point, not the grid's
    key(&mut a, KeyCode::Char('y'));
    let copied = tab(&a).copied.clone().unwrap_or_default();
    assert!(copied.starts_with("4.5678,"), "{copied}");
    // An arrow goes back to the grid.
    key(&mut a, KeyCode::Right);
    assert!(tab(&a).exact.is_none());

    // Refusals keep the field open with the reason.
    for (text, why) in [
        ("abc", "'abc' is not a frequency"),
        ("30", "30 Hz is outside the band 0.5–20 Hz"),
        ("-1", "outside the band"),
        ("NaN", "outside the band"),
    ] {
        key(&mut a, KeyCode::Char('g'));
        typ(&mut a, text);
        key(&mut a, KeyCode::Enter);
        let f = a.field.as_ref().expect("field stays open");
        let err = f.error.clone().unwrap_or_default();
        assert!(err.contains(why), "{text}: {err}");
        key(&mut a, KeyCode::Esc);
    }
    // "Hz" may follow the number.
    key(&mut a, KeyCode::Char('g'));
    typ(&mut a, "7 Hz");
    key(&mut a, KeyCode::Enter);
    assert_eq!(tab(&a).exact.map(|r| r.f_hz), Some(7.0));
}

#[test]
fn n_names_the_peak_and_its_function() {
    let mut a = on_tab(80, 24);
    let solver = Solver::new(&a.shared.body);
    let curve = solver.sweep(a.shared.band());
    let mut all: Vec<freq::Peak> = Function::ALL
        .iter()
        .flat_map(|&f| freq::find_peaks_in(&solver, &curve, f))
        .collect();
    all.sort_by(|x, y| x.f_hz.total_cmp(&y.f_hz));
    assert!(all.len() >= 3);
    // From 4.6 Hz the next peak up is DPMI's, then it wraps to the lowest.
    key(&mut a, KeyCode::Char('n'));
    let p = all.iter().find(|p| p.f_hz > 4.6).expect("a peak above");
    assert_eq!(p.function, Function::Dpmi);
    assert!(
        a.status.text.starts_with(&format!(
            "peak DPMI {} Hz",
            crate::view::format::num(p.f_hz, 4)
        )),
        "{}",
        a.status.text
    );
    assert_eq!(tab(&a).function(), Function::Dpmi);
    assert_eq!(tab(&a).exact.map(|r| r.f_hz), Some(p.f_hz));
    for want in &all {
        if want.f_hz <= p.f_hz {
            continue;
        }
        key(&mut a, KeyCode::Char('n'));
        assert!(
            a.status.text.contains(want.function.name()),
            "{}",
            a.status.text
        );
    }
    key(&mut a, KeyCode::Char('n'));
    assert_eq!(tab(&a).exact.map(|r| r.f_hz), Some(all[0].f_hz));
    assert!(
        a.status
            .text
            .starts_with(&format!("peak {} ", all[0].function.name())),
        "{}",
        a.status.text
    );
    // STHT's peak is read with 4 significant figures, phase too.
    let s = screen(&a, 160, 48);
    let r = solver.at(all[0].f_hz);
    let ph = crate::view::format::num(r.phase_deg(Function::Stht), 4);
    assert!(s.contains(&format!("∠{ph}°")), "{ph}\n{s}");
    assert_eq!(ph.trim_start_matches('-').replace('.', "").len(), 4, "{ph}");
}

#[test]
fn a_click_in_a_chart_moves_the_cursor_to_that_column_and_the_wheel_steps() {
    for (w, h, zoom) in [
        (80, 24, false),
        (160, 48, false),
        (60, 16, false),
        (80, 24, true),
    ] {
        let mut a = on_tab(w, h);
        key(&mut a, KeyCode::Char('M'));
        if zoom {
            key(&mut a, KeyCode::Char('z'));
            assert!(a.zoom);
        }
        let body = Rect::new(0, 1, w, h - 3);
        let t = tab(&a);
        let areas = view::areas(t, &a.shared, body, zoom);
        let &(i, cell) = areas.charts.last().expect("a chart");
        let c = view::chart(t, &a.shared, i, cell, areas.charts.len() == 1).expect("chart");
        let lay = chart::layout(cell, &c.series, &c.opts).expect("layout");
        let col = lay.column(12.0, false).expect("12 Hz on the axis");
        let row = lay.plot.y + 1;
        mouse(&mut a, MouseEventKind::Down(MouseButton::Left), col, row);
        let t = tab(&a);
        let f = a.shared.derived.as_ref().expect("d").curve[t.cursor].f_hz;
        assert_eq!(lay.column(f, false), Some(col), "{w}x{h}: cursor {f} Hz");
        assert!((f - 12.0).abs() < 0.5, "{w}x{h}: {f}");
        assert_eq!(t.func, i);
        let before = t.cursor;
        mouse(&mut a, MouseEventKind::ScrollUp, col, row);
        assert_eq!(tab(&a).cursor, before + 1);
        mouse(&mut a, MouseEventKind::ScrollDown, col, row);
        mouse(&mut a, MouseEventKind::ScrollDown, col, row);
        assert_eq!(tab(&a).cursor, before - 1);
    }
}

#[test]
fn z_shows_the_current_function_alone() {
    let mut a = on_tab(80, 24);
    key(&mut a, KeyCode::Char('f'));
    assert_eq!(tab(&a).function(), Function::Dpmi);
    key(&mut a, KeyCode::Char('z'));
    let s = screen(&a, 80, 24);
    assert!(s.contains("DPMI (driving-point"), "{s}");
    assert!(!s.contains("STHT (") && !s.contains("APMS ("), "{s}");
    snap("zoom_dpmi", &mut a);
}
