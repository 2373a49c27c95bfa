//! A figure drawn through plotters' SVG backend. Ticks come from
//! `view::axis::plan` (1-2-5 steps, as dense as the labels' estimated
//! widths allow) and are handed to plotters as the axes' key points, so the
//! SVG and the text charts agree on what a round tick is.

use super::key::{self, DrawResult, key_px};
use super::legend;
use super::model::{Axis, Curve, Figure, Panel};
use super::style::{CHAR_EM, FONT, GRID, INK, LABEL_PT, Look, ink, label_px, style_of};
use crate::view::axis::{self as ax, Plan, Scale, Tick};
use crate::view::format::clip;
use plotters::coord::Shift;
use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, Ranged};
use plotters::element::{DashedPathElement, ErrorBar};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// Room around a panel's plot, pixels.
const MARGIN: u32 = 12;
const Y_LABELS_PX: u32 = 64;
const X_LABELS_PX: u32 = 52;
/// Above the plot, below the caption: the y axis's title.
const TOP_PX: u32 = 24;
const CAPTION_PT: u32 = 18;
const TITLE_PT: u32 = 16;

impl Figure {
    /// The figure as an SVG document (ends with a newline).
    pub fn svg(&self) -> String {
        svg(self)
    }

    /// The figure as an `<svg>` element inside an HTML page: HTML5 puts it
    /// in the SVG namespace itself, so the page names no outside address.
    pub fn inline_svg(&self) -> String {
        self.svg()
            .replacen(" xmlns=\"http://www.w3.org/2000/svg\"", "", 1)
    }
}

fn svg(fig: &Figure) -> String {
    let mut s = String::new();
    {
        let root = SVGBackend::with_string(&mut s, fig.size()).into_drawing_area();
        // The string backend cannot fail to write; a plotters error here
        // would be a bug of ours (a range it refuses), and leaves the
        // figure with what was drawn so far rather than no output.
        let _ = draw_all(&root, fig);
        let _ = root.present();
    }
    let mut s = s.replacen("<svg ", "<svg version=\"1.1\" ", 1);
    // A name in a title (a day file's) may carry ESC or BEL, which XML
    // forbids and a page must not carry raw: each becomes U+FFFD.
    if s.contains(|c: char| c.is_control() && c != '\n' && c != '\t' && c != '\r') {
        s = s
            .chars()
            .map(|c| match c {
                '\n' | '\t' | '\r' => c,
                c if c.is_control() => '\u{fffd}',
                c => c,
            })
            .collect();
    }
    if !s.ends_with('\n') {
        s.push('\n');
    }
    s
}

fn draw_all<DB: DrawingBackend>(root: &DrawingArea<DB, Shift>, fig: &Figure) -> DrawResult<DB> {
    root.fill(&WHITE)?;
    let cols = fig.columns.max(1);
    let rows = fig.panels.len().div_ceil(cols).max(1);
    let areas = root.split_evenly((rows, cols));
    for (area, panel) in areas.iter().zip(&fig.panels) {
        draw_panel(root, area, panel)?;
    }
    Ok(())
}

/// An axis's extent in axis units (log10 on a log axis), over `values`.
fn extent(values: impl Iterator<Item = f64>, log: bool) -> Option<(f64, f64)> {
    values
        .filter(|v| v.is_finite() && (!log || *v > 0.0))
        .map(|v| if log { v.log10() } else { v })
        .fold(None, |acc, v| match acc {
            None => Some((v, v)),
            Some((a, b)) => Some((f64::min(a, v), f64::max(b, v))),
        })
}

/// A categorical axis over `length` pixels: category i at i, from -0.6
/// to n - 0.4, each name cut to the room its category has.
fn categories(names: &[String], length: f64) -> Plan {
    let n = names.len();
    let room = length / n.max(1) as f64;
    let chars = ((room - 6.0) / (CHAR_EM * f64::from(LABEL_PT)))
        .floor()
        .max(3.0) as usize;
    Plan {
        lo: -0.6,
        hi: n as f64 - 0.4,
        ticks: names
            .iter()
            .enumerate()
            .map(|(i, name)| Tick {
                at: i as f64,
                label: clip(name, chars),
            })
            .collect(),
    }
}

