//! Renders through TestBackend and key sequences through the real `update`.

use super::app::{App, Tab, update};
use super::event::Msg;
use super::theme::Theme;
use crate::view::chart::buffer_text;
use biodyn::{Function, Param, Preset};
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

pub fn app() -> App {
    App::new(Preset::builtin_default(), None, Theme::default())
}

pub fn screen(app: &App, w: u16, h: u16) -> String {
    let mut t = Terminal::new(TestBackend::new(w, h)).expect("test backend");
    t.draw(|f| super::draw(f, app)).expect("draw");
    buffer_text(t.backend().buffer()).join("\n")
}

pub fn key(app: &mut App, code: KeyCode) {
    update(app, Msg::Key(KeyEvent::new(code, KeyModifiers::NONE)));
}

pub fn ctrl(app: &mut App, c: char) {
    update(
        app,
        Msg::Key(KeyEvent::new(KeyCode::Char(c), KeyModifiers::CONTROL)),
    );
}

pub fn typ(app: &mut App, s: &str) {
    for c in s.chars() {
        key(app, KeyCode::Char(c));
    }
}

#[test]
#[ignore = "prints screens for a look"]
fn show() {
    let mut a = app();
    for (i, _) in Tab::ALL.iter().enumerate() {
        key(&mut a, KeyCode::Char(char::from(b'1' + i as u8)));
        println!("{}\n", screen(&a, 80, 24));
        println!("{}\n", screen(&a, 160, 48));
        println!("{}\n", screen(&a, 60, 16));
    }
}

fn stht_at_cursor(app: &App) -> f64 {
    app.derived.curve[app.responses.cursor].mag(Function::Stht)
}

#[test]
fn every_tab_renders_at_80x24_and_160x48() {
    let mut a = app();
    for (w, h) in [(80, 24), (160, 48)] {
        key(&mut a, KeyCode::Char('1'));
        let s = screen(&a, w, h);
        for want in [
            "1 Model",
            "paper-75kg",
            "head-neck",
            "pelvis-seat",
            "310000",
            "modes",
            "STHT",
            "4.561",
        ] {
            assert!(s.contains(want), "{w}x{h} model tab lacks {want:?}:\n{s}");
        }
        key(&mut a, KeyCode::Char('2'));
        let s = screen(&a, w, h);
        for want in [
            "STHT",
            "DPMI",
            "APMS",
            "N·s/m",
            "f 4.6 Hz",
            "←→ cursor",
            "peak 4.561 Hz, 1.815",
            "peak 5.271 Hz, 2981 N·s/m",
        ] {
            assert!(
                s.contains(want),
                "{w}x{h} responses tab lacks {want:?}:\n{s}"
            );
        }
        key(&mut a, KeyCode::Char('3'));
        let s = screen(&a, w, h);
        for want in [
            "body mass = 65 kg",
            "body mass = 85 kg",
            "peak magnitude",
            "rises",
            "falls",
        ] {
            assert!(s.contains(want), "{w}x{h} study tab lacks {want:?}:\n{s}");
        }
        key(&mut a, KeyCode::Char('4'));
        let s = screen(&a, w, h);
        for want in ["mass-stht", "learning rate", "held-out value", "t starts"] {
            assert!(
                s.contains(want),
                "{w}x{h} training tab lacks {want:?}:\n{s}"
            );
        }
    }
    // wide: the three study charts side by side, each with its legend
    key(&mut a, KeyCode::Char('3'));
    let s = screen(&a, 160, 48);
    assert!(
        s.contains("DPMI magnitude") && s.contains("APMS magnitude"),
        "{s}"
    );
    assert!(s.contains("As body mass rises, the STHT peak rises"), "{s}");
}

