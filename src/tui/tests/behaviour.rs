//! Key sequences through `update` and what the screen then shows (the
//! tests from before the tabs became components, with their meaning).

use super::*;
use crate::tui::popups::Overlay;
use crate::tui::popups::field::Purpose;
use biodyn::{Function, Param};

#[test]
#[ignore = "prints screens for a look"]
fn show() {
    let mut a = app();
    for i in 0..a.tabs.len() {
        key(&mut a, KeyCode::Char(char::from(b'1' + i as u8)));
        println!("{}\n", screen(&a, 80, 24));
        println!("{}\n", screen(&a, 160, 48));
        println!("{}\n", screen(&a, 60, 16));
    }
}

fn stht_at_cursor(app: &App) -> f64 {
    derived(app).curve[responses(app).cursor].mag(Function::Stht)
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
            "65 kg",
            "85 kg",
            "as body mass rises",
            "peak magnitude",
            "rises",
            "falls",
        ] {
            assert!(s.contains(want), "{w}x{h} study tab lacks {want:?}:\n{s}");
        }
        key(&mut a, KeyCode::Char('4'));
        let s = screen(&a, w, h);
        for want in ["mass-stht", "layers", "held-out value", "t starts"] {
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
    let before = derived(&a).curve.clone();
    let peak_before = derived(&a).first_main().map(|p| p.f_hz);
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
    assert_eq!(a.shared.body.get(Param::Mass(1)), 40.0);
    assert_ne!(derived(&a).curve, before);
    assert_ne!(derived(&a).first_main().map(|p| p.f_hz), peak_before);
    assert!(a.modified());
    assert!(screen(&a, 120, 30).contains("(built-in) *modified"));
    // undo brings the old curve back, clears the modified mark and says what it undid
    key(&mut a, KeyCode::Char('u'));
    assert_eq!(derived(&a).curve, before);
    assert!(!a.modified());
    assert_eq!(a.status.text, "undid m2 30.15 → 40 (^R redoes it)");
    ctrl(&mut a, 'r');
    assert_eq!(a.shared.body.get(Param::Mass(1)), 40.0);
    assert_eq!(a.status.text, "redid m2 30.15 → 40");
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
    let e = field_error(&a);
    assert!(e.contains("mass") && e.contains("> 0"), "{e}");
    assert_eq!(a.shared.body.get(Param::Mass(0)), 5.625);
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
        Some(Purpose::Param(Param::Stiffness(3)))
    ));
    for _ in 0..10 {
        key(&mut a, KeyCode::Backspace);
    }
    typ(&mut a, "-1");
    key(&mut a, KeyCode::Enter);
    assert!(a.field.as_ref().is_some_and(|f| f.error.is_some()));
    assert_eq!(a.shared.body.get(Param::Stiffness(3)), 90_000.0);
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
    key(&mut a, KeyCode::Up); // the last setting
    let last = training(&a).current().name();
    let s = screen(&a, 60, 16);
    assert!(s.contains(last), "{last}: {s}");
}

#[test]
fn nudge_and_body_mass_rescale() {
    let mut a = app();
    key(&mut a, KeyCode::Char('+'));
    let b = &a.shared.body;
    assert!((b.get(Param::BodyMass) - 78.75).abs() < 1e-9);
    assert!((b.get(Param::Mass(0)) - 0.075 * 78.75).abs() < 1e-9);
    assert_eq!(a.status.text, "body mass = 78.75 kg");
    key(&mut a, KeyCode::Char('-'));
    assert!((a.shared.body.get(Param::BodyMass) - 75.0).abs() < 1e-9);
    // + + - on k1 (1299.9 in the issue): one step up from where it began
    for _ in 0..5 {
        key(&mut a, KeyCode::Down);
    }
    let k = a.shared.body.get(Param::Stiffness(0));
    for c in ['+', '+', '-'] {
        key(&mut a, KeyCode::Char(c));
    }
    let got = a.shared.body.get(Param::Stiffness(0));
    assert!((got / (k * 1.05) - 1.0).abs() < 1e-12, "{got} vs {k}");
}

