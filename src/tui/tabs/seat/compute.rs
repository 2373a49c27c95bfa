//! What the Seat tab shows, computed from the model: SEAT and the travel
//! per input class (`biodyn::seat::SeatGrid::figures`, one grid per class,
//! built once) and the design map of the selected class over the
//! suspension's k and c (`biodyn::seat::design`). About 1 ms for the 16
//! classes and 30 ms for the map in a release build: done on the UI
//! thread, once per model edit or class change.

use biodyn::seat::{self, Design, FloorPsd, SeatFigures, SeatGrid, Vary};
use biodyn::time::CLASSES;
use biodyn::Body;

pub use biodyn::seat::{LIMIT_SHARE, SPAN, default_limit, suspension};

/// One grid per input class, in `CLASSES` order (they do not depend on the
/// model).
pub fn grids() -> Vec<Result<SeatGrid, String>> {
    CLASSES
        .iter()
        .map(|c| SeatGrid::new(&FloorPsd::Class(c)).map_err(|e| e.to_string()))
        .collect()
}

/// The box of the map around `centre` (`biodyn::seat::suspension_box`).
pub fn box_of(body: &Body, centre: [f64; 2]) -> Result<Vec<Vary>, String> {
    seat::suspension_box(body, centre).map_err(|e| e.to_string())
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
