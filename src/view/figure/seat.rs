//! The seat's figure (`biodyn seat --plot`, the Seat tab's `.svg`): its
//! transmissibility, pan over floor and floor to head, over the model's
//! band; and SEAT % per input spectral class (ISO 7096, EN 13490, ISO
//! 5007) against 100 %, the seat that passes the floor's a_w unchanged,
//! the selected floor's bar filled dark; and under the selected floor, the
//! design map over the suspension's k and c (`design.rs`), as the tab has it.

use super::design::{self, DesignFigure};
use super::model::{Axis, Bars, Curve, Figure, Panel};
use super::style::{Fill, Look};
use biodyn::time::CLASSES;
use biodyn::{Function, Response};

/// Each panel's size, pixels (one above the other: the classes' panel
/// needs the width for sixteen names).
pub const PANEL_PX: (u32, u32) = (800, 420);

/// A floor's bar: its name and SEAT %, None where it could not be computed.
pub type Floor = (String, Option<f64>);

/// What the seat figure shows.
#[derive(Debug, Clone, Copy)]
pub struct SeatFigure<'a> {
    /// The model's response over its band.
    pub curve: &'a [Response],
    pub floors: &'a [Floor],
    /// The floor drawn as selected.
    pub selected: Option<usize>,
    /// The design map under the selected floor, where there is one.
    pub design: Option<DesignFigure<'a>>,
}

/// The classes' bars, named in `CLASSES` order, from their SEAT % (None
/// where it could not be computed).
pub fn class_floors(pcts: impl IntoIterator<Item = Option<f64>>) -> Vec<Floor> {
    CLASSES
        .iter()
        .zip(pcts)
        .map(|(c, p)| (c.name.to_string(), p))
        .collect()
}

fn transmissibility(curve: &[Response]) -> Panel {
    Panel {
        title: "seat transmissibility".into(),
        x: Axis {
            title: "f (Hz)".into(),
            ..Axis::default()
        },
        y: Axis {
            title: "|T| (-)".into(),
            floor_zero: true,
            ..Axis::default()
        },
        curves: [Function::SeatTr, Function::FloorHead]
            .iter()
            .enumerate()
            .map(|(i, &f)| Curve {
                name: f.long_name().into(),
                points: curve.iter().map(|r| (r.f_hz, r.mag(f))).collect(),
                look: Look::Series(i),
            })
            .collect(),
        ..Panel::default()
    }
}

fn classes(floors: &[Floor], selected: Option<usize>) -> Panel {
    let at = |i: usize| (i as f64 - 0.35, i as f64 + 0.35);
    let mut bars = vec![Bars {
        name: "SEAT %".into(),
        bars: floors
            .iter()
            .enumerate()
            .filter(|(i, _)| Some(*i) != selected)
            .filter_map(|(i, (_, v))| Some((at(i).0, at(i).1, (*v)?)))
            .collect(),
        fill: Fill::Plain,
    }];
    if let Some(i) = selected
        && let Some((name, Some(v))) = floors.get(i)
    {
        bars.push(Bars {
            name: format!("{name}, selected"),
            bars: vec![(at(i).0, at(i).1, *v)],
            fill: Fill::Selected,
        });
    }
    Panel {
        title: "SEAT % per input spectral class".into(),
        x: Axis {
            title: "floor (input spectral class)".into(),
            names: floors.iter().map(|f| f.0.clone()).collect(),
            ..Axis::default()
        },
        y: Axis {
            title: "SEAT (%)".into(),
            floor_zero: true,
            ..Axis::default()
        },
        curves: vec![Curve {
            name: "100 %: the floor's a_w".into(),
            points: vec![(-0.6, 100.0), (floors.len() as f64 - 0.4, 100.0)],
            look: Look::Reference,
        }],
        bars,
        ..Panel::default()
    }
}

pub fn figure(s: &SeatFigure) -> Figure {
    let mut panels = vec![transmissibility(s.curve), classes(s.floors, s.selected)];
    panels.extend(s.design.as_ref().map(design::panels).unwrap_or_default());
    Figure {
        panels,
        columns: 1,
        panel_px: PANEL_PX,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_selected_floor_is_its_own_bar_and_a_failed_one_is_left_out() {
        let floors = vec![
            ("EM1".to_string(), Some(80.0)),
            ("EM2".to_string(), None),
            ("EM3".to_string(), Some(120.0)),
        ];
        let fig = figure(&SeatFigure {
            curve: &[],
            floors: &floors,
            selected: Some(2),
            design: None,
        });
        let p = &fig.panels[1];
        assert_eq!(p.x.names, vec!["EM1", "EM2", "EM3"]);
        assert_eq!(p.bars[0].bars, vec![(-0.35, 0.35, 80.0)]);
        assert_eq!(p.bars[1].bars, vec![(2.0 - 0.35, 2.0 + 0.35, 120.0)]);
        assert_eq!(p.bars[1].fill, Fill::Selected);
        assert_eq!(p.bars[1].name, "EM3, selected");
    }
}
