//! The compared model (`c`) drawn dimmed: grey and `·` in colour, `·`
//! without colour (NO_COLOR), `.` in ASCII, beneath the model's curve;
//! the legend line names it; the readout gives the peak differences
//! (every function's side by side, the current one's otherwise), checked
//! against peaks found on the compared body's own sweep. Snapshots at
//! 80×24 and 160×48 in colour, NO_COLOR and ASCII.

use super::ResponsesTab;
use super::tests_cursor::{on_tab, tab};
use crate::tui::app::App;
use crate::tui::event::Msg;
use crate::tui::tests::{key, screen, typ};
use crate::tui::theme::Theme;
use crate::tui::update::update;
use crate::view::chart::buffer_text;
use crate::view::format::{num, unit};
use biodyn::{freq, Function, Param, Preset, Solver};
use ratatui::buffer::Buffer;
use ratatui::crossterm::event::KeyCode;
use ratatui::style::Color;

const SIZES: [(u16, u16); 2] = [(80, 24), (160, 48)];

/// The paper's model at 85 kg, saved as "heavy".
fn heavy() -> (tempfile::TempDir, std::path::PathBuf, Preset) {
    let dir = tempfile::tempdir().expect("tempdir");
    let mut p = Preset::builtin_default();
    p.body.set(Param::BodyMass, 85.0).expect("85 kg");
    p.name = "heavy".into();
    let path = dir.path().join("heavy.toml");
    p.save(&path).expect("save");
    (dir, path, p)
}

/// Responses with "heavy" compared, in `theme`.
fn comparing(theme: Theme, path: &std::path::Path) -> App {
    let mut a = App::new(Preset::builtin_default(), None, theme);
    key(&mut a, KeyCode::Char('2'));
    key(&mut a, KeyCode::Char('c'));
    typ(&mut a, &path.display().to_string());
    key(&mut a, KeyCode::Enter);
    assert!(a.field.is_none(), "{:?}", a.field);
    a
}

fn buffer(a: &mut App, w: u16, h: u16) -> Buffer {
    update(a, Msg::Resize(w, h));
    crate::tui::tests::frame(a, w, h)
}

/// Cells (symbol, colour) inside the charts' rows, below the legend line;
/// not the `·` of a unit (N·s/m) or of " · peak" in a title.
fn chart_cells(buf: &Buffer, from_row: u16) -> Vec<(String, Color)> {
    let a = buf.area;
    let sym = |x: u16, y: u16| buf.cell((x, y)).map_or("", |c| c.symbol());
    (from_row..a.bottom().saturating_sub(2))
        .flat_map(|y| (a.left()..a.right()).map(move |x| (x, y)))
        .filter(|&(x, y)| !(x > 0 && sym(x - 1, y) == "N"))
        .filter(|&(x, y)| !(sym(x + 1, y) == " " && sym(x + 2, y) == "p"))
        .filter_map(|p| buf.cell(p).map(|c| (c.symbol().to_string(), c.fg)))
        .collect()
}

#[test]
fn the_compared_model_is_dimmed_in_every_theme() {
    let (_dir, path, _) = heavy();
    for (name, theme, glyph, grey) in [
        (
            "colour",
            Theme {
                mono: false,
                ascii: false,
            },
            "·",
            Color::DarkGray,
        ),
        (
            "nocolor",
            Theme {
                mono: true,
                ascii: false,
            },
            "·",
            Color::Reset,
        ),
        (
            "ascii",
            Theme {
                mono: true,
                ascii: true,
            },
            ".",
            Color::Reset,
        ),
    ] {
        let mut a = comparing(theme, &path);
        let how = if theme.mono { "dotted" } else { "grey, dotted" };
        assert_eq!(
            a.status.text,
            format!("comparing with heavy ({how}, \"ref\" in the legend); C clears"),
            "{name}"
        );
        for (w, h) in SIZES {
            let buf = buffer(&mut a, w, h);
            let text = buffer_text(&buf).join("\n");
            // Without colour nothing is dimmed: the legend names the dots
            // (issue 19 item 22), in colour the grey too.
            let how = if theme.mono { "dotted" } else { "grey, dotted" };
            let legend = format!("{glyph} ref: heavy ({how}; C clears)");
            assert!(!text.contains("dimmed"), "{name} {w}x{h}\n{text}");
            let row = text
                .lines()
                .position(|l| l.contains(&legend))
                .unwrap_or_else(|| panic!("{name} {w}x{h}: no legend line\n{text}"));
            let cells = chart_cells(&buf, row as u16 + 1);
            let dim: Vec<&(String, Color)> = cells.iter().filter(|(g, _)| g == glyph).collect();
            assert!(dim.len() >= 10, "{name} {w}x{h}: {} dim cells\n{text}", dim.len());
            assert!(
                dim.iter().all(|(_, c)| *c == grey),
                "{name} {w}x{h}: dim colours {:?}",
                dim.iter().map(|(_, c)| c).collect::<Vec<_>>()
            );
            // The model's curve keeps its own glyph (and colour).
            let main = if theme.ascii { "*" } else { "⠉" };
            assert!(cells.iter().any(|(g, _)| g == main), "{name} {w}x{h}\n{text}");
            if !theme.mono {
                assert!(
                    cells
                        .iter()
                        .filter(|(g, _)| g.starts_with(|c: char| ('\u{2801}'..='\u{28FF}').contains(&c)))
                        .all(|(_, c)| *c == Color::Cyan),
                    "{name} {w}x{h}: the model's braille is cyan"
                );
            }
            insta::assert_snapshot!(format!("compare_{name}_{w}x{h}"), text);
        }
    }
}

