//! `seat --plot` and `day --plot`: the figures read back. The seat's
//! transmissibility lies on `biodyn response`'s columns and its bars on
//! `seat --format json`'s SEAT %; the day's bars are the JSON's points of
//! each operation's highest axis and of the day, filled by the verdict,
//! with the action and limit lines at 100 and 529 points.

use super::common::{fails, ok, root, run, skip};
use super::figures::{off_curve, plain, png_size, response, rsvg_convert};
use biodyn_app::view::figure::read::{self, Element, Region};

const SEAT: &str = "paper-75kg-suspension-seat";

/// The seat figure's panels, one above the other, 800 × 420 each; the
/// day's, 800 × 460 (points, then the VDV).
fn row(k: usize, h: f64) -> Region {
    (0.0, k as f64 * h, 800.0, (k + 1) as f64 * h)
}

/// The bars filled `fill` in `region`: (centre x px, height through the y axis, one px in y units).
fn bars(els: &[Element], region: Region, fill: &str) -> Vec<(f64, f64, f64)> {
    let my = read::y_axis(els, region, false).expect("the y axis");
    assert!(my.worst_px <= 1.0, "{my:?}");
    let unit = (my.at.1 - my.at.0).abs() / (my.px.1 - my.px.0).abs().max(1.0);
    els.iter()
        .filter(|e| e.name == "rect" && e.attr("fill") == Some(fill))
        .filter_map(|e| Some((e.num("x")?, e.num("y")?, e.num("width")?)))
        .filter(|&(x, y, _)| x >= region.0 && x < region.2 && y >= region.1 && y < region.3)
        // The legend's sample is 20 px wide; a bar is wider.
        .filter(|&(_, _, w)| w > 24.0)
        .map(|(x, y, w)| (x + w / 2.0, my.value(y), unit))
        .collect()
}

/// The name of the category under pixel `x`.
fn under(cats: &[(f64, String)], x: f64) -> &str {
    cats.iter()
        .min_by(|a, b| (a.0 - x).abs().total_cmp(&(b.0 - x).abs()))
        .map_or("", |c| c.1.as_str())
}

#[test]
fn the_seat_figure_reads_back_as_the_response_and_the_classes_seat() {
    let dir = tempfile::tempdir().expect("a temp dir");
    let path = dir.path().join("seat.svg");
    let s = path.to_str().expect("utf-8");
    // With --class: the table is the one class's, the figure every class's.
    let table = ok(&["seat", "--preset", SEAT, "--class", "EM6", "--plot", s]);
    assert_eq!(table, ok(&["seat", "--preset", SEAT, "--class", "EM6"]));
    let els = plain(&std::fs::read_to_string(&path).expect("the figure"));

    let top = row(0, 420.0);
    let axes = read::axes(&els, top, false, false).expect("the axes");
    for (name, column) in [
        ("seat transmissibility (pan over floor)", "seat_tr_mag"),
        ("floor-to-head transmissibility", "floor_head_mag"),
    ] {
        let colour = read::legend_colour(&els, name).unwrap_or_else(|| panic!("no legend {name}"));
        let want = response(&["--preset", SEAT], column);
        let (worst, lo, hi) = off_curve(&els, &colour, axes, &want);
        assert!(worst <= 1.5, "{name}: {worst} px off");
        assert!((lo - want[0].0).abs() < 0.05, "{name} starts at {lo}");
        assert!(
            (hi - want[want.len() - 1].0).abs() < 0.05,
            "{name} ends at {hi}"
        );
    }

    let v: serde_json::Value =
        serde_json::from_str(&ok(&["seat", "--preset", SEAT, "--format", "json"])).expect("JSON");
    let classes = v["classes"].as_array().expect("classes");
    let low = row(1, 420.0);
    let cats = read::categories(&els, low);
    let names: Vec<&str> = cats.iter().map(|c| c.1.as_str()).collect();
    let want: Vec<&str> = classes.iter().filter_map(|c| c["class"].as_str()).collect();
    assert_eq!(names, want);
    let plain_bars = bars(&els, low, "#9EC9E2");
    let selected = bars(&els, low, "#0072B2");
    assert_eq!(plain_bars.len(), 15);
    assert_eq!(selected.len(), 1);
    assert_eq!(under(&cats, selected[0].0), "EM6");
    for (x, h, unit) in plain_bars.iter().chain(&selected) {
        let class = under(&cats, *x);
        let c = classes
            .iter()
            .find(|c| c["class"] == class)
            .expect("the class");
        let pct = c["seat_pct"].as_f64().expect("SEAT %");
        assert!(
            (h - pct).abs() <= 1.5 * unit,
            "{class}: {h} drawn, {pct} in the JSON"
        );
    }
    assert!(read::legend_colour(&els, "100 %: the floor's a_w").is_some());
    assert!(read::legend_colour(&els, "EM6, selected").is_some());
    // Under EM6, the design map of the Seat tab: 21 × 21 cells.
    let shades = [
        "#FFFFCC", "#C7E9B4", "#7FCDBB", "#41B6C4", "#1D91C0", "#225EA8", "#0C2C84", "#BBBBBB",
    ];
    let cells = els
        .iter()
        .filter(|e| e.name == "rect" && e.attr("fill").is_some_and(|f| shades.contains(&f)))
        .filter(|e| e.num("y").is_some_and(|y| y >= 840.0))
        .count();
    // Each shade's key swatch is one more rect.
    assert!((441..=441 + 8).contains(&cells), "{cells} cells");
}

