//! Chart tests: every tick label is drawn in the column (row) where the
//! data at its value land, on linear and log axes, at several sizes and in
//! both glyph sets; magnitude axes never go below 0; ASCII glyphs differ.

use super::*;

/// Sizes from the 40×10 minimum of a panel up to 200×60.
const SIZES: [(u16, u16); 6] = [(40, 10), (60, 16), (80, 20), (80, 24), (120, 30), (200, 60)];

fn draw(w: u16, h: u16, series: &[Series], opts: &ChartOpts) -> (Buffer, Layout) {
    let area = Rect::new(0, 0, w, h);
    let mut buf = Buffer::empty(area);
    render(area, &mut buf, series, opts);
    let lay = layout(area, series, opts).expect("room for a plot");
    (buf, lay)
}

fn sym(buf: &Buffer, x: u16, y: u16) -> String {
    buf.cell((x, y))
        .map(|c| c.symbol().to_string())
        .unwrap_or_default()
}

/// Tokens of row `y` between columns [x0, x1): (first column, text).
fn tokens(buf: &Buffer, y: u16, x0: u16, x1: u16) -> Vec<(u16, String)> {
    let mut out: Vec<(u16, String)> = Vec::new();
    let mut cur: Option<(u16, String)> = None;
    for x in x0..x1 {
        let s = sym(buf, x, y);
        if s == " " || s.is_empty() {
            out.extend(cur.take());
        } else {
            cur.get_or_insert((x, String::new())).1.push_str(&s);
        }
    }
    out.extend(cur);
    out
}

/// The x labels as drawn: (the column each is centred on, its value).
fn x_labels(buf: &Buffer, lay: &Layout) -> Vec<(u16, f64)> {
    let row = lay.plot.bottom() + 1;
    let right = buf.area.right() - 1;
    tokens(buf, row, buf.area.x + 1, right)
        .into_iter()
        .map(|(x, t)| {
            let v: f64 = t
                .parse()
                .unwrap_or_else(|_| panic!("label {t:?} is not a number"));
            (x + t.chars().count() as u16 / 2, v)
        })
        .collect()
}

/// The y labels as drawn: (row, value).
fn y_labels(buf: &Buffer, lay: &Layout) -> Vec<(u16, f64)> {
    (lay.plot.y..lay.plot.bottom())
        .filter_map(|y| {
            let t = tokens(buf, y, buf.area.x + 1, lay.plot.x - 1);
            let (_, text) = t.last()?;
            Some((y, text.parse().unwrap_or_else(|_| panic!("label {text:?}"))))
        })
        .collect()
}

/// A straight line over the band, then the same band with a one-point
/// spike at each of `at`: the bounds stay the same, and in the spikes' top
/// row only the spikes' columns are drawn.
fn spikes(at: &[f64]) -> Series {
    let (lo, hi, d) = (0.5, 20.0, 1e-7);
    let mut pts = vec![(lo, 0.1)];
    for &v in at {
        if v - d > lo {
            pts.push((v - d, 0.1));
        }
        pts.push((v, 1.0));
        if v + d < hi {
            pts.push((v + d, 0.1));
        }
    }
    pts.push((hi, 0.1));
    pts.sort_by(|a, b| a.0.total_cmp(&b.0));
    Series {
        name: String::new(),
        points: pts,
    }
}

fn opts(log_x: bool, ascii: bool) -> ChartOpts {
    ChartOpts {
        title: "STHT".into(),
        log_x,
        ascii,
        mono: true,
        ..Default::default()
    }
}

