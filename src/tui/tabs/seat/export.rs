//! The Seat tab's export (`x`): the figures per input class as CSV (the
//! columns `biodyn seat --format json` names: seat_pct, pan_aw_m_s2,
//! floor_aw_m_s2, stroke_rms_m, then stroke_available_m), or the tab's
//! charts as text (`.txt`: the tab drawn at 160×48 in plain ASCII, no
//! colour: the transmissibility chart, the bars, the stroke and the map),
//! or as a figure (`.svg`: the transmissibility over the model's band,
//! SEAT % per class, the selected one dark, and the design map as the tab
//! has it; at the tab's defaults, what `biodyn seat --class NAME --plot`
//! writes for the same model and band).

use super::SeatTab;
use super::view;
use crate::tui::effect::{Effect, Export, Format};
use crate::tui::shared::Shared;
use crate::tui::theme::Theme;
use crate::view::chart::buffer_text;
use crate::view::figure::design::DesignFigure;
use crate::view::figure::seat::{SeatFigure, class_floors, figure};
use biodyn::time::CLASSES;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;

/// The size the `.txt` export is drawn at.
pub const TEXT_SIZE: (u16, u16) = (160, 48);

pub fn effects(t: &SeatTab, s: &Shared) -> Vec<Effect> {
    if t.data.is_none() {
        return vec![Effect::Error(format!("nothing to export: {}", view::NO_SEAT))];
    }
    vec![Effect::Export(Export {
        what: "seat figures".into(),
        path_hint: format!("{}-seat.csv", s.preset.name),
        formats: vec![
            Format {
                ext: "csv",
                what: "class figures",
                contents: csv(t),
            },
            Format {
                ext: "txt",
                what: "text charts",
                contents: text(t, s),
            },
        ]
        .into_iter()
        .chain(svg(t, s).map(|contents| Format {
            ext: "svg",
            what: "figure",
            contents,
        }))
        .collect(),
    })]
}

/// The figure, once the model's curve is computed.
pub fn svg(t: &SeatTab, s: &Shared) -> Option<String> {
    let (d, derived) = (t.data.as_ref()?, s.derived.as_ref()?);
    let floors = class_floors(d.classes.iter().map(|r| r.as_ref().ok().map(|f| f.seat_pct)));
    let class = CLASSES.get(t.class)?;
    let design = match (&d.design, d.classes.get(t.class)) {
        (Ok(design), Some(Ok(figures))) => Some(DesignFigure {
            design,
            now: &d.now,
            now_figures: figures,
            floor: class.name,
        }),
        _ => None,
    };
    Some(
        figure(&SeatFigure {
            curve: &derived.curve,
            floors: &floors,
            selected: Some(t.class),
            design,
        })
        .svg(),
    )
}

/// One row per class: its name and standard, then the figures (shortest
/// round-trip numbers), or the error in the last column.
pub fn csv(t: &SeatTab) -> String {
    let mut out = String::from(
        "class,standard,seat_pct,pan_aw_m_s2,floor_aw_m_s2,stroke_rms_m,stroke_available_m,error\n",
    );
    let Some(d) = &t.data else {
        return out;
    };
    for (c, r) in CLASSES.iter().zip(&d.classes) {
        match r {
            Ok(f) => out.push_str(&format!(
                "{},{},{},{},{},{},{},\n",
                c.name,
                c.standard,
                f.seat_pct,
                f.pan_aw_m_s2,
                f.floor_aw_m_s2,
                f.stroke_rms_m,
                f.stroke_available_m
            )),
            Err(e) => out.push_str(&format!(
                "{},{},,,,,,\"{}\"\n",
                c.name,
                c.standard,
                e.replace('"', "\"\"")
            )),
        }
    }
    out
}

/// The tab as text lines at `TEXT_SIZE`, ASCII glyphs, no colour.
pub fn text(t: &SeatTab, s: &Shared) -> String {
    let area = Rect::new(0, 0, TEXT_SIZE.0, TEXT_SIZE.1);
    let mut buf = Buffer::empty(area);
    let plain = Theme {
        mono: true,
        ascii: true,
    };
    view::render_in(t, s, plain, area, &mut buf);
    crate::view::chart::asciify(area, &mut buf);
    let mut text = buffer_text(&buf).join("\n");
    text.push('\n');
    text
}
