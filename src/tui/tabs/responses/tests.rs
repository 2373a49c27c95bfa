//! The overlay and the fit dialog driven by keys through the real `update`:
//! loading data, the free-parameter choice, a fit run at once (no channel)
//! and on its thread (through the channel), applying as one undo step,
//! and snapshots at 80×24 and 160×48.

use super::{ResponsesTab, Stage};
use crate::tui::app::App;
use crate::tui::event::Msg;
use crate::tui::keys::{self, Key};
use crate::tui::tests::{app, key, screen, typ};
use crate::tui::theme::Theme;
use crate::tui::update::update;
use biodyn::{Band, Body, Function, Param, Preset, Solver};
use ratatui::crossterm::event::KeyCode;
use std::time::Duration;

/// The shipped example, relative to the crate (where `cargo test` runs),
/// so the snapshots do not hold this machine's paths.
const EXAMPLE: &str = "examples/synthetic-stht-apms-3pct-2deg.csv";

const SIZES: [(u16, u16); 2] = [(80, 24), (160, 48)];
/// The fit result is also drawn at the narrowest supported size.
const RESULT_SIZES: [(u16, u16); 3] = [(60, 16), (80, 24), (160, 48)];

fn snap(name: &str, a: &App) {
    for (w, h) in SIZES {
        insta::assert_snapshot!(format!("{name}_{w}x{h}"), screen(a, w, h));
    }
}

fn tab(a: &App) -> &ResponsesTab {
    a.tab_state().expect("responses tab")
}

fn tab_mut(a: &mut App) -> &mut ResponsesTab {
    a.tabs
        .iter_mut()
        .find_map(|t| (t.as_mut() as &mut dyn std::any::Any).downcast_mut::<ResponsesTab>())
        .expect("responses tab")
}

/// On the Responses tab with `path` loaded through D.
fn with_data(mut a: App, path: &str) -> App {
    key(&mut a, KeyCode::Char('2'));
    key(&mut a, KeyCode::Char('D'));
    let f = a.field.as_mut().expect("the data field");
    f.set_text(path);
    key(&mut a, KeyCode::Enter);
    a
}

/// Exact STHT and APMS (magnitude and phase) of `body` at 0.5–20 Hz, as a
/// data file; the engine's own sweep, not the fit's residual code.
fn exact_data(body: &Body) -> tempfile::NamedTempFile {
    let band = Band::new(0.5, 20.0, 0.1).expect("band");
    let mut text = String::from("f_hz,stht_mag,stht_phase_deg,apms_mag,apms_phase_deg\n");
    for r in Solver::new(body).sweep(&band) {
        let (s, m) = (Function::Stht, Function::Apms);
        text += &format!(
            "{},{},{},{},{}\n",
            r.f_hz,
            r.mag(s),
            r.phase_deg(s),
            r.mag(m),
            r.phase_deg(m)
        );
    }
    let f = tempfile::Builder::new()
        .suffix(".csv")
        .tempfile()
        .expect("temp file");
    std::fs::write(f.path(), text).expect("write data");
    f
}

/// Leaves only k4 and c4 free (from the default, every k and c) and 2 starts.
fn choose_k4_c4(a: &mut App) {
    let rows = tab(a).fit.as_ref().expect("dialog").rows.clone();
    for (i, r) in rows.iter().enumerate() {
        if let super::fit::Row::Param(Param::Stiffness(j) | Param::Damping(j)) = r
            && *j != 3
        {
            tab_mut(a).fit.as_mut().expect("dialog").sel = i;
            key(a, KeyCode::Char(' '));
        }
    }
    let starts = rows.len() - 2;
    tab_mut(a).fit.as_mut().expect("dialog").sel = starts;
    for _ in 0..6 {
        key(a, KeyCode::Left);
    }
}

