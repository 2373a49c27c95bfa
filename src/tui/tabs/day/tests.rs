//! The Day tab through the real `update`: snapshots at 80×24 and 160×48,
//! the numbers of an edited operation worked by hand, delete and undo,
//! save and reopen, refusals, the verdict across 0.5 and 1.15 m/s², a
//! record measured.

use super::DayTab;
use super::edit::Col;
use crate::tui::app::App;
use crate::tui::event::Msg;
use crate::tui::theme::Theme;
use crate::tui::update::update;
use crate::view::chart::buffer_text;
use biodyn::Preset;
use biodyn::time::Axis;
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use ratatui::style::Color;

fn app_with(theme: Theme) -> App {
    let mut a = App::new(Preset::builtin_default(), None, theme);
    key(&mut a, KeyCode::Char('6'));
    a
}

fn app() -> App {
    app_with(Theme::default())
}

fn key(a: &mut App, code: KeyCode) {
    update(a, Msg::Key(KeyEvent::new(code, KeyModifiers::NONE)));
}

fn ctrl(a: &mut App, c: char) {
    update(a, Msg::Key(KeyEvent::new(KeyCode::Char(c), KeyModifiers::CONTROL)));
}

fn typ(a: &mut App, s: &str) {
    for c in s.chars() {
        key(a, KeyCode::Char(c));
    }
}

fn tab(a: &App) -> &DayTab {
    a.tab_state().expect("day tab")
}

fn draw(a: &App, w: u16, h: u16) -> Terminal<TestBackend> {
    let mut t = Terminal::new(TestBackend::new(w, h)).expect("test backend");
    t.draw(|f| crate::tui::draw(f, a)).expect("draw");
    t
}

/// Through the layout check, as every snapshot.
fn screen(a: &App, w: u16, h: u16) -> String {
    crate::tui::tests::screen(a, w, h)
}

/// Moves to `col` of the selected operation.
fn go(a: &mut App, col: Col) {
    while tab(a).col != col {
        key(a, KeyCode::Right);
    }
}

/// Replaces the open field's text and presses Enter.
fn answer(a: &mut App, text: &str) {
    let f = a.field.as_mut().expect("a field is open");
    f.set_text("");
    typ(a, text);
    key(a, KeyCode::Enter);
}

/// Enter on `col` of the selected operation, `text`, Enter.
fn edit(a: &mut App, col: Col, text: &str) {
    go(a, col);
    key(a, KeyCode::Enter);
    answer(a, text);
}

fn snap(name: &str, a: &App) {
    for (w, h) in [(80, 24), (160, 48)] {
        insta::assert_snapshot!(format!("{name}_{w}x{h}"), screen(a, w, h));
    }
}

/// A day with no operations: the example row deleted.
fn empty() -> App {
    let mut a = app();
    key(&mut a, KeyCode::Char('d'));
    assert!(tab(&a).ops.is_empty());
    a
}

/// One operation of `hours` at z = `z` m/s², nothing else.
fn one(hours: &str, z: &str) -> App {
    let mut a = empty();
    key(&mut a, KeyCode::Char('a'));
    answer(&mut a, "seat");
    edit(&mut a, Col::Hours, hours);
    edit(&mut a, Col::Aw(Axis::Z), z);
    a
}

fn close(a: f64, b: f64, tol: f64) {
    assert!((a - b).abs() <= tol, "{a} vs {b}");
}

#[test]
fn snapshots_of_the_example_row_and_of_the_example_day() {
    let mut a = app();
    snap("day_example_row", &a);
    ctrl(&mut a, 'o');
    answer(&mut a, "examples/day.toml");
    assert_eq!(tab(&a).ops.len(), 3, "{:?}", a.status);
    snap("day_examples_day_toml", &a);
    let mut b = app_with(Theme {
        mono: true,
        ascii: true,
    });
    ctrl(&mut b, 'o');
    answer(&mut b, "examples/day.toml");
    snap("day_ascii_mono", &b);
    key(&mut a, KeyCode::Char('z'));
    insta::assert_snapshot!("day_bars_zoomed_80x24", screen(&a, 80, 24));
}

