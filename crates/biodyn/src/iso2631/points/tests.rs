use super::*;
use std::f64::consts::PI;

/// ISO 2631-1:1997 Table 1 and §8.2.2 (seated, comfort): backrest x Wc 0.8,
/// y Wd 0.5, z Wd 0.4; feet Wk 0.25, 0.25, 0.4; seat rotations rx, ry, rz We
/// 0.63, 0.4, 0.2 m/rad.
#[test]
fn the_table_is_the_standards() {
    let standard = [
        ("backrest_x", "Wc", 0.8),
        ("backrest_y", "Wd", 0.5),
        ("backrest_z", "Wd", 0.4),
        ("feet_x", "Wk", 0.25),
        ("feet_y", "Wk", 0.25),
        ("feet_z", "Wk", 0.4),
        ("rx", "We", 0.63),
        ("ry", "We", 0.4),
        ("rz", "We", 0.2),
    ];
    for ((r, c), (name, w, k)) in POINTS.iter().zip(PointAxis::ALL).zip(standard) {
        assert_eq!(r.channel, c);
        assert_eq!(point_rule(c), r);
        assert_eq!(c.name(), name);
        assert_eq!(r.weighting.name(), w, "{name}");
        assert_eq!(r.k, k, "{name}");
    }
}

/// Hand-worked: backrest a_w x 0.5, y 0.4, z 0.5 → k·a_w 0.4, 0.2, 0.2,
/// a_v = √0.24; feet z 1.0 → 0.4; seat 0.3: overall √(0.09 + 0.24 + 0.16)
/// = 0.7, "fairly uncomfortable" (Annex C: 0.5–1 m/s²).
#[test]
fn point_totals_and_the_overall_value_by_hand() {
    let ch = |p, a| PointAxis::new(p, a);
    let got = PointsComfort::of(
        &[
            (ch(Point::Backrest, Axis::X), 0.5),
            (ch(Point::Backrest, Axis::Y), 0.4),
            (ch(Point::Backrest, Axis::Z), 0.5),
            (ch(Point::Feet, Axis::Z), 1.0),
        ],
        0.3,
    );
    assert_eq!(got.points.len(), 2);
    let back = &got.points[0];
    assert_eq!(back.point, Point::Backrest);
    let weighted: Vec<f64> = back.axes.iter().map(PointAxisComfort::weighted).collect();
    assert_eq!(weighted, [0.4, 0.2, 0.2]);
    assert!((back.total - 0.24f64.sqrt()).abs() < 1e-15);
    let feet = &got.points[1];
    assert_eq!(
        (feet.point, feet.axes.len(), feet.total),
        (Point::Feet, 1, 0.4)
    );
    assert!((got.overall - 0.7).abs() < 1e-15, "{}", got.overall);
    assert_eq!(got.words, ["fairly uncomfortable"]);
    assert_eq!(got.seat, 0.3);
}

/// One sine per channel through the streaming weightings: a_w is
/// A/√2·|W(f)| by the analog weighting the table names (the digital filters
/// hold it within 1 % at 1 kHz), k·a_w and a_v follow.
#[test]
fn sines_at_every_point_give_their_weighted_values() {
    let fs = 1000.0;
    let sines = [
        (PointAxis::new(Point::Backrest, Axis::X), 1.0, 4.0),
        (PointAxis::new(Point::Feet, Axis::Z), 2.0, 8.0),
        (PointAxis::new(Point::Rotation, Axis::X), 0.5, 1.0),
        (PointAxis::new(Point::Rotation, Axis::Z), 0.8, 2.0),
    ];
    let mut present = PerPoint::default();
    for (c, _, _) in sines {
        present.set(c, ());
    }
    let mut acc = PointsAccumulator::new(&present, fs);
    assert!(!acc.is_empty());
    // 40 s, the first 10 s of the high-pass's settling outweighed.
    for k in 0..40_000 {
        let t = k as f64 / fs;
        let mut row = [0.0; 9];
        for (c, amp, f) in sines {
            row[c.slot()] = amp * (2.0 * PI * f * t).sin();
        }
        acc.push(&row);
    }
    let got = acc.results(0.0).unwrap();
    let mut squares = 0.0;
    for (c, amp, f) in sines {
        let r = point_rule(c);
        let want = amp / 2f64.sqrt() * r.weighting.analog(f).norm();
        let p = got.points.iter().find(|p| p.point == c.point).unwrap();
        let a = p.axes.iter().find(|a| a.rule.channel == c).unwrap();
        assert!((a.aw / want - 1.0).abs() < 0.01, "{c}: {} vs {want}", a.aw);
        assert_eq!(a.weighted(), r.k * a.aw);
        squares += a.weighted().powi(2);
    }
    assert_eq!(got.points.len(), 3);
    assert!((got.overall - squares.sqrt()).abs() < 1e-12);
    let rot = got
        .points
        .iter()
        .find(|p| p.point == Point::Rotation)
        .unwrap();
    let want_rot = total_value(rot.axes.iter().map(PointAxisComfort::weighted));
    assert_eq!(rot.total, want_rot);
    assert!(
        PointsAccumulator::new(&PerPoint::default(), fs)
            .results(1.0)
            .is_none()
    );
}