/// Ticks for one axis over `length` pixels: labels at least a gap apart.
fn plan(ext: Option<(f64, f64)>, axis: &Axis, length: f64, horizontal: bool, pad: f64) -> Plan {
    if !axis.names.is_empty() {
        return categories(&axis.names, length);
    }
    let (lo, hi) = ext.unwrap_or((0.0, 1.0));
    let scale = if axis.log {
        Scale::Log
    } else {
        Scale::Linear {
            pad,
            floor_zero: axis.floor_zero,
        }
    };
    let fits = move |lo: f64, hi: f64, ticks: &[Tick]| {
        let span = hi - lo;
        if span.is_nan() || span <= 0.0 {
            return false;
        }
        let px = |t: &Tick| (t.at - lo) / span * length;
        ticks.windows(2).all(|w| {
            let room = px(&w[1]) - px(&w[0]);
            if horizontal {
                let widths =
                    (label_px(&w[0].label, LABEL_PT) + label_px(&w[1].label, LABEL_PT)) / 2.0;
                room >= (widths + 16.0).max(50.0)
            } else {
                room >= 2.2 * f64::from(LABEL_PT)
            }
        })
    };
    ax::plan(lo, hi, scale, &fits)
}

/// A tick's value in data units.
fn data(at: f64, log: bool) -> f64 {
    if log { 10f64.powf(at) } else { at }
}

fn draw_panel<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    area: &DrawingArea<DB, Shift>,
    p: &Panel,
) -> DrawResult<DB> {
    let (w, h) = area.dim_in_pixel();
    let plot_w = f64::from(
        w.saturating_sub(2 * MARGIN + Y_LABELS_PX + key_px(p))
            .max(50),
    );
    let plot_h = f64::from(
        h.saturating_sub(2 * MARGIN + X_LABELS_PX + TOP_PX + CAPTION_PT + 8)
            .max(40),
    );
    let xs = p
        .curves
        .iter()
        .flat_map(|c| c.points.iter().map(|q| q.0))
        .chain(p.points.iter().flat_map(|d| d.points.iter().map(|q| q.0)))
        .chain(
            p.bars
                .iter()
                .flat_map(|b| b.bars.iter().flat_map(|q| [q.0, q.1])),
        )
        .chain(p.marks.iter().map(|m| m.0))
        .chain(
            p.cells
                .iter()
                .flat_map(|c| c.cells.iter().flat_map(|q| [q.0, q.1])),
        );
    let ys = p
        .curves
        .iter()
        .flat_map(|c| c.points.iter().map(|q| q.1))
        .chain(p.points.iter().flat_map(|d| {
            d.points
                .iter()
                .flat_map(|&(_, y, sd)| [y - sd.unwrap_or(0.0), y + sd.unwrap_or(0.0), y])
        }))
        .chain(p.bars.iter().flat_map(|b| b.bars.iter().map(|q| q.2)))
        .chain(p.marks.iter().map(|m| m.1))
        .chain(
            p.cells
                .iter()
                .flat_map(|c| c.cells.iter().flat_map(|q| [q.2, q.3])),
        );
    let xp = plan(extent(xs, p.x.log), &p.x, plot_w, true, 0.0);
    let y_ext = extent(ys, p.y.log);
    let mut yp = plan(y_ext, &p.y, plot_h, false, 0.05);
    let size = legend::size(p, (plot_w, plot_h), |n| label_px(n, LABEL_PT));
    let cells = legend::occupied(p, &xp, &yp);
    let (mut place, covered) = legend::corner(&cells, size);
    // Every corner covers data: a linear axis reaches higher, so that the
    // legend sits above it.
    if covered > 0 && legend::shown(p) && !p.y.log {
        if let (Some(top), Some((lo, _))) = (legend::headroom(&cells, &yp, size.1), y_ext) {
            yp = plan(Some((lo, top)), &p.y, plot_h, false, 0.0);
            place = legend::corner(&legend::occupied(p, &xp, &yp), size).0;
        }
    }
    let (xl, yl) = (p.x.log, p.y.log);
    let keyed = |p: &Plan, log: bool| Keyed {
        lo: data(p.lo, log),
        hi: data(p.hi, log),
        log,
        ticks: p.ticks.iter().map(|t| data(t.at, log)).collect(),
    };
    let cx = Ctx {
        root,
        area,
        panel: p,
        x: &xp,
        y: &yp,
        legend: place,
    };
    cx.chart(keyed(&xp, xl), keyed(&yp, yl))
}