#[test]
fn the_readout_gives_the_peak_differences() {
    let (_dir, path, p) = heavy();
    let mut a = comparing(Theme::default(), &path);
    let solver = Solver::new(&p.body);
    let curve = solver.sweep(a.shared.band());
    let own = Solver::new(&a.shared.body);
    let own_curve = own.sweep(a.shared.band());
    // "DPMI peak 5.271 Hz 2981 N·s/m (ref 4.891 Hz 3289 N·s/m, Δ +0.38 Hz"
    let line = |f: Function| {
        let r = freq::main_peak(&solver, &curve, f).expect("ref peak");
        let m = freq::main_peak(&own, &own_curve, f).expect("model peak");
        let u = match unit(f) {
            "" => String::new(),
            u => format!(" {u}"),
        };
        let df = m.f_hz - r.f_hz;
        let sign = if df < 0.0 { "−" } else { "+" };
        format!(
            "{} peak {} Hz {}{u} (ref {} Hz {}{u}, Δ {sign}{} Hz",
            f.name(),
            num(m.f_hz, 4),
            num(m.mag, 4),
            num(r.f_hz, 4),
            num(r.mag, 4),
            num(df.abs(), 3)
        )
    };
    let text = |a: &mut App, w, h| buffer_text(&buffer(a, w, h)).join("\n");
    // 160 columns: every function's peaks, as every chart shows.
    let wide = text(&mut a, 160, 48);
    for f in Function::ALL {
        let want = line(f);
        let got = wide.lines().find(|l| l.starts_with(&format!("{} peak", f.name())));
        let got = got.unwrap_or_else(|| panic!("{want}\n{wide}"));
        assert!(got.starts_with(&want), "{got}\nwant {want}");
    }
    // 80 columns: the current function's; f moves to the next.
    let narrow = text(&mut a, 80, 24);
    assert!(narrow.contains("STHT peak") && !narrow.contains("DPMI peak"), "{narrow}");
    key(&mut a, KeyCode::Char('f'));
    let narrow = text(&mut a, 80, 24);
    let want = line(Function::Dpmi);
    let got = narrow
        .lines()
        .find(|l| l.starts_with("DPMI peak"))
        .unwrap_or_else(|| panic!("{narrow}"));
    assert!(got.starts_with(&want), "{got}\nwant {want}");
    let t: &ResponsesTab = a.tab_state().expect("tab");
    assert_eq!(t.func, 1);
}

