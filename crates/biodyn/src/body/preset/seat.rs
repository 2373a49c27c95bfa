//! A preset's seat: `seat = true` on the seat's segments, the base called
//! `floor`, and the `[seat]` table that names the pan, the suspension and
//! the travel (SPEC §11).

use crate::body::model::{Body, Seat};
use crate::io::excerpt::{num, quote};
use serde::{Deserialize, Serialize};
use toml::Spanned;

/// The `[seat]` table.
#[derive(Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct SeatFile {
    /// The segment the seat-pan accelerometer (SAE pad) sits on.
    pub pan: Spanned<String>,
    /// The link whose deflection is the suspension travel.
    pub suspension: Spanned<String>,
    /// Available travel, end-stop to end-stop, m.
    pub stroke_m: Spanned<f64>,
}

/// Names a link's lower end may use for the base: "seat" for a body on a
/// rigid seat, "floor" for the cab floor under a seat (either is accepted).
pub(super) fn is_base(name: &str) -> bool {
    name == "seat" || name == "floor"
}

/// Why a base's name does not fit the preset: "floor" needs a `[seat]`
/// table, and under a seat the base is the floor, not "seat".
pub(super) fn base_mismatch(name: &str, has_seat: bool) -> Option<String> {
    match (name, has_seat) {
        ("floor", false) => Some(
            "lower = \"floor\": the floor is the base under a seat, and the preset has no [seat] table; add one, or write lower = \"seat\" for a rigid seat".into(),
        ),
        ("seat", true) => Some(
            "lower = \"seat\": with a [seat] table the base is the cab floor; write lower = \"floor\" (the seat's parts are segments)".into(),
        ),
        _ => None,
    }
}

/// What the base is called when written: the floor under a seat.
pub(super) fn base_name(body: &Body) -> &'static str {
    if body.has_seat() { "floor" } else { "seat" }
}

/// The `[seat]` table resolved against the parsed segments and links; an
/// error is (span, message) for the caller to place by line.
pub(super) fn resolve(
    file: &SeatFile,
    body: &Body,
) -> Result<Seat, (std::ops::Range<usize>, String)> {
    let pan = body
        .segments
        .iter()
        .position(|s| &s.name == file.pan.get_ref())
        .ok_or_else(|| {
            (
                file.pan.span(),
                format!(
                    "[seat] pan = \"{}\" is not a segment name: name the seat segment the body rests on",
                    quote(file.pan.get_ref())
                ),
            )
        })?;
    let suspension = body
        .links
        .iter()
        .position(|l| &l.name == file.suspension.get_ref())
        .ok_or_else(|| {
            (
                file.suspension.span(),
                format!(
                    "[seat] suspension = \"{}\" is not a link name: name the link from the seat's frame to the floor",
                    quote(file.suspension.get_ref())
                ),
            )
        })?;
    let stroke_m = *file.stroke_m.get_ref();
    if !(stroke_m.is_finite() && stroke_m > 0.0 && stroke_m <= crate::body::limits::MAX_STROKE_M) {
        return Err((
            file.stroke_m.span(),
            format!(
                "[seat] stroke_m = {}: the travel end-stop to end-stop must be > 0 and at most {} m (a typical suspension seat has 0.05–0.15 m)",
                num(stroke_m),
                num(crate::body::limits::MAX_STROKE_M)
            ),
        ));
    }
    Ok(Seat {
        pan,
        suspension,
        stroke_m,
    })
}

/// The `[seat]` table of a body, for saving.
pub(super) fn to_file(body: &Body) -> Option<SeatFile> {
    let seat = body.seat.as_ref()?;
    let seg = body.segments.get(seat.pan)?.name.clone();
    let link = body.links.get(seat.suspension)?.name.clone();
    Some(SeatFile {
        pan: Spanned::new(0..0, seg),
        suspension: Spanned::new(0..0, link),
        stroke_m: Spanned::new(0..0, seat.stroke_m),
    })
}