#[test]
fn an_added_operation_gets_its_numbers_as_hours_and_a_w_are_typed() {
    let mut a = empty();
    key(&mut a, KeyCode::Char('a'));
    answer(&mut a, "haul road");
    // a new operation: 1 h, no a_w yet, the hours cell selected
    assert_eq!(tab(&a).col, Col::Hours);
    assert_eq!(tab(&a).ops[0].hours, 1.0);
    assert!(screen(&a, 80, 24).contains("no a_w yet"));
    edit(&mut a, Col::Hours, "3.25");
    edit(&mut a, Col::Aw(Axis::Z), "0.52");
    let d = tab(&a).sheet.day.clone().expect("a day");
    // z, k = 1.0: A(8) = 0.52·√(3.25/8) = 0.52 × 0.637377 = 0.331436;
    // points = 100·(0.331436/0.5)² = 100 × 0.2704 × 0.40625 × 4 = 43.94
    close(d.a8, 0.331_436_268, 1e-9);
    close(d.points, 43.94, 1e-9);
    let s = screen(&a, 80, 24);
    assert!(s.contains("0.331") && s.contains("43.9"), "{s}");
    // hours to the action value: 8·(0.5/0.52)² = 7.396; to the limit 8·(1.15/0.52)² = 39.127
    assert!(s.contains("7.40") && s.contains("39.13"), "{s}");
    // x 0.36 is 1.4 × 0.36 = 0.504 > 0.52? no: z still rules; x 0.4 → 0.56 rules
    edit(&mut a, Col::Aw(Axis::X), "0.4");
    let d = tab(&a).sheet.day.clone().expect("a day");
    assert_eq!(d.a8_axis, Axis::X);
    // 0.56·√(3.25/8) = 0.356931; points 100·0.56²·0.40625·4 = 50.96
    close(d.a8, 0.56 * (3.25f64 / 8.0).sqrt(), 1e-12);
    close(d.points, 50.96, 1e-9);
    let s = screen(&a, 80, 24);
    assert!(s.contains("x     0.357   51.0◀") && s.contains("A(8) x: below action value"), "{s}");
    // Backspace on the x cell: not measured again, z rules
    go(&mut a, Col::Aw(Axis::X));
    key(&mut a, KeyCode::Backspace);
    assert_eq!(tab(&a).sheet.day.as_ref().map(|d| d.a8_axis), Some(Axis::Z));
}

#[test]
fn delete_undo_and_redo() {
    let mut a = app();
    let before = tab(&a).ops.clone();
    key(&mut a, KeyCode::Char('d'));
    assert!(tab(&a).ops.is_empty());
    assert!(a.status.text.contains("delete operation 'haul road'"), "{}", a.status.text);
    assert!(screen(&a, 80, 24).contains("no operations: a adds one"));
    // u is the app's key: on this tab it undoes the day's edit, not the model's
    key(&mut a, KeyCode::Char('u'));
    assert_eq!(tab(&a).ops, before);
    assert!(a.status.text.starts_with("undid delete"), "{}", a.status.text);
    ctrl(&mut a, 'r');
    assert!(tab(&a).ops.is_empty());
    key(&mut a, KeyCode::Char('u'));
    edit(&mut a, Col::Hours, "2");
    key(&mut a, KeyCode::Char('u'));
    assert_eq!(tab(&a).ops, before);
    // the model's undo is untouched
    assert!(a.undo.is_empty());
}

#[test]
fn save_and_reopen_give_the_same_day_and_the_title_says_modified() {
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("mon.toml");
    let mut a = app();
    ctrl(&mut a, 'o');
    answer(&mut a, "examples/day.toml");
    let title = |a: &App| screen(a, 80, 24).lines().next().unwrap_or_default().to_string();
    assert!(!title(&a).contains('*'), "{}", title(&a));
    edit(&mut a, Col::Name, "haul road (wet)");
    assert!(title(&a).contains("*modified") || title(&a).ends_with('*'), "{}", title(&a));
    ctrl(&mut a, 's');
    answer(&mut a, &path.display().to_string());
    assert!(a.field.is_none(), "{:?}", a.field);
    assert!(a.status.text.starts_with("saved the day"), "{}", a.status.text);
    assert!(!title(&a).contains('*'), "{}", title(&a));
    let saved = tab(&a).ops.clone();
    // the file loads back, through the library, to the same operations
    let file = biodyn::exposure::DayFile::load(&path).expect("loads");
    assert_eq!(file.operations, saved);
    key(&mut a, KeyCode::Char('d'));
    ctrl(&mut a, 'o');
    answer(&mut a, &path.display().to_string());
    assert_eq!(tab(&a).ops, saved);
    assert_eq!(tab(&a).ops[0].name, "haul road (wet)");
    // another file of the name is replaced only on a second Enter
    let other = dir.path().join("other.toml");
    std::fs::write(&other, "x").expect("write");
    ctrl(&mut a, 's');
    answer(&mut a, &other.display().to_string());
    let err = a.field.as_ref().and_then(|f| f.error.clone()).unwrap_or_default();
    assert!(err.contains("exists: Enter again replaces it"), "{err}");
    assert_eq!(std::fs::read_to_string(&other).ok().as_deref(), Some("x"));
    key(&mut a, KeyCode::Enter);
    assert!(a.field.is_none());
    assert_eq!(
        biodyn::exposure::DayFile::load(&other).map(|f| f.operations).ok(),
        Some(saved)
    );
}

