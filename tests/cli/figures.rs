//! `biodyn plot --format svg`: the figure read back. Its curves' vertices,
//! mapped through the printed tick labels, lie on the values `biodyn
//! response` prints for the same model; the legend names every curve; the
//! file is plain SVG (no transform, no script) and renders.

use super::common::{fails, ok, root, run, skip};
use biodyn_app::view::figure::read::{self, AxisMap, Element, Region};

/// The whole figure.
pub(crate) const ALL: Region = (0.0, 0.0, 1e6, 1e6);

/// `biodyn response` for `args`: (f, column values) per named column.
pub(crate) fn response(args: &[&str], column: &str) -> Vec<(f64, f64)> {
    let mut a = vec!["response", "--format", "csv"];
    a.extend_from_slice(args);
    let text = ok(&a);
    let mut lines = text.lines();
    let head: Vec<&str> = lines.next().expect("a header").split(',').collect();
    let i = head.iter().position(|h| *h == column).expect("the column");
    lines
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|x| x.parse().expect("a number")).collect();
            (v[0], v[i])
        })
        .collect()
}

/// Checks the plain-SVG promises and returns the elements.
pub(crate) fn plain(svg: &str) -> Vec<Element> {
    assert!(svg.starts_with("<svg version=\"1.1\" "), "{}", &svg[..80]);
    for banned in ["transform", "<script", "href", "<image", "<style"] {
        assert!(!svg.contains(banned), "the SVG has {banned}");
    }
    let els = read::elements(svg).expect("the SVG parses");
    for e in els.iter().filter(|e| e.name == "text") {
        assert_eq!(e.attr("font-family"), Some("sans-serif"), "{e:?}");
    }
    els
}

/// The largest distance, pixels, from each vertex stroked in `colour` to
/// the polyline of `expected` mapped through the axes; and how far the
/// vertices reach along x (first and last, data units).
pub(crate) fn off_curve(
    els: &[Element],
    colour: &str,
    axes: (AxisMap, AxisMap),
    expected: &[(f64, f64)],
) -> (f64, f64, f64) {
    let (mx, my) = axes;
    let px: Vec<(f64, f64)> = expected
        .iter()
        .map(|&(x, y)| (mx.pixel(x), my.pixel(y)))
        .collect();
    let vs = read::vertices(els, colour, ALL);
    assert!(vs.len() >= 10, "too few vertices in {colour}: {}", vs.len());
    let mut worst: f64 = 0.0;
    for &(x, y) in &vs {
        let d = px
            .windows(2)
            .map(|w| segment_distance((x, y), w[0], w[1]))
            .fold(f64::INFINITY, f64::min);
        worst = worst.max(d);
    }
    let xs = vs.iter().map(|v| v.0);
    let lo = xs.clone().fold(f64::INFINITY, f64::min);
    let hi = xs.fold(f64::NEG_INFINITY, f64::max);
    (worst, mx.value(lo), mx.value(hi))
}

fn segment_distance(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let l2 = dx * dx + dy * dy;
    let t = if l2 == 0.0 {
        0.0
    } else {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / l2).clamp(0.0, 1.0)
    };
    ((p.0 - a.0 - t * dx).powi(2) + (p.1 - a.1 - t * dy).powi(2)).sqrt()
}

pub(crate) fn has_text(els: &[Element], text: &str) -> bool {
    els.iter().any(|e| e.name == "text" && e.text == text)
}