#[test]
fn tiny_terminal_says_so_without_panic() {
    let mut a = app();
    for t in ['1', '2', '3', '4', '?'] {
        key(&mut a, KeyCode::Char(t));
        let s = screen(&a, 40, 10);
        assert!(s.contains("too small"), "{s}");
    }
    key(&mut a, KeyCode::Esc);
    // every tab and every dialog at the edge sizes: no panic, no "too small"
    // from the minimum up
    let sizes = [
        (1, 1),
        (40, 10),
        (59, 24),
        (60, 16),
        (61, 17),
        (80, 24),
        (250, 70),
    ];
    for t in ['1', '2', '3', '4'] {
        key(&mut a, KeyCode::Char(t));
        for open in 0..4 {
            match open {
                1 => key(&mut a, KeyCode::Char('?')),
                2 => ctrl(&mut a, 'o'),
                3 => ctrl(&mut a, 's'),
                _ => {}
            }
            for (w, h) in sizes {
                let s = screen(&a, w, h);
                if w >= 60 && h >= 16 {
                    assert!(!s.contains("too small"), "{w}x{h}:\n{s}");
                }
            }
            key(&mut a, KeyCode::Esc);
        }
    }
}

#[test]
fn editing_a_mass_changes_the_responses() {
    let mut a = app();
    let before = a.derived.curve.clone();
    let peak_before = a.derived.main[0].map(|p| p.f_hz);
    key(&mut a, KeyCode::Down); // m1
    key(&mut a, KeyCode::Down); // m2 chest
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.field.as_ref().map(|f| f.text.as_str()), Some("30.15"));
    // the rounded pre-fill committed as is changes nothing
    key(&mut a, KeyCode::Enter);
    assert!(a.field.is_none() && !a.modified() && a.undo.is_empty());
    key(&mut a, KeyCode::Enter);
    for _ in 0..20 {
        key(&mut a, KeyCode::Backspace);
    }
    typ(&mut a, "40");
    key(&mut a, KeyCode::Enter);
    assert!(a.field.is_none(), "field should close on a valid value");
    assert_eq!(a.body.get(Param::Mass(1)), 40.0);
    assert_ne!(a.derived.curve, before);
    assert_ne!(a.derived.main[0].map(|p| p.f_hz), peak_before);
    assert!(a.modified());
    assert!(screen(&a, 80, 24).contains("*modified"));
    // undo brings the old curve back and clears the modified mark
    key(&mut a, KeyCode::Char('u'));
    assert_eq!(a.derived.curve, before);
    assert!(!a.modified());
    ctrl(&mut a, 'r');
    assert_eq!(a.body.get(Param::Mass(1)), 40.0);
}

#[test]
fn invalid_values_are_refused_with_the_reason() {
    let mut a = app();
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Char('e'));
    for _ in 0..10 {
        key(&mut a, KeyCode::Backspace);
    }
    typ(&mut a, "abc");
    key(&mut a, KeyCode::Enter);
    let f = a.field.as_ref().expect("field stays open");
    assert!(
        f.error
            .as_deref()
            .is_some_and(|e| e.contains("not a number"))
    );
    assert!(screen(&a, 80, 24).contains("refused: 'abc' is not a number"));
    key(&mut a, KeyCode::Home);
    for _ in 0..3 {
        key(&mut a, KeyCode::Delete);
    }
    typ(&mut a, "-3");
    key(&mut a, KeyCode::Enter);
    let e = a
        .field
        .as_ref()
        .and_then(|f| f.error.clone())
        .unwrap_or_default();
    assert!(e.contains("mass") && e.contains("> 0"), "{e}");
    assert_eq!(a.body.get(Param::Mass(0)), 5.625);
    key(&mut a, KeyCode::Esc);
    assert!(a.field.is_none());
    assert!(!a.modified());
    // a negative stiffness is refused too (row 1 is m1; k4 is row 8)
    for _ in 0..7 {
        key(&mut a, KeyCode::Down);
    }
    key(&mut a, KeyCode::Enter);
    assert!(matches!(
        a.field.as_ref().map(|f| f.purpose),
        Some(super::field::Purpose::Param(Param::Stiffness(3)))
    ));
    for _ in 0..10 {
        key(&mut a, KeyCode::Backspace);
    }
    typ(&mut a, "-1");
    key(&mut a, KeyCode::Enter);
    assert!(a.field.as_ref().is_some_and(|f| f.error.is_some()));
    assert_eq!(a.body.get(Param::Stiffness(3)), 90_000.0);
}