#[test]
fn bad_values_are_refused_with_the_reason_and_change_nothing() {
    let mut a = app();
    let before = tab(&a).ops.clone();
    for (col, text, says) in [
        (Col::Hours, "-2", "'-2' is not hours: write 6.5, 6:30"),
        (Col::Hours, "abc", "'abc' is not hours"),
        (Col::Hours, "6:75", "minutes are 0 to 59"),
        (Col::Hours, "25", "24 h"),
        (Col::Aw(Axis::Y), "-0.1", "must be ≥ 0"),
        (Col::Aw(Axis::Y), "inf", "is not a number"),
        (Col::Name, " ", "1 to 200 printable characters"),
        (Col::Record, "run.csv axes=q=ax", "axes=q=ax"),
        (Col::Record, "run.csv unit=furlong", "the units are m/s2, g and mm/s2"),
    ] {
        edit(&mut a, col, text);
        let err = a.field.as_ref().and_then(|f| f.error.clone());
        assert!(err.as_deref().is_some_and(|e| e.contains(says)), "{text}: {err:?}");
        // the reason shows on screen, the field stays open
        assert!(screen(&a, 160, 48).contains(says), "{text}");
        key(&mut a, KeyCode::Esc);
        assert_eq!(tab(&a).ops, before, "{text}");
    }
    // the day at most 24 h: a second operation of 21 h beside 3.25 h
    key(&mut a, KeyCode::Char('a'));
    answer(&mut a, "long");
    edit(&mut a, Col::Hours, "21");
    let err = a.field.as_ref().and_then(|f| f.error.clone()).unwrap_or_default();
    // 3.25 + 21 = 24.25 h
    assert!(err.contains("24 h 15 min, over 24 h"), "{err}");
    // 2:30 as a day file writes it: 3.25 + 2.5 h.
    edit(&mut a, Col::Hours, "2:30");
    assert!(a.field.is_none(), "{:?}", a.field.as_ref().and_then(|f| f.error.clone()));
}

#[test]
fn the_verdict_changes_across_the_action_and_limit_values() {
    // 8 h at z: A(8) = a_w. The Directive acts when a value is exceeded.
    for (z, words, colour) in [
        ("0.5", "below action value", Color::Green),
        ("0.51", "above action value", Color::Yellow),
        ("1.15", "above action value", Color::Yellow),
        ("1.16", "above limit value", Color::Red),
    ] {
        for mono in [false, true] {
            let mut a = one("8", z);
            if mono {
                a.shared.theme = Theme {
                    mono: true,
                    ascii: false,
                };
            }
            let t = draw(&a, 80, 24);
            let buf = t.backend().buffer();
            let lines = buffer_text(buf);
            let (y, line) = lines
                .iter()
                .enumerate()
                .find(|(_, l)| l.contains(words))
                .unwrap_or_else(|| panic!("{z}: {}", lines.join("\n")));
            let x = line[..line.find(words).unwrap_or(0)].chars().count();
            let cell = &buf[(x as u16, y as u16)];
            let want = if mono { Color::Reset } else { colour };
            assert_eq!(cell.fg, want, "{z} mono {mono}");
        }
    }
    // 0.5 × 1.4 = 0.7 on x for 8 h is above action: k counts
    let mut a = one("8", "0.1");
    edit(&mut a, Col::Aw(Axis::X), "0.5");
    let s = screen(&a, 80, 24);
    assert!(s.contains("x     0.700  196.0◀") && s.contains("A(8) x: above action value"), "{s}");
}

/// A 1 m/s² 4 Hz sine on z, 10 s at 200 Hz, as a CSV record.
fn sine_record(dir: &std::path::Path) -> std::path::PathBuf {
    let p = dir.join("seat.csv");
    let mut s = String::from("t_s,az\n");
    for i in 0..2000 {
        let t = i as f64 / 200.0;
        s.push_str(&format!("{t},{}\n", (2.0 * std::f64::consts::PI * 4.0 * t).sin()));
    }
    std::fs::write(&p, s).expect("write");
    p
}