/// The cells of a map: (centre x px, centre y px, fill).
fn cells(els: &[Element]) -> Vec<(f64, f64, String)> {
    els.iter()
        .filter(|e| e.name == "rect")
        .filter_map(|e| {
            let f = e.attr("fill")?;
            let shade = f == "#BBBBBB"
                || [
                    "#FFFFCC", "#C7E9B4", "#7FCDBB", "#41B6C4", "#1D91C0", "#225EA8", "#0C2C84",
                ]
                .contains(&f);
            // The key's swatches are 22 px wide, beside the plot.
            (shade && e.num("x")? < 620.0).then(|| {
                Some((
                    e.num("x")? + e.num("width")? / 2.0,
                    e.num("y")? + e.num("height")? / 2.0,
                    f.to_string(),
                ))
            })?
        })
        .collect()
}

#[test]
fn the_design_searchs_map_puts_the_best_point_where_the_json_has_it() {
    let dir = tempfile::tempdir().expect("a temp dir");
    let path = dir.path().join("map.svg");
    let s = path.to_str().expect("utf-8");
    let search = [
        "seat",
        "--preset",
        SEAT,
        "--class",
        "EM6",
        "--vary",
        "suspension.k=4000..40000",
        "--vary",
        "suspension.c=200..4000",
        "--stroke-rms-max",
        "0.0012",
    ];
    let mut with_plot = search.to_vec();
    with_plot.extend(["--format", "json", "--plot", s]);
    let mut json_only = search.to_vec();
    json_only.extend(["--format", "json"]);
    let json = ok(&with_plot);
    assert_eq!(json, ok(&json_only), "--plot changes nothing printed");
    let v: serde_json::Value = serde_json::from_str(&json).expect("JSON");
    let els = plain(&std::fs::read_to_string(&path).expect("the figure"));
    let region = (0.0, 0.0, 1000.0, 560.0);
    let (mx, my) = read::axes(&els, region, true, true).expect("log axes");
    assert!(mx.worst_px <= 1.0 && my.worst_px <= 1.0, "{mx:?} {my:?}");
    // The best point: the cross at the JSON's best k and c.
    let best = &v["best"]["params"];
    let (bk, bc) = (
        best["suspension.k"].as_f64().expect("k"),
        best["suspension.c"].as_f64().expect("c"),
    );
    // A cross is two lines; its centre is their middle.
    let cross: Vec<(f64, f64)> = els
        .iter()
        .filter(|e| e.name == "line" && e.attr("stroke-width") == Some("2"))
        .filter_map(|e| {
            Some((
                (e.num("x1")? + e.num("x2")?) / 2.0,
                (e.num("y1")? + e.num("y2")?) / 2.0,
            ))
        })
        .collect();
    let (px, py) = (mx.pixel(bc), my.pixel(bk));
    assert!(
        cross
            .iter()
            .any(|&(x, y)| (x - px).abs() <= 7.0 && (y - py).abs() <= 7.0),
        "no cross at {px},{py}"
    );
    // The seat now: the circle at the preset's k = 8000, c = 800.
    let circle = els
        .iter()
        .find(|e| e.name == "circle")
        .expect("the seat now");
    assert!((circle.num("cx").expect("cx") - mx.pixel(800.0)).abs() <= 1.0);
    assert!((circle.num("cy").expect("cy") - my.pixel(8000.0)).abs() <= 1.0);
    // Every grid node's cell is there, grey where its travel passes the limit.
    let map = &v["map"];
    let nodes = |name: &str| -> Vec<f64> {
        map["axes"][name]
            .as_array()
            .expect(name)
            .iter()
            .filter_map(|x| x.as_f64())
            .collect()
    };
    let (ks, cs) = (nodes("suspension.k"), nodes("suspension.c"));
    let stroke: Vec<f64> = map["stroke_rms_m"]
        .as_array()
        .expect("stroke")
        .iter()
        .flat_map(|r| r.as_array().cloned().unwrap_or_else(|| vec![r.clone()]))
        .filter_map(|x| x.as_f64())
        .collect();
    assert_eq!(stroke.len(), ks.len() * cs.len());
    let drawn = cells(&els);
    assert_eq!(drawn.len(), ks.len() * cs.len());
    let mut grey = 0;
    for (i, &k) in ks.iter().enumerate() {
        for (j, &c) in cs.iter().enumerate() {
            let (x, y) = (mx.pixel(c), my.pixel(k));
            let cell = drawn
                .iter()
                .find(|d| (d.0 - x).abs() < 3.0 && (d.1 - y).abs() < 3.0)
                .unwrap_or_else(|| panic!("no cell at k {k}, c {c}"));
            let over = stroke[i * cs.len() + j] > 0.0012;
            assert_eq!(cell.2 == "#BBBBBB", over, "k {k}, c {c}: {}", cell.2);
            grey += usize::from(over);
        }
    }
    assert!(grey > 0 && grey < drawn.len(), "{grey} grey cells");
    assert!(read::legend_colour(&els, "r.m.s. stroke over 1.2 mm").is_some());
}