#[test]
fn cursor_reads_all_three_and_moves() {
    let mut a = app();
    key(&mut a, KeyCode::Char('2'));
    let f0 = derived(&a).curve[responses(&a).cursor].f_hz;
    let v0 = stht_at_cursor(&a);
    key(&mut a, KeyCode::Right);
    let f1 = derived(&a).curve[responses(&a).cursor].f_hz;
    assert!((f1 - f0 - 0.1).abs() < 1e-9);
    assert_ne!(v0, stht_at_cursor(&a));
    key(&mut a, KeyCode::End);
    assert!(screen(&a, 80, 24).contains("f 20 Hz"));
    key(&mut a, KeyCode::Char('p'));
    assert!(screen(&a, 80, 24).contains("phase"));
    key(&mut a, KeyCode::Char('a'));
    assert!(responses(&a).log);
    let _ = screen(&a, 160, 48);
    // n walks the peaks of all three functions in frequency order
    key(&mut a, KeyCode::Home);
    key(&mut a, KeyCode::Char('n'));
    let first = derived(&a)
        .functions
        .iter()
        .flat_map(|c| c.peaks.iter().map(|p| p.f_hz))
        .fold(f64::INFINITY, f64::min);
    let at = derived(&a).curve[responses(&a).cursor].f_hz;
    assert!((at - first).abs() <= 0.05 + 1e-9, "{at} vs {first}");
}

#[test]
fn study_values_are_edited_and_bad_lists_refused() {
    let mut a = app();
    key(&mut a, KeyCode::Char('3'));
    // go to k4 (body mass, m1..m4, k1..k4)
    for _ in 0..8 {
        key(&mut a, KeyCode::Right);
    }
    assert_eq!(study(&a).param(), Param::Stiffness(3));
    assert_eq!(study(&a).values, "-40%,0%,+40%");
    let s = screen(&a, 80, 24);
    assert!(s.contains("k4 B.V. +40% (126000)"), "{s}");
    key(&mut a, KeyCode::Enter);
    key(&mut a, KeyCode::End); // keep the list, append to it
    typ(&mut a, ",x");
    key(&mut a, KeyCode::Enter);
    assert!(a.field.as_ref().is_some_and(|f| f.error.is_some()));
    key(&mut a, KeyCode::Backspace);
    typ(&mut a, "+80%");
    key(&mut a, KeyCode::Enter);
    assert!(a.field.is_none());
    let variants = |a: &App| {
        study(a)
            .result
            .as_ref()
            .and_then(|r| r.as_ref().ok())
            .map(|s| s.variants.len())
    };
    assert_eq!(variants(&a), Some(4));
    // the paper's three studies are one key each
    key(&mut a, KeyCode::Char('c'));
    assert_eq!(study(&a).param(), Param::Damping(3));
    let s = screen(&a, 80, 24);
    assert!(
        s.contains("c4 B.V. -40%") && s.contains("as c4 rises"),
        "{s}"
    );
    key(&mut a, KeyCode::Char('m'));
    assert_eq!(study(&a).param(), Param::BodyMass);
    key(&mut a, KeyCode::Char('k'));
    // the list typed for k4 is remembered; r goes back to the paper's
    assert_eq!(study(&a).values, "-40%,0%,+40%,+80%");
    assert_eq!(study(&a).param(), Param::Stiffness(3));
    key(&mut a, KeyCode::Char('r'));
    assert_eq!(study(&a).values, "-40%,0%,+40%");
    // a model edit reruns the study on the new body
    let before = study(&a).series.clone();
    key(&mut a, KeyCode::Char('1'));
    key(&mut a, KeyCode::Char('+'));
    assert_ne!(study(&a).series, before);
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
    if let Overlay::Open(d) = &mut a.overlay {
        d.field.set_text(path.display().to_string());
    } else {
        panic!("open dialog expected");
    }
    key(&mut a, KeyCode::Enter);
    assert!(matches!(a.overlay, Overlay::Confirm(..)));
    key(&mut a, KeyCode::Char('y'));
    assert!((a.shared.body.get(Param::BodyMass) - 78.75).abs() < 1e-12);
    assert!(!a.modified());
    assert_eq!(a.shared.path.as_deref(), Some(path.as_path()));
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
    assert_eq!(a.shared.path.as_deref(), Some(other.as_path()));
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
    if let Overlay::Open(d) = &mut a.overlay {
        d.field.set_text("/nonexistent/preset.toml");
    }
    key(&mut a, KeyCode::Enter);
    let s = screen(&a, 80, 24);
    assert!(s.contains("refused"), "{s}");
    key(&mut a, KeyCode::Esc);
    ctrl(&mut a, 'o');
    // pick the 65 kg built-in from the list
    let idx = match &a.overlay {
        Overlay::Open(d) => d.entries.iter().position(|e| e.1 == "paper-65kg"),
        _ => None,
    }
    .expect("65 kg entry");
    for _ in 0..=idx {
        key(&mut a, KeyCode::Down);
    }
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.shared.body.get(Param::BodyMass), 65.0);
    assert!(screen(&a, 80, 24).contains("paper-65kg (built-in)"));
    // a preset with segment masses and no shares: the study starts on k4
    let mut b = App::open("boileau-rakheja-1998", Theme::default()).expect("built-in");
    assert_eq!(study(&b).param(), Param::Stiffness(3));
    assert!(study(&b).result.as_ref().is_some_and(|r| r.is_ok()));
    for (w, h) in [(80, 24), (60, 16)] {
        let s = screen(&b, w, h);
        assert!(s.contains("= m1+…+m4 (no shares)"), "{s}");
        assert!(!s.contains("9.62"), "no share column without shares:\n{s}");
    }
    key(&mut b, KeyCode::Char('+')); // body mass cannot be nudged without shares
    assert!(
        b.status.error && b.status.text.contains("edit m1…m4"),
        "{:?}",
        b.status
    );
    key(&mut b, KeyCode::Enter);
    assert!(b.field.is_none() && b.status.text.contains("55.2 kg"));
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
fn help_comes_from_the_key_tables() {
    let mut a = app();
    key(&mut a, KeyCode::Char('?'));
    key(&mut a, KeyCode::Home);
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
    assert_eq!(a.overlay, Overlay::None);
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
    t.draw(|f| crate::tui::draw(f, &a)).expect("draw");
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

#[test]
fn typing_into_a_fresh_field_replaces_the_value() {
    let mut a = app();
    key(&mut a, KeyCode::Down);
    key(&mut a, KeyCode::Down); // m2
    key(&mut a, KeyCode::Enter);
    typ(&mut a, "35");
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.shared.body.get(Param::Mass(1)), 35.0);
    // arrows keep the value and edit in place; Ctrl-U / Ctrl-W / Alt-Backspace as in a shell
    key(&mut a, KeyCode::Enter);
    key(&mut a, KeyCode::Left);
    typ(&mut a, ".");
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.shared.body.get(Param::Mass(1)), 3.5);
    key(&mut a, KeyCode::Enter);
    key(&mut a, KeyCode::End);
    ctrl(&mut a, 'u');
    typ(&mut a, "40");
    ctrl(&mut a, 'a');
    typ(&mut a, "1");
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.shared.body.get(Param::Mass(1)), 140.0);
    key(&mut a, KeyCode::Enter);
    update(
        &mut a,
        Msg::Key(KeyEvent::new(KeyCode::Backspace, KeyModifiers::ALT)),
    );
    typ(&mut a, "2");
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.shared.body.get(Param::Mass(1)), 2.0);
}