#[test]
fn x_labels_sit_in_the_column_of_their_value() {
    for (w, h) in SIZES {
        for log_x in [false, true] {
            for ascii in [false, true] {
                let o = opts(log_x, ascii);
                let line = Series {
                    name: String::new(),
                    points: vec![(0.5, 0.1), (20.0, 1.0)],
                };
                let (buf, lay) = draw(w, h, &[line], &o);
                let labels = x_labels(&buf, &lay);
                let what = format!("{w}x{h} log {log_x} ascii {ascii}");
                assert!(labels.len() >= 2, "{what}: {labels:?}");
                // The labels are the plan's, round, in order, apart.
                let want: Vec<f64> = lay
                    .x_plan
                    .ticks
                    .iter()
                    .map(|t| t.label.parse().unwrap())
                    .collect();
                assert_eq!(
                    labels.iter().map(|l| l.1).collect::<Vec<_>>(),
                    want,
                    "{what}"
                );
                // Same bounds with spikes at the labels' values, drawn as
                // series 0, 1 and 2 (braille, dots, quadrants; or three
                // ASCII glyphs): each marker lands in the label's column.
                let values: Vec<f64> = labels.iter().map(|l| l.1).filter(|v| *v >= 0.5).collect();
                let at: Vec<u16> = labels.iter().filter(|l| l.1 >= 0.5).map(|l| l.0).collect();
                for nth in 0..3 {
                    let mut s: Vec<Series> = (0..nth)
                        .map(|_| Series {
                            name: String::new(),
                            points: Vec::new(),
                        })
                        .collect();
                    s.push(spikes(&values));
                    let (buf2, lay2) = draw(w, h, &s, &o);
                    assert_eq!(lay2.x_plan, lay.x_plan, "{what}");
                    let p = lay2.plot;
                    let top = (p.y..p.bottom())
                        .find(|&y| (p.x..p.right()).any(|x| sym(&buf2, x, y) != " "))
                        .expect("a drawn row");
                    let drawn: Vec<u16> = (p.x..p.right())
                        .filter(|&x| sym(&buf2, x, top) != " ")
                        .collect();
                    assert_eq!(
                        drawn,
                        at,
                        "{what} series {nth}: spikes vs labels\n{}",
                        buffer_text(&buf2).join("\n")
                    );
                }
                let p = lay.plot;
                // The tick marks on the axis line too, and the cursor.
                for &(col, v) in &labels {
                    let mark = sym(&buf, col, p.bottom());
                    assert!(mark == "┬" || mark == "+", "{what}: {v} over {mark:?}");
                    let mut oc = o.clone();
                    oc.cursor_x = Some(v);
                    let line = Series {
                        name: String::new(),
                        points: vec![(0.5, 0.1), (20.0, 1.0)],
                    };
                    let (b3, _) = draw(w, h, &[line], &oc);
                    let c = if ascii { "|" } else { "│" };
                    if v >= 0.5 || !log_x {
                        let rows = (p.y..p.bottom()).filter(|&y| sym(&b3, col, y) == c).count();
                        assert!(rows as u16 >= p.height / 2, "{what}: cursor at {v}");
                    }
                }
            }
        }
    }
}

#[test]
fn x_labels_are_round_uncut_and_apart() {
    for (w, h) in SIZES {
        for log_x in [false, true] {
            let line = Series {
                name: String::new(),
                points: vec![(0.5, 0.1), (20.0, 1.0)],
            };
            let (buf, lay) = draw(w, h, &[line], &opts(log_x, false));
            let row = lay.plot.bottom() + 1;
            let toks = tokens(&buf, row, 1, w - 1);
            for pair in toks.windows(2) {
                let end = pair[0].0 + pair[0].1.chars().count() as u16;
                assert!(pair[1].0 > end, "{w}x{h}: {toks:?}");
            }
            let vals: Vec<f64> = toks.iter().map(|(_, t)| t.parse().unwrap()).collect();
            let is125 = |v: f64| {
                let m = v / 10f64.powf(v.log10().floor());
                [1.0, 2.0, 5.0, 10.0].iter().any(|r| (m - r).abs() < 1e-9)
            };
            if log_x {
                assert!(vals.iter().all(|&v| is125(v)), "{w}x{h}: {vals:?}");
            } else {
                // Multiples of one 1-2-5 step.
                let d = vals[1] - vals[0];
                assert!(is125(d), "{w}x{h}: {vals:?}");
                assert!(
                    vals.iter()
                        .all(|v| ((v / d) - (v / d).round()).abs() < 1e-9),
                    "{vals:?}"
                );
            }
            // Labels never run into the frame.
            assert_eq!(sym(&buf, w - 1, row), "│", "{w}x{h}");
            if w == 80 && !log_x {
                assert_eq!(toks.len(), 5, "{w}x{h}: {toks:?}");
            }
        }
    }
}

