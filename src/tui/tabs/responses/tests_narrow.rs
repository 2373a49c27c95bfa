//! The cursor across band changes, and the lines that must stay readable
//! at narrow widths (the compare peak line, the copied CSV line).

use super::{ResponsesTab, view};
use crate::tui::app::App;
use crate::tui::event::Msg;
use crate::tui::tests::{app, key, screen, typ};
use crate::tui::update::update;
use ratatui::crossterm::event::KeyCode;

fn tab(a: &App) -> &ResponsesTab {
    a.tab_state().expect("responses tab")
}

fn on_tab(w: u16, h: u16) -> App {
    let mut a = app();
    update(&mut a, Msg::Resize(w, h));
    key(&mut a, KeyCode::Char('2'));
    a
}

/// The cursor's frequency as the readout reads it.
fn cursor_hz(a: &App) -> f64 {
    view::at_cursor(tab(a), &a.shared).expect("a cursor").f_hz
}

fn band(a: &mut App, text: &str) {
    key(a, KeyCode::Char('b'));
    typ(a, text);
    key(a, KeyCode::Enter);
    assert!(a.field.is_none(), "band {text} refused");
}

#[test]
fn a_new_band_keeps_the_cursor_frequency_not_its_index() {
    let mut a = on_tab(80, 24);
    let f0 = cursor_hz(&a);
    assert!((f0 - 4.6).abs() < 1e-9, "starts on the STHT peak: {f0}");
    band(&mut a, "2 12 0.05");
    assert!((cursor_hz(&a) - 4.6).abs() < 1e-9, "{}", cursor_hz(&a));
    assert!(screen(&a, 80, 24).contains("f 4.6 Hz"));
    // A grid without 4.6: the nearest point of the new grid.
    band(&mut a, "0.5 20 0.25");
    assert!((cursor_hz(&a) - 4.5).abs() < 1e-9, "{}", cursor_hz(&a));
    // A band that ends below the cursor: clamped to its end.
    band(&mut a, "5 10 0.1");
    assert!((cursor_hz(&a) - 5.0).abs() < 1e-9, "{}", cursor_hz(&a));
    // Undo walks the band back; the cursor stays at 5 Hz.
    key(&mut a, KeyCode::Char('u'));
    assert!((cursor_hz(&a) - 5.0).abs() < 1e-9, "{}", cursor_hz(&a));
}

#[test]
fn an_exact_cursor_inside_the_new_band_stays_exact() {
    let mut a = on_tab(80, 24);
    key(&mut a, KeyCode::Char('g'));
    let f = a.field.as_mut().expect("go-to field");
    f.set_text("6.123");
    key(&mut a, KeyCode::Enter);
    band(&mut a, "2 12 0.05");
    assert!((cursor_hz(&a) - 6.123).abs() < 1e-12, "{}", cursor_hz(&a));
    assert!(screen(&a, 80, 24).contains("f 6.123 Hz"));
    // Outside the new band: the nearest grid point, clamped in.
    band(&mut a, "0.5 5 0.1");
    assert!((cursor_hz(&a) - 5.0).abs() < 1e-9, "{}", cursor_hz(&a));
    // A step moves from there along the grid.
    key(&mut a, KeyCode::Left);
    assert!((cursor_hz(&a) - 4.9).abs() < 1e-9, "{}", cursor_hz(&a));
}

/// The model's and the compared model's main peak of `f`, each found on
/// its own body's sweep (not by the tab).
fn peaks_of(a: &App, other: &biodyn::Body, f: biodyn::Function) -> (f64, f64, f64, f64) {
    use biodyn::Solver;
    use biodyn::freq::main_peak;
    let band = a.shared.band();
    let s1 = Solver::new(&a.shared.body);
    let s2 = Solver::new(other);
    let p1 = main_peak(&s1, &s1.sweep(band), f).expect("a peak");
    let p2 = main_peak(&s2, &s2.sweep(band), f).expect("a ref peak");
    (p1.f_hz, p1.mag, p2.f_hz, p2.mag)
}

#[test]
fn at_60x16_the_compared_peak_line_keeps_the_differences() {
    use crate::view::format::num;
    let dir = tempfile::tempdir().expect("tempdir");
    let mut p = biodyn::Preset::builtin_default();
    p.body.set(biodyn::Param::BodyMass, 85.0).expect("85 kg");
    p.name = "heavy".into();
    let path = dir.path().join("heavy.toml");
    p.save(&path).expect("save");
    for (w, h) in [(60u16, 16u16), (80, 24)] {
        let mut a = on_tab(w, h);
        key(&mut a, KeyCode::Char('c'));
        typ(&mut a, &path.display().to_string());
        key(&mut a, KeyCode::Enter);
        assert!(a.field.is_none(), "{:?}", a.field);
        for fi in 0..3 {
            let f = biodyn::Function::ALL[tab(&a).func];
            let (f1, m1, f2, m2) = peaks_of(&a, &p.body, f);
            let sign = |v: f64, sig| {
                let t = num(v.abs(), sig);
                if v < 0.0 { format!("−{t}") } else { format!("+{t}") }
            };
            let want = format!(
                "Δ {} Hz {} %",
                sign(f1 - f2, 3),
                sign((m1 / m2 - 1.0) * 100.0, 2)
            );
            let s = screen(&a, w, h);
            let line = s
                .lines()
                .find(|l| l.starts_with(&format!("{} ", f.name())) && l.contains("Δ"))
                .unwrap_or_else(|| panic!("{w}x{h} {fi}: no peak line\n{s}"));
            assert!(line.contains(&want), "{w}x{h}: {want} not in {line}");
            assert!(!line.contains('…'), "{line}");
            key(&mut a, KeyCode::Char('f'));
        }
    }
}

