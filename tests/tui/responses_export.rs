//! The Responses tab's export (`x`), driven through the real `update`:
//! the CSV is byte for byte `biodyn response --format csv`, the `.txt` is
//! what `biodyn plot <f>` prints for the same function and axes, for the
//! built-in model and for an edited model saved as a preset.

use super::drive::{app, biodyn, ch, export, key, typ};
use biodyn::{Param, Preset};
use ratatui::crossterm::event::KeyCode;

#[test]
fn responses_export_is_the_command_lines_csv_and_plot() {
    let dir = tempfile::tempdir().expect("tempdir");
    let mut a = app(Preset::builtin_default());
    ch(&mut a, '2');
    ch(&mut a, 'x');
    assert_eq!(
        a.field.as_ref().map(|f| f.text.as_str()),
        Some("paper-75kg-responses.csv")
    );
    key(&mut a, KeyCode::Esc);

    let csv = export(&mut a, &dir.path().join("r.csv"));
    assert_eq!(csv, biodyn(&["response", "--format", "csv"]));

    let txt = export(&mut a, &dir.path().join("stht.txt"));
    assert_eq!(
        txt,
        biodyn(&["plot", "stht", "--width", "100", "--height", "30"])
    );

    // f twice: APMS; a: log axes.
    ch(&mut a, 'f');
    ch(&mut a, 'f');
    ch(&mut a, 'a');
    let txt = export(&mut a, &dir.path().join("apms.txt"));
    let want = [
        "plot", "apms", "--log-x", "--log-y", "--width", "100", "--height", "30",
    ];
    assert_eq!(txt, biodyn(&want));
    // p: the phase, on a log frequency axis only.
    ch(&mut a, 'p');
    let txt = export(&mut a, &dir.path().join("apms-phase.txt"));
    let want = [
        "plot", "apms", "--phase", "--log-x", "--width", "100", "--height", "30",
    ];
    assert_eq!(txt, biodyn(&want));
    // .svg: the figure `plot --format svg` writes for the same axes.
    let svg = export(&mut a, &dir.path().join("apms-phase.svg"));
    let want = ["plot", "apms", "--phase", "--log-x", "--format", "svg"];
    assert_eq!(svg, biodyn(&want));
    assert!(svg.starts_with("<svg version=\"1.1\""));
}

#[test]
fn the_svg_export_carries_the_data_and_the_compared_model_as_the_cli_does() {
    let dir = tempfile::tempdir().expect("tempdir");
    let root = env!("CARGO_MANIFEST_DIR");
    let data = format!("{root}/examples/synthetic-stht-apms-3pct-2deg.csv");
    let compare = format!("{root}/presets/paper-85kg.toml");
    let mut a = app(Preset::builtin_default());
    ch(&mut a, '2');
    ch(&mut a, 'D');
    typ(&mut a, &data);
    key(&mut a, KeyCode::Enter);
    ch(&mut a, 'c');
    typ(&mut a, &compare);
    key(&mut a, KeyCode::Enter);
    assert!(a.field.is_none(), "{:?}", a.field);
    let svg = export(&mut a, &dir.path().join("stht.svg"));
    assert!(
        svg.contains("data: synthetic-stht-apms-3pct-2deg.csv"),
        "no data in the figure"
    );
    assert_eq!(
        svg,
        biodyn(&[
            "plot",
            "stht",
            "--data",
            &data,
            "--compare",
            &compare,
            "--format",
            "svg"
        ])
    );
}

#[test]
fn an_edited_models_export_matches_the_cli_on_its_saved_preset() {
    let dir = tempfile::tempdir().expect("tempdir");
    let mut p = Preset::builtin_default();
    p.body.set(Param::BodyMass, 85.0).expect("85 kg");
    p.name = "heavy".into();
    let preset = dir.path().join("heavy.toml");
    p.save(&preset).expect("save");
    let preset = preset.display().to_string();

    let mut a = app(p);
    ch(&mut a, '2');
    // A band edit too: from 1 to 12 Hz by 0.05.
    ch(&mut a, 'b');
    typ(&mut a, "1 12 0.05");
    key(&mut a, KeyCode::Enter);
    assert!(a.field.is_none(), "{:?}", a.field);
    ch(&mut a, 'x');
    assert_eq!(
        a.field.as_ref().map(|f| f.text.as_str()),
        Some("heavy-responses.csv")
    );
    key(&mut a, KeyCode::Esc);
    let band = ["--from", "1", "--to", "12", "--step", "0.05"];
    let csv = export(&mut a, &dir.path().join("h.csv"));
    let mut args = vec!["response", "--format", "csv", "--preset", &preset];
    args.extend(band);
    assert_eq!(csv, biodyn(&args));
    ch(&mut a, 'f');
    let txt = export(&mut a, &dir.path().join("h.txt"));
    let mut args = vec![
        "plot", "dpmi", "--width", "100", "--height", "30", "--preset", &preset,
    ];
    args.extend(band);
    assert_eq!(txt, biodyn(&args));
}
