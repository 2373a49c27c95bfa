//! The Vibration tab on a tri-axial record: snapshots at 80×24 and
//! 160×48 (colour, and ASCII without colour), the axes and unit settings
//! through the keys, the day's axis marked and moving, and the record's
//! refusals in the library's words.
//!
//! The record: 5 s at 1 kHz of x = 0.5 sin 2π·1t, y = 0.2 sin 2π·2t,
//! z = 1.0 sin 2π·5t (m/s², or g where said). It is written under
//! `target/vibration-tests/` by a relative path, not in a temporary folder,
//! because the path is on screen and the snapshots must not change with it.

use super::settings::{Kind, Row};
use super::tests::{app, app_with, edit, key, screen, tab};
use crate::tui::theme::Theme;
use biodyn::iso2631::assess_axes;
use biodyn::time::{Axis, PerAxis, Record, RecordOptions, Unit};
use ratatui::crossterm::event::KeyCode;
use std::path::Path;

/// Writes the record with `header` (4 columns: time, then the three
/// sines in that order) to `target/vibration-tests/{name}.csv`, whole or
/// not at all (rename), and returns that relative path.
fn record(name: &str, header: &str) -> String {
    let dir = Path::new("target/vibration-tests");
    std::fs::create_dir_all(dir).expect("test folder");
    let mut text = format!("{header}\n");
    let tau = std::f64::consts::TAU;
    for i in 0..5000 {
        let t = f64::from(i) / 1000.0;
        let (x, y, z) = (
            0.5 * (tau * t).sin(),
            0.2 * (tau * 2.0 * t).sin(),
            (tau * 5.0 * t).sin(),
        );
        text.push_str(&format!("{t:.3},{x:.6},{y:.6},{z:.6}\n"));
    }
    let path = dir.join(format!("{name}.csv"));
    let part = dir.join(format!("{name}.csv.part"));
    std::fs::write(&part, text).expect("write");
    std::fs::rename(&part, &path).expect("rename");
    path.display().to_string()
}

/// The app on tab 5 with `path` opened as a file source.
fn opened(theme: Theme, path: &str) -> crate::tui::app::App {
    let mut a = app_with(theme);
    key(&mut a, KeyCode::Left); // from sine back to the last kind: file
    assert_eq!(tab(&a).settings.kind, Kind::File);
    edit(&mut a, Row::Path, path);
    assert!(a.field.is_none(), "{:?}", a.field);
    a
}

/// Selects the unit row and steps it `n` times to the right.
fn unit_steps(a: &mut crate::tui::app::App, n: usize) {
    let i = tab(a).rows().iter().position(|&r| r == Row::Unit).expect("unit row");
    while tab(a).sel != i {
        key(a, KeyCode::Down);
    }
    for _ in 0..n {
        key(a, KeyCode::Right);
    }
}

#[test]
fn snapshots_of_a_tri_axial_record() {
    let p = record("tri-snap", "t_s,ax,ay,az");
    let a = opened(Theme::default(), &p);
    for (w, h) in [(80, 24), (160, 48)] {
        let s = screen(&a, w, h);
        // one column per axis and the head; z rules (1.4·0.354 < 0.74)
        assert!(s.contains("z *") && s.contains("head"), "{s}");
        assert!(s.contains("x ax, y ay, z az: m/s2 assumed"), "{s}");
        insta::assert_snapshot!(format!("vibration_tri_axial_{w}x{h}"), s);
    }
    // 160×48 stacks a chart per axis; 80×24 overlays them with a legend
    let big = screen(&a, 160, 48);
    for t in ["seat x (fore-and-aft)", "seat y (lateral)", "seat z (vertical)"] {
        assert!(big.contains(t), "{t}\n{big}");
    }
    assert!(screen(&a, 80, 24).contains("seat x⣿ y⣿ z⣿"));
    let mut a = opened(Theme { mono: true, ascii: true }, &p);
    key(&mut a, KeyCode::Char('w'));
    for (w, h) in [(80, 24), (160, 48)] {
        let s = screen(&a, w, h);
        assert!(s.is_ascii(), "{s}");
        insta::assert_snapshot!(format!("vibration_tri_axial_ascii_weighted_{w}x{h}"), s);
    }
    // without colour each overlaid axis has its own glyph
    let s = screen(&a, 80, 24);
    assert!(s.contains("seat x+ yo z*, Wd/Wk-weighted"), "{s}");
    assert!(screen(&a, 160, 48).contains("seat x (fore-and-aft), Wd-weighted"));
}

