//! `seat --plot FILE.svg`: the seat's figure, or the design search's.
//!
//! Without `--vary`: the transmissibility over the band, SEAT % per class
//! (then the `--psd` file's), the `--class`/`--psd` floor selected, and
//! under that floor the design map over the suspension's k and c from a
//! quarter to four times its own, kept to stroke/6: the Seat tab's default,
//! so its `.svg` is this file byte for byte. With `--vary`: the searched
//! box's map (two parameters) or SEAT and travel over it (one).

use super::seat::{SeatArgs, class};
use crate::view::figure::Figure;
use crate::view::figure::design::{self, DesignFigure, LINE_PX, MAP_PX};
use crate::view::figure::response::file_name;
use crate::view::figure::seat::{Floor, SeatFigure, figure};
use anyhow::Result;
use biodyn::seat::{self, Design, FloorPsd, SeatGrid};
use biodyn::time::CLASSES;
use biodyn::{Body, Solver};

/// The floor named on the command line: its PSD and its name in a figure.
fn floor(a: &SeatArgs) -> Result<Option<(FloorPsd, String)>> {
    Ok(match (&a.psd, &a.class) {
        (Some(path), _) => Some((FloorPsd::load(path)?, file_name(&path.to_string_lossy()))),
        (None, Some(name)) => {
            let c = class(name)?;
            Some((FloorPsd::Class(c), c.name.to_string()))
        }
        (None, None) => None,
    })
}

pub fn svg(a: &SeatArgs, searched: Option<&Design>) -> Result<String> {
    let preset = a.model.load()?;
    let body = &preset.body;
    let chosen = floor(a)?;
    if let (Some(d), Some((psd, name))) = (searched, &chosen) {
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
    let band = a.band.band(preset.band)?;
    band.check_work(body.n())?;
    let curve = Solver::try_new(body)?.sweep(&band);
    let mut floors: Vec<Floor> = Vec::with_capacity(CLASSES.len() + 1);
    for c in CLASSES.iter() {
        let pct = SeatGrid::new(&FloorPsd::Class(c))?.figures(body)?.seat_pct;
        floors.push((c.name.to_string(), Some(pct)));
    }
    let selected = match (&chosen, &a.psd) {
        (Some((psd, name)), Some(_)) => {
            let pct = SeatGrid::new(psd)?.figures(body)?.seat_pct;
            floors.push((name.clone(), Some(pct)));
            Some(floors.len() - 1)
        }
        (Some((_, name)), None) => CLASSES.iter().position(|k| k.name == name),
        (None, _) => None,
    };
    let map = match &chosen {
        Some((psd, name)) => default_map(body, psd)?.map(|(d, now, f)| (d, now, f, name.clone())),
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
