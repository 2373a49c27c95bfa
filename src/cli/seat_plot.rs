//! `seat --plot FILE.svg`: the seat's figure, or the design search's.
//!
//! Without `--vary`: the transmissibility over the band, SEAT % per class
//! (then the `--psd` file's), the `--class`/`--psd` floor selected, and
//! under that floor the design map over the suspension's k and c from a
//! quarter to four times its own, kept to stroke/6: the Seat tab's default,
//! so its `.svg` is this file byte for byte. With `--vary`: the searched
//! box's map (two parameters) or SEAT and travel over it (one).

use crate::view::figure::Figure;
use crate::view::figure::design::{self, DesignFigure, LINE_PX, MAP_PX};
use crate::view::figure::seat::{Floor, SeatFigure, figure};
use anyhow::Result;
use biodyn::seat::{self, Design, FloorPsd, SeatGrid};
use biodyn::time::CLASSES;
use biodyn::{Band, Body, Solver};

/// The floor the command names, for the figure: its PSD, its name, and
/// whether it is a file's (a bar of its own) or a class's.
pub struct Chosen {
    pub psd: FloorPsd,
    pub name: String,
    pub file: bool,
}

/// The figure of `body` over `band`, under `chosen`; the search's when
/// `searched`.
pub fn svg(
    body: &Body,
    band: &Band,
    chosen: Option<&Chosen>,
    searched: Option<&Design>,
) -> Result<String> {
    if let (Some(d), Some(Chosen { psd, name, .. })) = (searched, chosen) {
        let now: Vec<f64> = d.vary.iter().map(|v| body.get(v.param)).collect();
        let figures = SeatGrid::new(psd)?.figures(body)?;
        let panels = design::panels(&DesignFigure {
            design: d,
            now: &now,
            now_figures: &figures,
            floor: name,
        });
        let size = if d.vary.len() == 2 { MAP_PX } else { LINE_PX };
        return Ok(Figure {
            panels,
            columns: 1,
            panel_px: size,
        }
        .svg());
    }
    band.check_work(body.n())?;
    let curve = Solver::try_new(body)?.sweep(band);
    let mut floors: Vec<Floor> = Vec::with_capacity(CLASSES.len() + 1);
    for c in CLASSES.iter() {
        let pct = SeatGrid::new(&FloorPsd::Class(c))?.figures(body)?.seat_pct;
        floors.push((c.name.to_string(), Some(pct)));
    }
    let selected = match chosen {
        Some(c) if c.file => {
            let pct = SeatGrid::new(&c.psd)?.figures(body)?.seat_pct;
            floors.push((c.name.clone(), Some(pct)));
            Some(floors.len() - 1)
        }
        Some(c) => CLASSES.iter().position(|k| k.name == c.name),
        None => None,
    };
    let map = match chosen {
        Some(c) => default_map(body, &c.psd)?.map(|(d, now, f)| (d, now, f, c.name.clone())),
        None => None,
    };
    let design = map.as_ref().map(|(d, now, f, name)| DesignFigure {
        design: d,
        now: now.as_slice(),
        now_figures: f,
        floor: name,
    });
    Ok(figure(&SeatFigure {
        curve: &curve,
        floors: &floors,
        selected,
        design,
    })
    .svg())
}

/// The Seat tab's default map under `psd`: the suspension's k and c ×¼–×4,
/// the travel kept to stroke/6; None where the search finds no feasible
/// point (the tab shows why instead of a map).
fn default_map(
    body: &Body,
    psd: &FloorPsd,
) -> Result<Option<(Design, Vec<f64>, seat::SeatFigures)>> {
    let (Some((_, k, c)), Some(limit)) = (seat::suspension(body), seat::default_limit(body)) else {
        return Ok(None);
    };
    let grid = SeatGrid::new(psd)?;
    let vary = seat::suspension_box(body, [k, c])?;
    let figures = grid.figures(body)?;
    Ok(seat::design(body, &grid, &vary, limit)
        .ok()
        .map(|d| (d, vec![k, c], figures)))
}