#[test]
fn d_overlays_the_data_and_keeps_it_while_the_model_changes() {
    let mut a = with_data(app(), EXAMPLE);
    assert!(a.field.is_none(), "{:?}", a.field);
    assert!(a.status.text.contains("196 frequencies"), "{:?}", a.status);
    let s = screen(&a, 160, 48);
    assert!(s.contains("model") && s.contains(" data:"), "{s}");
    snap("fit_overlay", &a);
    // phase mode draws the phase columns
    key(&mut a, KeyCode::Char('p'));
    let stht = tab(&a)
        .data
        .as_ref()
        .and_then(|o| {
            let d = a.shared.derived.as_ref()?;
            o.series(Function::Stht, true, &d.functions[0].phase)
        })
        .expect("stht phase data");
    assert_eq!(stht.points.len(), 196);
    key(&mut a, KeyCode::Char('p'));
    // an edit on the Model tab, another preset: the data stay
    key(&mut a, KeyCode::Char('1'));
    key(&mut a, KeyCode::Char('+'));
    assert!(a.modified());
    key(&mut a, KeyCode::Char('2'));
    assert!(tab(&a).data.is_some());
    // the charts' copy of the model curve follows the edit
    let d = a.shared.derived.as_ref().expect("derived");
    assert_eq!(tab(&a).overlaid[0][0], d.functions[0].mag);
    assert!(tab(&a).overlaid[1].is_empty(), "no DPMI column in the file");
    key(&mut a, KeyCode::Char('p'));
    let d = a.shared.derived.as_ref().expect("derived");
    assert_eq!(tab(&a).overlaid[2][0], d.functions[2].phase);
    key(&mut a, KeyCode::Char('p'));
    key(&mut a, KeyCode::Char('X'));
    assert!(tab(&a).data.is_none());
    assert_eq!(a.status.text, "measured data cleared");
}

#[test]
fn a_bad_file_keeps_the_field_open_with_the_librarys_message() {
    let mut a = with_data(app(), "/nonexistent/data.csv");
    let f = a.field.as_ref().expect("field still open");
    assert!(
        f.error
            .as_deref()
            .is_some_and(|e| e.contains("/nonexistent/data.csv"))
    );
    key(&mut a, KeyCode::Esc);
    let bad = tempfile::Builder::new()
        .suffix(".csv")
        .tempfile()
        .expect("tmp");
    std::fs::write(bad.path(), "f_hz,apms_mag\n1,50\n2,-3\n").expect("write");
    let mut a = with_data(a, &bad.path().display().to_string());
    let e = a
        .field
        .as_ref()
        .and_then(|f| f.error.clone())
        .unwrap_or_default();
    assert!(e.contains("line 3") && e.contains("apms_mag"), "{e}");
    // the whole message is on screen, wrapped inside the field
    let s = screen(&a, 80, 24);
    assert!(
        s.contains("refused:") && s.contains("leave the cell"),
        "{s}"
    );
    key(&mut a, KeyCode::Esc);
    key(&mut a, KeyCode::Char('F'));
    assert!(
        a.status.error && a.status.text.contains("D loads"),
        "{:?}",
        a.status
    );
    assert!(tab(&a).fit.is_none());
}

