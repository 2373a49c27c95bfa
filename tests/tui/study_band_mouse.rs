//! The TUI's export, band and mouse, driven through the real `update` with
//! synthesised keys and crossterm mouse events; exports are compared byte
//! for byte with the `biodyn` binary's output for the same model and band.

use biodyn::Preset;
use biodyn_app::tui::app::App;
use biodyn_app::tui::event::Msg;
use biodyn_app::tui::tabs::study::StudyTab;
use biodyn_app::tui::theme::Theme;
use biodyn_app::tui::update::update;
use biodyn_app::view::chart::buffer_text;
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{
    KeyCode, KeyEvent, KeyModifiers, MouseButton, MouseEvent, MouseEventKind,
};
use std::process::Command;

fn app(w: u16, h: u16) -> App {
    let mut a = App::new(Preset::builtin_default(), None, Theme::default());
    update(&mut a, Msg::Resize(w, h));
    a
}

fn key(a: &mut App, code: KeyCode) {
    update(a, Msg::Key(KeyEvent::new(code, KeyModifiers::NONE)));
}

fn ch(a: &mut App, c: char) {
    key(a, KeyCode::Char(c));
}

fn typ(a: &mut App, s: &str) {
    s.chars().for_each(|c| ch(a, c));
}

fn mouse(a: &mut App, kind: MouseEventKind, column: u16, row: u16) {
    update(
        a,
        Msg::Mouse(MouseEvent {
            kind,
            column,
            row,
            modifiers: KeyModifiers::NONE,
        }),
    );
}

fn click(a: &mut App, column: u16, row: u16) {
    mouse(a, MouseEventKind::Down(MouseButton::Left), column, row);
}

fn screen(a: &App) -> Vec<String> {
    let (w, h) = a.size.expect("size");
    let mut t = Terminal::new(TestBackend::new(w, h)).expect("backend");
    t.draw(|f| biodyn_app::tui::draw(f, a)).expect("draw");
    buffer_text(t.backend().buffer())
}

fn study(a: &App) -> &StudyTab {
    a.tab_state().expect("study tab")
}

fn biodyn(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_biodyn"))
        .args(args)
        .output()
        .expect("run biodyn");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("utf-8")
}

/// Opens the export field, replaces the pre-filled path by `path`, commits.
fn export_to(a: &mut App, path: &std::path::Path) {
    ch(a, 'x');
    let f = a.field.as_ref().expect("export field");
    assert!(f.path, "the export field completes paths");
    typ(a, &path.display().to_string());
    key(a, KeyCode::Enter);
}

#[test]
fn study_export_is_the_command_lines_csv_and_plot() {
    let dir = tempfile::tempdir().expect("tempdir");
    let mut a = app(80, 24);
    ch(&mut a, '3');
    ch(&mut a, 'k');
    ch(&mut a, 'x');
    assert_eq!(
        a.field.as_ref().map(|f| f.text.as_str()),
        Some("paper-75kg-study-k4.csv")
    );
    key(&mut a, KeyCode::Esc);
    assert!(a.export.is_none());

    let csv = dir.path().join("k4.csv");
    export_to(&mut a, &csv);
    assert!(a.field.is_none(), "{:?}", a.field);
    let cli = biodyn(&["study", "k4", "-40%,0%,+40%", "--format", "csv"]);
    assert_eq!(std::fs::read_to_string(&csv).expect("written"), cli);

    // The chart as text: DPMI (f once), log axes (a).
    ch(&mut a, 'f');
    ch(&mut a, 'a');
    let txt = dir.path().join("k4-dpmi.txt");
    export_to(&mut a, &txt);
    let cli = biodyn(&[
        "plot",
        "dpmi",
        "--study",
        "k4=-40%,0%,+40%",
        "--log-x",
        "--log-y",
        "--width",
        "100",
        "--height",
        "30",
    ]);
    assert_eq!(std::fs::read_to_string(&txt).expect("written"), cli);
    let svg = dir.path().join("k4-dpmi.svg");
    export_to(&mut a, &svg);
    let cli = biodyn(&[
        "plot",
        "dpmi",
        "--study",
        "k4=-40%,0%,+40%",
        "--log-x",
        "--log-y",
        "--format",
        "svg",
    ]);
    assert_eq!(std::fs::read_to_string(&svg).expect("written"), cli);

    // An existing file is replaced only on a second Enter; a wrong
    // extension is refused with the choices; a folder is refused.
    std::fs::write(&csv, "old").expect("write");
    export_to(&mut a, &csv);
    let err = a
        .field
        .as_ref()
        .and_then(|f| f.error.clone())
        .expect("asks");
    assert!(err.contains("Enter again replaces it"), "{err}");
    assert_eq!(std::fs::read_to_string(&csv).expect("kept"), "old");
    key(&mut a, KeyCode::Enter);
    assert!(a.field.is_none());
    assert!(
        std::fs::read_to_string(&csv)
            .expect("read")
            .starts_with("variant,value,f_hz")
    );

    export_to(&mut a, &dir.path().join("k4.xlsx"));
    let err = a
        .field
        .as_ref()
        .and_then(|f| f.error.clone())
        .expect("refused");
    assert!(err.contains(".csv") && err.contains(".txt"), "{err}");
    key(&mut a, KeyCode::Esc);
    let sub = dir.path().join("sub.csv");
    std::fs::create_dir(&sub).expect("mkdir");
    export_to(&mut a, &sub);
    let err = a
        .field
        .as_ref()
        .and_then(|f| f.error.clone())
        .expect("refused");
    assert!(err.contains("Is a directory"), "{err}");
    key(&mut a, KeyCode::Esc);
    // A FIFO is not replaced (nor opened: nothing blocks).
    #[cfg(unix)]
    {
        let fifo = dir.path().join("pipe.csv");
        let made = Command::new("mkfifo").arg(&fifo).status();
        if made.is_ok_and(|s| s.success()) {
            export_to(&mut a, &fifo);
            let err = a
                .field
                .as_ref()
                .and_then(|f| f.error.clone())
                .expect("refused");
            assert!(err.contains("not a regular file"), "{err}");
            key(&mut a, KeyCode::Enter);
            let err = a
                .field
                .as_ref()
                .and_then(|f| f.error.clone())
                .expect("refused");
            assert!(err.contains("not a regular file"), "{err}");
            key(&mut a, KeyCode::Esc);
        }
    }
}