/// An axis with our ticks as its key points, linear or log: one type for
/// both, so a panel is drawn by one function whatever its scales.
#[derive(Debug, Clone)]
struct Keyed {
    lo: f64,
    hi: f64,
    log: bool,
    ticks: Vec<f64>,
}

impl Keyed {
    fn unit(&self, v: f64) -> f64 {
        if self.log { v.log10() } else { v }
    }
}

impl Ranged for Keyed {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, v: &f64, limit: (i32, i32)) -> i32 {
        let (a, b) = (self.unit(self.lo), self.unit(self.hi));
        let t = (self.unit(*v) - a) / (b - a);
        // `as` saturates (NaN: 0): a value off the axis cannot panic.
        (f64::from(limit.0) + t * f64::from(limit.1 - limit.0)).round() as i32
    }

    fn key_points<H: KeyPointHint>(&self, hint: H) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            Vec::new()
        } else {
            self.ticks.clone()
        }
    }

    fn range(&self) -> std::ops::Range<f64> {
        self.lo..self.hi
    }
}

struct Ctx<'a, DB: DrawingBackend> {
    root: &'a DrawingArea<DB, Shift>,
    area: &'a DrawingArea<DB, Shift>,
    panel: &'a Panel,
    x: &'a Plan,
    y: &'a Plan,
    legend: SeriesLabelPosition,
}

/// The label of the tick at `v` (data units) on an axis planned as `p`.
fn tick_label(p: &Plan, log: bool, v: f64) -> String {
    p.ticks
        .iter()
        .find(|t| {
            let d = data(t.at, log);
            (d - v).abs() <= 1e-9 * d.abs().max(1e-300)
        })
        .map_or_else(|| format!("{v}"), |t| t.label.clone())
}