#[test]
fn a_study_figure_reads_back_as_the_responses_of_each_mass() {
    let svg = ok(&[
        "plot",
        "apms",
        "--study",
        "mass=65,75,85",
        "--format",
        "svg",
    ]);
    let els = plain(&svg);
    let axes = read::axes(&els, ALL, false, false).expect("axes");
    assert!(axes.0.labels >= 5 && axes.1.labels >= 5, "{axes:?}");
    assert!(
        axes.0.worst_px <= 1.0 && axes.1.worst_px <= 1.0,
        "ticks off their labels: {axes:?}"
    );
    for t in ["APMS — apparent mass", "f (Hz)", "|APMS| (kg)", "peak"] {
        assert!(has_text(&els, t), "no text {t}");
    }
    let mut colours = Vec::new();
    for m in ["65", "75", "85"] {
        let name = format!("body mass = {m} kg");
        let colour =
            read::legend_colour(&els, &name).unwrap_or_else(|| panic!("{name} not in the legend"));
        let expected = response(&["--body-mass", m], "apms_mag");
        let (worst, lo, hi) = off_curve(&els, &colour, axes, &expected);
        assert!(worst <= 1.5, "{name}: a vertex {worst} px off the curve");
        assert!(
            lo <= 0.55 && hi >= 19.5,
            "{name}: drawn over {lo}..{hi} Hz only"
        );
        colours.push(colour);
    }
    colours.sort();
    colours.dedup();
    assert_eq!(colours.len(), 3, "the curves share a colour");
}

#[test]
fn log_axes_and_the_phase_read_back() {
    let expected = response(&[], "stht_mag");
    let svg = ok(&["plot", "stht", "--log-x", "--log-y", "--format", "svg"]);
    let els = plain(&svg);
    let axes = read::axes(&els, ALL, true, true).expect("axes");
    assert!(axes.0.worst_px <= 1.0 && axes.1.worst_px <= 1.0, "{axes:?}");
    let colour = read::legend_colour(&els, "paper-75kg").expect("the model in the legend");
    let (worst, lo, hi) = off_curve(&els, &colour, axes, &expected);
    assert!(
        worst <= 1.5 && lo <= 0.55 && hi >= 19.5,
        "{worst} px, {lo}..{hi}"
    );

    let expected = response(&[], "stht_phase_deg");
    let svg = ok(&["plot", "stht", "--phase", "--format", "svg"]);
    let els = plain(&svg);
    assert!(has_text(&els, "STHT phase (deg)"));
    let axes = read::axes(&els, ALL, false, false).expect("axes");
    let colour = read::vertices(&els, "#0072B2", ALL);
    assert!(
        !colour.is_empty(),
        "the first curve's colour is the table's first"
    );
    let (worst, _, _) = off_curve(&els, "#0072B2", axes, &expected);
    assert!(worst <= 1.5, "{worst} px");
}

#[test]
fn measured_points_carry_their_error_bars_and_a_compared_model_lies_beneath() {
    let dir = tempfile::tempdir().expect("a temp dir");
    let data = dir.path().join("m.csv");
    std::fs::write(
        &data,
        "f_hz,apms_mag,apms_mag_sd\n2,70,5\n4,90,10\n8,40,4\n",
    )
    .expect("written");
    let d = data.to_str().expect("utf-8");
    let svg = ok(&[
        "plot",
        "apms",
        "--data",
        d,
        "--compare",
        "paper-85kg",
        "--format",
        "svg",
    ]);
    let els = plain(&svg);
    let (mx, my) = read::axes(&els, ALL, false, false).expect("axes");
    assert!(has_text(&els, "data: m.csv") && has_text(&els, "paper-85kg (compared)"));
    let circles: Vec<(f64, f64)> = els
        .iter()
        .filter(|e| e.name == "circle")
        .filter_map(|e| Some((mx.value(e.num("cx")?), my.value(e.num("cy")?))))
        .collect();
    for (f, v) in [(2.0, 70.0), (4.0, 90.0), (8.0, 40.0)] {
        let near = circles.iter().any(|&(x, y)| {
            (mx.pixel(x) - mx.pixel(f)).abs() <= 1.0 && (my.pixel(y) - my.pixel(v)).abs() <= 1.0
        });
        assert!(near, "no point at ({f}, {v}) among {circles:?}");
    }
    // Each error bar spans value ± sd: a vertical line from v-sd to v+sd.
    let bars: Vec<(f64, f64, f64)> = els
        .iter()
        .filter(|e| e.name == "line" || e.name == "polyline")
        .filter_map(|e| {
            let p = if e.name == "line" {
                vec![(e.num("x1")?, e.num("y1")?), (e.num("x2")?, e.num("y2")?)]
            } else {
                e.points()
            };
            (p.len() == 2 && p[0].0 == p[1].0 && p[0].1 != p[1].1).then(|| {
                let (a, b) = (my.value(p[0].1), my.value(p[1].1));
                (mx.value(p[0].0), a.min(b), a.max(b))
            })
        })
        .collect();
    for (f, lo, hi) in [(4.0, 80.0, 100.0), (8.0, 36.0, 44.0)] {
        let tol = (my.value(0.0) - my.value(1.0)).abs() * 1.5;
        let found = bars.iter().any(|&(x, a, b)| {
            (x - f).abs() < 0.1 && (a - lo).abs() <= tol && (b - hi).abs() <= tol
        });
        assert!(found, "no error bar {lo}..{hi} at {f} Hz in {bars:?}");
    }
    let compared = response(&["--preset", "paper-85kg"], "apms_mag");
    let (worst, _, _) = off_curve(&els, "#888888", (mx, my), &compared);
    assert!(worst <= 1.5, "{worst} px");
    // Text too: the data and the compared model are in the chart's legend.
    let text = ok(&[
        "plot",
        "apms",
        "--data",
        d,
        "--compare",
        "paper-85kg",
        "--width",
        "100",
        "--height",
        "30",
    ]);
    assert!(
        text.contains("data: m.csv") && text.contains("paper-85kg"),
        "{text}"
    );
}