#[test]
fn the_seat_figure_takes_a_band_and_a_psd_and_refuses_what_it_cannot_draw() {
    let dir = tempfile::tempdir().expect("a temp dir");
    let path = dir.path().join("s.svg");
    let s = path.to_str().expect("utf-8");
    let psd = dir.path().join("floor.csv");
    std::fs::write(&psd, "f_hz,psd_m2_s4_hz\n0.5,0.1\n2,0.4\n10,0.2\n40,0.01\n").expect("psd");
    let p = psd.to_str().expect("utf-8");
    run_ok(&[
        "seat", "--preset", SEAT, "--psd", p, "--plot", s, "--from", "1", "--to", "8",
    ]);
    let els = plain(&std::fs::read_to_string(&path).expect("the figure"));
    let (mx, _) = read::axes(&els, row(0, 420.0), false, false).expect("axes");
    let colour =
        read::legend_colour(&els, "seat transmissibility (pan over floor)").expect("legend");
    let xs: Vec<f64> = read::vertices(&els, &colour, row(0, 420.0))
        .iter()
        .map(|v| mx.value(v.0))
        .collect();
    let (lo, hi) = xs
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    assert!(
        (lo - 1.0).abs() < 0.05 && (hi - 8.0).abs() < 0.05,
        "{lo}..{hi}"
    );
    // The file's floor is the 17th bar, selected.
    let cats = read::categories(&els, row(1, 420.0));
    assert_eq!(cats.len(), 17);
    assert!(read::legend_colour(&els, "floor.csv, selected").is_some());

    let e = fails(&["seat", "--preset", SEAT, "--plot", "seat.png"]);
    assert!(e.contains("does not end in .svg"), "{e}");
    let e = fails(&["seat", "--preset", SEAT, "--from", "2"]);
    assert!(e.contains("the band is the seat figure's"), "{e}");
    let e = fails(&[
        "seat",
        "--preset",
        SEAT,
        "--class",
        "EM6",
        "--vary",
        "suspension.c=200..4000",
        "--stroke-rms-max",
        "0.015",
        "--plot",
        s,
        "--from",
        "2",
    ]);
    assert!(e.contains("the band is the seat figure's"), "{e}");
    // Not onto its own input: the PSD file stays as it was.
    let before = std::fs::read(&psd).expect("psd");
    let (code, _, err) = run(&["seat", "--preset", SEAT, "--psd", p, "--plot", p]);
    assert_eq!(code, Some(1), "{err}");
    assert_eq!(std::fs::read(&psd).expect("psd"), before);
}