#[test]
fn help_opens_at_the_tab_pages_and_searches() {
    let mut a = app();
    a.size = Some((80, 24));
    key(&mut a, KeyCode::Char('3'));
    key(&mut a, KeyCode::Char('?'));
    let s = screen(&a, 80, 24);
    let first_row = s.lines().nth(2).unwrap_or("");
    assert!(first_row.contains("3 Study"), "{s}");
    let Overlay::Help(h) = &a.overlay else {
        panic!("help not open")
    };
    let at = h.scroll;
    key(&mut a, KeyCode::PageDown);
    let Overlay::Help(h) = &a.overlay else {
        panic!("help not open")
    };
    assert_eq!(h.scroll, at + 18);
    key(&mut a, KeyCode::Home);
    typ(&mut a, "/redo");
    key(&mut a, KeyCode::Enter);
    let s = screen(&a, 80, 24);
    assert!(s.lines().nth(2).unwrap_or("").contains("Ctrl-R"), "{s}");
    typ(&mut a, "n");
    let Overlay::Help(h) = &a.overlay else {
        panic!("help not open")
    };
    assert!(h.scroll > 0);
    key(&mut a, KeyCode::Esc); // clears the search
    key(&mut a, KeyCode::Esc); // closes
    assert_eq!(a.overlay, Overlay::None);
}

#[test]
fn keys_wait_while_the_terminal_is_too_small() {
    let mut a = app();
    a.size = Some((40, 10));
    key(&mut a, KeyCode::Char('2'));
    key(&mut a, KeyCode::Char('?'));
    assert_eq!((a.current, &a.overlay), (0, &Overlay::None));
    update(&mut a, Msg::Resize(80, 24));
    key(&mut a, KeyCode::Char('2'));
    assert_eq!(a.current, 1);
}

#[test]
fn messages_expire_and_stay_on_their_tab() {
    let mut a = app();
    key(&mut a, KeyCode::Char('u'));
    assert_eq!(a.status.text, "nothing to undo");
    assert!(!a.expire(a.status.at));
    assert!(a.expire(a.status.at + crate::tui::app::ERROR_TTL));
    assert_eq!(a.status.text, "");
    key(&mut a, KeyCode::Char('u'));
    key(&mut a, KeyCode::Char('2'));
    assert!(!screen(&a, 80, 24).contains("nothing to undo"));
}

