//! Presets with a seat: the shipped two, round trips, and every refusal of
//! the `[seat]` table and the seat's rules, each naming what to fix.

use biodyn::Preset;
use biodyn::body::Origin;

fn shipped() -> String {
    Preset::builtin("paper-75kg-suspension-seat")
        .expect("shipped")
        .expect("parses")
        .to_toml()
}

fn parse(text: &str) -> Result<Preset, String> {
    Preset::parse(text, &Origin::Builtin("t".into())).map_err(|e| e.to_string())
}

#[test]
fn the_shipped_seats_round_trip_exactly() {
    for name in ["paper-75kg-suspension-seat", "paper-75kg-rigid-seat"] {
        let p = Preset::builtin(name).unwrap().unwrap();
        let seat = p.body.seat.clone().expect("a seat");
        assert_eq!(p.body.segments[seat.pan].name, "pad");
        assert_eq!(p.body.links[seat.suspension].name, "suspension");
        assert_eq!(seat.stroke_m, 0.10);
        assert_eq!(
            p.body
                .segments
                .iter()
                .filter(|s| s.seat)
                .map(|s| s.name.as_str())
                .collect::<Vec<_>>(),
            ["pad", "frame"]
        );
        let text = p.to_toml();
        assert!(
            text.contains("[seat]") && text.contains("lower = \"floor\""),
            "{text}"
        );
        assert!(text.contains("seat = true"));
        let back = parse(&text).unwrap();
        assert_eq!(back.body, p.body);
        // A body mass change scales the body, never the seat.
        let mut b = p.body.clone();
        b.set_body_mass(90.0).unwrap();
        assert_eq!(b.segments[seat.pan].mass, p.body.segments[seat.pan].mass);
        assert!((b.seated_mass() - 0.781 * 90.0).abs() < 1e-9);
    }
    // A body without a seat still writes "seat" as its base.
    let plain = Preset::builtin("paper-75kg").unwrap().unwrap().to_toml();
    assert!(plain.contains("lower = \"seat\"") && !plain.contains("[seat]"));
}

#[test]
fn every_seat_refusal_names_the_field_and_the_fix() {
    let base = shipped();
    let cases: Vec<(String, &str)> = vec![
        (
            base.replace("stroke_m = 0.1", "stroke_m = 0.0"),
            "stroke_m = 0",
        ),
        (
            base.replace("stroke_m = 0.1", "stroke_m = -1.0"),
            "must be > 0",
        ),
        (
            base.replace("stroke_m = 0.1", "stroke_m = 3.0"),
            "at most 1 m",
        ),
        (
            base.replace("pan = \"pad\"", "pan = \"nosuch\""),
            "pan = \"nosuch\" is not a segment name",
        ),
        (
            base.replace("pan = \"pad\"", "pan = \"pelvis\""),
            "is not a seat segment",
        ),
        (
            base.replace("suspension = \"suspension\"", "suspension = \"nosuch\""),
            "suspension = \"nosuch\" is not a link name",
        ),
        (
            base.replace("suspension = \"suspension\"", "suspension = \"cushion\""),
            "does not reach the floor",
        ),
        (
            base.replacen("seat = true", "seat = false", 1),
            "the pan is the seat part the body rests on",
        ),
        (cut_seat_table(&base), "has no [seat] table"),
        (
            base.replace("head = \"head-neck\"", "head = \"pad\""),
            "is a seat segment",
        ),
        (
            base.replace("lower = \"pad\"", "lower = \"floor\""),
            "to the floor: with a seat the body rests on the pan only",
        ),
        (
            base.replace("lower = \"pad\"", "lower = \"frame\""),
            "not to the pan 'pad'",
        ),
        (
            base.replace("name = \"frame\"", "name = \"floor\""),
            "reserved for the base",
        ),
        (
            base.replace("stroke_m = 0.1", "stroke_m = 0.1\nextra = 1"),
            "unknown field",
        ),
    ];
    for (text, want) in cases {
        assert_ne!(
            text, base,
            "the case for '{want}' did not change the preset"
        );
        let e = parse(&text).expect_err(want);
        assert!(e.contains(want), "want '{want}' in: {e}");
    }
}

/// The shipped text without its `[seat]` table.
fn cut_seat_table(text: &str) -> String {
    let start = text.find("[seat]").expect("table");
    let end = start + text[start..].find("\n\n").expect("end of table");
    format!("{}{}", &text[..start], &text[end + 2..])
}
