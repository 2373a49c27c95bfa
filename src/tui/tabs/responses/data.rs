//! Measured data over the charts: a file read by `biodyn::fit::Measured`
//! (the same reader and checks as `biodyn fit --data`), drawn as a series
//! named "data" beside the model's. It belongs to the tab, not the model,
//! so it stays while the model changes and the user sees a fit improve.

use crate::view::chart::Series;
use biodyn::Function;
use crate::view::figure::response::measured;
use biodyn::fit::Measured;

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
    /// whole turns next to `model`, as the fit compares them (wrapped
    /// difference): the figure's own rule (`figure::response::measured`).
    pub fn series(&self, function: Function, phase: bool, model: &Series) -> Option<Series> {
        let points = measured(&self.data, function, phase, &model.points)?;
        Some(Series {
            name: "data".into(),
            points: points.iter().map(|p| (p.0, p.1)).collect(),
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