#[test]
fn y_labels_sit_in_the_row_of_their_value() {
    // Plateaus at the levels, one per stretch of x; each level's row is
    // the only one drawn in the middle of its stretch.
    let cases: [(&[f64], bool); 3] = [
        (&[0.0, 0.5, 1.0, 1.5, 2.0], false),
        (&[0.0, 1000.0, 2000.0, 3000.0, 4000.0], false),
        (&[0.2, 0.5, 1.0, 2.0], true),
    ];
    for (w, h) in SIZES {
        for (levels, log_y) in cases {
            for ascii in [false, true] {
                let mut pts = Vec::new();
                for (k, &l) in levels.iter().enumerate() {
                    pts.push((k as f64 + 0.1, l));
                    pts.push((k as f64 + 0.9, l));
                }
                let s = Series {
                    name: String::new(),
                    points: pts,
                };
                let o = ChartOpts {
                    log_y,
                    ascii,
                    mono: true,
                    ..Default::default()
                };
                let (buf, lay) = draw(w, h, std::slice::from_ref(&s), &o);
                let what = format!("{w}x{h} {levels:?} ascii {ascii}");
                let labels = y_labels(&buf, &lay);
                assert!(labels.len() >= 2, "{what}: {labels:?}");
                if lay.plot.height >= 12 {
                    assert!(labels.len() >= 4, "{what}: {labels:?}");
                }
                let mut checked = 0;
                for &(row, v) in &labels {
                    let Some(k) = levels.iter().position(|l| (l - v).abs() < 1e-9) else {
                        continue;
                    };
                    let col = lay.column(k as f64 + 0.5, false).unwrap();
                    let drawn: Vec<u16> = (lay.plot.y..lay.plot.bottom())
                        .filter(|&y| sym(&buf, col, y) != " ")
                        .collect();
                    assert_eq!(
                        drawn,
                        [row],
                        "{what}: level {v}\n{}",
                        buffer_text(&buf).join("\n")
                    );
                    let mark = sym(&buf, lay.plot.x - 1, row);
                    assert!(mark == "┤" || mark == "+", "{what}: {v}");
                    checked += 1;
                }
                assert!(checked >= labels.len().min(3) - 1, "{what}: {labels:?}");
                for pair in labels.windows(2) {
                    assert!(pair[1].1 < pair[0].1, "{what}: order {labels:?}");
                    if labels.len() > 2 {
                        assert!(pair[1].0 - pair[0].0 >= 3, "{what}: {labels:?}");
                    }
                }
            }
        }
    }
}

