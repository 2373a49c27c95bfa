//! The floor's vertical acceleration PSD G(f), one-sided, (m/s²)²/Hz: an
//! input spectral class's formula, or a table read from a CSV file with the
//! header `f_hz,psd_m2_s4_hz` (comment lines start with `#`), linear between
//! its rows and 0 outside them.

use super::error::SeatError;
use crate::io::excerpt::quote;
use crate::io::{FileKind, read_text};
use crate::time::InputClass;
use std::path::Path;

/// Where a class's PSD is integrated, Hz: past the weighting's band limits
/// (0.4–100 Hz) at the top, and below every class's high-pass.
pub const CLASS_RANGE_HZ: (f64, f64) = (0.1, 100.0);

/// Largest density, (m/s²)²/Hz: the acceleration cap (`time::MAX_ACC`,
/// 10⁴ m/s²) squared, in one hertz; beyond it is a unit slip.
const MAX_DENSITY: f64 = crate::time::MAX_ACC * crate::time::MAX_ACC;

/// Most rows a PSD file may hold.
const MAX_ROWS: usize = 1_000_000;

#[derive(Debug, Clone, PartialEq)]
pub enum FloorPsd {
    Class(&'static InputClass),
    /// Rows (f_hz, G), f rising strictly, G ≥ 0; `name` labels reports.
    Table {
        name: String,
        rows: Vec<(f64, f64)>,
    },
}

impl FloorPsd {
    /// The PSD at `f_hz`.
    pub fn at(&self, f_hz: f64) -> f64 {
        match self {
            FloorPsd::Class(c) => c.psd(f_hz),
            FloorPsd::Table { rows, .. } => {
                // The first row at or above f: a row's own value, or the line
                // from the row before; nothing outside the table.
                let i = rows.partition_point(|r| r.0 < f_hz);
                match (rows.get(i), i.checked_sub(1).map(|j| rows[j])) {
                    (Some(&(f1, g1)), _) if f1 == f_hz => g1,
                    (Some(&(f1, g1)), Some((f0, g0))) => g0 + (g1 - g0) * (f_hz - f0) / (f1 - f0),
                    _ => 0.0,
                }
            }
        }
    }

    /// The frequencies it is integrated over, Hz.
    pub fn range(&self) -> (f64, f64) {
        match self {
            FloorPsd::Class(_) => CLASS_RANGE_HZ,
            FloorPsd::Table { rows, .. } => (rows[0].0, rows[rows.len() - 1].0),
        }
    }

    /// "EM6" or the file's name.
    pub fn name(&self) -> String {
        match self {
            FloorPsd::Class(c) => c.name.to_string(),
            FloorPsd::Table { name, .. } => name.clone(),
        }
    }

    /// Reads a PSD file (regular files only, capped).
    pub fn load(path: &Path) -> Result<FloorPsd, SeatError> {
        let shown = path.display().to_string();
        let text = read_text(path, FileKind::Psd).map_err(|e| SeatError::Read {
            path: shown.clone(),
            why: e.to_string(),
        })?;
        FloorPsd::parse(&text, &shown)
    }

