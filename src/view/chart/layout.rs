//! Where the parts of a chart go: the frame, the y labels' width, the plot
//! rectangle, and the axis plans (bounds and ticks) whose labels fit.

use super::opts::{ChartOpts, Series};
use crate::view::axis::{self, Mapping, Plan, Scale, Tick};
use crate::view::glyph::{dots, marker};
use ratatui::layout::Rect;
use ratatui::widgets::{Block, Borders};

/// Least spacing of x ticks in columns, and of y ticks in rows.
const X_SPACING: i32 = 10;
const Y_SPACING: i32 = 3;

/// Where the parts of a chart go, and how values map to cells.
#[derive(Debug, Clone, PartialEq)]
pub struct Layout {
    /// The plot: data cells only, axes and labels outside it.
    pub plot: Rect,
    pub x: Mapping,
    pub y: Mapping,
    pub x_plan: Plan,
    pub y_plan: Plan,
}

impl Layout {
    /// The column of an x value (in data units), None outside the plot.
    pub fn column(&self, x: f64, log: bool) -> Option<u16> {
        let v = if log { x.log10() } else { x };
        self.x.cell(v).map(|c| self.plot.x + c)
    }

    /// The x value (in data units) at the middle of a terminal column: the
    /// inverse of `column` (a click's frequency). None outside the plot.
    pub fn x_at(&self, column: u16, log: bool) -> Option<f64> {
        let c = column.checked_sub(self.plot.x)?;
        if c >= self.plot.width
            || self.x.cells == 0
            || self.x.hi.partial_cmp(&self.x.lo) != Some(std::cmp::Ordering::Greater)
        {
            return None;
        }
        // `Mapping::cell` rounds a position on a grid of cells × sub dots;
        // the middle of the column's dots maps back into the column.
        let sub = f64::from(self.x.sub.max(1));
        let res = f64::from(self.x.cells) * sub;
        let dot = f64::from(c) * sub + (sub - 1.0) / 2.0;
        let t = if res > 1.0 { dot / (res - 1.0) } else { 0.0 };
        let t = if self.x.flip { 1.0 - t } else { t };
        let v = self.x.lo + t.clamp(0.0, 1.0) * (self.x.hi - self.x.lo);
        Some(if log { 10f64.powf(v) } else { v })
    }

    /// The row of a y value (in data units), None outside the plot.
    pub fn row(&self, y: f64, log: bool) -> Option<u16> {
        let v = if log { y.log10() } else { y };
        self.y.cell(v).map(|c| self.plot.y + c)
    }
}

/// The data of each series in axis units (log10 where asked), without the
/// points a log axis or a NaN cannot show.
pub(super) fn transformed(series: &[Series], opts: &ChartOpts) -> Vec<Vec<(f64, f64)>> {
    let t = |v: f64, log: bool| if log { v.log10() } else { v };
    series
        .iter()
        .map(|s| {
            s.points
                .iter()
                .filter(|(x, y)| {
                    x.is_finite()
                        && y.is_finite()
                        && (!opts.log_x || *x > 0.0)
                        && (!opts.log_y || *y > 0.0)
                })
                .map(|&(x, y)| (t(x, opts.log_x), t(y, opts.log_y)))
                .collect()
        })
        .collect()
}

/// The frame of the chart: a full border when tall enough, else only the
/// top rule with the title (two more rows of plot where they matter most).
pub(super) fn frame(area: Rect, opts: &ChartOpts) -> Block<'static> {
    let block = if area.height < 10 {
        // The rule starts with a rule cell where the frame has its corner:
        // the title never stands at the panel's edge as if cut from it.
        Block::new()
            .borders(Borders::TOP)
            .title(format!("─{}", opts.title))
    } else {
        Block::bordered().title(opts.title.clone())
    };
    if opts.ascii {
        block.border_set(ratatui::symbols::border::PLAIN)
    } else {
        block
    }
}

/// Lays a chart out in `area`: bounds, ticks and the plot rectangle. None
/// when the area is too small for a plot.
pub fn layout(area: Rect, series: &[Series], opts: &ChartOpts) -> Option<Layout> {
    layout_of(area, &transformed(series, opts), opts)
}

