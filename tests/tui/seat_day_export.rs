//! The Seat and Day tabs' `.svg` (and the Day tab's `.csv`), driven
//! through the real `update`: each figure is byte for byte the one the
//! command line writes with `--plot` for the same model or day file.

use super::drive::{app, biodyn, ch, export, key, typ};
use biodyn::Preset;
use biodyn_app::tui::event::Msg;
use biodyn_app::tui::update::update;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use std::path::Path;

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).expect("the figure")
}

#[test]
fn the_seat_tabs_figure_is_the_command_lines_for_the_selected_class() {
    let dir = tempfile::tempdir().expect("tempdir");
    let preset = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/presets/paper-75kg-suspension-seat.toml"
    );
    let mut a = app(Preset::load(Path::new(preset)).expect("the seat preset"));
    ch(&mut a, '7');
    // EM6 first; → twice: EM8.
    for (class, steps) in [("EM6", 0), ("EM8", 2)] {
        for _ in 0..steps {
            key(&mut a, KeyCode::Right);
        }
        let svg = export(&mut a, &dir.path().join(format!("{class}.svg")));
        let cli = dir.path().join(format!("{class}-cli.svg"));
        let c = cli.display().to_string();
        biodyn(&["seat", "--preset", preset, "--class", class, "--plot", &c]);
        assert_eq!(svg, read(&cli), "{class}");
        assert!(svg.contains(&format!("{class}, selected")), "{class}");
    }
}

#[test]
fn the_day_tabs_figure_and_sheet_are_the_saved_days() {
    let dir = tempfile::tempdir().expect("tempdir");
    let mut a = app(Preset::builtin_default());
    ch(&mut a, '6');
    // Ctrl-S: the example day saved, to run `biodyn day` on.
    let day = dir.path().join("day.toml");
    update(
        &mut a,
        Msg::Key(KeyEvent::new(KeyCode::Char('s'), KeyModifiers::CONTROL)),
    );
    assert!(a.field.is_some(), "the save field");
    typ(&mut a, &day.display().to_string());
    key(&mut a, KeyCode::Enter);
    assert!(day.exists(), "saved: {:?}", a.status);
    let d = day.display().to_string();

    let svg = export(&mut a, &dir.path().join("tab.svg"));
    let cli = dir.path().join("cli.svg");
    biodyn(&["day", &d, "--plot", &cli.display().to_string()]);
    assert_eq!(svg, read(&cli));

    // The sheet: the JSON's numbers, operation by axis.
    let csv = export(&mut a, &dir.path().join("sheet.csv"));
    // `biodyn day --format csv` writes the same sheet, byte for byte.
    assert_eq!(csv, biodyn(&["day", &d, "--format", "csv"]));
    let v: serde_json::Value =
        serde_json::from_str(&biodyn(&["day", &d, "--format", "json"])).expect("JSON");
    let op = &v["operations"][0];
    for line in csv.lines().skip(1).filter(|l| !l.starts_with("the day")) {
        let cells: Vec<&str> = line.split(',').collect();
        let axis = &op["axes"][cells[1]];
        assert_eq!(cells[0], op["name"].as_str().expect("a name"));
        for (i, key) in [(3, "kaw_m_s2"), (4, "a8_m_s2"), (5, "points")] {
            let got: f64 = cells[i].parse().expect("a number");
            assert_eq!(Some(got), axis[key].as_f64(), "{line}: {key}");
        }
    }
    assert_eq!(csv.lines().filter(|l| !l.starts_with("the day")).count(), 4);

    // An operation without an a_w: the day is not whole, nothing exported.
    ch(&mut a, 'a');
    key(&mut a, KeyCode::Enter);
    ch(&mut a, 'x');
    assert!(a.field.is_none(), "no export field");
    let why = a.status.text.clone();
    assert!(a.status.error, "{why}");
    assert!(why.contains("1 operation is not evaluated yet"), "{why}");
}