    /// Parses a PSD table; `path` labels errors.
    pub fn parse(text: &str, path: &str) -> Result<FloorPsd, SeatError> {
        let p = || path.to_string();
        let mut lines = text
            .lines()
            .enumerate()
            .map(|(i, l)| (i + 1, l.trim()))
            .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
        let Some((hline, header)) = lines.next() else {
            return Err(SeatError::Empty { path: p() });
        };
        let names: Vec<&str> = header.split(',').map(str::trim).collect();
        if names != ["f_hz", "psd_m2_s4_hz"] {
            return Err(SeatError::Header {
                path: p(),
                line: hline,
                found: quote(header),
            });
        }
        let mut rows: Vec<(f64, f64)> = Vec::new();
        for (line, l) in lines {
            let cells: Vec<&str> = l.split(',').map(str::trim).collect();
            let field = |field: &'static str, value: &str, why: &str| SeatError::Field {
                path: p(),
                line,
                field,
                value: quote(value),
                why: why.to_string(),
            };
            if cells.len() != 2 {
                return Err(field(
                    "row",
                    l,
                    "does not have two fields: write f_hz,psd_m2_s4_hz",
                ));
            }
            let f: f64 = cells[0]
                .parse()
                .map_err(|_| field("f_hz", cells[0], "is not a number"))?;
            if !(f.is_finite() && f > 0.0) {
                return Err(field("f_hz", cells[0], "must be finite and > 0 Hz"));
            }
            let g: f64 = cells[1]
                .parse()
                .map_err(|_| field("psd_m2_s4_hz", cells[1], "is not a number"))?;
            if !(g.is_finite() && g >= 0.0) {
                return Err(field(
                    "psd_m2_s4_hz",
                    cells[1],
                    "must be finite and ≥ 0 (m/s²)²/Hz: a density is never negative",
                ));
            }
            if g > MAX_DENSITY {
                return Err(field(
                    "psd_m2_s4_hz",
                    cells[1],
                    "is over 1e8 (m/s²)²/Hz, the 10 000 m/s² acceleration cap in one hertz: check the unit",
                ));
            }
            if let Some(&(before, _)) = rows.last()
                && f <= before
            {
                return Err(SeatError::Unsorted {
                    path: p(),
                    line,
                    f_hz: f,
                    before,
                });
            }
            if rows.len() == MAX_ROWS {
                return Err(field(
                    "row",
                    l,
                    "is past the million rows a PSD file may hold",
                ));
            }
            rows.push((f, g));
        }
        if rows.len() < 2 {
            return Err(SeatError::TooFew {
                path: p(),
                rows: rows.len(),
            });
        }
        if rows.iter().all(|r| r.1 == 0.0) {
            return Err(SeatError::Silent { path: p() });
        }
        let name = Path::new(path)
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_else(p);
        Ok(FloorPsd::Table { name, rows })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_table_is_linear_between_rows_and_zero_outside() {
        let t = FloorPsd::parse("f_hz,psd_m2_s4_hz\n1,2\n3,4\n", "x.csv").unwrap();
        assert_eq!(t.at(2.0), 3.0);
        assert_eq!(t.at(1.0), 2.0);
        assert_eq!(t.at(3.0), 4.0);
        assert_eq!(t.at(0.5), 0.0);
        assert_eq!(t.at(3.5), 0.0);
        assert_eq!(t.range(), (1.0, 3.0));
    }

    #[test]
    fn bad_files_name_the_line_and_field() {
        let e = |t: &str| FloorPsd::parse(t, "p.csv").unwrap_err().to_string();
        assert!(e("").contains("no rows"));
        assert!(e("f,g\n1,2\n").contains("line 1"));
        assert!(e("f_hz,psd_m2_s4_hz\n1,2\n2,-1\n").contains("line 3: psd_m2_s4_hz = '-1'"));
        assert!(e("f_hz,psd_m2_s4_hz\n2,1\n1,1\n").contains("line 3: f_hz = 1 is not above"));
        assert!(e("f_hz,psd_m2_s4_hz\n1,1\n1,1\n").contains("rise strictly"));
        assert!(e("f_hz,psd_m2_s4_hz\n1,x\n").contains("is not a number"));
        assert!(e("f_hz,psd_m2_s4_hz\n1,1\n").contains("at least two"));
        assert!(e("f_hz,psd_m2_s4_hz\n1,0\n2,0\n").contains("every density is 0"));
        assert!(e("f_hz,psd_m2_s4_hz\n0,1\n2,1\n").contains("> 0 Hz"));
        assert!(
            e("f_hz,psd_m2_s4_hz\n1,1e308\n2,1\n")
                .contains("line 2: psd_m2_s4_hz = '1e308' is over 1e8")
        );
        assert!(e("f_hz,psd_m2_s4_hz\n1,1,1\n").contains("two fields"));
        assert!(e("# c\nf_hz,psd_m2_s4_hz\n1,nan\n").contains("line 3"));
    }
}
