//! The Vibration tab's ISO 2631-5 block: `p` and the spine row, the block
//! equal to the library's, the peaks marked on the seat trace, refusals in
//! the library's words; snapshots at 80×24 and 160×48.

use super::settings::Row;
use super::tests::{RANDOM_SHOCK, app, app_with, edit, key, screen, tab};
use crate::tui::theme::Theme;
use biodyn::Preset;
use biodyn::iso2631::assess_with;
use biodyn::iso2631::spine::{Person, Sex};
use biodyn::time::{Axis, Generator, PerAxis, Signal};
use ratatui::crossterm::event::KeyCode;

fn spine_on(theme: Theme) -> crate::tui::app::App {
    let mut a = app_with(theme);
    edit(&mut a, Row::Spec, RANDOM_SHOCK);
    key(&mut a, KeyCode::Char('p'));
    a
}

#[test]
fn snapshots_with_the_spine() {
    let mut a = spine_on(Theme::default());
    for (w, h) in [(80, 24), (160, 48)] {
        insta::assert_snapshot!(format!("vibration_spine_{w}x{h}"), screen(&a, w, h));
    }
    key(&mut a, KeyCode::Char('s'));
    key(&mut a, KeyCode::Char('s'));
    insta::assert_snapshot!("vibration_spine_notes_80x24", screen(&a, 80, 24));
    let b = spine_on(Theme {
        mono: true,
        ascii: true,
    });
    let s = screen(&b, 80, 24);
    assert!(s.is_ascii(), "{s}");
    assert!(s.contains("v spine peaks"), "{s}");
    insta::assert_snapshot!("vibration_spine_ascii_80x24", s);
}

/// `p` turns the block on and off; on, it is the library's assessment of
/// the same signal for Annex C's example person, and its peaks are marked.
#[test]
fn p_toggles_the_librarys_spine_block_and_its_marks() {
    let mut a = app();
    edit(&mut a, Row::Spec, RANDOM_SHOCK);
    assert!(tab(&a).outcome().unwrap().assessment.spine.is_none());
    let off = screen(&a, 80, 24);
    assert!(!off.contains('▼') && off.contains("p spine"), "{off}");
    key(&mut a, KeyCode::Char('p'));
    let who = Person::new(25.0, 10, 240, Sex::Male).unwrap();
    assert_eq!(tab(&a).input().spine, Some(who));
    let got = tab(&a).outcome().unwrap().assessment.spine.clone();
    let sig = Signal::parse(RANDOM_SHOCK).unwrap();
    let g = Generator::new(&sig, 1000.0, 10.0).unwrap();
    let mut z = PerAxis::default();
    z.set(Axis::Z, ());
    let body = Preset::builtin_default().body;
    let want = assess_with(&body, 1000.0, g.map(|a| Ok([0.0, 0.0, a])), &z, 8.0, Some(&who))
        .unwrap()
        .spine;
    assert_eq!(got, want);
    let sp = got.unwrap().unwrap();
    let on = screen(&a, 80, 24);
    assert!(on.contains("▼ spine peaks"), "{on}");
    assert!(on.contains(&format!("spine R {:.2} P {:.2}", sp.risk.r, sp.risk.probability)), "{on}");
    key(&mut a, KeyCode::Char('p'));
    assert!(tab(&a).outcome().unwrap().assessment.spine.is_none());
    assert!(!screen(&a, 80, 24).contains('▼'));
}

/// The spine row takes the `--spine` grammar: a bad person keeps the field
/// open with the library's reason; `off` turns it off; Enter on the row as
/// it stands (off) turns it on with the last person.
#[test]
fn the_spine_row_edits_the_person() {
    let mut a = app();
    edit(&mut a, Row::Spine, "age=-3,years=10,days=240,sex=male");
    let f = a.field.as_ref().expect("the field stays open");
    assert!(f.error.as_deref().is_some_and(|e| e.contains("age -3")), "{:?}", f.error);
    key(&mut a, KeyCode::Esc);
    assert!(!tab(&a).settings.spine_on);
    edit(&mut a, Row::Spine, "age=40,years=5,days=200,sex=female");
    assert!(a.field.is_none());
    let p = tab(&a).input().spine.unwrap();
    assert_eq!((p.age, p.years, p.days, p.sex), (40.0, 5, 200, Sex::Female));
    assert!(tab(&a).outcome().unwrap().assessment.spine.as_ref().unwrap().is_ok());
    edit(&mut a, Row::Spine, "off");
    assert!(tab(&a).input().spine.is_none());
    // Off: Enter, Enter keeps the woman and turns the block on.
    key(&mut a, KeyCode::Enter);
    key(&mut a, KeyCode::Enter);
    assert_eq!(tab(&a).input().spine.map(|p| p.sex), Some(Sex::Female));
}

/// A record the spine cannot judge (a one-sided shock: its mean is 10 % of
/// its largest peak) keeps its ISO 2631-1 assessment, the notes say why;
/// a record too short to judge at all gets no verdict, the run says why.
#[test]
fn what_the_spine_cannot_judge_is_said_in_the_notes() {
    let mut a = spine_on(Theme::default());
    edit(&mut a, Row::Spec, "shock:peak=30,width=0.5,at=1");
    edit(&mut a, Row::Duration, "3");
    let o = tab(&a).outcome().expect("ISO 2631-1 still judged");
    assert!(matches!(o.assessment.spine, Some(Err(_))));
    key(&mut a, KeyCode::Char('s'));
    key(&mut a, KeyCode::Char('s'));
    let s = screen(&a, 160, 48);
    assert!(s.contains("! ISO 2631-5: spine: the seat's z"), "{s}");
    edit(&mut a, Row::Spec, "sine:freq=5,amp=2");
    edit(&mut a, Row::Duration, "1");
    assert!(a.field.is_none(), "{:?}", a.field);
    assert!(tab(&a).outcome().is_none());
    let s = screen(&a, 160, 48);
    assert!(s.contains("too short to judge"), "{s}");
}