fn run_ok(args: &[&str]) {
    let (code, _, err) = run(args);
    assert_eq!(code, Some(0), "{args:?}: {err}");
}

#[test]
fn the_day_figure_reads_back_as_the_jsons_points_and_verdicts() {
    let dir = tempfile::tempdir().expect("a temp dir");
    let path = dir.path().join("day.svg");
    let s = path.to_str().expect("utf-8");
    let day = "examples/day.toml";
    let json = ok(&["day", day, "--format", "json", "--plot", s]);
    let v: serde_json::Value = serde_json::from_str(&json).expect("JSON");
    let els = plain(&std::fs::read_to_string(&path).expect("the figure"));
    let panel = row(0, 460.0);
    let cats = read::categories(&els, panel);
    // Each operation on its highest axis by points, then the day's.
    let mut want: Vec<(String, f64, f64)> = Vec::new();
    for o in v["operations"].as_array().expect("operations") {
        let (axis, e) = o["axes"]
            .as_object()
            .expect("axes")
            .iter()
            .max_by(|a, b| {
                let p = |e: &serde_json::Value| e["points"].as_f64().unwrap_or(f64::NAN);
                p(a.1).total_cmp(&p(b.1))
            })
            .expect("an axis");
        let name = format!("{} ({axis})", o["name"].as_str().expect("name"));
        want.push((
            name,
            e["points"].as_f64().expect("points"),
            e["a8_m_s2"].as_f64().expect("a8"),
        ));
    }
    let d = &v["daily"];
    want.push((
        format!("the day ({})", d["a8_axis"].as_str().expect("axis")),
        d["points"].as_f64().expect("points"),
        d["a8_m_s2"].as_f64().expect("a8"),
    ));
    let names: Vec<&str> = cats.iter().map(|c| c.1.as_str()).collect();
    let want_names: Vec<&str> = want.iter().map(|w| w.0.as_str()).collect();
    assert_eq!(names, want_names);
    let mut seen = 0;
    for (fill, lo, hi) in [
        ("#9EC9E2", 0.0, 0.5),
        ("#E69F00", 0.5, 1.15),
        ("#D55E00", 1.15, 1e9),
    ] {
        for (x, h, unit) in bars(&els, panel, fill) {
            let name = under(&cats, x);
            let w = want
                .iter()
                .find(|w| w.0 == name)
                .expect("a bar of the JSON");
            assert!(
                (h - w.1).abs() <= 1.5 * unit,
                "{name}: {h} drawn, {} points",
                w.1
            );
            assert!(
                (w.2 > lo || lo == 0.0) && w.2 <= hi,
                "{name}: A(8) {} filled {fill}",
                w.2
            );
            seen += 1;
        }
    }
    assert_eq!(seen, want.len());
    // The two lines, level at 100 and 529 points.
    let my = read::y_axis(&els, panel, false).expect("y");
    for (name, at) in [
        ("action value: 100 points (0.5 m/s²)", 100.0),
        ("limit value: 529 points (1.15 m/s²)", 529.0),
    ] {
        let colour = read::legend_colour(&els, name).unwrap_or_else(|| panic!("no legend {name}"));
        let ys: Vec<f64> = read::vertices(&els, &colour, panel)
            .iter()
            .map(|v| my.value(v.1))
            .collect();
        assert!(!ys.is_empty(), "{name}");
        assert!(ys.iter().all(|y| (y - at).abs() < 1.5), "{name}: {ys:?}");
    }
}

