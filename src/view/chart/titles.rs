//! Where a chart's axis titles go. The y title sits at the top left of the
//! plot and the x title at its bottom right, each on the nearest row of
//! its half of the plot where it covers no plotted cell (a curve, a peak
//! mark, the legend) and keeps one blank cell between itself and the data
//! on its inner side; where no such row is, the title is left out (the
//! chart's title and the axis labels still say what is plotted). The
//! cursor's line is no data: a title may cross it (else a cursor under
//! the y title's width would drop the title at every row). Shared by the chart widget and the Vibration tab's traces,
//! which draw their curves through ratatui's Chart but their titles here.

use crate::view::probe;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Color, Style};

/// Where the cursor's line is: its column and its glyph.
pub type Cursor = Option<(u16, char)>;

/// Draws `y_title` and `x_title` in `plot` of `buf`, whose data are
/// already drawn, away from every plotted cell and from `avoid` (the
/// legend, drawn after); cells of the `cursor` line do not count as
/// plotted. Returns the titles' cells.
pub fn place(
    plot: Rect,
    buf: &mut Buffer,
    (x_title, y_title): (&str, &str),
    avoid: &[Rect],
    cursor: Cursor,
) -> Vec<Rect> {
    let p = plot.intersection(buf.area);
    let on_cursor = |x: u16, sym: &str| {
        cursor.is_some_and(|(c, g)| c == x && sym.chars().eq(std::iter::once(g)))
    };
    let plotted: Vec<(u16, u16)> = (p.top()..p.bottom())
        .flat_map(|y| (p.left()..p.right()).map(move |x| (x, y)))
        .filter(|&(x, y)| {
            buf.cell((x, y))
                .is_some_and(|c| c.symbol() != " " && !on_cursor(x, c.symbol()))
        })
        .collect();
    let mut taken = vec![false; usize::from(p.width) * usize::from(p.height)];
    let index = |x: u16, y: u16| usize::from(y - p.y) * usize::from(p.width) + usize::from(x - p.x);
    for &(x, y) in &plotted {
        taken[index(x, y)] = true;
    }
    for r in avoid {
        let r = r.intersection(p);
        for y in r.top()..r.bottom() {
            for x in r.left()..r.right() {
                taken[index(x, y)] = true;
            }
        }
    }
    let free = |taken: &[bool], x0: u16, x1: u16, y: u16| {
        (x0.max(p.x)..x1.min(p.right())).all(|x| !taken[index(x, y)])
    };
    let mut labels = Vec::new();
    let yw = y_title.chars().count() as u16;
    if !y_title.is_empty() && yw + 1 < p.width && p.height > 2 {
        // The top half, downwards; the cell after the title stays blank.
        let rows = p.y..=p.y + (p.height - 1) / 2;
        if let Some(y) = rows
            .into_iter()
            .find(|&y| free(&taken, p.x, p.x + yw + 1, y))
        {
            let r = Rect::new(p.x, y, yw, 1);
            put(buf, r, y_title);
            for x in r.left()..(r.right() + 1).min(p.right()) {
                taken[index(x, y)] = true;
            }
            labels.push(r);
        }
    }
    let xw = x_title.chars().count() as u16;
    if !x_title.is_empty() && xw < p.width && p.height > 2 {
        // The bottom half, upwards; the cell before the title stays blank.
        let x = p.right() - xw;
        let rows = (p.y + p.height / 2..p.bottom()).rev();
        if let Some(y) = rows
            .into_iter()
            .find(|&y| free(&taken, x.saturating_sub(1), p.right(), y))
        {
            let r = Rect::new(x, y, xw, 1);
            put(buf, r, x_title);
            labels.push(r);
        }
    }
    probe::chart(p, &plotted, &labels);
    labels
}

/// Writes `text` into the row of `r`, in the plain style over a reset cell.
fn put(buf: &mut Buffer, r: Rect, text: &str) {
    for (i, ch) in text.chars().take(usize::from(r.width)).enumerate() {
        if let Some(cell) = buf.cell_mut((r.x + i as u16, r.y)) {
            cell.set_char(ch)
                .set_fg(Color::Reset)
                .set_style(Style::default());
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 12×4 plot with `rows` of curve glyphs (`#`) at the given columns.
    fn plot(rows: &[(u16, std::ops::Range<u16>)]) -> Buffer {
        let mut buf = Buffer::empty(Rect::new(0, 0, 12, 4));
        for (y, xs) in rows {
            for x in xs.clone() {
                buf[(x, *y)].set_char('#');
            }
        }
        buf
    }

    #[test]
    fn a_title_moves_off_the_curve_and_is_left_out_where_no_row_is_free() {
        let area = Rect::new(0, 0, 12, 4);
        // The curve runs through the bottom right: the x title goes up a row.
        let mut buf = plot(&[(3, 6..12)]);
        let l = place(area, &mut buf, ("f Hz", ""), &[], None);
        assert_eq!(l, [Rect::new(8, 2, 4, 1)]);
        // Through both rows of the bottom half: no x title at all.
        let mut buf = plot(&[(2, 7..8), (3, 6..12)]);
        assert!(place(area, &mut buf, ("f Hz", ""), &[], None).is_empty());
        // The y title crosses the cursor's line but not a curve.
        let mut buf = plot(&[(0, 8..9)]);
        buf[(3, 0)].set_char('│');
        let l = place(area, &mut buf, ("", "|STHT|"), &[], Some((3, '│')));
        assert_eq!(l, [Rect::new(0, 0, 6, 1)]);
        let mut buf = plot(&[(0, 3..4)]);
        let l = place(area, &mut buf, ("", "|STHT|"), &[], None);
        assert_eq!(l, [Rect::new(0, 1, 6, 1)], "one row down, off the curve");
    }
}