#[test]
fn the_band_edits_undoes_and_saves_with_the_preset() {
    let dir = tempfile::tempdir().expect("tempdir");
    let mut a = app(80, 24);
    ch(&mut a, '3');
    ch(&mut a, 'b');
    assert_eq!(
        a.field.as_ref().map(|f| f.text.as_str()),
        Some("0.5 20 0.1")
    );
    typ(&mut a, "20 1 0.1");
    key(&mut a, KeyCode::Enter);
    let err = a
        .field
        .as_ref()
        .and_then(|f| f.error.clone())
        .expect("refused");
    assert!(err.contains("'from' must be below 'to'"), "{err}");
    key(&mut a, KeyCode::Esc);
    assert!(!a.modified());

    ch(&mut a, 'b');
    typ(&mut a, "1:10:0.5");
    key(&mut a, KeyCode::Enter);
    assert!(a.field.is_none(), "{:?}", a.field);
    let band = a.shared.preset.band;
    assert_eq!((band.from, band.to, band.step), (1.0, 10.0, 0.5));
    assert!(a.modified(), "a band edit is an unsaved edit");
    // Every tab recomputes: the responses and the study are on the new grid.
    let d = a.shared.derived.as_ref().expect("derived");
    assert_eq!(d.curve.len(), 19);
    assert_eq!(d.curve.first().map(|r| r.f_hz), Some(1.0));
    let Some(Ok(st)) = &study(&a).result else {
        panic!("study")
    };
    assert!(st.variants.iter().all(|v| v.curve.len() == 19));
    // The study tab kept its parameter (an edit, not a new model).
    ch(&mut a, 'k');
    let k4 = study(&a).sel;
    ch(&mut a, 'b');
    typ(&mut a, "1 10 0.25");
    key(&mut a, KeyCode::Enter);
    assert_eq!(study(&a).sel, k4);

    ch(&mut a, 'u');
    assert!(a.status.text.contains("undid band"), "{}", a.status.text);
    assert_eq!(a.shared.preset.band.step, 0.5);
    ch(&mut a, 'u');
    assert_eq!(a.shared.preset.band, biodyn::Band::default());
    assert!(!a.modified());
    assert_eq!(a.shared.derived.as_ref().expect("derived").curve.len(), 196);
    update(
        &mut a,
        Msg::Key(KeyEvent::new(KeyCode::Char('r'), KeyModifiers::CONTROL)),
    );
    assert_eq!(a.shared.preset.band.step, 0.5);

    // Saved with the preset; opening the file gives the band back.
    let path = dir.path().join("narrow.toml");
    update(
        &mut a,
        Msg::Key(KeyEvent::new(KeyCode::Char('s'), KeyModifiers::CONTROL)),
    );
    typ(&mut a, &path.display().to_string());
    key(&mut a, KeyCode::Enter);
    assert!(a.field.is_none(), "{:?}", a.field);
    assert!(!a.modified());
    let back = Preset::open(&path.display().to_string()).expect("reopen");
    assert_eq!(
        (back.band.from, back.band.to, back.band.step),
        (1.0, 10.0, 0.5)
    );
    // And the CLI reads that band from the file.
    let csv = biodyn(&[
        "response",
        "--preset",
        &path.display().to_string(),
        "--format",
        "csv",
    ]);
    assert_eq!(csv.lines().count(), 1 + 19);
}