#[test]
fn the_table_is_the_librarys_per_axis_assessment() {
    let p = record("tri-numbers", "t_s,ax,ay,az");
    let a = opened(Theme::default(), &p);
    let o = tab(&a).outcome().expect("a run");
    let rec = Record::open(Path::new(&p), &RecordOptions::default()).unwrap();
    let present = rec.axes();
    let want = assess_axes(&a.shared.body, rec.fs(), rec.map(|r| r.map_err(Into::into)), &present, 8.0)
        .unwrap();
    assert_eq!(o.assessment.axes, want.axes);
    assert_eq!(o.traces.samples(), 5000);
    let (x, z) = (
        o.assessment.axes.get(Axis::X).unwrap(),
        o.assessment.axes.get(Axis::Z).unwrap(),
    );
    // 8 h of exposure: A(8) = k·a_w (√(8/8) = 1), k 1.4 on x, 1 on z
    assert!((x.a8 - 1.4 * x.metrics.aw).abs() < 1e-12);
    assert_eq!(z.a8, z.metrics.aw);
    // a sine's r.m.s. is A/√2: the Wk gain at 5 Hz is near 1 (ISO 2631-1
    // Table 3: 1.04), so a_w,z ≈ 0.707·1.04 = 0.74
    assert!((0.70..0.78).contains(&z.metrics.aw), "{}", z.metrics.aw);
    assert_eq!(o.assessment.health.a8_axis, Axis::Z);
    let s = screen(&a, 160, 48);
    let row = s.lines().find(|l| l.contains("A(8) m/s²")).expect("A(8) row");
    for v in [x.a8, z.a8] {
        assert!(row.contains(&format!("{v:.3}")), "{v:.3} in {row}");
    }
    assert!(s.contains(&format!("A(8) {:.3} m/s² (z): above action value", z.a8)), "{s}");
    // the raw x trace peaks at its amplitude, the Wd one lower (|Wd(1 Hz)| ≈ 1)
    assert!((o.traces.seat_x.abs_max - 0.5).abs() < 1e-6);
    assert!((o.traces.seat_y.abs_max - 0.2).abs() < 1e-6);
    assert!(o.traces.seat_x_w.abs_max > 0.4 && o.traces.seat_x_w.abs_max < 0.6);
}

#[test]
fn the_unit_g_scales_every_axis_by_9_80665() {
    let p = record("tri-unit", "t_s,ax,ay,az");
    let mut a = opened(Theme::default(), &p);
    let before = tab(&a).outcome().expect("run").assessment.axes;
    // from header → m/s2: the same numbers; → g: × 9.80665 (ISO 80000-3)
    unit_steps(&mut a, 1);
    assert_eq!(tab(&a).settings.unit, Some(Unit::MetrePerSecondSquared));
    assert_eq!(a.status.text, "unit = m/s2");
    assert_eq!(tab(&a).outcome().expect("run").assessment.axes, before);
    key(&mut a, KeyCode::Right);
    assert_eq!(tab(&a).settings.unit, Some(Unit::G));
    let after = tab(&a).outcome().expect("run").assessment.axes;
    for axis in Axis::ALL {
        let (b, g) = (before.get(axis).unwrap(), after.get(axis).unwrap());
        let ratio = g.metrics.aw / b.metrics.aw;
        assert!((ratio - 9.80665).abs() < 1e-9, "{axis}: {ratio}");
    }
    let z = after.get(Axis::Z).unwrap();
    assert!(screen(&a, 160, 48).contains(&format!("{:.3}", z.metrics.aw)));
    assert!(screen(&a, 80, 24).contains("in g"));
    // a suffix contradicting the unit given: the path is kept (the unit
    // row fixes it) and the run shows the library's words
    let q = record("tri-suffix", "t_s,ax_m_s2,ay_m_s2,az_m_s2");
    edit(&mut a, Row::Path, &q);
    assert!(a.field.is_none(), "{:?}", a.field);
    let e = match &tab(&a).result {
        Some(Err(e)) => e.clone(),
        other => panic!("{:?}", other.as_ref().map(|r| r.is_ok())),
    };
    assert!(e.contains("but the unit given is g"), "{e}");
    assert!(screen(&a, 160, 48).contains("but the unit given is g"));
    // back to the header's word: read as the suffixes say
    unit_steps(&mut a, 2);
    assert_eq!(tab(&a).settings.unit, None);
    assert_eq!(tab(&a).outcome().expect("run").assessment.axes, before);
}