#[test]
fn with_measured_data_too_only_the_compared_model_is_dimmed() {
    use super::view;
    use crate::view::chart::Emphasis;
    let (_dir, path, _) = heavy();
    let mut a = comparing(Theme::default(), &path);
    key(&mut a, KeyCode::Char('D'));
    let f = a.field.as_mut().expect("the data field");
    f.set_text("examples/synthetic-stht-apms-3pct-2deg.csv");
    key(&mut a, KeyCode::Enter);
    assert!(a.field.is_none(), "{:?}", a.field);
    let t: &ResponsesTab = a.tab_state().expect("tab");
    let cell = ratatui::layout::Rect::new(0, 0, 80, 12);
    let spec = |i: usize| view::chart(t, &a.shared, i, cell, false).expect("chart");
    // STHT: model, data, ref; DPMI (no such column in the file): model, ref.
    let stht = spec(0);
    assert_eq!(
        stht.emphasis,
        [Emphasis::Normal, Emphasis::Normal, Emphasis::Dim]
    );
    assert_eq!(stht.series[1].name, "data");
    assert!(stht.series[2].name.starts_with("ref "));
    let dpmi = spec(1);
    assert_eq!(dpmi.emphasis, [Emphasis::Normal, Emphasis::Dim]);
    assert!(dpmi.series[1].name.starts_with("ref "));
    // Without the compared model nothing is dimmed.
    key(&mut a, KeyCode::Char('C'));
    let t: &ResponsesTab = a.tab_state().expect("tab");
    let stht = view::chart(t, &a.shared, 0, cell, false).expect("chart");
    assert!(stht.emphasis.iter().all(|e| *e == Emphasis::Normal));
}

/// Snapshots at both sizes, named after this module (insta's rule).
fn snap(name: &str, a: &mut App) {
    for (w, h) in [(80, 24), (160, 48)] {
        update(a, Msg::Resize(w, h));
        insta::assert_snapshot!(format!("{name}_{w}x{h}"), screen(a, w, h));
    }
}

#[test]
fn compare_lays_a_second_model_over_the_charts_and_keeps_it_across_edits() {
    let dir = tempfile::tempdir().expect("tempdir");
    let mut p = Preset::builtin_default();
    p.body.set(Param::BodyMass, 85.0).expect("85 kg");
    p.name = "heavy".into();
    let path = dir.path().join("heavy.toml");
    p.save(&path).expect("save");

    let mut a = on_tab(80, 24);
    key(&mut a, KeyCode::Char('c'));
    assert!(a.field.as_ref().is_some_and(|f| f.path));
    typ(&mut a, &path.display().to_string());
    key(&mut a, KeyCode::Enter);
    assert!(a.field.is_none(), "{:?}", a.field);
    let c = tab(&a).compare.as_ref().expect("compared");
    assert_eq!(c.name, "heavy");
    // The reference's peak, computed independently from the saved body.
    let solver = Solver::new(&p.body);
    let curve = solver.sweep(a.shared.band());
    let want = freq::main_peak(&solver, &curve, Function::Stht).expect("peak");
    assert_eq!(c.peaks[0].map(|q| q.f_hz), Some(want.f_hz));
    let s = screen(&a, 80, 24);
    assert!(s.contains("ref: heavy"), "{s}");
    assert!(
        s.contains(&format!(
            "(ref {} Hz",
            crate::view::format::num(want.f_hz, 4)
        )),
        "{s}"
    );
    assert!(s.contains("Δ −") || s.contains("Δ +"), "{s}");
    snap("compare", &mut a);
    assert_eq!(tab(&a).overlaid[0].len(), 2);

    // A model edit keeps the reference; so does phase mode.
    key(&mut a, KeyCode::Char('1'));
    key(&mut a, KeyCode::Char('+'));
    assert!(a.modified());
    key(&mut a, KeyCode::Char('2'));
    assert!(tab(&a).compare.is_some());
    let d = a.shared.derived.as_ref().expect("derived");
    assert_eq!(tab(&a).overlaid[0][0], d.functions[0].mag);

    // Empty: the model as last saved (here: as loaded).
    key(&mut a, KeyCode::Char('c'));
    a.field.as_mut().expect("field").set_text("");
    key(&mut a, KeyCode::Enter);
    let c = tab(&a).compare.as_ref().expect("compared");
    assert_eq!(c.name, "as last saved");
    assert!(
        a.status.text.contains("comparing with the model as last saved"),
        "{}",
        a.status.text
    );
    let saved = Solver::new(&a.shared.saved).sweep(a.shared.band());
    assert_eq!(c.curve, saved);

    // A missing file is refused in the field.
    key(&mut a, KeyCode::Char('c'));
    a.field
        .as_mut()
        .expect("field")
        .set_text("/nonexistent/x.toml");
    key(&mut a, KeyCode::Enter);
    assert!(a.field.as_ref().is_some_and(|f| f.error.is_some()));
    key(&mut a, KeyCode::Esc);

    key(&mut a, KeyCode::Char('C'));
    assert!(tab(&a).compare.is_none());
    assert!(tab(&a).overlaid.is_empty());
    key(&mut a, KeyCode::Char('C'));
    assert!(
        a.status.text.contains("no compared model"),
        "{}",
        a.status.text
    );
}
