//! The Seat tab: with and without a seat, at both sizes, in colour and
//! ASCII (insta snapshots); its keys; its numbers against the library's
//! (`SeatGrid::figures`, `seat::design`), also after an edit on the Model
//! tab; the Model tab's structure edits on a seat model.

use super::SeatTab;
use super::compute;
use crate::tui::app::App;
use crate::tui::effect::Effect;
use crate::tui::tests::{app, key, screen, typ};
use crate::tui::theme::Theme;
use biodyn::seat::{FloorPsd, SeatGrid, design};
use biodyn::time::{CLASSES, InputClass};
use biodyn::{Body, Preset};
use ratatui::crossterm::event::KeyCode;

const SIZES: [(u16, u16); 2] = [(80, 24), (160, 48)];
const ASCII: Theme = Theme {
    mono: false,
    ascii: true,
};

pub fn seat_app(theme: Theme) -> App {
    let p = Preset::builtin("paper-75kg-suspension-seat")
        .and_then(Result::ok)
        .expect("the shipped seat preset");
    App::new(p, None, theme)
}

fn seat_tab(a: &App) -> &SeatTab {
    a.tab_state().expect("seat tab")
}

/// Opens the Seat tab (the last one).
fn open(a: &mut App) {
    let n = a.tabs.len();
    key(a, KeyCode::Char(char::from(b'0' + n as u8)));
    assert_eq!(a.tab().title(), "Seat");
}

fn snap(name: &str, a: &App) {
    for (w, h) in SIZES {
        insta::assert_snapshot!(format!("{name}_{w}x{h}"), screen(a, w, h));
    }
}

/// The library's figures of `body` under `class`.
fn figures(body: &Body, class: &str) -> biodyn::seat::SeatFigures {
    let c = InputClass::parse(class).expect("class");
    let grid = SeatGrid::new(&FloorPsd::Class(c)).expect("grid");
    grid.figures(body).expect("figures")
}

#[test]
fn the_seat_tab_with_a_seat_in_colour_and_ascii() {
    let mut a = seat_app(Theme::default());
    open(&mut a);
    snap("seat_tab", &a);
    let mut a = seat_app(ASCII);
    open(&mut a);
    snap("seat_tab_ascii", &a);
    for (w, h) in SIZES {
        let s = screen(&a, w, h);
        assert!(s.is_ascii(), "ASCII at {w}x{h}:\n{s}");
    }
}

#[test]
fn the_seat_tab_without_a_seat_says_how_to_load_one() {
    for (theme, name) in [(Theme::default(), "seat_tab_no_seat"), (ASCII, "seat_tab_no_seat_ascii")] {
        let mut a = App::new(Preset::builtin_default(), None, theme);
        open(&mut a);
        snap(name, &a);
        let s = screen(&a, 80, 24);
        assert!(s.contains("this model has no seat"), "{s}");
        assert!(s.contains("paper-75kg-suspension-seat"), "{s}");
        // Its keys say why they do nothing.
        key(&mut a, KeyCode::Char('s'));
        assert!(a.status.error && a.status.text.contains("no seat"), "{:?}", a.status);
        assert!(a.field.is_none());
    }
}

#[test]
fn arrows_select_a_class_and_its_numbers_are_the_librarys() {
    let mut a = seat_app(Theme::default());
    open(&mut a);
    assert_eq!(CLASSES[seat_tab(&a).class].name, "EM6");
    key(&mut a, KeyCode::Right);
    assert_eq!(CLASSES[seat_tab(&a).class].name, "EM7");
    key(&mut a, KeyCode::Home);
    assert_eq!(seat_tab(&a).class, 0);
    key(&mut a, KeyCode::Left); // wraps to the last
    assert_eq!(CLASSES[seat_tab(&a).class].name, "AG3");
    key(&mut a, KeyCode::Char('h'));
    assert_eq!(CLASSES[seat_tab(&a).class].name, "AG2");
    let d = seat_tab(&a).data.as_ref().expect("data");
    let want = figures(&a.shared.body, "AG2");
    assert_eq!(d.classes[14].as_ref().ok(), Some(&want));
    // The stroke panel and the map are the selected class's.
    let s = screen(&a, 160, 48);
    assert!(s.contains("AG2 ISO 5007:2003"), "{s}");
    assert!(s.contains("design map AG2"), "{s}");
    let seat = crate::view::format::num(want.seat_pct, 4);
    assert!(s.contains(&format!("SEAT {seat} %")), "{seat}\n{s}");
    // The map is the library's search for that class over ×1/4 … ×4.
    let grid = SeatGrid::new(&FloorPsd::Class(&CLASSES[14])).expect("grid");
    let vary = compute::box_of(&a.shared.body, [8000.0, 800.0]).expect("box");
    let lib = design(&a.shared.body, &grid, &vary, 0.1 / 6.0).expect("design");
    assert_eq!(d.design.as_ref().ok(), Some(&lib));
}