#[test]
fn output_takes_its_format_from_the_extension_and_refuses_the_rest() {
    let dir = tempfile::tempdir().expect("a temp dir");
    let svg = dir.path().join("f.svg");
    let txt = dir.path().join("f.txt");
    let (s, t) = (svg.to_str().expect("utf-8"), txt.to_str().expect("utf-8"));
    assert_eq!(ok(&["plot", "stht", "--output", s]), "");
    assert_eq!(
        std::fs::read_to_string(&svg).expect("written"),
        ok(&["plot", "stht", "--format", "svg"])
    );
    ok(&["plot", "stht", "--output", t]);
    assert_eq!(
        std::fs::read_to_string(&txt).expect("written"),
        ok(&["plot", "stht"])
    );
    let png = dir.path().join("f.png");
    let err = fails(&["plot", "stht", "--output", png.to_str().expect("utf-8")]);
    assert!(
        err.contains("neither .svg nor .txt") && err.contains("rsvg-convert"),
        "{err}"
    );
    assert!(!png.exists());
    let (code, _, err) = run(&["plot", "stht", "--format", "text", "--output", s]);
    assert_eq!(code, Some(1));
    assert!(err.contains("disagrees"), "{err}");
    let missing = dir.path().join("no/such/f.svg");
    let (code, _, err) = run(&["plot", "stht", "--output", missing.to_str().expect("utf-8")]);
    assert_eq!(code, Some(1), "{err}");
    // Never over the command's own input.
    let preset = dir.path().join("p.svg");
    std::fs::copy(root().join("presets/paper-75kg.toml"), &preset).expect("copied");
    let p = preset.to_str().expect("utf-8");
    let (code, _, err) = run(&["plot", "stht", "--preset", p, "--output", p]);
    assert_eq!(code, Some(1), "{err}");
    assert_eq!(
        std::fs::read(&preset).expect("kept"),
        std::fs::read(root().join("presets/paper-75kg.toml")).expect("the preset"),
        "the preset was replaced: {err}"
    );
    let (code, _, err) = run(&["plot", "stht", "--format", "svg", "--width", "10"]);
    assert_eq!(code, Some(1));
    assert!(err.contains("200..4000"), "{err}");
    let err = fails(&[
        "plot",
        "dpmi",
        "--data",
        "examples/synthetic-stht-apms-3pct-2deg.csv",
    ]);
    assert!(err.contains("no dpmi_mag column"), "{err}");
}

