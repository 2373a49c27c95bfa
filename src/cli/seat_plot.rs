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
use crate::view::figure::seat::{SeatFigure, class_floors, figure};
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
    // The named floor's grid and the seat's figures on it, once.
    let on = match chosen {
        Some(c) => {
            let grid = SeatGrid::new(&c.psd)?;
            let figures = grid.figures(body)?;
            Some((c, grid, figures))
        }
        None => None,
    };
    if let (Some(d), Some((c, _, figures))) = (searched, &on) {
        let now: Vec<f64> = d.vary.iter().map(|v| body.get(v.param)).collect();
        let panels = design::panels(&DesignFigure {
            design: d,
            now: &now,
            now_figures: figures,
            floor: &c.name,
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
    let mut pcts = Vec::with_capacity(CLASSES.len());
    for c in CLASSES.iter() {
        pcts.push(Some(
            SeatGrid::new(&FloorPsd::Class(c))?.figures(body)?.seat_pct,
        ));
    }
    let mut floors = class_floors(pcts);
    let selected = match &on {
        Some((c, _, f)) if c.file => {
            floors.push((c.name.clone(), Some(f.seat_pct)));
            Some(floors.len() - 1)
        }
        Some((c, _, _)) => CLASSES.iter().position(|k| k.name == c.name),
        None => None,
    };
    // The Seat tab's default map under that floor: the suspension's k and
    // c ×¼–×4, the travel kept to stroke/6; none where the search finds no
    // feasible point (the tab shows why instead of a map).
    let map = match (&on, seat::suspension(body), seat::default_limit(body)) {
        (Some((c, grid, f)), Some((_, k, cc)), Some(limit)) => {
            let vary = seat::suspension_box(body, [k, cc])?;
            seat::design(body, grid, &vary, limit)
                .ok()
                .map(|d| (d, [k, cc], f, c.name.as_str()))
        }
        _ => None,
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