/// The suspension's k typed on the Model tab: the Seat tab's figures are
/// the library's for the edited body, and the map keeps its box (the
/// current point moves in it).
#[test]
fn editing_the_suspension_on_the_model_tab_updates_the_seat_tab() {
    let mut a = seat_app(Theme::default());
    let before = seat_tab(&a).data.clone().expect("data");
    key(&mut a, KeyCode::Char('1'));
    key(&mut a, KeyCode::Home);
    for _ in 0..12 {
        key(&mut a, KeyCode::Down); // row 12: link 6, suspension
    }
    key(&mut a, KeyCode::Enter); // k
    typ(&mut a, "12000");
    key(&mut a, KeyCode::Enter);
    assert!(!a.status.error, "{:?}", a.status);
    assert_eq!(a.shared.body.links[5].k, 12000.0);
    open(&mut a);
    let d = seat_tab(&a).data.as_ref().expect("data");
    for (c, got) in CLASSES.iter().zip(&d.classes) {
        assert_eq!(got.as_ref().ok(), Some(&figures(&a.shared.body, c.name)), "{}", c.name);
    }
    assert_ne!(d.classes[5], before.classes[5], "EM6 changed");
    assert_eq!(d.centre, [8000.0, 800.0], "the box stays");
    assert_eq!(d.now, [12000.0, 800.0]);
    let s = screen(&a, 160, 48);
    assert!(s.contains("k 12000 N/m"), "{s}");
    let seat = crate::view::format::num(figures(&a.shared.body, "EM6").seat_pct, 4);
    assert!(s.contains(&format!("SEAT {seat} %")), "{s}");
    // Undo brings the old figures back; `c` lays the box around k now.
    key(&mut a, KeyCode::Char('u'));
    assert_eq!(seat_tab(&a).data.as_ref().expect("data").classes, before.classes);
    key(&mut a, KeyCode::Char('1'));
    key(&mut a, KeyCode::Enter);
    typ(&mut a, "40000");
    key(&mut a, KeyCode::Enter);
    open(&mut a);
    // 40000 is past 8000 × 4: the box follows it.
    assert_eq!(seat_tab(&a).data.as_ref().expect("data").centre, [40000.0, 800.0]);
}

#[test]
fn the_stroke_limit_is_editable_and_checked() {
    let mut a = seat_app(Theme::default());
    open(&mut a);
    assert!(screen(&a, 80, 24).contains("limit 16.7 mm = stroke/6"));
    key(&mut a, KeyCode::Home); // EM1: the travel matters
    key(&mut a, KeyCode::Char('s'));
    assert!(a.field.is_some());
    typ(&mut a, "0 mm");
    key(&mut a, KeyCode::Enter);
    let err = crate::tui::tests::field_error(&a);
    assert!(err.contains("stroke limit '0 mm'"), "{err}");
    key(&mut a, KeyCode::Esc);
    key(&mut a, KeyCode::Char('s'));
    typ(&mut a, "4");
    key(&mut a, KeyCode::Enter);
    assert!(a.field.is_none());
    let t = seat_tab(&a);
    assert_eq!(t.limit_m, Some(0.004));
    let d = t.data.as_ref().expect("data");
    assert_eq!(d.limit_m, 0.004);
    match &d.design {
        Ok(design) => assert!(design.best.figures.stroke_rms_m <= 0.004),
        Err(e) => assert!(e.contains("no point of the box"), "{e}"),
    }
    assert!(screen(&a, 160, 48).contains("limit 4 mm r.m.s. (typed)"));
    // Empty: back to stroke/6.
    key(&mut a, KeyCode::Char('s'));
    for _ in 0..3 {
        key(&mut a, KeyCode::Backspace);
    }
    key(&mut a, KeyCode::Enter);
    assert_eq!(seat_tab(&a).limit_m, None);
    assert_eq!(seat_tab(&a).data.as_ref().expect("data").limit_m, 0.1 / 6.0);
}

#[test]
fn x_exports_the_figures_per_class_and_the_charts_as_text() {
    let a = seat_app(Theme::default());
    let t = seat_tab(&a);
    let effects = super::export::effects(t, &a.shared);
    let [Effect::Export(e)] = effects.as_slice() else {
        panic!("{effects:?}");
    };
    assert_eq!(e.path_hint, "paper-75kg-suspension-seat-seat.csv");
    let csv = &e.formats[0].contents;
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(lines.len(), 17, "{csv}");
    let f = figures(&a.shared.body, "EM6");
    assert_eq!(
        lines[6],
        format!(
            "EM6,ISO 7096:2000,{},{},{},{},{},",
            f.seat_pct, f.pan_aw_m_s2, f.floor_aw_m_s2, f.stroke_rms_m, f.stroke_available_m
        )
    );
    let txt = &e.formats[1].contents;
    assert!(txt.is_ascii());
    assert!(txt.contains("design map EM6") && txt.contains("seat transmissibility"), "{txt}");
    assert_eq!(txt.lines().count(), 48);
    // Without a seat: said, no export.
    let b = app();
    let t: &SeatTab = b.tab_state().expect("seat tab");
    let effects = super::export::effects(t, &b.shared);
    assert!(matches!(effects.as_slice(), [Effect::Error(e)] if e.contains("no seat")));
}