#[test]
fn the_selection_stays_in_view_on_a_short_terminal() {
    let mut a = app();
    for _ in 0..8 {
        key(&mut a, KeyCode::Down); // k4 of pelvis-seat, the last row
    }
    let s = screen(&a, 60, 16);
    assert!(s.contains("pelvis-seat"), "{s}");
    key(&mut a, KeyCode::Char('4'));
    key(&mut a, KeyCode::Up); // held-out value, the last setting
    let s = screen(&a, 60, 16);
    assert!(s.contains("held-out value"), "{s}");
}

#[test]
fn nudge_and_body_mass_rescale() {
    let mut a = app();
    key(&mut a, KeyCode::Char('+'));
    assert!((a.body.get(Param::BodyMass) - 78.75).abs() < 1e-9);
    assert!((a.body.get(Param::Mass(0)) - 0.075 * 78.75).abs() < 1e-9);
    key(&mut a, KeyCode::Char('-'));
    assert!((a.body.get(Param::BodyMass) - 74.8125).abs() < 1e-9);
}

#[test]
fn cursor_reads_all_three_and_moves() {
    let mut a = app();
    key(&mut a, KeyCode::Char('2'));
    let f0 = a.derived.curve[a.responses.cursor].f_hz;
    let v0 = stht_at_cursor(&a);
    key(&mut a, KeyCode::Right);
    let f1 = a.derived.curve[a.responses.cursor].f_hz;
    assert!((f1 - f0 - 0.1).abs() < 1e-9);
    assert_ne!(v0, stht_at_cursor(&a));
    key(&mut a, KeyCode::End);
    assert!(screen(&a, 80, 24).contains("f 20 Hz"));
    key(&mut a, KeyCode::Char('p'));
    assert!(screen(&a, 80, 24).contains("phase"));
    key(&mut a, KeyCode::Char('a'));
    assert!(a.responses.log);
    let _ = screen(&a, 160, 48);
}

#[test]
fn study_values_are_edited_and_bad_lists_refused() {
    let mut a = app();
    key(&mut a, KeyCode::Char('3'));
    // go to k4 (body mass, m1..m4, k1..k4)
    for _ in 0..8 {
        key(&mut a, KeyCode::Right);
    }
    assert_eq!(a.study.param(), Param::Stiffness(3));
    assert_eq!(a.study.values, "-40%,0%,+40%");
    let s = screen(&a, 80, 24);
    assert!(s.contains("k4 B.V. +40% (126000)"), "{s}");
    key(&mut a, KeyCode::Enter);
    typ(&mut a, ",x");
    key(&mut a, KeyCode::Enter);
    assert!(a.field.as_ref().is_some_and(|f| f.error.is_some()));
    key(&mut a, KeyCode::Backspace);
    typ(&mut a, "+80%");
    key(&mut a, KeyCode::Enter);
    assert!(a.field.is_none());
    assert_eq!(
        a.study.result.as_ref().map(|s| s.variants.len()).ok(),
        Some(4)
    );
    // the paper's three studies are one key each
    key(&mut a, KeyCode::Char('c'));
    assert_eq!(a.study.param(), Param::Damping(3));
    let s = screen(&a, 80, 24);
    assert!(
        s.contains("c4 B.V. -40%") && s.contains("as c4 rises"),
        "{s}"
    );
    key(&mut a, KeyCode::Char('m'));
    assert_eq!(a.study.param(), Param::BodyMass);
    key(&mut a, KeyCode::Char('k'));
    assert_eq!(a.study.values, "-40%,0%,+40%");
    assert_eq!(a.study.param(), Param::Stiffness(3));
}