/// Under the points, the VDV: each operation's highest VDV over its hours
/// (the JSON's `vdv_exposure_m_s175`), then the day's, filled by the VDV
/// verdict, against 9.1 and 21 m/s^1.75 (Directive 2002/44/EC Art. 3). A
/// day whose operations lack VDVs shows its known part "at least", and an
/// operation without one has no bar.
#[test]
fn the_day_figure_shows_the_vdv_under_the_points() {
    let dir = tempfile::tempdir().expect("a temp dir");
    let path = dir.path().join("day.svg");
    let s = path.to_str().expect("utf-8");
    let json = ok(&["day", "examples/day.toml", "--format", "json", "--plot", s]);
    let v: serde_json::Value = serde_json::from_str(&json).expect("JSON");
    let els = plain(&std::fs::read_to_string(&path).expect("the figure"));
    let panel = row(1, 460.0);
    let cats = read::categories(&els, panel);
    let mut want: Vec<(String, f64)> = Vec::new();
    for o in v["operations"].as_array().expect("operations") {
        let (axis, vdv) = o["axes"]
            .as_object()
            .expect("axes")
            .iter()
            .map(|(a, e)| (a.clone(), e["vdv_exposure_m_s175"].as_f64().expect("a VDV")))
            .max_by(|a, b| a.1.total_cmp(&b.1))
            .expect("an axis");
        want.push((
            format!("{} ({axis})", o["name"].as_str().expect("name")),
            vdv,
        ));
    }
    let d = &v["daily"];
    want.push((
        format!("the day ({})", d["vdv_axis"].as_str().expect("axis")),
        d["vdv_exposure_m_s175"].as_f64().expect("the day's VDV"),
    ));
    let names: Vec<&str> = cats.iter().map(|c| c.1.as_str()).collect();
    assert_eq!(names, want.iter().map(|w| w.0.as_str()).collect::<Vec<_>>());
    let mut seen = 0;
    for (fill, lo, hi) in [
        ("#9EC9E2", 0.0, 9.1),
        ("#E69F00", 9.1, 21.0),
        ("#D55E00", 21.0, 1e9),
    ] {
        for (x, h, unit) in bars(&els, panel, fill) {
            let name = under(&cats, x);
            let w = want
                .iter()
                .find(|w| w.0 == name)
                .expect("a bar of the JSON");
            assert!(
                (h - w.1).abs() <= 1.5 * unit,
                "{name}: {h} drawn, VDV {}",
                w.1
            );
            assert!(
                (w.1 > lo || lo == 0.0) && w.1 <= hi,
                "{name}: VDV {} filled {fill}",
                w.1
            );
            seen += 1;
        }
    }
    assert_eq!(seen, want.len());
    // The day, 23.66, is over the limit: the vermillion fill names it.
    assert!(read::legend_colour(&els, "VDV above the limit value").is_some());
    let my = read::y_axis(&els, panel, false).expect("y");
    for (name, at) in [
        ("action value: VDV 9.1 m/s^1.75", 9.1),
        ("limit value: VDV 21 m/s^1.75", 21.0),
    ] {
        let colour = read::legend_colour(&els, name).unwrap_or_else(|| panic!("no legend {name}"));
        let ys: Vec<f64> = read::vertices(&els, &colour, panel)
            .iter()
            .map(|v| my.value(v.1))
            .collect();
        assert!(!ys.is_empty(), "{name}");
        assert!(ys.iter().all(|y| (y - at).abs() < 0.1), "{name}: {ys:?}");
    }

    // A VDV missing from "idle": no bar for it, the day's known part named.
    let day = dir.path().join("partial.toml");
    std::fs::write(
        &day,
        "[[operation]]\nname = \"rough\"\nhours = 1\naw_m_s2 = { z = 0.5 }\nvdv_m_s175 = { z = 35.41 }\nmeasured_s = 3600\n\n[[operation]]\nname = \"idle\"\nhours = 4\naw_m_s2 = { z = 0.2 }\n",
    )
    .expect("a day file");
    ok(&["day", day.to_str().expect("utf-8"), "--plot", s]);
    let els = plain(&std::fs::read_to_string(&path).expect("the figure"));
    let cats = read::categories(&els, panel);
    let names: Vec<&str> = cats.iter().map(|c| c.1.as_str()).collect();
    assert_eq!(
        names,
        ["rough (z)", "idle (no VDV)", "the day (z, at least)"]
    );
    let red = bars(&els, panel, "#D55E00");
    let drawn: Vec<&str> = red.iter().map(|b| under(&cats, b.0)).collect();
    assert_eq!(drawn, ["rough (z)", "the day (z, at least)"]);
    assert!(
        red.iter().all(|b| (b.1 - 35.41).abs() <= 1.5 * b.2),
        "{red:?}"
    );
}

