//! The key of a panel whose plot a map fills (every corner covered, so no
//! legend can sit over it): drawn by us beside the plot, each entry's
//! sample left of its name as plotters draws a legend's, so the same
//! reader finds it.

use super::model::Panel;
use super::style::{FONT, LABEL_PT, ink, label_px, style_of};
use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// What drawing a figure returns (the string backend cannot fail; plotters
/// can refuse a range).
pub type DrawResult<DB> = Result<(), DrawingAreaErrorKind<<DB as DrawingBackend>::ErrorType>>;

/// The key beside a map's plot, pixels wide (0 for a panel without cells:
/// its legend goes over the plot).
pub fn key_px(p: &Panel) -> u32 {
    if p.cells.is_empty() {
        return 0;
    }
    let widest = super::legend::names(p)
        .map(|n| label_px(n, LABEL_PT))
        .fold(0.0, f64::max);
    // The sample and the gaps either side: 16 + 34 px before a name.
    (widest + 60.0).clamp(150.0, f64::from(KEY_MAX_PX)) as u32
}
/// The widest a key gets, pixels (a longer name runs past the panel).
const KEY_MAX_PX: u32 = 420;
/// A key row's height, pixels.
const KEY_ROW_PX: i32 = 22;

/// A map's key, drawn by us beside the plot (from its top right
/// corner `at`): each shade's swatch, then the curves', the points'
/// and the marks' samples, each left of its name as a legend has it.
pub fn draw<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    p: &Panel,
    at: (i32, i32),
) -> DrawResult<DB> {
    let font = TextStyle::from((FONT, LABEL_PT).into_font()).pos(Pos::new(HPos::Left, VPos::Top));
    let x = at.0 + 16 + 34;
    let mut y = at.1;
    let row = |name: &str, y: &mut i32| -> DrawResult<DB> {
        root.draw(&Text::new(name.to_string(), (x, *y), font.clone()))?;
        *y += KEY_ROW_PX;
        Ok(())
    };
    for c in &p.cells {
        let fill = c.fill.color().filled();
        root.draw(&Rectangle::new([(x - 30, y + 2), (x - 8, y + 14)], fill))?;
        root.draw(&Rectangle::new([(x - 30, y + 2), (x - 8, y + 14)], ink(1)))?;
        row(&c.name, &mut y)?;
    }
    for c in &p.curves {
        let pen = c.look.pen();
        let (on, off) = pen.dash;
        let line = vec![(x - 34, y + 8), (x - 6, y + 8)];
        if on == 0 {
            root.draw(&PathElement::new(line, style_of(pen)))?;
        } else {
            root.draw(&DashedPathElement::new(line, on, off, style_of(pen)))?;
        }
        row(&c.name, &mut y)?;
    }
    for d in &p.points {
        root.draw(&Circle::new((x - 20, y + 8), 4, ink(1)))?;
        row(&d.name, &mut y)?;
    }
    if !p.marks.is_empty() {
        root.draw(&Cross::new((x - 20, y + 8), 6, ink(2)))?;
        row(&p.marks_name, &mut y)?;
    }
    Ok(())
}
