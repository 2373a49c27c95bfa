//! The Vibration tab's `x` export, driven by keys through the real
//! `update`, is byte for byte what the real binary's `biodyn simulate
//! --format csv` prints for the same model and signal: a generated sine, a
//! random record plus a shock, and a CSV record read from a file.

use biodyn::Preset;
use biodyn_app::tui::app::App;
use biodyn_app::tui::event::Msg;
use biodyn_app::tui::tabs::vibration::VibrationTab;
use biodyn_app::tui::tabs::vibration::settings::Row;
use biodyn_app::tui::theme::Theme;
use biodyn_app::tui::update::update;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use std::path::Path;
use std::process::Command;

fn key(a: &mut App, code: KeyCode) {
    update(a, Msg::Key(KeyEvent::new(code, KeyModifiers::NONE)));
}

fn typ(a: &mut App, s: &str) {
    for c in s.chars() {
        key(a, KeyCode::Char(c));
    }
}

fn tab(a: &App) -> &VibrationTab {
    a.tab_state().expect("vibration tab")
}

fn edit(a: &mut App, row: Row, text: &str) {
    let i = tab(a).rows().iter().position(|&r| r == row).expect("row");
    while tab(a).sel != i {
        key(a, KeyCode::Down);
    }
    key(a, KeyCode::Enter);
    a.field.as_mut().expect("field").set_text("");
    typ(a, text);
    key(a, KeyCode::Enter);
    assert!(a.field.is_none(), "{:?}", a.field);
}

fn export(a: &mut App, path: &Path) -> Vec<u8> {
    key(a, KeyCode::Char('x'));
    a.field.as_mut().expect("export field").set_text("");
    typ(a, &path.display().to_string());
    key(a, KeyCode::Enter);
    assert!(a.status.text.starts_with("exported"), "{:?}", a.status);
    std::fs::read(path).expect("exported file")
}

fn cli(args: &[&str]) -> Vec<u8> {
    let out = Command::new(env!("CARGO_BIN_EXE_biodyn"))
        .args(args)
        .output()
        .expect("run biodyn");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    out.stdout
}

#[test]
fn the_export_equals_biodyn_simulate_byte_for_byte() {
    let dir = tempfile::tempdir().expect("tempdir");
    let mut a = App::new(Preset::builtin_default(), None, Theme::default());
    key(&mut a, KeyCode::Char('5'));

    let mine = export(&mut a, &dir.path().join("sine.csv"));
    let theirs = cli(&[
        "simulate",
        "--signal",
        "sine:freq=5,amp=5",
        "--format",
        "csv",
    ]);
    assert_eq!(mine.len(), theirs.len());
    assert!(mine == theirs, "sine: the files differ");

    let spec = "random:rms=0.8,band=1-20,seed=1+shock:peak=15,width=0.1,at=2";
    edit(&mut a, Row::Spec, spec);
    edit(&mut a, Row::Duration, "4");
    edit(&mut a, Row::Fs, "500");
    let mine = export(&mut a, &dir.path().join("rs.csv"));
    let theirs = cli(&[
        "simulate",
        "--signal",
        spec,
        "--duration",
        "4",
        "--fs",
        "500",
        "--format",
        "csv",
    ]);
    assert!(mine == theirs, "random+shock: the files differ");

    // a record from a file, with a time column that does not start at 0
    let rec = dir.path().join("seat.csv");
    let mut text = String::from("t_s,z_m_s2\n");
    for i in 0..3000 {
        let t = 1.5 + i as f64 / 400.0;
        text.push_str(&format!(
            "{t},{}\n",
            2.0 * (7.0 * t).sin() + (31.0 * t).cos()
        ));
    }
    std::fs::write(&rec, text).expect("write record");
    for _ in 0..4 {
        key(&mut a, KeyCode::Left);
        if tab(&a).settings.signal().is_none() {
            break;
        }
    }
    assert!(tab(&a).settings.signal().is_none(), "file kind");
    edit(&mut a, Row::Path, &rec.display().to_string());
    let mine = export(&mut a, &dir.path().join("rec.csv"));
    let theirs = cli(&[
        "simulate",
        "--input",
        &rec.display().to_string(),
        "--format",
        "csv",
    ]);
    assert!(mine == theirs, "record: the files differ");
    assert_eq!(
        tab(&a).outcome().map(|o| o.traces.seat.len),
        Some(3000),
        "the tab ran the record too"
    );
}