#[test]
fn magnitude_axes_start_at_zero() {
    // DPMI-like magnitudes of a study: once drawn from -5000.
    let s: Vec<Series> = [65.0, 75.0, 85.0]
        .iter()
        .map(|kg| Series {
            name: format!("{kg} kg"),
            points: (0..=390)
                .map(|i| {
                    let f = 0.5 + i as f64 * 0.05;
                    (f, kg * 40.0 * (1.0 + (f - 5.0).abs()).recip() + 50.0)
                })
                .collect(),
        })
        .collect();
    for (w, h) in SIZES.into_iter().chain([(80, 8), (60, 6)]) {
        let (buf, lay) = draw(w, h, &s, &ChartOpts::default());
        assert_eq!(lay.y_plan.lo, 0.0, "{w}x{h}");
        assert!(lay.y_plan.ticks.iter().all(|t| t.at >= 0.0), "{w}x{h}");
        let text = buffer_text(&buf).join("\n");
        assert!(!text.contains('-') || !text.contains("-1"), "{text}");
        // Log magnitudes stay positive, with a round lower bound.
        let o = ChartOpts {
            log_y: true,
            ..Default::default()
        };
        let lay = layout(Rect::new(0, 0, w, h), &s, &o).unwrap();
        let lo = 10f64.powf(lay.y_plan.lo);
        let min = s[0]
            .points
            .iter()
            .map(|p| p.1)
            .fold(f64::INFINITY, f64::min);
        assert!(lo > 0.0 && lo <= min && lo > min / 5.0, "{w}x{h}: {lo}");
    }
    // A phase keeps its negative side.
    let ph = Series {
        name: "phase".into(),
        points: vec![(0.5, -5.0), (20.0, -170.0)],
    };
    let lay = layout(Rect::new(0, 0, 80, 20), &[ph], &ChartOpts::default()).unwrap();
    assert!(lay.y_plan.lo <= -170.0 && lay.y_plan.hi >= -5.0, "{lay:?}");
}

#[test]
fn ascii_glyphs_are_distinct_and_the_legend_uses_them() {
    let glyphs: Vec<&str> = (0..11).map(|i| legend_glyph(i, true)).collect();
    let mut all = glyphs.clone();
    all.extend([peak_glyph(true), cursor_glyph(true)]);
    let mut uniq = all.clone();
    uniq.sort();
    uniq.dedup();
    assert_eq!(uniq.len(), all.len(), "{all:?}");
    assert!(all.iter().all(|g| g.is_ascii() && g.chars().count() == 1));
    let uni: Vec<&str> = (0..11).map(|i| legend_glyph(i, false)).collect();
    let mut u = uni.clone();
    u.extend([peak_glyph(false), cursor_glyph(false)]);
    u.sort();
    u.dedup();
    assert_eq!(u.len(), 13, "{uni:?}");

    // Three curves, the cursor and peaks: each glyph on screen, each named
    // in the legend by the glyph it is drawn with.
    let series: Vec<Series> = (0..3)
        .map(|k| Series {
            name: format!("{} kg", 65 + 10 * k),
            points: (0..80)
                .map(|i| {
                    let f = 0.5 + i as f64 * 0.25;
                    (f, (f * 0.4 + k as f64).sin() + 2.0 + k as f64 * 0.5)
                })
                .collect(),
        })
        .collect();
    let o = ChartOpts {
        title: "STHT".into(),
        ascii: true,
        mono: true,
        cursor_x: Some(15.0),
        marks: vec![(3.0, 2.5)],
        ..Default::default()
    };
    let (buf, lay) = draw(80, 24, &series, &o);
    let text = buffer_text(&buf).join("\n");
    assert!(text.is_ascii(), "{text}");
    let plot: String = (lay.plot.y..lay.plot.bottom())
        .flat_map(|y| (lay.plot.x..lay.plot.right()).map(move |x| (x, y)))
        .map(|(x, y)| sym(&buf, x, y))
        .collect();
    for g in ["*", "+", "o", "|", "^"] {
        assert!(plot.contains(g), "{g} missing\n{text}");
    }
    for (i, s) in series.iter().enumerate() {
        let entry = format!("{} {}", legend_glyph(i, true), s.name);
        assert!(text.contains(&entry), "{entry}\n{text}");
    }
    assert!(text.contains("^ peak"), "{text}");
}