#[test]
fn mouse_opens_tabs_scrolls_help_and_drives_the_study_tab() {
    let mut a = app(160, 48);
    assert!(!a.mouse, "capture starts off: the terminal selects text");
    click(&mut a, 30, 0);
    assert_eq!(a.current, 0, "with capture off a click does nothing");
    assert!(screen(&a)[47].contains("M mouse off"));
    ch(&mut a, 'M');
    assert!(a.mouse);
    assert!(screen(&a)[47].contains("M mouse on"));

    // Click the tab bar where "3 Study" is drawn.
    let title = &screen(&a)[0];
    let col = title.find("3 Study").expect("study in the bar");
    let col = title[..col].chars().count() as u16 + 2;
    click(&mut a, col, 0);
    assert_eq!(a.current, 2);
    let title = &screen(&a)[0];
    let col = title[..title.find("1 Model").expect("model")]
        .chars()
        .count() as u16;
    click(&mut a, col, 0);
    assert_eq!(a.current, 0);
    click(&mut a, 159, 0);
    assert_eq!(a.current, 0, "the file name opens no tab");
    ch(&mut a, '3');

    // The header's ▶ picks the next parameter, ◀ the previous.
    let before = study(&a).sel;
    let header = &screen(&a)[1];
    let right = header[..header.find('▶').expect("▶")].chars().count() as u16;
    click(&mut a, right, 1);
    assert_eq!(study(&a).sel, before + 1);
    let header = &screen(&a)[1];
    let left = header[..header.find('◀').expect("◀")].chars().count() as u16;
    click(&mut a, left, 1);
    assert_eq!(study(&a).sel, before);
    // A click on the values opens their field.
    let header = &screen(&a)[1];
    let v = header[..header.find("65,75,85").expect("values")]
        .chars()
        .count() as u16;
    click(&mut a, v + 1, 1);
    assert!(a.field.is_some());
    key(&mut a, KeyCode::Esc);

    // At 160 columns the three charts stand side by side: a click in the
    // right one makes APMS the function x exports.
    assert_eq!(study(&a).func, 0);
    click(&mut a, 150, 10);
    assert_eq!(study(&a).func, 2);
    ch(&mut a, 'x');
    let x = a.export.as_ref().expect("export");
    assert!(x.formats[1].contents.contains("APMS"));
    key(&mut a, KeyCode::Esc);

    // The wheel scrolls the help page, three lines a step.
    ch(&mut a, '?');
    mouse(&mut a, MouseEventKind::ScrollDown, 50, 20);
    let s = screen(&a).join("\n");
    ch(&mut a, '?');
    ch(&mut a, '?');
    assert_ne!(s, screen(&a).join("\n"), "scrolled");
    mouse(&mut a, MouseEventKind::ScrollDown, 50, 20);
    mouse(&mut a, MouseEventKind::ScrollUp, 50, 20);
    let mut b = app(160, 48);
    ch(&mut b, '3');
    ch(&mut b, '?');
    assert_eq!(screen(&a)[1..46], screen(&b)[1..46], "back at the top");
    key(&mut a, KeyCode::Esc);

    // At 80×24 eleven variants do not fit: the wheel scrolls the legend.
    update(&mut a, Msg::Resize(80, 24));
    ch(&mut a, 'e');
    typ(&mut a, "50 55 60 65 70 75 80 85 90 95 100");
    key(&mut a, KeyCode::Enter);
    assert_eq!(study(&a).legend_top, 0);
    mouse(&mut a, MouseEventKind::ScrollDown, 40, 20);
    mouse(&mut a, MouseEventKind::ScrollDown, 40, 20);
    assert_eq!(study(&a).legend_top, 2);
    assert!(screen(&a).join("\n").contains("60 kg"));
    mouse(&mut a, MouseEventKind::ScrollUp, 40, 20);
    assert_eq!(study(&a).legend_top, 1);

    // Too small: clicks do nothing.
    update(&mut a, Msg::Resize(40, 10));
    click(&mut a, 1, 0);
    assert_eq!(a.current, 2);
}