#[test]
fn naming_the_axes_moves_the_days_axis() {
    let p = record("tri-axes", "t_s,ax,ay,az");
    let mut a = opened(Theme::default(), &p);
    assert!(screen(&a, 80, 24).contains("A(8) z 0."));
    // the 5 Hz column read as x (Wd, k 1.4) and the 1 Hz one as z (Wk):
    // Wk falls to about 0.48 at 1 Hz, Wd is still about 0.25 at 5 Hz
    // (ISO 2631-1 Table 3), so 1.4·0.707·0.25 ≈ 0.25 > 0.354·0.48 ≈ 0.17
    edit(&mut a, Row::Axes, "x=az,y=ay,z=ax");
    assert!(a.field.is_none(), "{:?}", a.field);
    let o = tab(&a).outcome().expect("run");
    let (x, z) = (
        o.assessment.axes.get(Axis::X).unwrap(),
        o.assessment.axes.get(Axis::Z).unwrap(),
    );
    assert!(1.4 * x.metrics.aw > z.metrics.aw, "{x:?} {z:?}");
    assert_eq!(o.assessment.health.a8_axis, Axis::X);
    for (w, h) in [(80, 24), (160, 48)] {
        let s = screen(&a, w, h);
        assert!(s.contains("x *") && !s.contains("z *"), "{s}");
    }
    assert!(screen(&a, 80, 24).contains(&format!("A(8) x {:.3}", x.a8)));
    assert!(screen(&a, 80, 24).contains("x az, y ay, z ax: m/s2 assumed"));
    // one axis only (a bare name is z, as --column): one column, no mark
    edit(&mut a, Row::Axes, "ay");
    let o = tab(&a).outcome().expect("run");
    let present: PerAxis<()> = o.traces.axes;
    assert_eq!(present.axes().collect::<Vec<_>>(), [Axis::Z]);
    let s = screen(&a, 160, 48);
    let lines: Vec<&str> = s.lines().collect();
    let title = lines.iter().position(|l| l.contains("ISO 2631-1, 8 h/day")).expect("table");
    let left: String = lines[title + 1].chars().take(46).collect();
    let head: Vec<&str> = left.split(['│', ' ']).filter(|w| !w.is_empty()).collect();
    assert_eq!(head, ["z", "head"], "{s}");
    assert!(!s.contains("highest A(8)") && s.contains("z ay: m/s2 assumed"), "{s}");
}

#[test]
fn a_record_that_names_no_axis_or_no_z_is_refused_in_the_librarys_words() {
    // two acceleration columns, neither names an axis: the path is kept,
    // the run says which columns and shows the axes grammar
    let p = record("tri-unnamed", "t_s,ax,acc1,acc2");
    let mut a = app();
    key(&mut a, KeyCode::Left); // from sine back to the last kind: file
    edit(&mut a, Row::Path, &p);
    assert!(a.field.is_none(), "{:?}", a.field);
    let e = match &tab(&a).result {
        Some(Err(e)) => e.clone(),
        other => panic!("{:?}", other.as_ref().map(|r| r.is_ok())),
    };
    assert!(e.contains("say which column is which axis (x=COL,y=COL,z=COL)"), "{e}");
    // naming them on the axes row runs it
    edit(&mut a, Row::Axes, "x=ax,z=acc2");
    assert!(tab(&a).outcome().is_some_and(|o| o.traces.axes.has(Axis::X)));
    // a column that is not there: refused at the field
    edit(&mut a, Row::Axes, "x=ax,z=nope");
    let e = a.field.as_ref().and_then(|f| f.error.clone()).unwrap_or_default();
    assert!(e.contains("no column named 'nope'"), "{e}");
    key(&mut a, KeyCode::Esc);
    // x and y but no z: the run and the export give the library's reason
    edit(&mut a, Row::Axes, "x=ax,y=acc1");
    assert!(a.field.is_none(), "{:?}", a.field);
    let e = match &tab(&a).result {
        Some(Err(e)) => e.clone(),
        other => panic!("{:?}", other.as_ref().map(|r| r.is_ok())),
    };
    assert!(e.contains("no z (vertical) axis"), "{e}");
    let dir = tempfile::tempdir().expect("tempdir");
    key(&mut a, KeyCode::Char('x'));
    let out = dir.path().join("run.csv");
    a.field
        .as_mut()
        .expect("export field")
        .set_text(out.display().to_string());
    key(&mut a, KeyCode::Enter);
    assert!(
        a.status.error && a.status.text.contains("no z (vertical) column, only x = ax (m/s2)"),
        "{:?}",
        a.status
    );
    assert!(!out.exists());
}

/// A record with other points' columns (ISO 2631-1 §8.2.2: backrest, the
/// seat's roll) runs as before on the seat's axes: the tab reads the
/// seat's rows and leaves the points to `biodyn assess`.
#[test]
fn a_record_with_other_points_runs_on_the_seat() {
    let p = record("points", "t_s,backrest_x,rx,az");
    let a = opened(Theme::default(), &p);
    let o = tab(&a).outcome().expect("a run");
    assert_eq!(o.assessment.axes.axes().collect::<Vec<_>>(), [Axis::Z]);
    assert_eq!(o.traces.samples(), 5000);
    let z = o.assessment.axes.get(Axis::Z).unwrap();
    assert!((0.70..0.78).contains(&z.metrics.aw), "{}", z.metrics.aw);
    let s = screen(&a, 160, 48);
    assert!(s.contains("z az: m/s2 assumed") && s.contains("a_w m/s²"), "{s}");
}