#[test]
fn save_and_reload_through_the_ui() {
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("edited.toml");
    let mut a = app();
    key(&mut a, KeyCode::Char('+')); // body mass 78.75
    ctrl(&mut a, 's');
    let f = a.field.as_mut().expect("save prompt");
    assert_eq!(f.text, "paper-75kg.toml");
    f.set_text(path.display().to_string());
    key(&mut a, KeyCode::Enter);
    assert!(a.field.is_none(), "saved: {:?}", a.field);
    assert!(!a.modified());
    assert!(screen(&a, 120, 30).contains("edited.toml"));
    // change it, then open the saved file: asks before discarding
    key(&mut a, KeyCode::Char('+'));
    ctrl(&mut a, 'o');
    typ(&mut a, "");
    if let super::app::Overlay::Open(d) = &mut a.overlay {
        d.field.set_text(path.display().to_string());
    } else {
        panic!("open dialog expected");
    }
    key(&mut a, KeyCode::Enter);
    assert!(matches!(a.overlay, super::app::Overlay::Confirm(..)));
    key(&mut a, KeyCode::Char('y'));
    assert!((a.body.get(Param::BodyMass) - 78.75).abs() < 1e-12);
    assert!(!a.modified());
    assert_eq!(a.path.as_deref(), Some(path.as_path()));
    // saving over another existing file asks for a second Enter
    let other = dir.path().join("other.toml");
    std::fs::write(&other, "keep me").expect("write");
    ctrl(&mut a, 's');
    if let Some(f) = a.field.as_mut() {
        f.set_text(other.display().to_string());
    }
    key(&mut a, KeyCode::Enter);
    assert!(
        a.field
            .as_ref()
            .and_then(|f| f.error.as_deref())
            .is_some_and(|e| e.contains("exists"))
    );
    assert_eq!(
        std::fs::read_to_string(&other).ok().as_deref(),
        Some("keep me")
    );
    key(&mut a, KeyCode::Enter);
    assert!(a.field.is_none());
    assert!(Preset::load(&other).is_ok());
    assert_eq!(a.path.as_deref(), Some(other.as_path()));
    // a save to an impossible path is refused and the prompt stays
    ctrl(&mut a, 's');
    if let Some(f) = a.field.as_mut() {
        f.set_text(dir.path().join("no/such/dir/x.toml").display().to_string());
    }
    key(&mut a, KeyCode::Enter);
    assert!(a.field.as_ref().is_some_and(|f| f.error.is_some()));
}

#[test]
fn open_dialog_lists_builtins_and_reports_errors() {
    let mut a = app();
    ctrl(&mut a, 'o');
    let s = screen(&a, 80, 24);
    assert!(s.contains("paper-65kg (built-in)"), "{s}");
    if let super::app::Overlay::Open(d) = &mut a.overlay {
        d.field.set_text("/nonexistent/preset.toml");
    }
    key(&mut a, KeyCode::Enter);
    let s = screen(&a, 80, 24);
    assert!(s.contains("refused"), "{s}");
    key(&mut a, KeyCode::Esc);
    ctrl(&mut a, 'o');
    // pick the 65 kg built-in from the list
    let idx = match &a.overlay {
        super::app::Overlay::Open(d) => d.entries.iter().position(|e| e.1 == "paper-65kg"),
        _ => None,
    }
    .expect("65 kg entry");
    for _ in 0..=idx {
        key(&mut a, KeyCode::Down);
    }
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.body.get(Param::BodyMass), 65.0);
    assert!(screen(&a, 80, 24).contains("paper-65kg (built-in)"));
    // a preset with segment masses and no shares: the study starts on k4
    let mut b = App::open("boileau-rakheja-1998", Theme::default()).expect("built-in");
    assert_eq!(b.study.param(), Param::Stiffness(3));
    assert!(b.study.result.is_ok());
    assert!(screen(&b, 80, 24).contains("no shares"));
    key(&mut b, KeyCode::Char('+')); // body mass cannot be nudged without shares
    assert!(
        b.status.error && b.status.text.contains("share"),
        "{:?}",
        b.status
    );
    assert!(!b.modified());
}

#[test]
fn quit_asks_with_unsaved_edits_and_ctrl_c_always_quits() {
    let mut a = app();
    key(&mut a, KeyCode::Char('q'));
    assert!(a.quit);
    let mut a = app();
    key(&mut a, KeyCode::Char('+'));
    key(&mut a, KeyCode::Char('q'));
    assert!(!a.quit);
    assert!(screen(&a, 80, 24).contains("unsaved edits"));
    key(&mut a, KeyCode::Char('n'));
    assert!(!a.quit);
    key(&mut a, KeyCode::Char('q'));
    key(&mut a, KeyCode::Char('y'));
    assert!(a.quit);
    let mut a = app();
    key(&mut a, KeyCode::Enter); // a field is open
    ctrl(&mut a, 'c');
    assert!(a.quit);
}