#[test]
fn a_record_operation_is_measured_and_a_bad_one_says_why() {
    let dir = tempfile::tempdir().expect("tempdir");
    let p = sine_record(dir.path());
    let mut a = app();
    edit(&mut a, Col::Record, &p.display().to_string());
    // measured at once (no channel): what the library's reader gives
    let want = crate::tui::tabs::day::records::measure(&match &tab(&a).ops[0].source {
        biodyn::exposure::Source::Record(r) => r.clone(),
        other => panic!("{other:?}"),
    })
    .expect("measured");
    let aw = want.axes.get(Axis::Z).expect("z").aw;
    // a 1 m/s² peak sine has r.m.s. 0.707; Wk near 4 Hz is close to 1
    assert!(aw > 0.6 && aw < 0.8, "{aw}");
    let d = tab(&a).sheet.day.clone().expect("a day");
    close(d.a8, aw * (3.25f64 / 8.0).sqrt(), 1e-12);
    assert!(tab(&a).sheet.complete());
    // Backspace on the record types its a_w in
    key(&mut a, KeyCode::Backspace);
    match &tab(&a).ops[0].source {
        biodyn::exposure::Source::Measured { aw: typed, .. } => {
            assert_eq!(typed.get(Axis::Z).copied(), Some(aw))
        }
        other => panic!("{other:?}"),
    }
    // a record that is not there: the reason in the tab, no verdict
    key(&mut a, KeyCode::Char('u'));
    edit(&mut a, Col::Record, "no-such-record.csv");
    let s = screen(&a, 160, 48);
    assert!(s.contains("no-such-record.csv") && s.contains("not judged"), "{s}");
    assert!(!tab(&a).sheet.complete());
}

#[test]
fn records_are_read_on_a_worker_and_the_result_lands_in_the_sheet() {
    let dir = tempfile::tempdir().expect("tempdir");
    let p = sine_record(dir.path());
    let mut a = App::new(Preset::builtin_default(), None, Theme::default());
    let (tx, rx) = std::sync::mpsc::channel();
    a.connect(tx);
    key(&mut a, KeyCode::Char('6'));
    edit(&mut a, Col::Record, &p.display().to_string());
    assert!(screen(&a, 80, 24).contains("reading the record"));
    for _ in 0..2 {
        let msg = rx
            .recv_timeout(std::time::Duration::from_secs(20))
            .expect("the worker's report");
        update(&mut a, msg);
    }
    assert!(tab(&a).sheet.complete());
    assert!(screen(&a, 80, 24).contains("below action value"));
}

#[test]
fn six_tabs_fit_80_columns_and_the_title_names_the_tabs_own_file() {
    let mut a = app();
    let bar = screen(&a, 80, 24).lines().next().unwrap_or_default().to_string();
    assert!(bar.contains("1 Model") && bar.contains("6 Day") && bar.contains("new day"), "{bar}");
    edit(&mut a, Col::Hours, "4");
    // Full tab names at 80 columns: the mark shortens to "*" (issue 19 item 19).
    let bar = screen(&a, 80, 24).lines().next().unwrap_or_default().to_string();
    assert!(bar.ends_with("new day *"), "{bar}");
    let bar = screen(&a, 120, 30).lines().next().unwrap_or_default().to_string();
    assert!(bar.contains("new day *modified"), "{bar}");
    // on the Model tab the title is the model's, unmodified
    key(&mut a, KeyCode::Char('1'));
    let bar = screen(&a, 120, 30).lines().next().unwrap_or_default().to_string();
    assert!(bar.contains("paper-75kg (built-in)") && !bar.contains('*'), "{bar}");
    // quitting asks, naming the day
    assert_eq!(a.quit_reasons(), vec!["the day has unsaved edits"]);
}

/// With unsaved edits to both the model and the day, the quit prompt does
/// not offer `s` (it would save the model alone and lose the day): y or n.
#[test]
fn quitting_with_an_unsaved_day_never_offers_save_the_model_only() {
    let mut a = app();
    key(&mut a, KeyCode::Char('1'));
    key(&mut a, KeyCode::Char('+'));
    key(&mut a, KeyCode::Char('q'));
    let last = |a: &App| screen(a, 80, 24).lines().last().unwrap_or_default().to_string();
    assert!(last(&a).contains("s save+quit"), "{}", last(&a));
    key(&mut a, KeyCode::Esc);
    key(&mut a, KeyCode::Char('6'));
    edit(&mut a, Col::Hours, "4");
    key(&mut a, KeyCode::Char('q'));
    let h = last(&a);
    assert!(h.contains("y yes") && !h.contains("save"), "{h}");
    key(&mut a, KeyCode::Char('s'));
    assert!(a.field.is_none());
    assert!(a.quit_reasons().contains(&"the day has unsaved edits"));
}