impl<DB: DrawingBackend> Ctx<'_, DB> {
    fn chart(&self, xr: Keyed, yr: Keyed) -> DrawResult<DB> {
        let p = self.panel;
        // The caption and the y title are ours, in the top margin: plotters'
        // top label area would repeat the x axis there.
        let mut chart = ChartBuilder::on(self.area)
            .margin(MARGIN)
            .margin_top(MARGIN + CAPTION_PT + 8 + TOP_PX)
            .margin_right(MARGIN + key_px(p))
            .set_label_area_size(LabelAreaPosition::Left, Y_LABELS_PX)
            .set_label_area_size(LabelAreaPosition::Bottom, X_LABELS_PX)
            .build_cartesian_2d(xr.clone(), yr.clone())?;
        let (xp, yp) = (self.x, self.y);
        let (xl, yl) = (p.x.log, p.y.log);
        let fx = move |v: &f64| tick_label(xp, xl, *v);
        let fy = move |v: &f64| tick_label(yp, yl, *v);
        chart
            .configure_mesh()
            .light_line_style(TRANSPARENT)
            .bold_line_style(GRID)
            .axis_style(INK)
            .x_labels(100)
            .y_labels(100)
            .x_label_formatter(&fx)
            .y_label_formatter(&fy)
            .label_style((FONT, LABEL_PT))
            .axis_desc_style((FONT, TITLE_PT))
            .x_desc(p.x.title.as_str())
            .draw()?;

        // The y axis's title, level above the axis (no rotation: no transform).
        let (px, py) = chart.plotting_area().get_pixel_range();
        let (x0, y0) = self.area.get_base_pixel();
        let width = self.area.dim_in_pixel().0 as i32;
        self.root.draw(&Text::new(
            p.title.clone(),
            (x0 + width / 2, y0 + MARGIN as i32),
            TextStyle::from((FONT, CAPTION_PT).into_font()).pos(Pos::new(HPos::Center, VPos::Top)),
        ))?;
        self.root.draw(&Text::new(
            p.y.title.clone(),
            (px.start - Y_LABELS_PX as i32 + 4, py.start - 8),
            TextStyle::from((FONT, TITLE_PT).into_font()).pos(Pos::new(HPos::Left, VPos::Bottom)),
        ))?;

        for c in &p.cells {
            let fill = c.fill.color().filled();
            chart.draw_series(
                c.cells
                    .iter()
                    .filter(|q| {
                        [q.0, q.1, q.2, q.3]
                            .iter()
                            .all(|v| v.is_finite() && (!(xl || yl) || *v > 0.0))
                    })
                    .map(|&(a, z, lo, hi)| Rectangle::new([(a, lo), (z, hi)], fill)),
            )?;
        }
        let on_axes =
            |x: f64, y: f64| x.is_finite() && y.is_finite() && (!xl || x > 0.0) && (!yl || y > 0.0);
        let yb = yr.range().start;
        for b in &p.bars {
            let fill = b.fill.color().filled();
            let shown: Vec<[(f64, f64); 2]> = b
                .bars
                .iter()
                .filter(|q| q.2.is_finite() && (!yl || q.2 > 0.0))
                .map(|&(a, z, v)| [(a, yb), (z, v)])
                .collect();
            chart
                .draw_series(shown.iter().map(|&c| Rectangle::new(c, fill)))?
                .label(b.name.as_str())
                .legend(move |(x, y)| Rectangle::new([(x, y - 6), (x + 20, y + 6)], fill));
            chart.draw_series(shown.iter().map(|&c| Rectangle::new(c, ink(1))))?;
        }

        // A compared model first, so the model's own curves lie over it.
        let mut curves: Vec<&Curve> = p.curves.iter().collect();
        curves.sort_by_key(|c| c.look != Look::Reference);
        for c in curves {
            let pts: Vec<(f64, f64)> = c
                .points
                .iter()
                .copied()
                .filter(|&(x, y)| on_axes(x, y))
                .collect();
            let pen = c.look.pen();
            let style = style_of(pen);
            let (on, off) = pen.dash;
            if on == 0 {
                chart
                    .draw_series(LineSeries::new(pts, style))?
                    .label(c.name.as_str())
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 28, y)], style));
            } else {
                chart
                    .draw_series(std::iter::once(DashedPathElement::new(pts, on, off, style)))?
                    .label(c.name.as_str())
                    .legend(move |(x, y)| {
                        DashedPathElement::new(vec![(x, y), (x + 28, y)], on, off, style)
                    });
            }
        }
        let ink1 = ink(1);
        for d in &p.points {
            let lo_y = yr.range().start;
            let pts: Vec<(f64, f64, Option<f64>)> = d
                .points
                .iter()
                .copied()
                .filter(|&(x, y, _)| on_axes(x, y))
                .collect();
            chart.draw_series(pts.iter().filter_map(|&(x, y, sd)| {
                let s = sd.filter(|s| s.is_finite() && *s > 0.0)?;
                let low = if yl && y - s <= 0.0 { lo_y } else { y - s };
                Some(ErrorBar::new_vertical(x, low, y, y + s, ink1, 8))
            }))?;
            chart
                .draw_series(pts.iter().map(|&(x, y, _)| Circle::new((x, y), 4, ink1)))?
                .label(d.name.as_str())
                .legend(move |(x, y)| Circle::new((x + 14, y), 4, ink1));
        }
        if !p.marks.is_empty() {
            let mark = ink(2);
            chart
                .draw_series(
                    p.marks
                        .iter()
                        .filter(|&&(x, y)| on_axes(x, y))
                        .map(|&(x, y)| Cross::new((x, y), 6, mark)),
                )?
                .label(p.marks_name.as_str())
                .legend(move |(x, y)| Cross::new((x + 14, y), 6, mark));
        }
        if !p.cells.is_empty() {
            key::draw(self.root, p, (px.end, py.start))?;
        } else if legend::shown(p) {
            chart
                .configure_series_labels()
                .position(self.legend.clone())
                .margin(10)
                .legend_area_size(34)
                .border_style(INK)
                .background_style(WHITE.mix(0.9))
                .label_font((FONT, LABEL_PT))
                .draw()?;
        }
        Ok(())
    }
}
