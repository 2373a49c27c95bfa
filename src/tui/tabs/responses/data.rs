//! Measured data over the charts: a file read by `biodyn::fit::Measured`
//! (the same reader and checks as `biodyn fit --data`), drawn as a series
//! named "data" beside the model's. It belongs to the tab, not the model,
//! so it stays while the model changes and the user sees a fit improve.

use crate::view::chart::Series;
use biodyn::Function;
use biodyn::fit::{Measured, Quantity};

/// The shipped synthetic example, offered when nothing was loaded yet.
pub const EXAMPLE: &str = "examples/synthetic-stht-apms-3pct-2deg.csv";

/// A loaded data file.
#[derive(Debug, Clone, PartialEq)]
pub struct DataOverlay {
    pub data: Measured,
}

impl DataOverlay {
    /// Reads `text` as a path (`~` expanded); the library's message on refusal.
    pub fn load(text: &str) -> Result<DataOverlay, String> {
        let t = text.trim();
        if t.is_empty() {
            return Err(format!(
                "give the path of a CSV with f_hz and any of {}",
                biodyn::fit::KNOWN
            ));
        }
        let data = Measured::load(&crate::tui::paths::expand(t)).map_err(|e| e.to_string())?;
        Ok(DataOverlay { data })
    }

    /// The measured points of `function`'s magnitude or phase, as (f Hz,
    /// value); None when the file has no such column. A phase is moved by
    /// whole turns next to `model` (the model's phase at the same grid),
    /// as the fit compares them (wrapped difference).
    pub fn series(&self, function: Function, phase: bool, model: &Series) -> Option<Series> {
        let q = if phase {
            Quantity::Phase
        } else {
            Quantity::Mag
        };
        let col = self
            .data
            .columns
            .iter()
            .find(|c| c.channel.function == function && c.channel.quantity == q)?;
        let points = self
            .data
            .f_hz
            .iter()
            .zip(&col.values)
            .filter_map(|(&f, v)| v.map(|v| (f, v)))
            .map(|(f, v)| match (phase, nearest(model, f)) {
                (true, Some(m)) => (f, v + 360.0 * ((m - v) / 360.0).round()),
                _ => (f, v),
            })
            .collect();
        Some(Series {
            name: "data".into(),
            points,
        })
    }

    /// "file.csv: 196 frequencies, 0.5–20 Hz, stht_mag, apms_mag".
    pub fn describe(&self) -> String {
        let d = &self.data;
        let range = match (d.f_hz.first(), d.f_hz.last()) {
            (Some(a), Some(b)) => format!(", {a}–{b} Hz"),
            _ => String::new(),
        };
        format!(
            "{}: {} frequencies{range}, {}",
            d.path,
            d.f_hz.len(),
            d.column_names().join(", ")
        )
    }
}

/// The model's value at the grid point nearest `f` (the grid is uniform
/// and sorted, so a binary search finds it).
fn nearest(model: &Series, f: f64) -> Option<f64> {
    let pts = &model.points;
    let i = pts.partition_point(|p| p.0 < f);
    let after = pts.get(i);
    let before = i.checked_sub(1).and_then(|j| pts.get(j));
    match (before, after) {
        (Some(a), Some(b)) if (f - a.0).abs() <= (b.0 - f).abs() => Some(a.1),
        (_, Some(b)) => Some(b.1),
        (Some(a), None) => Some(a.1),
        (None, None) => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn phases_move_by_whole_turns_next_to_the_model() {
        let data = Measured::parse(
            "f_hz,stht_mag,stht_phase_deg\n1,1.0,-179\n2,2.0,10\n3,1.5,\n",
            "t.csv",
        )
        .expect("valid data");
        let o = DataOverlay { data };
        let model = Series {
            name: "STHT".into(),
            points: vec![(1.0, 179.0), (2.0, 5.0), (3.0, -20.0)],
        };
        let ph = o
            .series(Function::Stht, true, &model)
            .expect("phase column");
        assert_eq!(ph.points, vec![(1.0, 181.0), (2.0, 10.0)]);
        let mag = o.series(Function::Stht, false, &model).expect("mag column");
        assert_eq!(mag.points, vec![(1.0, 1.0), (2.0, 2.0), (3.0, 1.5)]);
        assert!(o.series(Function::Apms, false, &model).is_none());
    }
}
