//! Numbers and reasons are never cut: a tiny value in the table and the
//! field, the exact value kept when a field is committed unchanged, an
//! error in a panel, the no-shares advice, a refused body mass and a
//! narrow title bar.

use super::super::theme::Theme;
use super::*;
use biodyn::Param;

/// The last row (k of the last link), its value typed in, then Enter.
fn set_last_stiffness(a: &mut App, text: &str) {
    key(a, KeyCode::End);
    key(a, KeyCode::Enter);
    typ(a, text);
    key(a, KeyCode::Enter);
}

#[test]
fn a_tiny_value_shows_whole_in_the_table_and_compact_in_the_field() {
    let mut a = app();
    set_last_stiffness(&mut a, "1e-320");
    assert!(a.field.is_none(), "{:?}", a.field);
    let s = screen(&a, 80, 24);
    assert!(s.contains("pelvis-seat            1e-320      2064"), "{s}");
    key(&mut a, KeyCode::Enter);
    let f = a.field.as_ref().expect("field");
    assert_eq!(f.text, "1e-320");
    // A huge value too: never 31 digits in the field.
    key(&mut a, KeyCode::Esc);
    set_last_stiffness(&mut a, "1e30");
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.field.as_ref().map(|f| f.text.as_str()), Some("1e30"));
}

#[test]
fn committing_the_prefilled_text_unchanged_keeps_the_exact_value() {
    let mut a = app();
    key(&mut a, KeyCode::Char('-'));
    let exact = a.shared.body.get(Param::BodyMass);
    assert_eq!(exact, 75.0 / 1.05);
    key(&mut a, KeyCode::Enter);
    assert_eq!(
        a.field.as_ref().map(|f| f.text.as_str()),
        Some("71.4285714286")
    );
    key(&mut a, KeyCode::Enter);
    assert!(a.field.is_none());
    assert_eq!(
        a.shared.body.get(Param::BodyMass).to_bits(),
        exact.to_bits()
    );
    assert_eq!(a.status.text, "unchanged");
}

/// The right-hand panels' text, one line per screen row (joined so a
/// wrapped message reads whole).
fn panel_text(s: &str, from_col: usize) -> String {
    s.lines()
        .map(|l| {
            let t: String = l.chars().skip(from_col).collect();
            t.trim_matches(|c| c == '│' || c == ' ').to_string()
        })
        .collect::<Vec<_>>()
        .join(" ")
}

#[test]
fn a_modes_error_wraps_whole_in_its_panel() {
    let mut a = app();
    key(&mut a, KeyCode::End);
    key(&mut a, KeyCode::Right);
    key(&mut a, KeyCode::Enter);
    typ(&mut a, "1e7");
    key(&mut a, KeyCode::Enter);
    for (w, h) in [(80, 24), (200, 60)] {
        let s = screen(&a, w, h);
        let right = panel_text(&s, if w >= 120 { 72 } else { usize::from(w) - 34 });
        for want in [
            "cannot be trusted",
            "span too many orders of magnitude",
            "1e9 N/m)",
        ] {
            assert!(right.contains(want), "{w}x{h} lacks {want:?}:\n{s}");
        }
        assert!(s.contains("(band edge)"), "{w}x{h}:\n{s}");
    }
}

#[test]
fn the_no_shares_advice_shows_whole() {
    let mut b = App::open("boileau-rakheja-1998", Theme::default()).expect("built-in");
    key(&mut b, KeyCode::Enter);
    let want = "no shares: edit m1…m4 (body mass = sum, 55.2 kg)";
    assert_eq!(b.status.text, want);
    for (w, h) in [(80, 24), (60, 16)] {
        let s = screen(&b, w, h);
        assert!(s.contains(want), "{w}x{h}:\n{s}");
    }
    let docs = super::docs_text();
    assert!(docs.contains(&format!("mass says `{want}`")));
}

#[test]
fn a_huge_body_mass_is_refused_without_a_contradiction() {
    let mut a = app();
    key(&mut a, KeyCode::Enter);
    typ(&mut a, "1e30");
    key(&mut a, KeyCode::Enter);
    let e = field_error(&a);
    assert_eq!(
        e,
        "body mass is 1e30 kg: it must be a number from 1e-3 to 1e6 kg"
    );
    assert!(screen(&a, 80, 24).contains("refused: body mass is 1e30 kg: it must be a number"));
}

#[test]
fn a_narrow_title_bar_drops_built_in_before_cutting_the_name() {
    let mut a = app();
    let top = |a: &App, w: u16| screen(a, w, 16).lines().next().unwrap_or("").to_string();
    assert!(top(&a, 60).ends_with(" paper-75kg"), "{}", top(&a, 60));
    key(&mut a, KeyCode::Char('+'));
    let t = top(&a, 60);
    assert!(!t.contains('…') && t.contains("paper-75kg *"), "{t}");
    let mut b = App::open("boileau-rakheja-1998", Theme::default()).expect("built-in");
    assert!(
        top(&b, 60).ends_with(" boileau-rakheja-1998"),
        "{}",
        top(&b, 60)
    );
    key(&mut b, KeyCode::Down);
    key(&mut b, KeyCode::Char('+'));
    let t = top(&b, 60);
    assert!(t.ends_with(" boileau-rakheja-1998 *"), "{t}");
    // 80 columns keep the full tab names (issue 19 item 19): the mark is "*".
    assert!(top(&a, 80).ends_with(" paper-75kg *"), "{}", top(&a, 80));
    assert!(
        top(&a, 120).ends_with("paper-75kg (built-in) *modified"),
        "{}",
        top(&a, 120)
    );
}