#[test]
fn the_dialog_offers_every_parameter_with_the_librarys_default() {
    let mut a = with_data(app(), EXAMPLE);
    key(&mut a, KeyCode::Char('F'));
    let body = a.shared.body.clone();
    let d = tab(&a).fit.as_ref().expect("dialog open");
    // body mass, 4 masses, 4 k, 4 c, starts, seed
    assert_eq!(d.rows.len(), 1 + 12 + 2);
    assert_eq!(
        d.free,
        biodyn::fit::resolve(&body, &[biodyn::fit::Free::Links]).expect("links")
    );
    assert_eq!(d.free_list(&body), "k1,k2,k3,k4,c1,c2,c3,c4");
    // At 80×24 the dialog takes the tab's whole area: no strip of a chart
    // (its axis labels) below it, and the data's columns whole (issue 21).
    let s = screen(&a, 80, 24);
    let rows: Vec<&str> = s.lines().collect();
    assert!(rows[1].starts_with('┌') && rows[21].starts_with('└'), "{s}");
    assert!(s.contains("apms_phase_deg") && !s.contains("Hz,…"), "{s}");
    // A few rows taller, the centred dialog would leave a strip of the
    // charts above and below it (a readout, an axis's labels): it takes the
    // whole area instead.
    let s = screen(&a, 80, 30);
    let rows: Vec<&str> = s.lines().collect();
    assert!(rows[1].starts_with('┌') && rows[27].starts_with('└'), "{s}");
    assert!(rows[1..28].iter().all(|r| r.starts_with(['┌', '│', '└'])), "{s}");
    snap("fit_dialog", &a);
    key(&mut a, KeyCode::Char(' ')); // body-mass on
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Char(' ')); // m2 on
    let d = tab(&a).fit.as_ref().expect("dialog open");
    assert_eq!(d.free_list(&body), "body-mass,m2,k1,k2,k3,k4,c1,c2,c3,c4");
    // the library refuses body mass with a mass: said in the dialog
    key(&mut a, KeyCode::Enter);
    let d = tab(&a).fit.as_ref().expect("dialog open");
    assert!(matches!(d.stage, Stage::Setup));
    assert!(
        d.note.as_deref().is_some_and(|n| n.contains("m2")),
        "{:?}",
        d.note
    );
    assert!(a.status.error);
    key(&mut a, KeyCode::Char('a'));
    assert_eq!(tab(&a).fit.as_ref().map(|d| d.free.len()), Some(12));
    key(&mut a, KeyCode::Char('d'));
    assert_eq!(tab(&a).fit.as_ref().map(|d| d.free.len()), Some(8));
    // a letter of the charts underneath does nothing; undo still works
    key(&mut a, KeyCode::Char('p'));
    assert!(!tab(&a).phase);
    key(&mut a, KeyCode::Esc);
    assert!(tab(&a).fit.is_none());
    assert!(!a.modified());
}

#[test]
fn a_fit_applies_as_one_undo_step() {
    let start = Preset::builtin_default().body;
    let mut truth = start.clone();
    truth.links[3].k *= 1.6;
    truth.links[3].c *= 0.7;
    let file = exact_data(&truth);
    let mut a = with_data(app(), &file.path().display().to_string());
    key(&mut a, KeyCode::Char('F'));
    choose_k4_c4(&mut a);
    let d = tab(&a).fit.as_ref().expect("dialog");
    assert_eq!((d.free_list(&start).as_str(), d.starts), ("k4,c4", 2));
    // no channel: the fit runs at once
    key(&mut a, KeyCode::Enter);
    let Some(Stage::Result { fit, .. }) = tab(&a).fit.as_ref().map(|d| &d.stage) else {
        panic!("no result: {:?}", a.status);
    };
    for p in &fit.params {
        let want = truth.get(p.param);
        assert!(
            (p.value / want - 1.0).abs() < 1e-6,
            "{} {} vs {want}",
            p.name,
            p.value
        );
        assert!(p.determined, "{p:?}");
    }
    assert!(screen(&a, 80, 24).contains("Every free parameter is determined"));
    key(&mut a, KeyCode::Enter);
    assert!(tab(&a).fit.is_none());
    assert!(
        a.status.text.starts_with("applied the fitted k4, c4"),
        "{:?}",
        a.status
    );
    let (k, c) = (a.shared.body.links[3].k, a.shared.body.links[3].c);
    assert!((k / truth.links[3].k - 1.0).abs() < 1e-6);
    assert!((c / truth.links[3].c - 1.0).abs() < 1e-6);
    assert_eq!(a.undo.len(), 1);
    key(&mut a, KeyCode::Char('u'));
    assert_eq!(a.shared.body, start, "one undo restores every fitted value");
    key(&mut a, KeyCode::Char('u'));
    assert_eq!(a.status.text, "nothing to undo");
    // Esc on a result discards it
    key(&mut a, KeyCode::Char('F'));
    key(&mut a, KeyCode::Enter);
    key(&mut a, KeyCode::Esc);
    assert!(tab(&a).fit.is_none() && a.shared.body == start);
}

