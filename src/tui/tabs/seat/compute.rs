//! What the Seat tab shows, computed from the model: SEAT and the travel
//! per input class (`biodyn::seat::SeatGrid::figures`, one grid per class,
//! built once) and the design map of the selected class over the
//! suspension's k and c (`biodyn::seat::design`). About 1 ms for the 16
//! classes and 30 ms for the map in a release build: done on the UI
//! thread, once per model edit or class change.

use biodyn::seat::{self, Design, FloorPsd, SeatFigures, SeatGrid, Vary};
use biodyn::time::CLASSES;
use biodyn::{Body, Param};

/// How far the map reaches either side of its centre: ×1/4 … ×4.
pub const SPAN: f64 = 4.0;

/// The default r.m.s. travel limit as a share of the travel: stroke/6, so
/// that ±3σ fits within ±stroke/2 (end-stop to end-stop).
pub const LIMIT_SHARE: f64 = 1.0 / 6.0;

/// One grid per input class, in `CLASSES` order (they do not depend on the
/// model).
pub fn grids() -> Vec<Result<SeatGrid, String>> {
    CLASSES
        .iter()
        .map(|c| SeatGrid::new(&FloorPsd::Class(c)).map_err(|e| e.to_string()))
        .collect()
}

/// The suspension link's index, stiffness and damping, when the model has a seat.
pub fn suspension(body: &Body) -> Option<(usize, f64, f64)> {
    let i = body.seat.as_ref()?.suspension;
    let l = body.links.get(i)?;
    Some((i, l.k, l.c))
}

/// The default limit for `body`'s travel, m.
pub fn default_limit(body: &Body) -> Option<f64> {
    body.seat.as_ref().map(|s| s.stroke_m * LIMIT_SHARE)
}

/// The box of the map: k and c of the suspension link over
/// [centre/SPAN, centre·SPAN], log.
pub fn box_of(body: &Body, centre: [f64; 2]) -> Result<Vec<Vary>, String> {
    let (i, _, _) = suspension(body).ok_or("the model has no seat")?;
    let name = body.links[i].name.clone();
    let params = [(Param::Stiffness(i), "k"), (Param::Damping(i), "c")];
    Ok(params
        .iter()
        .zip(centre)
        .map(|(&(param, what), v)| Vary {
            name: format!("{name}.{what}"),
            param,
            lo: v / SPAN,
            hi: v * SPAN,
        })
        .collect())
}

/// Everything the tab draws for a model with a seat.
#[derive(Debug, Clone)]
pub struct SeatData {
    /// SEAT and travel per class, in `CLASSES` order.
    pub classes: Vec<Result<SeatFigures, String>>,
    /// The map of the selected class, or why there is none.
    pub design: Result<Design, String>,
    /// The map's centre: the suspension's k and c it was laid around.
    pub centre: [f64; 2],
    /// The suspension's k and c now (the current point).
    pub now: [f64; 2],
    /// The r.m.s. travel limit of the map, m.
    pub limit_m: f64,
}

/// The figures of every class for `body`.
pub fn classes(grids: &[Result<SeatGrid, String>], body: &Body) -> Vec<Result<SeatFigures, String>> {
    grids
        .iter()
        .map(|g| match g {
            Ok(g) => g.figures(body).map_err(|e| e.to_string()),
            Err(e) => Err(e.clone()),
        })
        .collect()
}

/// The design map of `grid` over the box around `centre`, kept within `limit_m`.
pub fn design_of(
    body: &Body,
    grid: &Result<SeatGrid, String>,
    centre: [f64; 2],
    limit_m: f64,
) -> Result<Design, String> {
    let grid = grid.as_ref().map_err(Clone::clone)?;
    let vary = box_of(body, centre)?;
    seat::design(body, grid, &vary, limit_m).map_err(|e| e.to_string())
}

/// True when `now` lies inside the box around `centre`.
pub fn inside(centre: [f64; 2], now: [f64; 2]) -> bool {
    centre
        .iter()
        .zip(now)
        .all(|(&c, v)| v >= c / SPAN * (1.0 - 1e-12) && v <= c * SPAN * (1.0 + 1e-12))
}