/// `layout` for data already in axis units.
pub(super) fn layout_of(area: Rect, data: &[Vec<(f64, f64)>], opts: &ChartOpts) -> Option<Layout> {
    if area.width < 10 || area.height < 5 {
        return None;
    }
    let inner = frame(area, opts).inner(area);
    if inner.height < 4 || inner.width < 8 {
        return None;
    }
    let (kx, ky) = dots(marker(0, opts.ascii));
    let (mut x0, mut x1, mut y0, mut y1) = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    for &(x, y) in data.iter().flatten() {
        x0 = x0.min(x);
        x1 = x1.max(x);
        y0 = y0.min(y);
        y1 = y1.max(y);
    }
    if !x0.is_finite() {
        (x0, x1, y0, y1) = (0.0, 1.0, 0.0, 1.0);
    }

    // y first: its labels' width decides where the plot starts.
    let plot_h = inner.height - 2;
    let y_scale = match opts.y_range {
        Some((a, b)) if a.is_finite() && b.is_finite() && (!opts.log_y || a > 0.0) => {
            let t = |v: f64| if opts.log_y { v.log10() } else { v };
            (y0, y1) = (t(a), t(b));
            Scale::Fixed { log: opts.log_y }
        }
        _ if opts.log_y => Scale::Log,
        _ => Scale::Linear {
            pad: 0.05,
            floor_zero: true,
        },
    };
    let y_map = |lo: f64, hi: f64| Mapping {
        lo,
        hi,
        cells: plot_h,
        sub: ky,
        flip: true,
    };
    let y_fits = |lo: f64, hi: f64, ticks: &[Tick]| {
        let m = y_map(lo, hi);
        let rows: Option<Vec<i32>> = ticks.iter().map(|t| m.cell(t.at).map(i32::from)).collect();
        let Some(rows) = rows else { return false };
        let gap = if ticks.len() <= 2 { 1 } else { Y_SPACING };
        rows.windows(2).all(|w| (w[0] - w[1]).abs() >= gap)
            && ticks
                .iter()
                .all(|t| t.label.chars().count() < inner.width as usize / 3)
    };
    let y_plan = axis::plan(y0, y1, y_scale, &y_fits);
    let yw = y_plan
        .ticks
        .iter()
        .map(|t| t.label.chars().count() as u16)
        .max()
        .unwrap_or(0);

    // x: labels centred on their column may reach left under the y labels;
    // on the right the plot gives up what the last label needs.
    let px0 = inner.x + yw + 1;
    let x_scale = if opts.log_x {
        Scale::Log
    } else {
        Scale::Linear {
            pad: 0.0,
            floor_zero: false,
        }
    };
    let x_for = |margin: u16, strict: bool| -> Option<(Plan, u16)> {
        let w = inner.right().checked_sub(px0 + margin)?;
        if w < 2 {
            return None;
        }
        let fits =
            |lo: f64, hi: f64, ticks: &[Tick]| x_fits(lo, hi, ticks, w, kx, px0, inner, strict);
        Some((axis::plan(x0, x1, x_scale, &fits), w))
    };
    let (first, w) = x_for(0, false)?;
    let over = overflow(&first, w, kx, px0, inner);
    let (x_plan, plot_w) = if over == 0 {
        (first, w)
    } else {
        x_for(over, true)?
    };
    let plot = Rect::new(px0, inner.y, plot_w, plot_h);
    Some(Layout {
        plot,
        x: Mapping {
            lo: x_plan.lo,
            hi: x_plan.hi,
            cells: plot_w,
            sub: kx,
            flip: false,
        },
        y: y_map(y_plan.lo, y_plan.hi),
        x_plan,
        y_plan,
    })
}

/// Columns (first, last) of an x label centred on column `col`.
pub(super) fn label_span(col: i32, label: &str) -> (i32, i32) {
    let n = label.chars().count() as i32;
    let start = col - n / 2;
    (start, start + n - 1)
}

/// Do the x labels fit: inside the frame, apart, no closer than
/// `X_SPACING` columns when there are more than two?
#[allow(clippy::too_many_arguments)]
fn x_fits(
    lo: f64,
    hi: f64,
    ticks: &[Tick],
    w: u16,
    kx: u16,
    px0: u16,
    inner: Rect,
    strict: bool,
) -> bool {
    let m = Mapping {
        lo,
        hi,
        cells: w,
        sub: kx,
        flip: false,
    };
    let mut prev: Option<(i32, i32)> = None;
    for t in ticks {
        let Some(c) = m.cell(t.at) else {
            return false;
        };
        let col = i32::from(px0) + i32::from(c);
        let (a, b) = label_span(col, &t.label);
        if a < i32::from(inner.x) || (strict && b >= i32::from(inner.right())) {
            return false;
        }
        if let Some((pc, pb)) = prev {
            let spacing = if ticks.len() > 2 { X_SPACING } else { 0 };
            if a <= pb + 1 || col - pc < spacing {
                return false;
            }
        }
        prev = Some((col, b));
    }
    true
}

/// Columns the x labels of `plan` reach past the frame on the right.
fn overflow(plan: &Plan, w: u16, kx: u16, px0: u16, inner: Rect) -> u16 {
    let m = Mapping {
        lo: plan.lo,
        hi: plan.hi,
        cells: w,
        sub: kx,
        flip: false,
    };
    plan.ticks
        .iter()
        .filter_map(|t| {
            let col = i32::from(px0) + i32::from(m.cell(t.at)?);
            let (_, b) = label_span(col, &t.label);
            Some((b - i32::from(inner.right()) + 1).max(0) as u16)
        })
        .max()
        .unwrap_or(0)
}