/// The Model tab's refusal of the pending delete.
fn refusal(a: &App) -> String {
    let m: &crate::tui::tabs::model::ModelTab = a.tab_state().expect("model tab");
    m.refusal.clone().unwrap_or_default()
}

fn select(a: &mut App, row: usize) {
    key(a, KeyCode::Char('1'));
    key(a, KeyCode::Home);
    for _ in 0..row {
        key(a, KeyCode::Down);
    }
}

/// Deletes keep `Body.seat` right: the pan and the suspension follow the
/// removal, and deleting either is refused with the reason.
#[test]
fn model_tab_structure_edits_keep_the_seat_right() {
    let mut a = seat_app(Theme::default());
    let before = a.shared.body.clone();
    // The pan (m5, row 5) and the frame (m6: its link is the suspension).
    select(&mut a, 5);
    key(&mut a, KeyCode::Char('d'));
    key(&mut a, KeyCode::Char('y'));
    assert!(a.status.error);
    assert!(refusal(&a).starts_with("'pad' is the seat's pan"));
    key(&mut a, KeyCode::Esc);
    select(&mut a, 6);
    key(&mut a, KeyCode::Char('d'));
    key(&mut a, KeyCode::Char('y'));
    assert!(refusal(&a).contains("the seat's suspension link 'suspension'"));
    key(&mut a, KeyCode::Esc);
    // The suspension link (link 6, row 12).
    select(&mut a, 12);
    key(&mut a, KeyCode::Char('d'));
    key(&mut a, KeyCode::Char('y'));
    assert!(refusal(&a).starts_with("'suspension' is the seat's suspension"));
    key(&mut a, KeyCode::Esc);
    assert_eq!(a.shared.body, before);
    // The lower torso (m3) goes, its links rejoined: pan and suspension
    // move down by one each and still name the pad and the suspension.
    select(&mut a, 3);
    key(&mut a, KeyCode::Char('d'));
    key(&mut a, KeyCode::Char('y'));
    assert!(!a.status.error, "{:?}", a.status);
    let b = &a.shared.body;
    b.validate().expect("valid");
    let seat = b.seat.as_ref().expect("seat");
    assert_eq!(b.segments[seat.pan].name, "pad");
    assert_eq!(b.links[seat.suspension].name, "suspension");
    assert_eq!((seat.pan, seat.suspension), (3, 4));
    // The Seat tab follows, with the library's numbers for the new body.
    let d = seat_tab(&a).data.as_ref().expect("data");
    assert_eq!(d.classes[5].as_ref().ok(), Some(&figures(b, "EM6")));
    // A link before the suspension goes: its index follows.
    key(&mut a, KeyCode::Char('u'));
    key(&mut a, KeyCode::Char('A'));
    typ(&mut a, "head-neck chest 1e5 500 extra");
    key(&mut a, KeyCode::Enter);
    assert!(!a.status.error, "{:?}", a.status);
    select(&mut a, 7); // link 1 head-neck-chest
    key(&mut a, KeyCode::Char('d'));
    key(&mut a, KeyCode::Char('y'));
    assert!(!a.status.error, "{:?}", a.status);
    let b = &a.shared.body;
    b.validate().expect("valid");
    let seat = b.seat.as_ref().expect("seat");
    assert_eq!(b.links[seat.suspension].name, "suspension");
    assert_eq!(seat.suspension, 4);
    // Renaming the suspension keeps it the suspension.
    select(&mut a, 11); // link 5 is now the suspension
    key(&mut a, KeyCode::Char('r'));
    for _ in 0..20 {
        key(&mut a, KeyCode::Backspace);
    }
    typ(&mut a, "spring");
    key(&mut a, KeyCode::Enter);
    assert!(!a.status.error, "{:?}", a.status);
    let b = &a.shared.body;
    b.validate().expect("valid");
    assert_eq!(b.links[b.seat.as_ref().expect("seat").suspension].name, "spring");
    // The marks: P the pan, S a seat part, ~ the suspension, base = floor.
    let s = screen(&a, 160, 48);
    assert!(s.contains("P seat pan, S seat part"), "{s}");
    assert!(s.contains("frame–floor"), "{s}");
}


#[test]
fn the_model_tabs_body_mass_counts_the_body_not_the_seat() {
    // The seat's pad and frame have masses, not shares: the body's four
    // shares still make the body mass editable, and an edit leaves the seat.
    let mut a = seat_app(Theme::default());
    let s = screen(&a, 100, 30);
    assert!(s.contains("seated 58.58 kg"), "{s}");
    assert!(!s.contains("no shares"), "{s}");
    select(&mut a, 0);
    key(&mut a, KeyCode::Enter);
    typ(&mut a, "90");
    key(&mut a, KeyCode::Enter);
    assert!(!a.status.error, "{:?}", a.status);
    let b = &a.shared.body;
    assert!((b.seated_mass() - 0.781 * 90.0).abs() < 1e-9);
    let pad = b.segments.iter().find(|s| s.name == "pad").expect("pad");
    assert_eq!(pad.mass, 1.5);
}
