//! `biodyn seat --vary`'s report: the best point of the box, and the map of
//! SEAT % and r.m.s. stroke the search started from.

use super::{Report, csv, json, table};
use crate::view::format::num;
use biodyn::seat::Design;
use serde_json::json;

/// Every how many map points the table shows (the CSV and JSON have all).
const TABLE_EVERY: usize = 2;

/// A design search's result on one floor PSD.
pub struct SeatDesign {
    pub model: String,
    /// The class's name, or the PSD file as given.
    pub input: String,
    pub design: Design,
}

impl SeatDesign {
    fn feasible(&self, stroke_rms_m: f64) -> bool {
        stroke_rms_m <= self.design.stroke_rms_max_m
    }

    /// "suspension.c = 1234.5 N·s/m, …".
    fn best_params(&self) -> String {
        let d = &self.design;
        d.vary
            .iter()
            .zip(&d.best.values)
            .map(|(v, x)| format!("{} = {} {}", v.name, num(*x, 5), v.param.unit()))
            .collect::<Vec<_>>()
            .join(", ")
    }

    /// The map as rows of the first parameter (one row when one is varied).
    fn rows<'a>(&self, values: &'a [f64]) -> Vec<&'a [f64]> {
        match self.design.map.axes.get(1) {
            Some(cols) if !cols.is_empty() => values.chunks(cols.len()).collect(),
            _ => vec![values],
        }
    }

    fn map_table(&self) -> String {
        let d = &self.design;
        let map = &d.map;
        let keep = |i: &usize| i % TABLE_EVERY == 0;
        let cell = |seat: f64, stroke: f64| {
            let mark = if self.feasible(stroke) { " " } else { "x" };
            format!("{}{mark}", table::fx(seat, 1))
        };
        if d.vary.len() == 1 {
            let v = &d.vary[0];
            let title = format!("{} {}", v.name, v.param.unit());
            let header = [
                title.as_str(),
                "SEAT %",
                "r.m.s. stroke mm",
                "keeps the limit",
            ];
            let rows: Vec<Vec<String>> = (0..map.axes[0].len())
                .filter(keep)
                .map(|i| {
                    let stroke = map.stroke_rms_m[i];
                    vec![
                        num(map.axes[0][i], 4),
                        table::fx(map.seat_pct[i], 1),
                        table::fx(1e3 * stroke, 2),
                        if self.feasible(stroke) { "yes" } else { "no" }.to_string(),
                    ]
                })
                .collect();
            return table::table(&header, &rows);
        }
        let (a, b) = (&d.vary[0], &d.vary[1]);
        let corner = format!("{} \\ {}", a.name, b.name);
        let cols: Vec<usize> = (0..map.axes[1].len()).filter(keep).collect();
        let mut header = vec![corner];
        header.extend(cols.iter().map(|&j| format!("{} ", num(map.axes[1][j], 3))));
        let seat = self.rows(&map.seat_pct);
        let stroke = self.rows(&map.stroke_rms_m);
        let rows: Vec<Vec<String>> = (0..map.axes[0].len())
            .filter(keep)
            .map(|i| {
                let mut r = vec![num(map.axes[0][i], 3)];
                r.extend(cols.iter().map(|&j| cell(seat[i][j], stroke[i][j])));
                r
            })
            .collect();
        let h: Vec<&str> = header.iter().map(String::as_str).collect();
        format!(
            "rows {} {}, columns {} {}\n{}",
            a.name,
            a.param.unit(),
            b.name,
            b.param.unit(),
            table::table(&h, &rows)
        )
    }
}

impl Report for SeatDesign {
    fn table(&self) -> String {
        let d = &self.design;
        let f = &d.best.figures;
        let every = if d.vary.len() == 1 {
            "every other point"
        } else {
            "every other row and column"
        };
        format!(
            "{model} on {input}: the lowest SEAT with an r.m.s. stroke ≤ {limit} mm\n\
             best: {params}\n  \
             SEAT {seat} %, r.m.s. stroke {stroke} mm of {avail} mm available, pan a_w {pan} m/s², floor a_w {floor} m/s²\n  \
             {n} figures computed (the map, then a compass search from its best feasible points)\n\n\
             SEAT % over the box ({every} of the map; x: the r.m.s. stroke is over the limit)\n{map}",
            model = self.model,
            input = self.input,
            limit = num(1e3 * d.stroke_rms_max_m, 4),
            params = self.best_params(),
            seat = table::fx(f.seat_pct, 2),
            stroke = table::fx(1e3 * f.stroke_rms_m, 3),
            avail = table::fx(1e3 * f.stroke_available_m, 1),
            pan = table::fx(f.pan_aw_m_s2, 3),
            floor = table::fx(f.floor_aw_m_s2, 3),
            n = d.evaluations,
            map = self.map_table(),
        )
    }

    /// The map's points, one row each (the first parameter the slower).
    fn csv(&self) -> Option<String> {
        let d = &self.design;
        let map = &d.map;
        let name = |n: &str| {
            if n.contains([',', '"']) {
                csv::text_cell(n)
            } else {
                n.to_string()
            }
        };
        let mut s: String = d
            .vary
            .iter()
            .map(|v| name(&v.name) + ",")
            .collect::<String>();
        s += "seat_pct,stroke_rms_m,feasible\n";
        let width = map.axes.get(1).map_or(1, Vec::len).max(1);
        for (k, (&seat, &stroke)) in map.seat_pct.iter().zip(&map.stroke_rms_m).enumerate() {
            let (i, j) = if d.vary.len() == 1 {
                (k, 0)
            } else {
                (k / width, k % width)
            };
            s += &map.axes[0][i].to_string();
            s.push(',');
            if d.vary.len() == 2 {
                s += &map.axes[1][j].to_string();
                s.push(',');
            }
            s += &format!("{seat},{stroke},{}\n", self.feasible(stroke));
        }
        Some(s)
    }

    fn json(&self) -> Result<String, serde_json::Error> {
        let d = &self.design;
        let f = &d.best.figures;
        let params: serde_json::Map<String, serde_json::Value> = d
            .vary
            .iter()
            .zip(&d.best.values)
            .map(|(v, x)| (v.name.clone(), (*x).into()))
            .collect();
        let axes: serde_json::Map<String, serde_json::Value> = d
            .vary
            .iter()
            .zip(&d.map.axes)
            .map(|(v, a)| (v.name.clone(), a.clone().into()))
            .collect();
        let grid = |values: &[f64]| -> serde_json::Value {
            if d.vary.len() == 1 {
                values.to_vec().into()
            } else {
                self.rows(values)
                    .into_iter()
                    .map(|r| serde_json::Value::from(r.to_vec()))
                    .collect()
            }
        };
        let names: Vec<&str> = d.vary.iter().map(|v| v.name.as_str()).collect();
        json::pretty(&json!({
            "model": self.model,
            "input": self.input,
            "stroke_rms_max_m": d.stroke_rms_max_m,
            "best": {
                "params": params,
                "seat_pct": f.seat_pct,
                "stroke_rms_m": f.stroke_rms_m,
                "pan_aw_m_s2": f.pan_aw_m_s2,
                "floor_aw_m_s2": f.floor_aw_m_s2,
                "stroke_available_m": f.stroke_available_m,
            },
            "map": {
                "params": names,
                "axes": axes,
                "seat_pct": grid(&d.map.seat_pct),
                "stroke_rms_m": grid(&d.map.stroke_rms_m),
            },
            "evaluations": d.evaluations,
        }))
    }
}
