//! What a frame drew where, for the tests' layout check (`tui/tests/layout.rs`):
//! the cells each chart plotted and where it put its axis titles, and the
//! rectangle each dialog claims. The buffer alone cannot tell a title
//! letter from the curve glyph it covered, nor a dialog's blank from the
//! layer below left standing, so the drawing code says so here.
//!
//! Only test builds keep anything: in every other build each function is
//! an empty inline call and a dialog draws over the screen as it is.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;

/// One chart as drawn: its plot, the cells its curves, cursor and peak
/// marks took (before any title went on), and the axis titles' cells.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct ChartMark {
    pub plot: Rect,
    pub plotted: Vec<(u16, u16)>,
    pub labels: Vec<Rect>,
}

/// One dialog: the rectangle it claims, and the cells of the layer below
/// as they were before it drew (to put back what it left undrawn).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct DialogMark {
    pub rect: Rect,
    pub below: Vec<ratatui::buffer::Cell>,
}

/// Everything one frame recorded, in drawing order.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Marks {
    pub charts: Vec<ChartMark>,
    pub dialogs: Vec<DialogMark>,
}

/// The symbol a dialog's rectangle holds before the dialog draws (test
/// builds): a cell still holding it was never drawn by the dialog.
pub const UNDRAWN: &str = "\u{E000}";

#[cfg(test)]
thread_local! {
    static MARKS: std::cell::RefCell<Marks> = std::cell::RefCell::default();
}

/// A chart's plot, the cells plotted in it and its axis titles' cells.
#[inline]
pub fn chart(plot: Rect, plotted: &[(u16, u16)], labels: &[Rect]) {
    #[cfg(test)]
    MARKS.with(|m| {
        m.borrow_mut().charts.push(ChartMark {
            plot,
            plotted: plotted.to_vec(),
            labels: labels.to_vec(),
        })
    });
    #[cfg(not(test))]
    let _ = (plot, plotted, labels);
}

/// A dialog claims `rect` of `buf` and is about to draw in it: in a test
/// build the layer below is kept and the rectangle filled with `UNDRAWN`,
/// so a cell the dialog does not draw (it forgot ratatui's `Clear`) shows.
#[inline]
pub fn dialog(rect: Rect, buf: &mut Buffer) {
    #[cfg(test)]
    {
        let rect = rect.intersection(buf.area);
        let mut below = Vec::with_capacity(usize::from(rect.width) * usize::from(rect.height));
        for y in rect.top()..rect.bottom() {
            for x in rect.left()..rect.right() {
                if let Some(c) = buf.cell_mut((x, y)) {
                    below.push(c.clone());
                    c.reset();
                    c.set_symbol(UNDRAWN);
                }
            }
        }
        MARKS.with(|m| m.borrow_mut().dialogs.push(DialogMark { rect, below }));
    }
    #[cfg(not(test))]
    let _ = (rect, buf);
}

/// What was recorded on this thread since the last call (test builds;
/// empty in others).
pub fn take() -> Marks {
    #[cfg(test)]
    {
        MARKS.with(|m| std::mem::take(&mut *m.borrow_mut()))
    }
    #[cfg(not(test))]
    {
        Marks::default()
    }
}
