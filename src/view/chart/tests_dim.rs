//! A dimmed series (a compared model): its own light glyph and grey, in
//! colour, NO_COLOR and ASCII; it gives way to a normal curve and to the
//! cursor wherever they share a cell; the legend names it with its glyph.

use super::*;
use ratatui::style::Color;

fn flat(name: &str, y: f64) -> Series {
    Series {
        name: name.into(),
        points: (0..=40).map(|i| (f64::from(i) * 0.5, y)).collect(),
    }
}

fn opts(ascii: bool, mono: bool) -> ChartOpts {
    ChartOpts {
        title: "STHT".into(),
        ascii,
        mono,
        y_range: Some((0.0, 2.0)),
        ..Default::default()
    }
}

fn draw(series: &[Series], emphasis: &[Emphasis], o: &ChartOpts) -> (Buffer, Layout) {
    let area = Rect::new(0, 0, 80, 24);
    let mut buf = Buffer::empty(area);
    render_with(area, &mut buf, series, emphasis, o);
    let lay = layout(area, series, o).expect("room for a plot");
    (buf, lay)
}

/// The symbols and colours of the plot's row `y`.
fn row(buf: &Buffer, lay: &Layout, y: u16) -> Vec<(String, Color)> {
    (lay.plot.x..lay.plot.right())
        .filter_map(|x| buf.cell((x, y)).map(|c| (c.symbol().to_string(), c.fg)))
        .collect()
}

#[test]
fn a_dim_series_gets_its_own_glyph_and_grey() {
    let s = [flat("", 1.5), flat("", 0.5)];
    for (ascii, mono) in [(false, false), (false, true), (true, false), (true, true)] {
        let o = opts(ascii, mono);
        let (buf, lay) = draw(&s, &[Emphasis::Normal, Emphasis::Dim], &o);
        let dim_row = lay.row(0.5, false).expect("0.5 on the axis");
        let main_row = lay.row(1.5, false).expect("1.5 on the axis");
        let glyph = if ascii { "." } else { "·" };
        let cells = row(&buf, &lay, dim_row);
        assert!(
            cells.iter().all(|(g, _)| g == glyph),
            "ascii {ascii} mono {mono}: {cells:?}"
        );
        let grey = if mono { Color::Reset } else { Color::DarkGray };
        assert!(cells.iter().all(|(_, c)| *c == grey), "{cells:?}");
        // The normal curve keeps marker 0 and its colour.
        let main = row(&buf, &lay, main_row);
        assert!(main.iter().all(|(g, _)| g != glyph && g != " "), "{main:?}");
        if !mono {
            assert!(main.iter().all(|(_, c)| *c == Color::Cyan), "{main:?}");
        }
        // The same series not dimmed is drawn with its marker instead.
        let (buf, _) = draw(&s, &[], &o);
        assert!(
            row(&buf, &lay, dim_row).iter().all(|(g, _)| g != glyph),
            "not dimmed: no dim glyph"
        );
    }
}

#[test]
fn the_normal_curve_wins_every_cell_it_shares_with_a_dim_one() {
    for ascii in [false, true] {
        let o = opts(ascii, false);
        let main = flat("", 1.0);
        let (alone, lay) = draw(std::slice::from_ref(&main), &[], &o);
        let both = [main.clone(), main.clone()];
        let (buf, _) = draw(&both, &[Emphasis::Normal, Emphasis::Dim], &o);
        for y in lay.plot.y..lay.plot.bottom() {
            assert_eq!(row(&buf, &lay, y), row(&alone, &lay, y), "row {y}");
        }
        // Two normal curves on the same cells take turns instead.
        let (buf, _) = draw(&both, &[], &o);
        let r = lay.row(1.0, false).expect("row");
        let glyphs: std::collections::HashSet<String> =
            row(&buf, &lay, r).into_iter().map(|(g, _)| g).collect();
        assert!(glyphs.len() >= 2, "{glyphs:?}");
    }
}

#[test]
fn the_cursor_stays_whole_over_a_dim_curve_and_under_a_normal_one() {
    let o = ChartOpts {
        cursor_x: Some(10.0),
        ..opts(true, true)
    };
    let s = [flat("", 1.5), flat("", 0.5)];
    let (buf, lay) = draw(&s, &[Emphasis::Normal, Emphasis::Dim], &o);
    let col = lay.column(10.0, false).expect("column");
    let at = |v: f64| {
        let r = lay.row(v, false).expect("row");
        buf.cell((col, r)).map(|c| c.symbol().to_string())
    };
    assert_eq!(
        at(0.5).as_deref(),
        Some("|"),
        "the cursor over the dim curve"
    );
    assert_eq!(
        at(1.5).as_deref(),
        Some("*"),
        "the main curve over the cursor"
    );
    // A dim curve alone is drawn beneath the cursor too.
    let (buf, lay) = draw(&s[1..], &[Emphasis::Dim], &o);
    let r = lay.row(0.5, false).expect("row");
    assert_eq!(buf.cell((col, r)).map(|c| c.symbol()), Some("|"));
    assert_eq!(buf.cell((col + 1, r)).map(|c| c.symbol()), Some("."));
}

#[test]
fn the_legend_shows_the_dim_glyph_beside_its_name() {
    for ascii in [false, true] {
        let o = opts(ascii, true);
        let s = [flat("model", 1.5), flat("ref heavy", 0.5)];
        let (buf, _) = draw(&s, &[Emphasis::Normal, Emphasis::Dim], &o);
        let text = buffer_text(&buf).join("\n");
        let dim = if ascii { ". ref heavy" } else { "· ref heavy" };
        let main = if ascii { "* model" } else { "⣿ model" };
        assert!(text.contains(dim), "{text}");
        assert!(text.contains(main), "{text}");
    }
}