#[test]
fn coinciding_curves_both_stay_visible() {
    // The prediction chart: a network right on the analytic curve.
    let curve: Vec<(f64, f64)> = (0..200)
        .map(|i| (0.5 + i as f64 * 0.1, 1.0 + (i as f64 * 0.05).sin()))
        .collect();
    let s = [
        Series {
            name: "analytic".into(),
            points: curve.clone(),
        },
        Series {
            name: "network".into(),
            points: curve,
        },
    ];
    for ascii in [true, false] {
        let o = ChartOpts {
            ascii,
            mono: true,
            ..Default::default()
        };
        let (buf, lay) = draw(80, 20, &s, &o);
        let count = |g: &str| {
            (lay.plot.y..lay.plot.bottom())
                .flat_map(|y| (lay.plot.x..lay.plot.right()).map(move |x| (x, y)))
                .filter(|&(x, y)| sym(&buf, x, y) == g)
                .count()
        };
        let (a, b) = if ascii { ("*", "+") } else { ("•", "•") };
        if ascii {
            assert!(
                count(a) > 20 && count(b) > 20,
                "{}",
                buffer_text(&buf).join("\n")
            );
        } else {
            // The braille curve shows between the dots.
            assert!(count(b) > 20, "{}", buffer_text(&buf).join("\n"));
            let braille = (lay.plot.y..lay.plot.bottom())
                .flat_map(|y| (lay.plot.x..lay.plot.right()).map(move |x| (x, y)))
                .filter(|&(x, y)| {
                    sym(&buf, x, y)
                        .chars()
                        .all(|c| ('\u{2801}'..='\u{28FF}').contains(&c))
                })
                .count();
            assert!(braille > 20, "{}", buffer_text(&buf).join("\n"));
            let _ = a;
        }
    }
}

#[test]
fn tiny_and_empty_charts_do_not_panic() {
    for (w, h) in [(10, 5), (12, 6), (9, 4), (300, 5), (10, 200)] {
        let area = Rect::new(0, 0, w, h);
        let mut buf = Buffer::empty(area);
        let o = ChartOpts {
            cursor_x: Some(3.0),
            marks: vec![(1.0, 1.0)],
            log_x: true,
            log_y: true,
            ..Default::default()
        };
        render(area, &mut buf, &[], &o);
        render(
            area,
            &mut buf,
            &[Series {
                name: "x".into(),
                points: vec![(0.0, 0.0), (f64::NAN, 1.0), (1e300, 1e-300)],
            }],
            &o,
        );
        render(
            area,
            &mut buf,
            &[Series {
                name: "c".into(),
                points: vec![(2.0, 5.0); 3],
            }],
            &ChartOpts::default(),
        );
    }
}

#[test]
fn log_axis_labels_are_in_data_units() {
    let area = Rect::new(0, 0, 60, 16);
    let mut buf = Buffer::empty(area);
    let s = vec![Series {
        name: "x".into(),
        points: vec![(1.0, 10.0), (10.0, 1000.0)],
    }];
    let opts = ChartOpts {
        log_y: true,
        log_x: true,
        ..Default::default()
    };
    render(area, &mut buf, &s, &opts);
    let text = buffer_text(&buf).join("\n");
    assert!(text.contains("10"), "{text}");
}

/// `x_at` is the inverse of `column`: every column of the plot gives back
/// an x that lands in that column, on linear and log axes, at every size;
/// columns outside the plot give None.
#[test]
fn x_at_inverts_column() {
    let s = Series {
        name: "s".into(),
        points: (0..=195)
            .map(|i| (0.5 + 0.1 * f64::from(i), 1.0 + f64::from(i % 7)))
            .collect(),
    };
    for log in [false, true] {
        for ascii in [false, true] {
            let opts = ChartOpts {
                log_x: log,
                ascii,
                ..Default::default()
            };
            for (w, h) in SIZES {
                let lay =
                    layout(Rect::new(3, 2, w, h), std::slice::from_ref(&s), &opts).expect("room");
                let p = lay.plot;
                for c in p.x..p.x + p.width {
                    let x = lay.x_at(c, log).expect("inside");
                    assert_eq!(
                        lay.column(x, log),
                        Some(c),
                        "{w}x{h} log {log} column {c} x {x}"
                    );
                }
                assert_eq!(
                    lay.x_at(p.x.saturating_sub(1), log).filter(|_| p.x > 0),
                    None
                );
                assert_eq!(lay.x_at(p.x + p.width, log), None);
            }
        }
    }
}
