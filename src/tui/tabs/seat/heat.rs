//! The design map as a heat map: SEAT % over the suspension's k (rows, up)
//! and c (columns, right), both log, interpolated between the library's
//! grid points; the r.m.s. stroke limit as a contour (`•`, ASCII `o`: the
//! cells on the allowed side of it), the region over the limit dimmed,
//! the best point (`◆`, ASCII `*`) and the model's own (`●`, ASCII `+`).
//! The shades say SEAT without colour (`░▒▓█`, ASCII `.:=#`: low to high);
//! colour adds green to red.

use crate::tui::theme::Theme;
use biodyn::seat::DesignMap;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Color, Style};

/// Shades from low SEAT to high, (unicode, ascii).
pub const SHADES: [(char, char); 4] = [('░', '.'), ('▒', ':'), ('▓', '='), ('█', '#')];
const COLOURS: [Color; 4] = [Color::Green, Color::Cyan, Color::Yellow, Color::Red];
pub const CONTOUR: (char, char) = ('•', 'o');
pub const BEST: (char, char) = ('◆', '*');
pub const NOW: (char, char) = ('●', '+');

pub fn glyph(g: (char, char), ascii: bool) -> char {
    if ascii { g.1 } else { g.0 }
}

/// A value of the map at fractional grid position (row `r`, column `c`),
/// bilinear between its four neighbours.
fn at(values: &[f64], n: usize, r: f64, c: f64) -> f64 {
    let last = (n - 1) as f64;
    let (r, c) = (r.clamp(0.0, last), c.clamp(0.0, last));
    let (r0, c0) = (r.floor() as usize, c.floor() as usize);
    let (r1, c1) = ((r0 + 1).min(n - 1), (c0 + 1).min(n - 1));
    let (fr, fc) = (r - r0 as f64, c - c0 as f64);
    let v = |i: usize, j: usize| values.get(i * n + j).copied().unwrap_or(f64::NAN);
    let top = v(r0, c0) * (1.0 - fc) + v(r0, c1) * fc;
    let bottom = v(r1, c0) * (1.0 - fc) + v(r1, c1) * fc;
    top * (1.0 - fr) + bottom * fr
}

/// Where a value sits along an axis of the map, 0 … 1 (log).
pub fn t_of(axis: &[f64], v: f64) -> f64 {
    match (axis.first(), axis.last()) {
        (Some(&lo), Some(&hi)) if hi > lo && v > 0.0 => (v / lo).ln() / (hi / lo).ln(),
        _ => 0.5,
    }
}

/// The lowest and highest SEAT of the map.
pub fn range(map: &DesignMap) -> (f64, f64) {
    map.seat_pct
        .iter()
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| {
            (lo.min(v), hi.max(v))
        })
}

/// The cell of (k, c) in an area of `w`×`h` cells, if inside the map.
pub fn cell_of(map: &DesignMap, k: f64, c: f64, w: u16, h: u16) -> Option<(u16, u16)> {
    let (tk, tc) = (t_of(&map.axes[0], k), t_of(&map.axes[1], c));
    let inside = |t: f64| (-1e-9..=1.0 + 1e-9).contains(&t);
    if !(inside(tk) && inside(tc)) || w == 0 || h == 0 {
        return None;
    }
    let x = (tc * f64::from(w - 1)).round() as u16;
    let y = ((1.0 - tk) * f64::from(h - 1)).round() as u16;
    Some((x.min(w - 1), y.min(h - 1)))
}

/// The heat map over `area` (no frame, no labels): the shades, the contour,
/// then the marks `best` and `now` as (k, c).
pub fn draw(
    map: &DesignMap,
    limit_m: f64,
    best: (f64, f64),
    now: (f64, f64),
    th: Theme,
    area: Rect,
    buf: &mut Buffer,
) {
    let n = map.axes.first().map_or(0, Vec::len);
    if map.axes.len() != 2 || n < 2 || area.width < 2 || area.height < 2 {
        return;
    }
    let (w, h) = (usize::from(area.width), usize::from(area.height));
    let (lo, hi) = range(map);
    let span = (hi - lo).max(1e-12);
    // Grid position of each screen cell: rows are k (first axis), from the
    // top (highest k) down; columns c.
    let pos = |x: usize, y: usize| {
        let r = (1.0 - y as f64 / (h - 1) as f64) * (n - 1) as f64;
        let c = x as f64 / (w - 1) as f64 * (n - 1) as f64;
        (r, c)
    };
    let over: Vec<Vec<bool>> = (0..h)
        .map(|y| {
            (0..w)
                .map(|x| {
                    let (r, c) = pos(x, y);
                    at(&map.stroke_rms_m, n, r, c) > limit_m
                })
                .collect()
        })
        .collect();
    for y in 0..h {
        for x in 0..w {
            let (r, c) = pos(x, y);
            let seat = at(&map.seat_pct, n, r, c);
            let level = (((seat - lo) / span) * SHADES.len() as f64).floor();
            let level = (level.max(0.0) as usize).min(SHADES.len() - 1);
            let is_over = over[y][x];
            let edge = !is_over
                && [(0i64, 1i64), (0, -1), (1, 0), (-1, 0)].iter().any(|(dx, dy)| {
                    let (xx, yy) = (x as i64 + dx, y as i64 + dy);
                    xx >= 0
                        && yy >= 0
                        && (xx as usize) < w
                        && (yy as usize) < h
                        && over[yy as usize][xx as usize]
                });
            let (ch, style) = if edge {
                (glyph(CONTOUR, th.ascii), th.heading())
            } else if is_over {
                (glyph(SHADES[level], th.ascii), th.dim())
            } else if th.mono {
                (glyph(SHADES[level], th.ascii), Style::default())
            } else {
                (glyph(SHADES[level], th.ascii), Style::default().fg(COLOURS[level]))
            };
            put(buf, area, x, y, ch, style);
        }
    }
    for ((k, c), g) in [(now, NOW), (best, BEST)] {
        if let Some((x, y)) = cell_of(map, k, c, area.width, area.height) {
            put(buf, area, usize::from(x), usize::from(y), glyph(g, th.ascii), th.title());
        }
    }
}

fn put(buf: &mut Buffer, area: Rect, x: usize, y: usize, ch: char, style: Style) {
    let (Ok(dx), Ok(dy)) = (u16::try_from(x), u16::try_from(y)) else {
        return;
    };
    if let Some(cell) = buf.cell_mut((area.x + dx, area.y + dy)) {
        cell.set_char(ch);
        cell.set_style(style);
    }
}
