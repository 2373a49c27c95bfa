//! How each curve of a figure looks: one table of colour and dash pattern.
//! Colours are Okabe and Ito's palette (distinct under the common colour
//! vision deficiencies); the dash patterns tell the curves apart printed in
//! black and white.

use plotters::style::{Color, RGBColor, ShapeStyle};

/// How a curve is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Look {
    /// The i-th of the figure's own curves: `LOOKS[i % len]`.
    Series(usize),
    /// A reference beneath the others (a compared model): grey, dotted.
    Reference,
    /// A time trace: thin and solid in the i-th colour (a trace is dense;
    /// dashes would not show on it).
    Trace(usize),
}

/// One entry of the table: colour, dash (pixels on, pixels off; 0 on is
/// solid) and line width.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pen {
    pub color: RGBColor,
    pub dash: (u32, u32),
    pub width: u32,
}

const LOOKS: [Pen; 6] = [
    Pen {
        color: RGBColor(0x00, 0x72, 0xB2),
        dash: (0, 0),
        width: 2,
    },
    Pen {
        color: RGBColor(0xD5, 0x5E, 0x00),
        dash: (10, 5),
        width: 2,
    },
    Pen {
        color: RGBColor(0x00, 0x9E, 0x73),
        dash: (4, 4),
        width: 2,
    },
    Pen {
        color: RGBColor(0xCC, 0x79, 0xA7),
        dash: (16, 4),
        width: 2,
    },
    Pen {
        color: RGBColor(0xE6, 0x9F, 0x00),
        dash: (2, 3),
        width: 2,
    },
    Pen {
        color: RGBColor(0x00, 0x00, 0x00),
        dash: (7, 2),
        width: 1,
    },
];

/// The compared model's pen.
const REFERENCE: Pen = Pen {
    color: RGBColor(0x88, 0x88, 0x88),
    dash: (2, 2),
    width: 2,
};

impl Look {
    pub fn pen(self) -> Pen {
        match self {
            Look::Series(i) => LOOKS[i % LOOKS.len()],
            Look::Reference => REFERENCE,
            Look::Trace(i) => Pen {
                dash: (0, 0),
                width: 1,
                ..LOOKS[i % LOOKS.len()]
            },
        }
    }
}

/// Measured points, error bars and marks: black.
pub const INK: RGBColor = RGBColor(0, 0, 0);
/// Grid lines at the ticks.
pub const GRID: RGBColor = RGBColor(0xDD, 0xDD, 0xDD);
/// How a set of bars is filled (their outline is `INK`). The fills grow
/// darker in this order, so they stay apart printed in grey.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Fill {
    /// Bands, classes, operations below the action value.
    #[default]
    Plain,
    /// Above the action value (amber).
    Action,
    /// Above the limit value (vermillion).
    Limit,
    /// The one selected (the TUI's class, the command's own floor).
    Selected,
    /// The i-th of a map's `SHADES`, light (low) to dark (high).
    Shade(usize),
    /// A map's cells outside a limit: grey.
    Off,
}

/// A map's shades, light to dark: ColorBrewer's YlGnBu in 7 classes
/// (sequential, in even steps of lightness: it reads in grey too).
pub const SHADES: [RGBColor; 7] = [
    RGBColor(0xFF, 0xFF, 0xCC),
    RGBColor(0xC7, 0xE9, 0xB4),
    RGBColor(0x7F, 0xCD, 0xBB),
    RGBColor(0x41, 0xB6, 0xC4),
    RGBColor(0x1D, 0x91, 0xC0),
    RGBColor(0x22, 0x5E, 0xA8),
    RGBColor(0x0C, 0x2C, 0x84),
];

impl Fill {
    pub fn color(self) -> RGBColor {
        match self {
            Fill::Plain => BAR,
            Fill::Action => RGBColor(0xE6, 0x9F, 0x00),
            Fill::Limit => RGBColor(0xD5, 0x5E, 0x00),
            Fill::Selected => RGBColor(0x00, 0x72, 0xB2),
            Fill::Shade(i) => SHADES[i.min(SHADES.len() - 1)],
            Fill::Off => RGBColor(0xBB, 0xBB, 0xBB),
        }
    }
}

/// The plain bars' fill.
pub const BAR: RGBColor = RGBColor(0x9E, 0xC9, 0xE2);
/// The font: a generic family, so any SVG reader has it.
pub const FONT: &str = "sans-serif";

/// Tick labels' and legend names' size, points.
pub const LABEL_PT: u32 = 15;
/// Estimated label width per character, as a share of the font size (a
/// sans-serif digit is about 0.55 em).
pub const CHAR_EM: f64 = 0.6;

/// A label's estimated width, pixels.
pub fn label_px(text: &str, pt: u32) -> f64 {
    CHAR_EM * f64::from(pt) * text.chars().count() as f64
}

/// Black lines of `width` px: error bars, marks, bar outlines.
pub fn ink(width: u32) -> ShapeStyle {
    ShapeStyle {
        color: INK.to_rgba(),
        filled: false,
        stroke_width: width,
    }
}

pub fn style_of(pen: Pen) -> ShapeStyle {
    ShapeStyle {
        color: pen.color.to_rgba(),
        filled: false,
        stroke_width: pen.width,
    }
}