/// A day file with ISO 2631-5's person and doses (examples/day-shocks.toml)
/// keeps both through the tab: editing an operation's name and saving
/// writes the person and every dose back; clearing z's a_w drops z's dose
/// with it (a dose without z would not load back); undo restores both.
#[test]
fn the_spine_and_the_doses_survive_the_tab() {
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("shocks.toml");
    let mut a = app();
    ctrl(&mut a, 'o');
    answer(&mut a, "examples/day-shocks.toml");
    let original = biodyn::exposure::DayFile::load(std::path::Path::new("examples/day-shocks.toml")).expect("loads");
    assert_eq!(tab(&a).spine, original.spine);
    edit(&mut a, Col::Name, "loaded, wet track");
    ctrl(&mut a, 's');
    answer(&mut a, &path.display().to_string());
    assert!(a.status.text.starts_with("saved the day"), "{}", a.status.text);
    let back = biodyn::exposure::DayFile::load(&path).expect("loads");
    assert_eq!(back.spine, original.spine);
    assert!(back.spine.is_some());
    let dose = |f: &biodyn::exposure::DayFile, i: usize| match &f.operations[i].source {
        biodyn::exposure::Source::Measured { dz, .. } => *dz,
        _ => None,
    };
    assert_eq!((dose(&back, 0), dose(&back, 1)), (Some(24.5), Some(8.2)));
    // Backspace on z's a_w: the dose goes too, the day still saves.
    edit(&mut a, Col::Aw(Axis::Z), "");
    let Some(biodyn::exposure::Source::Measured { dz, .. }) = tab(&a).ops.first().map(|o| &o.source) else {
        panic!("measured")
    };
    assert_eq!(*dz, None);
    ctrl(&mut a, 's');
    answer(&mut a, &path.display().to_string());
    let back = biodyn::exposure::DayFile::load(&path).expect("still loads");
    assert_eq!(dose(&back, 0), None);
    key(&mut a, KeyCode::Char('u'));
    key(&mut a, KeyCode::Char('u'));
    assert_eq!(tab(&a).spine, original.spine);
}

/// Issue 19 item 5 on the Day tab: an edit, Ctrl-S, `u`: the day is still
/// the saved file's, with an unsaved edit; redo is unmodified again.
#[test]
fn undo_after_a_save_keeps_the_day_file_and_says_modified() {
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("mon.toml");
    let mut a = app();
    edit(&mut a, Col::Hours, "4");
    ctrl(&mut a, 's');
    answer(&mut a, &path.display().to_string());
    assert!(!tab(&a).modified());
    key(&mut a, KeyCode::Char('u'));
    assert_eq!(tab(&a).path.as_deref(), Some(path.as_path()));
    assert!(tab(&a).modified());
    let bar = screen(&a, 120, 30).lines().next().unwrap_or_default().to_string();
    assert!(bar.contains("mon.toml") && bar.contains("*modified"), "{bar}");
    assert_eq!(a.quit_reasons(), vec!["the day has unsaved edits"]);
    ctrl(&mut a, 'r');
    assert!(!tab(&a).modified());
}