#[test]
fn loading_a_preset_is_undoable() {
    let mut a = app();
    key(&mut a, KeyCode::Char('+'));
    ctrl(&mut a, 'o');
    if let Overlay::Open(d) = &mut a.overlay {
        d.field.set_text("paper-65kg");
    }
    key(&mut a, KeyCode::Enter);
    key(&mut a, KeyCode::Char('y'));
    assert_eq!(a.shared.preset.name, "paper-65kg");
    key(&mut a, KeyCode::Char('u'));
    assert_eq!(a.shared.preset.name, "paper-75kg");
    assert!(a.modified(), "the unsaved edit comes back with the model");
    assert_eq!(
        a.status.text,
        "undid open paper-65kg (built-in) (^R redoes it)"
    );
}

#[test]
fn study_lists_take_tabs_spaces_semicolons_and_one_value_says_so() {
    let mut a = app();
    key(&mut a, KeyCode::Char('3'));
    key(&mut a, KeyCode::Enter);
    // a pasted spreadsheet row: 65<TAB>75<TAB>85
    typ(&mut a, "65");
    key(&mut a, KeyCode::Tab);
    typ(&mut a, "75");
    key(&mut a, KeyCode::Tab);
    typ(&mut a, "85");
    key(&mut a, KeyCode::Enter);
    assert_eq!(study(&a).values, "65,75,85");
    key(&mut a, KeyCode::Enter);
    typ(&mut a, "60; 70 80 %");
    key(&mut a, KeyCode::Enter);
    assert_eq!(study(&a).values, "60,70,80%");
    for list in ["5%", "75,75"] {
        key(&mut a, KeyCode::Enter);
        typ(&mut a, list);
        key(&mut a, KeyCode::Enter);
        let s = screen(&a, 80, 24);
        assert!(s.contains("nothing to compare"), "{list}:\n{s}");
        assert!(!s.contains("flat"), "{list}:\n{s}");
    }
    // a custom list survives cycling the parameter
    key(&mut a, KeyCode::Right);
    key(&mut a, KeyCode::Left);
    assert_eq!(study(&a).values, "75,75");
}

#[test]
fn eleven_study_variants_keep_a_framed_chart_and_the_trends_at_80x24() {
    let mut a = app();
    key(&mut a, KeyCode::Char('3'));
    key(&mut a, KeyCode::Enter);
    typ(&mut a, "50,55,60,65,70,75,80,85,90,95,100");
    key(&mut a, KeyCode::Enter);
    let s = screen(&a, 80, 24);
    let framed = s.lines().filter(|l| l.starts_with('│')).count();
    assert!(framed >= 14, "{s}");
    assert!(s.contains("STHT magnitude"), "{s}");
    assert!(s.contains("peak magnitude") && s.contains("1–"), "{s}");
    assert!(s.contains("/11 ↑↓"), "{s}");
    assert!(!s.contains("100 kg"), "{s}");
    for _ in 0..20 {
        key(&mut a, KeyCode::Down);
    }
    let s = screen(&a, 80, 24);
    assert!(s.contains("100 kg") && s.contains("–11/11"), "{s}");
}

#[test]
fn z_zooms_the_tabs_chart_and_esc_comes_back() {
    let mut a = app();
    key(&mut a, KeyCode::Char('3'));
    key(&mut a, KeyCode::Char('z'));
    assert!(a.zoom);
    let s = screen(&a, 80, 24);
    assert!(
        s.contains("STHT magnitude") && !s.contains("main peaks and trends"),
        "{s}"
    );
    key(&mut a, KeyCode::Esc);
    assert!(!a.zoom);
    key(&mut a, KeyCode::Char('1'));
    key(&mut a, KeyCode::Char('z'));
    assert!(
        screen(&a, 80, 24).contains("STHT (seat-to-head"),
        "{}",
        screen(&a, 80, 24)
    );
    key(&mut a, KeyCode::Char('z'));
    assert!(!a.zoom);
}