#[test]
fn the_figure_renders_with_rsvg_convert() {
    if !rsvg_convert() {
        return skip("rsvg-convert (librsvg2-bin)");
    }
    let dir = tempfile::tempdir().expect("a temp dir");
    let svg = dir.path().join("f.svg");
    let png = dir.path().join("f.png");
    ok(&[
        "plot",
        "apms",
        "--study",
        "mass=65,75,85",
        "--log-x",
        "--output",
        svg.to_str().expect("utf-8"),
    ]);
    assert_eq!(png_size(&svg, &png), (800, 500));
}

/// Whether rsvg-convert is there to render with.
pub(crate) fn rsvg_convert() -> bool {
    std::process::Command::new("rsvg-convert")
        .arg("--version")
        .output()
        .is_ok()
}

/// `svg` rendered by rsvg-convert to `png`: the PNG's width and height,
/// read from its IHDR.
pub(crate) fn png_size(svg: &std::path::Path, png: &std::path::Path) -> (u32, u32) {
    let out = std::process::Command::new("rsvg-convert")
        .arg(svg)
        .arg("-o")
        .arg(png)
        .output()
        .expect("rsvg-convert runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let b = std::fs::read(png).expect("a PNG");
    assert_eq!(&b[1..4], b"PNG");
    let be = |i: usize| u32::from_be_bytes([b[i], b[i + 1], b[i + 2], b[i + 3]]);
    (be(16), be(20))
}

/// Panel `k` of a two-column grid of 640 × 300 panels (`assess --plot`).
fn panel(k: usize) -> Region {
    let (c, r) = ((k % 2) as f64, (k / 2) as f64);
    (c * 640.0, r * 300.0, (c + 1.0) * 640.0, (r + 1.0) * 300.0)
}

/// The bars in `region`: (centre f, height) through the panel's axes.
fn bars(els: &[Element], region: Region) -> Vec<(f64, f64, f64)> {
    let (mx, my) = read::axes(els, region, true, false).expect("the panel's axes");
    assert!(mx.worst_px <= 1.0 && my.worst_px <= 1.0, "{mx:?} {my:?}");
    let px = my.px.1.max(my.px.0) - my.px.1.min(my.px.0);
    els.iter()
        .filter(|e| e.name == "rect" && e.attr("fill") == Some("#9EC9E2"))
        .filter_map(|e| Some((e.num("x")?, e.num("y")?, e.num("width")?)))
        .filter(|&(x, y, _)| x >= region.0 && x < region.2 && y >= region.1 && y < region.3)
        .map(|(x, y, w)| {
            let f = (mx.value(x) * mx.value(x + w)).sqrt();
            // One pixel of the y axis, in its units.
            let unit = (my.at.1 - my.at.0).abs() / px.max(1.0);
            (f, my.value(y), unit)
        })
        .collect()
}

#[test]
fn assess_plot_draws_each_axis_and_the_head_with_the_jsons_bands() {
    let dir = tempfile::tempdir().expect("a temp dir");
    let svg = dir.path().join("a.svg");
    let s = svg.to_str().expect("utf-8");
    let signal = "random:rms=0.8,band=1-20,seed=1";
    let json = ok(&[
        "assess",
        "--signal",
        signal,
        "--duration",
        "30",
        "--format",
        "json",
        "--plot",
        s,
    ]);
    let v: serde_json::Value = serde_json::from_str(&json).expect("JSON");
    assert_eq!(
        json,
        ok(&[
            "assess",
            "--signal",
            signal,
            "--duration",
            "30",
            "--format",
            "json"
        ])
    );
    let text = std::fs::read_to_string(&svg).expect("the figure");
    let els = plain(&text);
    for t in [
        "seat z, weighted (Wk)",
        "seat z: one-third-octave bands",
        "head-neck z, weighted (Wk): the model's prediction",
        "t (s)",
        "a_w (m/s²)",
    ] {
        assert!(has_text(&els, t), "no {t}");
    }
    let bands = v["bands"].as_array().expect("bands");
    for (k, key) in [(1, "seat_m_s2"), (3, "head_m_s2")] {
        let drawn = bars(&els, panel(k));
        let want: Vec<(f64, f64)> = bands
            .iter()
            .filter_map(|b| Some((b["f_hz"].as_f64()?, b[key].as_f64()?)))
            .collect();
        assert_eq!(drawn.len(), want.len(), "{key}: bars {drawn:?}");
        for ((f, h, unit), (wf, wh)) in drawn.iter().zip(&want) {
            assert!((f / wf - 1.0).abs() < 0.03, "{key}: bar at {f} Hz for {wf}");
            assert!(
                (h - wh).abs() <= 1.5 * unit,
                "{key} {wf} Hz: {h} drawn, {wh} in the JSON"
            );
        }
    }
    // The trace spans the record: 0 to 30 s.
    let (mx, _) = read::axes(&els, panel(0), false, false).expect("axes");
    let xs: Vec<f64> = read::vertices(&els, "#0072B2", panel(0))
        .iter()
        .map(|p| mx.value(p.0))
        .collect();
    let (lo, hi) = xs
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    assert!(lo < 0.1 && hi > 29.9, "{lo}..{hi} s");
}

#[test]
fn assess_plot_has_a_panel_pair_per_axis_and_refuses_what_is_not_svg() {
    let dir = tempfile::tempdir().expect("a temp dir");
    let svg = dir.path().join("a.svg");
    let s = svg.to_str().expect("utf-8");
    ok(&[
        "assess",
        "--input",
        "examples/car-seat-points.csv",
        "--plot",
        s,
    ]);
    let els = plain(&std::fs::read_to_string(&svg).expect("the figure"));
    for a in ["x, weighted (Wd)", "y, weighted (Wd)", "z, weighted (Wk)"] {
        assert!(has_text(&els, &format!("seat {a}")), "no seat {a}");
    }
    for k in [1, 3, 5, 7] {
        assert!(bars(&els, panel(k)).len() >= 15, "panel {k}");
    }
    let png = dir.path().join("a.png");
    let err = fails(&[
        "assess",
        "--signal",
        "sine:freq=5,amp=1",
        "--plot",
        png.to_str().expect("utf-8"),
    ]);
    assert!(err.contains("does not end in .svg"), "{err}");
    assert!(!png.exists());
    // Its own input is never replaced.
    let rec = dir.path().join("r.svg");
    std::fs::copy(root().join("examples/car-seat-points.csv"), &rec).expect("copied");
    let r = rec.to_str().expect("utf-8");
    let (code, out, err) = run(&["assess", "--input", r, "--plot", r]);
    assert_eq!(code, Some(1), "{err}");
    assert!(out.is_empty());
    assert_eq!(
        std::fs::read(&rec).expect("kept"),
        std::fs::read(root().join("examples/car-seat-points.csv")).expect("the record")
    );
}

#[test]
fn the_assess_report_carries_the_same_figure_inline() {
    let dir = tempfile::tempdir().expect("a temp dir");
    let (svg, page) = (dir.path().join("a.svg"), dir.path().join("a.html"));
    let signal = "random:rms=0.8,band=1-20,seed=1";
    let (s, h) = (svg.to_str().expect("utf-8"), page.to_str().expect("utf-8"));
    let (code, _, err) = run(&[
        "assess",
        "--signal",
        signal,
        "--duration",
        "20",
        "--plot",
        s,
        "--report",
        h,
    ]);
    assert_eq!(code, Some(0), "{err}");
    let html = std::fs::read_to_string(&page).expect("the page");
    let figure = std::fs::read_to_string(&svg).expect("the figure");
    let inline = figure.replacen(" xmlns=\"http://www.w3.org/2000/svg\"", "", 1);
    assert!(
        html.contains(inline.trim_end()),
        "the page's figure is not the --plot figure"
    );
    let (code, _, err) = run(&["assess", "--signal", signal, "--plot", s, "--report", s]);
    assert_eq!(code, Some(1));
    assert!(err.contains("the same file"), "{err}");
}