#[test]
fn help_comes_from_the_key_table() {
    let mut a = app();
    key(&mut a, KeyCode::Char('?'));
    let s = screen(&a, 100, 40);
    assert!(
        s.contains("Ctrl-S") && s.contains("raise the selected value by 5 %"),
        "{s}"
    );
    for _ in 0..200 {
        key(&mut a, KeyCode::Down);
    }
    let s = screen(&a, 100, 40);
    assert!(s.contains("close help"), "{s}");
    key(&mut a, KeyCode::Esc);
    assert_eq!(a.overlay, super::app::Overlay::None);
}

#[test]
fn selection_is_reverse_video_so_no_color_loses_nothing() {
    let mut a = App::new(
        Preset::builtin_default(),
        None,
        Theme {
            mono: true,
            ascii: true,
        },
    );
    key(&mut a, KeyCode::Down);
    let mut t = Terminal::new(TestBackend::new(80, 24)).expect("backend");
    t.draw(|f| super::draw(f, &a)).expect("draw");
    let buf = t.backend().buffer();
    let mut reversed = String::new();
    for y in 0..24 {
        for x in 0..80 {
            let c = &buf[(x, y)];
            assert_eq!(c.fg, ratatui::style::Color::Reset, "colour at {x},{y}");
            if c.modifier.contains(ratatui::style::Modifier::REVERSED) && y > 0 {
                reversed.push_str(c.symbol());
            }
        }
    }
    assert!(reversed.contains("5.625"), "{reversed:?}");
    assert!(buffer_text(buf).join("\n").is_ascii());
}

/// Feeds worker messages into `update` until `done` holds (or 20 s pass).
fn pump(a: &mut App, rx: &std::sync::mpsc::Receiver<Msg>, done: impl Fn(&App) -> bool) {
    let end = std::time::Instant::now() + std::time::Duration::from_secs(20);
    while !done(a) && std::time::Instant::now() < end {
        if let Ok(m) = rx.recv_timeout(std::time::Duration::from_millis(20)) {
            update(a, m);
        }
    }
    assert!(done(a), "timed out waiting for the worker");
}

fn epoch(a: &App) -> u64 {
    a.training
        .run
        .as_ref()
        .and_then(|r| r.last.as_ref())
        .map_or(0, |p| p.epoch)
}