/// Issue 30: the Day tab shows the VDV verdict, and a known part judged as
/// the lower bound it is. z 35.41 m/s^1.75 (measured over the hour it
/// lasts) is over the limit 21 (Directive 2002/44/EC Art. 3) whatever
/// "idle", without a VDV, adds: above the limit, in red, "≥" on the axis.
/// At 12.5 only the action value is passed; at 8.5 nothing is judged.
#[test]
fn the_vdv_verdict_shows_and_a_known_part_is_a_lower_bound() {
    let dir = tempfile::tempdir().expect("tempdir");
    let day = |z: &str| {
        let p = dir.path().join(format!("day-{z}.toml"));
        std::fs::write(
            &p,
            format!("[[operation]]\nname = \"rough\"\nhours = 1\naw_m_s2 = {{ z = 0.5 }}\nvdv_m_s175 = {{ z = {z} }}\nmeasured_s = 3600\n\n[[operation]]\nname = \"idle\"\nhours = 4\naw_m_s2 = {{ z = 0.2 }}\n"),
        )
        .expect("a day file");
        let mut a = app();
        ctrl(&mut a, 'o');
        answer(&mut a, &p.display().to_string());
        a
    };
    let a = day("35.41");
    let t = draw(&a, 80, 24);
    let buf = t.backend().buffer();
    let lines = buffer_text(buf);
    let words = "VDV z: above limit value";
    let (y, line) = lines
        .iter()
        .enumerate()
        .find(|(_, l)| l.contains(words))
        .unwrap_or_else(|| panic!("{}", lines.join("\n")));
    let x = line[..line.find(words).unwrap_or(0)].chars().count();
    assert_eq!(buf[(x as u16, y as u16)].fg, Color::Red);
    assert!(lines.iter().any(|l| l.contains("≥35.41◀")), "{}", lines.join("\n"));
    let s = screen(&a, 160, 48);
    assert!(s.contains("VDV z: above limit value (9.1/21)"), "{s}");
    assert!(s.contains("≥: 1 operation without a VDV"), "{s}");
    // idle's hours to the VDV values: not judged, "-", never 0.
    assert!(s.contains("   -         -         -"), "{s}");
    assert!(screen(&day("12.5"), 80, 24).contains("VDV z: at least above action"));
    assert!(screen(&day("12.5"), 160, 48).contains("VDV z: at least above action, limit open"));
    assert!(screen(&day("8.5"), 80, 24).contains("VDV not judged (≥8.50 z)"));
}

/// The tab's `.csv` is `biodyn day --format csv`'s writer: the VDVs and
/// their hours in it.
#[test]
fn the_exported_sheet_has_the_vdvs() {
    let mut a = app();
    ctrl(&mut a, 'o');
    answer(&mut a, "examples/day.toml");
    let d = tab(&a).sheet.day.clone().expect("a day");
    let csv = super::export::csv(&d);
    assert_eq!(csv, crate::view::report::day::csv(&d));
    let head = csv.lines().next().expect("a header");
    assert!(head.contains("vdv_exposure_m_s175,hours_to_vdv_eav,hours_to_vdv_elv"), "{head}");
    assert!(csv.contains("the day,highest VDV: z,,,,,,,23.6635"), "{csv}");
}

/// The sine record on 1 g of gravity (a DC-coupled accelerometer), its
/// header naming no unit.
fn gravity_record(dir: &std::path::Path) -> std::path::PathBuf {
    let p = dir.join("dc.csv");
    let mut s = String::from("t_s,az\n");
    for i in 0..2000 {
        let t = i as f64 / 200.0;
        let a = 9.80665 + (2.0 * std::f64::consts::PI * 4.0 * t).sin();
        s.push_str(&format!("{t},{a}\n"));
    }
    std::fs::write(&p, s).expect("write");
    p
}

#[test]
fn a_records_notes_show_under_its_rows_and_remove_mean_reads_it_again() {
    let dir = tempfile::tempdir().expect("tempdir");
    let p = gravity_record(dir.path());
    let mut a = app();
    // the offset refused, as `biodyn day` refuses it, with the way out
    edit(&mut a, Col::Record, &p.display().to_string());
    let s = screen(&a, 160, 48);
    assert!(s.contains("remove_mean"), "{s}");
    assert!(!tab(&a).sheet.complete());
    // remove_mean: the same record read again (the key holds the option),
    // judged, and the notes say what was assumed and removed
    edit(&mut a, Col::Record, &format!("{} remove_mean", p.display()));
    assert!(tab(&a).sheet.complete(), "{}", screen(&a, 160, 48));
    let s = screen(&a, 160, 48);
    assert!(s.contains("note: m/s² assumed for 'az'"), "{s}");
    assert!(s.contains("note: mean removed: z 9.8066 m/s²"), "{s}");
    // the a_w is the clean sine's
    let clean = sine_record(dir.path());
    edit(&mut a, Col::Record, &clean.display().to_string());
    let want = tab(&a).sheet.day.clone().expect("a day").a8;
    assert!(!screen(&a, 160, 48).contains("note: mean removed"));
    edit(&mut a, Col::Record, &format!("{} remove_mean", p.display()));
    close(tab(&a).sheet.day.clone().expect("a day").a8, want, 1e-9);
    // at 80 columns the note is there, wrapped in the panel
    assert!(screen(&a, 80, 24).contains("note: m/s"));
}
