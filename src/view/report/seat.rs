//! `biodyn seat`'s figures: SEAT %, the pan's and the floor's a_w and the
//! suspension's r.m.s. stroke, for one floor PSD or for every input class.
//! The design search's report is in `seat_design.rs`.

use super::{Report, csv, json, table};
use biodyn::seat::SeatFigures;
use biodyn::time::InputClass;
use serde_json::json;

/// The figures' CSV columns and JSON keys, in this order.
pub const FIGURE_KEYS: [&str; 5] = [
    "seat_pct",
    "pan_aw_m_s2",
    "floor_aw_m_s2",
    "stroke_rms_m",
    "stroke_available_m",
];

/// The figures in `FIGURE_KEYS` order.
pub fn figure_values(f: &SeatFigures) -> [f64; 5] {
    [
        f.seat_pct,
        f.pan_aw_m_s2,
        f.floor_aw_m_s2,
        f.stroke_rms_m,
        f.stroke_available_m,
    ]
}

/// The figures as JSON members, keyed as `FIGURE_KEYS`.
pub fn figures_json(f: &SeatFigures) -> serde_json::Map<String, serde_json::Value> {
    FIGURE_KEYS
        .iter()
        .zip(figure_values(f))
        .map(|(k, v)| (k.to_string(), v.into()))
        .collect()
}

/// A table's cells of the figures: SEAT %, a_w in m/s², strokes in mm.
fn figure_cells(f: &SeatFigures) -> [String; 5] {
    [
        table::fx(f.seat_pct, 1),
        table::fx(f.pan_aw_m_s2, 3),
        table::fx(f.floor_aw_m_s2, 3),
        table::fx(1e3 * f.stroke_rms_m, 2),
        table::fx(1e3 * f.stroke_available_m, 1),
    ]
}

/// The figures' table titles.
const FIGURE_TITLES: [&str; 5] = [
    "SEAT %",
    "pan a_w m/s²",
    "floor a_w m/s²",
    "r.m.s. stroke mm",
    "available mm",
];

/// One floor PSD: a class or a file.
pub struct SeatOne {
    pub model: String,
    /// The class's name, or the PSD file as given.
    pub input: String,
    /// What the input is, for the table's title: "EM6, ISO 7096:2000".
    pub about: String,
    /// The frequencies integrated over, Hz: the PSD's own within 0.1–1000 Hz.
    pub integrated_hz: (f64, f64),
    pub figures: SeatFigures,
}

impl Report for SeatOne {
    fn table(&self) -> String {
        let mut s = format!("{} on {} ({})\n", self.model, self.input, self.about);
        let rows = vec![figure_cells(&self.figures).to_vec()];
        s += &table::table(&FIGURE_TITLES, &rows);
        s
    }

    fn csv(&self) -> Option<String> {
        let mut s = format!("model,input,{}\n", FIGURE_KEYS.join(","));
        let cells: Vec<String> = figure_values(&self.figures)
            .iter()
            .map(|v| v.to_string())
            .collect();
        s += &format!(
            "{},{},{}\n",
            csv::text_cell(&self.model),
            csv::text_cell(&self.input),
            cells.join(",")
        );
        Some(s)
    }

    fn json(&self) -> Result<String, serde_json::Error> {
        let mut m = figures_json(&self.figures);
        m.insert("model".into(), self.model.clone().into());
        m.insert("input".into(), self.input.clone().into());
        m.insert(
            "integrated_hz".into(),
            json!([self.integrated_hz.0, self.integrated_hz.1]),
        );
        json::pretty(&m)
    }
}

/// Every input class: the "SEAT % per input class" view.
pub struct SeatClasses {
    pub model: String,
    pub rows: Vec<(&'static InputClass, SeatFigures)>,
}

impl Report for SeatClasses {
    fn table(&self) -> String {
        let mut header = vec!["class", "standard"];
        header.extend(FIGURE_TITLES);
        let rows: Vec<Vec<String>> = self
            .rows
            .iter()
            .map(|(c, f)| {
                let mut r = vec![c.name.to_string(), c.standard.to_string()];
                r.extend(figure_cells(f));
                r
            })
            .collect();
        format!(
            "{}: SEAT % per input class\n{}",
            self.model,
            table::table(&header, &rows)
        )
    }

    fn csv(&self) -> Option<String> {
        let mut s = format!("class,standard,{}\n", FIGURE_KEYS.join(","));
        for (c, f) in &self.rows {
            let cells: Vec<String> = figure_values(f).iter().map(|v| v.to_string()).collect();
            s += &format!(
                "{},{},{}\n",
                c.name,
                csv::text_cell(c.standard),
                cells.join(",")
            );
        }
        Some(s)
    }

    fn json(&self) -> Result<String, serde_json::Error> {
        let classes: Vec<serde_json::Value> = self
            .rows
            .iter()
            .map(|(c, f)| {
                let mut m = figures_json(f);
                m.insert("class".into(), c.name.into());
                m.insert("standard".into(), c.standard.into());
                serde_json::Value::Object(m)
            })
            .collect();
        json::pretty(&json!({ "model": self.model, "classes": classes }))
    }
}