#[test]
fn the_result_view_on_the_example_data() {
    let mut a = with_data(app(), EXAMPLE);
    key(&mut a, KeyCode::Char('F'));
    let n = tab(&a).fit.as_ref().map_or(0, |d| d.rows.len());
    tab_mut(&mut a).fit.as_mut().expect("dialog").sel = n - 2;
    for _ in 0..4 {
        key(&mut a, KeyCode::Left); // 4 starts
    }
    key(&mut a, KeyCode::Enter);
    let Some(Stage::Result { fit, .. }) = tab_mut(&mut a).fit.as_mut().map(|d| &mut d.stage) else {
        panic!("no result: {:?}", a.status);
    };
    fit.seconds = 0.0; // the one number that differs from run to run
    // The widest verdict there is, to be drawn at every size.
    fit.params[5].at_bound = true;
    fit.params[5].other_minimum = true;
    let s = screen(&a, 160, 48);
    assert!(
        s.contains("95 % interval") && s.contains("residual r.m.s.: stht_mag"),
        "{s}"
    );
    for (w, h) in RESULT_SIZES {
        insta::assert_snapshot!(format!("fit_result_{w}x{h}"), screen(&a, w, h));
    }
    // Narrow, the verdict and its mark stay; the start value goes first.
    let narrow = screen(&a, 60, 16);
    assert!(narrow.contains("determined") && narrow.contains("yes at bound *"), "{narrow}");
    assert!(!narrow.contains("start "), "{narrow}");
    let wide = screen(&a, 80, 24);
    assert!(wide.contains("unit") && wide.contains("N·s/m"), "{wide}");
    for _ in 0..40 {
        key(&mut a, KeyCode::Down);
    }
    let s = screen(&a, 80, 24);
    assert!(s.contains("Enter applies"), "scrolled to the end: {s}");
}

#[test]
fn a_fit_on_its_thread_reports_progress_and_can_be_cancelled() {
    let (tx, rx) = std::sync::mpsc::channel();
    let a = App::with_channel(Preset::builtin_default(), None, Theme::default(), Some(tx));
    let mut a = with_data(a, EXAMPLE);
    key(&mut a, KeyCode::Char('F'));
    choose_k4_c4(&mut a);
    key(&mut a, KeyCode::Enter);
    assert!(tab(&a).fit.as_ref().is_some_and(|d| d.running()));
    assert!(a.quit_reasons().contains(&"a fit is running"));
    assert!(screen(&a, 80, 24).contains("fit: start 0 of 2"));
    let (mut progress, mut profiled) = (0, 0);
    while tab(&a).fit.as_ref().is_some_and(|d| d.running()) {
        let msg = rx
            .recv_timeout(Duration::from_secs(60))
            .expect("a fit message");
        if let Msg::Tab(_, m) = &msg
            && let Some(super::fit::FitMsg::Progress(p)) = m.downcast_ref::<super::fit::FitMsg>()
        {
            if p.done == p.starts && p.profiled > 0 {
                // The intervals are walked after the starts, and said so.
                profiled = profiled.max(p.profiled);
            } else if p.done > progress {
                assert_eq!(p.done, progress + 1);
                progress += 1;
                assert!(screen(&a, 80, 24).contains("fit: start"));
            }
        }
        if profiled > 0 {
            assert!(screen(&a, 80, 24).contains("fit: intervals"), "{}", screen(&a, 80, 24));
        }
        update(&mut a, msg);
    }
    assert_eq!(progress, 2, "one progress message per start");
    assert_eq!(profiled, 2, "the last interval's message always goes");
    assert!(matches!(
        tab(&a).fit.as_ref().map(|d| &d.stage),
        Some(Stage::Result { .. })
    ));
    // a long fit, cancelled at once: back to the setup, model unchanged
    key(&mut a, KeyCode::Esc);
    key(&mut a, KeyCode::Char('F'));
    typ(&mut a, "a");
    tab_mut(&mut a).fit.as_mut().expect("dialog").starts = 1000;
    key(&mut a, KeyCode::Enter);
    key(&mut a, KeyCode::Esc);
    while tab(&a).fit.as_ref().is_some_and(|d| d.running()) {
        let msg = rx
            .recv_timeout(Duration::from_secs(60))
            .expect("a fit message");
        update(&mut a, msg);
    }
    let d = tab(&a).fit.as_ref().expect("dialog");
    assert!(matches!(d.stage, Stage::Setup));
    assert_eq!(d.note.as_deref(), Some("cancelled; the model is unchanged"));
    assert!(!a.modified());
}