/// The assessment the tab shows, exported by `x` to a `.json` or `.txt`
/// path, is byte for byte what `biodyn assess --format json` / `biodyn
/// assess` print for the same signal or record, exposure, person and model
/// (issue 19 item 21).
#[test]
fn the_assessment_export_equals_biodyn_assess_byte_for_byte() {
    let dir = tempfile::tempdir().expect("tempdir");
    let mut a = App::new(Preset::builtin_default(), None, Theme::default());
    key(&mut a, KeyCode::Char('5'));
    let both = |a: &mut App, name: &str, args: &[&str]| {
        let json = export(a, &dir.path().join(format!("{name}.json")));
        assert!(
            a.status
                .text
                .contains("(what biodyn assess --format json prints)"),
            "{:?}",
            a.status
        );
        let mut with = vec!["assess"];
        with.extend_from_slice(args);
        let mut as_json = with.clone();
        as_json.extend(["--format", "json"]);
        assert!(json == cli(&as_json), "{name}: the JSON differs");
        let text = export(a, &dir.path().join(format!("{name}.TXT")));
        assert!(
            a.status.text.contains("(what biodyn assess prints)"),
            "{:?}",
            a.status
        );
        assert!(text == cli(&with), "{name}: the text differs");
        assert!(
            String::from_utf8_lossy(&text).contains("EU 2002/44/EC"),
            "{name}"
        );
        // .svg: the figure `assess --plot` writes.
        let svg = export(a, &dir.path().join(format!("{name}.svg")));
        assert!(
            a.status
                .text
                .contains("(what biodyn assess --plot FILE.svg writes)"),
            "{:?}",
            a.status
        );
        let file = dir.path().join(format!("{name}-cli.svg"));
        let file_arg = file.display().to_string();
        let mut plot = with.clone();
        plot.extend(["--plot", file_arg.as_str()]);
        cli(&plot);
        let want = std::fs::read(&file).expect("the command's figure");
        assert!(svg == want, "{name}: the figure differs");
        assert!(svg.starts_with(b"<svg version=\"1.1\""), "{name}");
    };

    // the paper's sine, as the tab opens
    both(&mut a, "sine", &["--signal", "sine:freq=5,amp=5"]);

    // a shock-laden ride, 6 h a day, the spine on (Annex C's example person)
    let spec = "random:rms=0.8,band=1-20,seed=1+shock:peak=15,width=0.1,at=2";
    edit(&mut a, Row::Spec, spec);
    edit(&mut a, Row::Duration, "4");
    edit(&mut a, Row::Fs, "500");
    edit(&mut a, Row::Exposure, "6");
    let ride = [
        "--signal",
        spec,
        "--duration",
        "4",
        "--fs",
        "500",
        "--exposure",
        "6",
    ];
    // without --spine: the crest-factor note sends it to ISO 2631-5
    both(&mut a, "ride", &ride);
    key(&mut a, KeyCode::Char('p'));
    let person = tab(&a).settings.person.spec();
    let mut spine = ride.to_vec();
    spine.extend(["--spine", &person]);
    both(&mut a, "ride-spine", &spine);
    key(&mut a, KeyCode::Char('p'));

    // a tri-axial record with a backrest channel beside the seat's
    let rec = dir.path().join("seat.csv");
    let mut text = String::from("t_s,ax,ay,az,backrest_x\n");
    for i in 0..2400 {
        let t = i as f64 / 400.0;
        text.push_str(&format!(
            "{t},{},{},{},{}\n",
            0.5 * (6.0 * t).sin(),
            0.2 * (13.0 * t).cos(),
            2.0 * (31.0 * t).sin(),
            0.4 * (9.0 * t).sin()
        ));
    }
    std::fs::write(&rec, text).expect("write record");
    for _ in 0..4 {
        key(&mut a, KeyCode::Left);
        if tab(&a).settings.signal().is_none() {
            break;
        }
    }
    let rec_s = rec.display().to_string();
    edit(&mut a, Row::Path, &rec_s);
    both(&mut a, "record", &["--input", &rec_s, "--exposure", "6"]);
    // the simulation of the same record is still the CSV of simulate
    let csv = export(&mut a, &dir.path().join("record.csv"));
    assert!(csv == cli(&["simulate", "--input", &rec_s, "--format", "csv"]));
}
