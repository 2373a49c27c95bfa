//! The box a seat's design map is laid over when none is given: the
//! suspension link's stiffness and damping, each from a quarter to four
//! times a centre (its own values), and the travel limit that goes with
//! it: stroke/6, so that ±3 r.m.s. fit within ±stroke/2, end-stop to
//! end-stop (a Gaussian travel passes 3σ 0.27 % of the time).

use super::design::Vary;
use super::error::SeatError;
use crate::body::model::{Body, Param};

/// How far the box reaches either side of its centre: ×1/4 … ×4.
pub const SPAN: f64 = 4.0;

/// The default r.m.s. travel limit as a share of the seat's travel.
pub const LIMIT_SHARE: f64 = 1.0 / 6.0;

/// The suspension link's index, stiffness and damping, when `body` has a seat.
pub fn suspension(body: &Body) -> Option<(usize, f64, f64)> {
    let i = body.seat.as_ref()?.suspension;
    let l = body.links.get(i)?;
    Some((i, l.k, l.c))
}

/// The default r.m.s. travel limit of `body`'s seat, m.
pub fn default_limit(body: &Body) -> Option<f64> {
    body.seat.as_ref().map(|s| s.stroke_m * LIMIT_SHARE)
}

/// k and c of the suspension link over [centre/SPAN, centre·SPAN], named
/// `<link>.k` and `<link>.c` as `--vary` names them.
pub fn suspension_box(body: &Body, centre: [f64; 2]) -> Result<Vec<Vary>, SeatError> {
    let (i, _, _) = suspension(body).ok_or(SeatError::NoSeat)?;
    let name = &body.links[i].name;
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::body::preset::Preset;

    #[test]
    fn the_box_is_a_quarter_to_four_times_the_suspensions_own_k_and_c() {
        let p = Preset::builtin("paper-75kg-suspension-seat")
            .expect("a built-in")
            .expect("it loads");
        let (i, k, c) = suspension(&p.body).expect("a seat");
        let b = suspension_box(&p.body, [k, c]).expect("a box");
        let link = &p.body.links[i].name;
        assert_eq!(b[0].name, format!("{link}.k"));
        assert_eq!(b[1].name, format!("{link}.c"));
        assert_eq!((b[0].lo, b[0].hi), (k / 4.0, k * 4.0));
        assert_eq!((b[1].lo, b[1].hi), (c / 4.0, c * 4.0));
        assert_eq!(b[0].param, Param::Stiffness(i));
        assert_eq!(b[1].param, Param::Damping(i));
        let stroke = p.body.seat.as_ref().expect("a seat").stroke_m;
        assert_eq!(default_limit(&p.body), Some(stroke / 6.0));
        let bare = Preset::builtin_default();
        assert!(matches!(
            suspension_box(&bare.body, [1.0, 1.0]),
            Err(SeatError::NoSeat)
        ));
        assert_eq!(default_limit(&bare.body), None);
    }
}