#[test]
fn the_dialog_tables_hide_no_app_key_and_bind_none_twice() {
    let mut everywhere: Vec<Key> = (0..9).filter_map(keys::tab_key).collect();
    everywhere.extend(keys::GLOBAL.iter().flat_map(|b| b.doc.keys.iter().copied()));
    for table in [
        super::fit_keys::SETUP,
        super::fit_keys::RUNNING,
        super::fit_keys::RESULT,
    ] {
        let mut seen: Vec<Key> = Vec::new();
        for b in table {
            for k in b.doc.keys {
                assert!(!everywhere.contains(k), "{k:?} works everywhere");
                assert!(!seen.contains(k), "{k:?} twice");
                seen.push(*k);
            }
        }
    }
    // while open, the hint bar shows the dialog's keys first
    let mut a = with_data(app(), EXAMPLE);
    key(&mut a, KeyCode::Char('F'));
    let s = screen(&a, 160, 48);
    let hints = s.lines().last().unwrap_or_default();
    assert!(hints.trim_start().starts_with("↑↓ row"), "{hints}");
    assert!(
        hints.contains("Enter fit") && hints.contains("? help"),
        "{hints}"
    );
    // ? passes through the dialog; the page lists the dialog's keys
    key(&mut a, KeyCode::Char('?'));
    assert!(matches!(
        a.overlay,
        crate::tui::popups::Overlay::Help { .. }
    ));
    let help = crate::tui::frame::help_lines(&a);
    assert!(help.iter().any(|l| matches!(l,
        crate::tui::popups::help::HelpLine::Row { keys, help } if keys == "space" && help.starts_with("fit: free"))));
    key(&mut a, KeyCode::Esc);
    assert!(tab(&a).fit.is_some(), "closing help leaves the dialog open");
}

#[test]
fn without_colour_the_data_have_their_own_marker() {
    use crate::view::chart;
    for ascii in [false, true] {
        let glyph = chart::legend_glyph(1, ascii);
        assert_ne!(glyph, chart::legend_glyph(0, ascii));
        assert_ne!(glyph, chart::cursor_glyph(ascii));
        assert_ne!(glyph, chart::peak_glyph(ascii));
        let theme = Theme { mono: true, ascii };
        let a = App::new(Preset::builtin_default(), None, theme);
        let a = with_data(a, EXAMPLE);
        let s = screen(&a, 160, 48);
        let legend = s.lines().nth(2).unwrap_or_default();
        assert!(legend.contains(&format!("{glyph} data:")), "{legend}");
        let drawn = s
            .lines()
            .skip(3)
            .map(|l| l.matches(glyph).count())
            .sum::<usize>();
        assert!(drawn > 100, "{drawn} data glyphs:\n{s}");
        assert!(!ascii || s.is_ascii(), "{s}");
    }
}