/// The CSV row of the readout, from the library's curve and the report's
/// own CSV writer (what `biodyn response --format csv` writes).
fn csv_row(a: &App) -> String {
    let r = *view::at_cursor(tab(a), &a.shared).expect("a cursor");
    let mut want = String::new();
    crate::view::report::csv::curve_rows(&mut want, "", &[r]);
    want.trim_end().to_string()
}

#[test]
fn y_shows_the_csv_row_whole_broken_only_after_commas() {
    for (w, h) in [(60u16, 16u16), (80, 24)] {
        let mut a = on_tab(w, h);
        key(&mut a, KeyCode::Char('g'));
        a.field.as_mut().expect("go-to").set_text("4.5678");
        key(&mut a, KeyCode::Enter);
        screen(&a, w, h); // drawn once, as a terminal would
        key(&mut a, KeyCode::Char('y'));
        let want = csv_row(&a);
        assert!(want.chars().count() > usize::from(w), "{want}");
        // The status line would cut it: it points above instead.
        assert!(!a.status.text.contains(&want[..10]), "{}", a.status.text);
        assert!(a.status.text.contains("above the charts"), "{}", a.status.text);
        let s = screen(&a, w, h);
        let first = s
            .lines()
            .position(|l| l.starts_with("4.5678,"))
            .unwrap_or_else(|| panic!("{s}"));
        let mut got = String::new();
        for l in s.lines().skip(first) {
            got += l.trim_end();
            if !l.trim_end().ends_with(',') {
                break;
            }
        }
        assert_eq!(got, want, "{s}");
        // Every value sits whole on one line.
        for l in s.lines().skip(first).take_while(|l| !got.is_empty() && want.contains(l.trim_end())) {
            for v in l.trim_end().split(',').filter(|v| !v.is_empty()) {
                assert!(want.split(',').any(|x| x == v), "{v} cut in\n{s}");
            }
        }
    }
    // Wide enough: on the status line whole, and not above the charts.
    let mut a = on_tab(160, 48);
    screen(&a, 160, 48);
    key(&mut a, KeyCode::Char('y'));
    assert_eq!(a.status.text, csv_row(&a));
}

#[test]
fn breaking_after_commas_keeps_every_value_whole() {
    let line = "4.5678,1.8151192329775043,-44.58831495886048,2798.0281182214108";
    // At 8 a value longer than the width is cut: the only way it fits.
    for w in [8usize, 20, 30, 200] {
        let parts = super::view::break_after_commas(line, w);
        assert_eq!(parts.concat(), line);
        assert!(parts.iter().all(|p| p.chars().count() <= w), "{w}: {parts:?}");
        if w >= 20 {
            for p in &parts[..parts.len() - 1] {
                assert!(p.ends_with(','), "{w}: {parts:?}");
            }
        }
    }
}

#[test]
fn another_model_with_another_band_puts_the_cursor_on_its_own_peak() {
    let mut a = on_tab(80, 24);
    let mut p = biodyn::Preset::builtin_default();
    p.body.set(biodyn::Param::BodyMass, 85.0).expect("85 kg");
    p.band = biodyn::Band::new(2.0, 12.0, 0.05).expect("band");
    let want = {
        use biodyn::freq::main_peak;
        let s = biodyn::Solver::new(&p.body);
        main_peak(&s, &s.sweep(&p.band), biodyn::Function::Stht).expect("a peak")
    };
    a.load(p, None);
    let f = cursor_hz(&a);
    // On the new grid, within half a step of the STHT peak.
    assert!((f - want.f_hz).abs() <= 0.025 + 1e-9, "{f} vs {}", want.f_hz);
}

#[test]
fn at_60x16_one_framed_chart_and_the_whole_readout() {
    let mut a = on_tab(60, 16);
    let s = screen(&a, 60, 16);
    let lines: Vec<&str> = s.lines().collect();
    for want in [
        "f 4.6 Hz",
        "STHT 1.815 ∠-45.45°",
        "DPMI 2815 N·s/m ∠48.03°",
        "APMS 97.39 kg ∠-41.97°",
    ] {
        assert!(s.contains(want), "{want}\n{s}");
    }
    assert!(
        lines
            .iter()
            .any(|l| l.starts_with("┌STHT magnitude vs f Hz")),
        "{s}"
    );
    assert!(
        lines.iter().any(|l| l.starts_with("└")),
        "bottom frame\n{s}"
    );
    assert!(
        lines.iter().any(|l| l.contains('└') && l.contains('┬')),
        "x axis\n{s}"
    );
    assert!(s.contains("20"), "{s}");
    insta::assert_snapshot!("responses_60x16", s);
    key(&mut a, KeyCode::Char('f'));
    let s = screen(&a, 60, 16);
    assert!(s.contains("DPMI magnitude"), "{s}");
}