#[test]
fn saving_refreshes_a_stale_description_and_keeps_the_name() {
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("heavier.toml");
    let mut a = app();
    key(&mut a, KeyCode::Enter);
    typ(&mut a, "85");
    key(&mut a, KeyCode::Enter);
    ctrl(&mut a, 's');
    if let Some(f) = a.field.as_mut() {
        f.set_text(path.display().to_string());
    }
    key(&mut a, KeyCode::Enter);
    assert!(a.field.is_none(), "{:?}", a.field);
    let p = Preset::open(&path.display().to_string()).expect("saved preset");
    assert_eq!(p.name, "paper-75kg");
    assert!(
        p.description.contains("x 85 kg") && !p.description.contains("75 kg"),
        "{}",
        p.description
    );
    // a folder is refused at once, not after "Enter again replaces it"
    ctrl(&mut a, 's');
    if let Some(f) = a.field.as_mut() {
        f.set_text(dir.path().display().to_string());
    }
    key(&mut a, KeyCode::Enter);
    let e = field_error(&a);
    assert!(e.contains("Is a directory"), "{e}");
}

#[test]
fn popups_clear_their_rows_and_open_errors_wrap() {
    let mut a = app();
    ctrl(&mut a, 'o');
    let s = screen(&a, 80, 24);
    let row = s
        .lines()
        .find(|l| l.contains("open preset"))
        .unwrap_or_default()
        .to_string();
    // nothing of the panels behind shows beside the popup's frame
    assert_eq!(row.trim_end().chars().last(), Some('┐'), "{row}");
    assert!(row.starts_with("  ┌"), "{row}");
    if let Overlay::Open(d) = &mut a.overlay {
        d.field
            .set_text("/nonexistent/a-long-folder-name/and-a-longer-preset-name.toml");
    }
    key(&mut a, KeyCode::Enter);
    let s = screen(&a, 80, 24);
    assert!(s.contains("(os error 2)"), "the whole reason shows:\n{s}");
}

#[test]
fn a_damping_refusal_quotes_the_damping_range_only() {
    let mut a = app();
    for _ in 0..8 {
        key(&mut a, KeyCode::Down); // k4
    }
    key(&mut a, KeyCode::Right); // c4
    key(&mut a, KeyCode::Enter);
    typ(&mut a, "-1");
    key(&mut a, KeyCode::Enter);
    let e = field_error(&a);
    assert!(e.contains("damping must be in [0, 1e10] N·s/m"), "{e}");
    assert!(!e.contains("stiffness"), "{e}");
    key(&mut a, KeyCode::Esc);
    key(&mut a, KeyCode::Left); // k4
    key(&mut a, KeyCode::Enter);
    typ(&mut a, "2e12");
    key(&mut a, KeyCode::Enter);
    let e = field_error(&a);
    assert!(
        e.contains("stiffness must be in [0, 1e12] N/m") && !e.contains("damping"),
        "{e}"
    );
}

/// In ASCII an arrow would become `<` `>` `^` `v`, which are keys of their
/// own (the Study tab's cursor is `<` `>`): the hint bar and the `?` page
/// spell the arrows out.
#[test]
fn ascii_spells_out_arrow_keys_where_they_would_read_as_keys() {
    let mut a = App::new(
        Preset::builtin_default(),
        None,
        Theme {
            mono: true,
            ascii: true,
        },
    );
    key(&mut a, KeyCode::Char('3'));
    let s = screen(&a, 200, 30);
    let hints = s.lines().last().unwrap_or_default();
    assert!(hints.contains("Left/Right parameter"), "{hints}");
    assert!(hints.contains("<> cursor"), "{hints}");
    assert!(!hints.contains("<> parameter"), "{hints}");
    key(&mut a, KeyCode::Char('?'));
    let s = screen(&a, 100, 40);
    assert!(s.contains("Left / h"), "{s}");
    assert!(s.contains("Up/Down PgUp/PgDn"), "{s}");
    assert!(!s.contains("< / h"), "{s}");
}

/// The same for the edit field's own hint and for arrows side by side in
/// the hint bar (the Model tab's "↑↓←→ move"): each arrow a word, `/`
/// between them.
#[test]
fn ascii_spells_out_the_field_hint_and_joined_arrows() {
    let mut a = App::new(
        Preset::builtin_default(),
        None,
        Theme {
            mono: true,
            ascii: true,
        },
    );
    let s = screen(&a, 80, 24);
    let hints = s.lines().last().unwrap_or_default();
    assert!(hints.contains("Up/Down/Left/Right move"), "{hints}");
    key(&mut a, KeyCode::Enter); // body mass
    let s = screen(&a, 80, 24);
    assert!(s.contains("(type to replace, Left to edit)"), "{s}");
    assert!(!s.contains("< to edit"), "{s}");
    assert_eq!(
        crate::tui::keys::ascii_arrows("↑↓←→ move, ◀ back"),
        "Up/Down/Left/Right move, Left back"
    );
}