#[test]
fn a_week_has_a_panel_per_day_and_the_day_report_carries_the_figure() {
    let dir = tempfile::tempdir().expect("a temp dir");
    let path = dir.path().join("week.svg");
    let s = path.to_str().expect("utf-8");
    let day = "examples/day.toml";
    let shocks = "examples/day-shocks.toml";
    run_ok(&["day", day, shocks, "--week", "--plot", s]);
    let els = plain(&std::fs::read_to_string(&path).expect("the figure"));
    for t in [
        "day 1, day.toml: points per operation, its highest axis",
        "day 2, day-shocks.toml: points per operation, its highest axis",
    ] {
        assert!(
            els.iter().any(|e| e.name == "text" && e.text == t),
            "no {t}"
        );
    }
    let page = dir.path().join("day.html");
    let (code, _, err) = run(&["day", day, "--report", page.to_str().expect("utf-8")]);
    assert_eq!(code, Some(0), "{err}");
    let html = std::fs::read_to_string(&page).expect("the page");
    let svg = ok(&["day", day, "--plot", s]);
    assert!(!svg.is_empty());
    let figure = std::fs::read_to_string(&path).expect("the figure");
    let inline = figure.replacen(" xmlns=\"http://www.w3.org/2000/svg\"", "", 1);
    assert!(
        html.contains(inline.trim_end()),
        "the page lacks the figure"
    );
    // --plot and --report on one file, and onto the day file itself: refused.
    let e = fails(&["day", day, "--plot", s, "--report", s]);
    assert!(e.contains("same file"), "{e}");
    let (code, _, _) = run(&["day", day, "--plot", &format!("{}/{day}", root().display())]);
    assert_eq!(code, Some(1));
}

#[test]
fn the_seat_and_day_figures_render_with_rsvg_convert() {
    if !rsvg_convert() {
        return skip("rsvg-convert (librsvg2-bin)");
    }
    let dir = tempfile::tempdir().expect("a temp dir");
    for (name, args, size) in [
        ("seat", vec!["seat", "--preset", SEAT], (800u32, 840u32)),
        ("day", vec!["day", "examples/day.toml"], (800, 920)),
    ] {
        let svg = dir.path().join(format!("{name}.svg"));
        let png = dir.path().join(format!("{name}.png"));
        let mut a = args.clone();
        a.extend(["--plot", svg.to_str().expect("utf-8")]);
        ok(&a);
        assert_eq!(png_size(&svg, &png), size, "{name}");
    }
}

#[test]
fn a_one_parameter_search_draws_seat_and_travel_over_it_with_the_limit() {
    let dir = tempfile::tempdir().expect("a temp dir");
    let path = dir.path().join("line.svg");
    let s = path.to_str().expect("utf-8");
    let search = [
        "seat",
        "--preset",
        SEAT,
        "--class",
        "EM6",
        "--vary",
        "suspension.c=200..4000",
        "--stroke-rms-max",
        "0.015",
        "--format",
        "json",
    ];
    let mut with_plot = search.to_vec();
    with_plot.extend(["--plot", s]);
    let v: serde_json::Value = serde_json::from_str(&ok(&with_plot)).expect("JSON");
    let els = plain(&std::fs::read_to_string(&path).expect("the figure"));
    let map = &v["map"];
    let c: Vec<f64> = map["axes"]["suspension.c"]
        .as_array()
        .expect("c")
        .iter()
        .filter_map(|x| x.as_f64())
        .collect();
    let column = |key: &str, scale: f64| -> Vec<(f64, f64)> {
        let ys = map[key]
            .as_array()
            .expect(key)
            .iter()
            .filter_map(|x| x.as_f64());
        c.iter().copied().zip(ys.map(|y| y * scale)).collect()
    };
    for (k, name, key, scale) in [
        (0, "SEAT %", "seat_pct", 1.0),
        (1, "r.m.s. stroke", "stroke_rms_m", 1e3),
    ] {
        let region = row(k, 380.0);
        let axes = read::axes(&els, region, true, false).expect("axes");
        let colour = read::legend_colour(&els, name).unwrap_or_else(|| panic!("no {name}"));
        let want = column(key, scale);
        assert_eq!(want.len(), 41);
        let (worst, lo, hi) = off_curve(&els, &colour, axes, &want);
        assert!(worst <= 1.5, "{name}: {worst} px off");
        assert!(
            (lo / 200.0 - 1.0).abs() < 0.01 && (hi / 4000.0 - 1.0).abs() < 0.01,
            "{lo}..{hi}"
        );
    }
    // The limit, level at 15 mm.
    let region = row(1, 380.0);
    let (_, my) = read::axes(&els, region, true, false).expect("axes");
    let colour = read::legend_colour(&els, "limit 15 mm").expect("the limit's legend");
    let ys = read::vertices(&els, &colour, region);
    assert!(!ys.is_empty());
    assert!(
        ys.iter().all(|p| (my.value(p.1) - 15.0).abs() < 0.1),
        "{ys:?}"
    );
}