#[test]
fn training_starts_pauses_resumes_stops_and_keeps_the_result() {
    let (tx, rx) = std::sync::mpsc::channel();
    let mut a = app();
    a.tx = Some(tx);
    key(&mut a, KeyCode::Char('4'));
    for _ in 0..3 {
        key(&mut a, KeyCode::Right); // mass-stht → k4-stht
    }
    assert_eq!(a.training.case, biodyn::ann::Case::K4Stht);
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Left); // lm → backprop
    assert_eq!(a.training.settings.trainer, biodyn::ann::Trainer::Backprop);
    for _ in 0..7 {
        key(&mut a, KeyCode::Down); // epoch limit
    }
    key(&mut a, KeyCode::Enter);
    for _ in 0..10 {
        key(&mut a, KeyCode::Backspace);
    }
    typ(&mut a, "50000000");
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.training.settings.epochs, 50_000_000);
    key(&mut a, KeyCode::Char('t'));
    assert!(a.training.running());
    pump(&mut a, &rx, |a| epoch(a) > 0);
    let rms0 = a
        .training
        .run
        .as_ref()
        .and_then(|r| r.last.as_ref())
        .map(|p| p.rms);
    assert!(screen(&a, 80, 24).contains("running"));
    key(&mut a, KeyCode::Char(' '));
    pump(&mut a, &rx, |a| {
        a.training
            .run
            .as_ref()
            .and_then(|r| r.last.as_ref())
            .is_some_and(|p| p.paused)
    });
    let e_paused = epoch(&a);
    assert!(screen(&a, 80, 24).contains("paused"));
    assert!(screen(&a, 80, 24).contains("whole run"));
    key(&mut a, KeyCode::Char('v'));
    assert!(screen(&a, 80, 24).contains("recent window"));
    key(&mut a, KeyCode::Char('v'));
    // other tabs keep working and show the run on the status line
    key(&mut a, KeyCode::Char('2'));
    assert!(screen(&a, 120, 30).contains("paused k4-stht"));
    key(&mut a, KeyCode::Char('4'));
    key(&mut a, KeyCode::Char(' '));
    pump(&mut a, &rx, |a| epoch(a) > e_paused);
    let rms1 = a
        .training
        .run
        .as_ref()
        .and_then(|r| r.last.as_ref())
        .map(|p| p.rms);
    assert_ne!(rms0, rms1, "the RMS moved");
    key(&mut a, KeyCode::Char('s'));
    pump(&mut a, &rx, |a| !a.training.running());
    let run = a.training.run.as_ref().expect("run kept");
    let out = run.outcome.as_ref().expect("outcome kept");
    assert_eq!(out.stop, biodyn::ann::StopReason::Cancelled);
    assert_eq!(out.holdout.len(), 4);
    assert!(run.prediction.is_some());
    for (w, h) in [(80, 24), (160, 48)] {
        let s = screen(&a, w, h);
        assert!(s.contains("ended: cancelled"), "{s}");
        assert!(s.contains("interp") && s.contains("extrap"), "{s}");
    }
    // the held-out value picks another prediction
    let before = run.prediction.as_ref().map(|p| p.value);
    key(&mut a, KeyCode::Up); // epoch limit (8) → 7, then down to the held-out value (10)
    for _ in 0..3 {
        key(&mut a, KeyCode::Down);
    }
    assert_eq!(a.training.row, 10);
    key(&mut a, KeyCode::Right);
    let after = a
        .training
        .run
        .as_ref()
        .and_then(|r| r.prediction.as_ref())
        .map(|p| p.value);
    assert_ne!(before, after);
    // save the network
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("net.json");
    key(&mut a, KeyCode::Char('w'));
    if let Some(f) = a.field.as_mut() {
        f.set_text(path.display().to_string());
    }
    key(&mut a, KeyCode::Enter);
    assert!(a.field.is_none(), "{:?}", a.field);
    assert!(biodyn::ann::netfile::load(&path).is_ok());
}

#[test]
fn bad_training_settings_are_refused() {
    let mut a = app();
    key(&mut a, KeyCode::Char('4'));
    for _ in 0..4 {
        key(&mut a, KeyCode::Down); // momentum
    }
    key(&mut a, KeyCode::Enter);
    for _ in 0..10 {
        key(&mut a, KeyCode::Backspace);
    }
    typ(&mut a, "1.5");
    key(&mut a, KeyCode::Enter);
    assert!(a.field.as_ref().is_some_and(|f| f.error.is_some()));
    assert_eq!(a.training.settings.momentum, 0.9);
    key(&mut a, KeyCode::Esc);
    key(&mut a, KeyCode::Up);
    key(&mut a, KeyCode::Up); // layers
    key(&mut a, KeyCode::Enter);
    for _ in 0..20 {
        key(&mut a, KeyCode::Backspace);
    }
    typ(&mut a, "3-4-1");
    key(&mut a, KeyCode::Enter);
    let e = a
        .field
        .as_ref()
        .and_then(|f| f.error.clone())
        .unwrap_or_default();
    assert!(e.contains('5') || e.contains("input"), "{e}");
}

#[test]
#[ignore = "prints the key table as Markdown for README-tui.md"]
fn key_table_markdown() {
    for (heading, keys, what) in super::keys::help_lines() {
        match heading {
            Some(h) => println!("\n**{h}**\n\n| keys | what |\n|---|---|"),
            None => println!("| {} | {what} |", keys.replace('|', "\\|")),
        }
    }
}
