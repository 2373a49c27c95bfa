//! Measured data: a CSV with `f_hz` and any of the columns `biodyn response
//! --format csv` prints, each optionally weighted by a `<column>_sd` column.
//! Empty cells are values not measured. Unknown columns are refused rather
//! than ignored: a misspelt `apms_mg` must not silently drop out of the fit.

use super::error::DataError;
use crate::band::{MAX_HZ, MIN_HZ};
use crate::freq::function::Function;
use crate::io::excerpt::{message, quote};
use crate::io::{FileKind, read_text};
use std::path::Path;

/// Longest line of a measured-data file, bytes.
pub const MAX_LINE: usize = 64 * 1024;

/// Magnitude or phase of a response function.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    Mag,
    Phase,
}

/// One measurable series: a function and a quantity (`apms_phase_deg`, …).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Channel {
    pub function: Function,
    pub quantity: Quantity,
}

impl Channel {
    /// Every channel, in the order of `biodyn response --format csv`: each
    /// function of [`Function::ALL`], magnitude then phase.
    pub const ALL: [Channel; 2 * Function::ALL.len()] = {
        let mut out = [Channel::new(Function::ALL[0], Quantity::Mag); 2 * Function::ALL.len()];
        let mut i = 0;
        while i < Function::ALL.len() {
            out[2 * i] = Channel::new(Function::ALL[i], Quantity::Mag);
            out[2 * i + 1] = Channel::new(Function::ALL[i], Quantity::Phase);
            i += 1;
        }
        out
    };

    pub const fn new(function: Function, quantity: Quantity) -> Channel {
        Channel { function, quantity }
    }

    /// The CSV column name, from the function's table entry: `stht_mag`,
    /// `apms_phase_deg`, …
    pub fn key(self) -> String {
        match self.quantity {
            Quantity::Mag => self.function.mag_column(),
            Quantity::Phase => self.function.phase_column(),
        }
        .to_string()
    }

    fn parse(name: &str) -> Option<Channel> {
        Channel::ALL.into_iter().find(|c| c.key() == name)
    }
}

/// One measured column; `values[i]` belongs to the file's row i.
#[derive(Debug, Clone, PartialEq)]
pub struct Column {
    pub channel: Channel,
    /// Magnitudes in the function's unit, phases in degrees; None = not measured.
    pub values: Vec<Option<f64>>,
    /// Standard deviations in the same unit, when the file has `<column>_sd`.
    pub sd: Option<Vec<Option<f64>>>,
}

/// A measured-data file, checked: frequencies positive and increasing,
/// magnitudes positive, every weighted value with its standard deviation.
#[derive(Debug, Clone, PartialEq)]
pub struct Measured {
    /// The file as named by the user, for messages and the saved preset.
    pub path: String,
    pub f_hz: Vec<f64>,
    /// Columns with at least one value, in the order of [`Channel::ALL`].
    pub columns: Vec<Column>,
}

/// Where a header name goes.
enum Slot {
    Freq,
    Value(Channel),
    Sd(Channel),
}

impl Measured {
    /// Reads and checks a data file (regular files only, within the cap).
    pub fn load(path: &Path) -> Result<Measured, DataError> {
        let text = read_text(path, FileKind::Measured)?;
        Measured::parse(&text, &path.display().to_string())
    }

    /// Checks data already in memory; `path` names it in messages.
    pub fn parse(text: &str, path: &str) -> Result<Measured, DataError> {
        let p = || path.to_string();
        // Spreadsheets often save UTF-8 with a byte-order mark.
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        if text.trim().is_empty() {
            return Err(DataError::Empty { path: p() });
        }
        // One row is a few numbers: a line over 64 KiB is not measured data,
        // and would only make the CSV reader buffer it whole.
        if let Some(line) = text.split('\n').position(|l| l.len() > MAX_LINE) {
            return Err(DataError::Csv {
                path: p(),
                line: line as u64 + 1,
                message: format!(
                    "the line is over {} KiB: one row of numbers per line (is this a CSV file?)",
                    MAX_LINE / 1024
                ),
            });
        }
        let mut reader = csv::ReaderBuilder::new()
            .has_headers(true)
            .trim(csv::Trim::All)
            .from_reader(text.as_bytes());
        let csv_err = |e: csv::Error| DataError::Csv {
            path: p(),
            line: e.position().map_or(1, |q| q.line()),
            message: message(&e.to_string()),
        };
        let header = reader.headers().map_err(csv_err)?.clone();
        let mut slots = Vec::with_capacity(header.len());
        for (i, name) in header.iter().enumerate() {
            let col = i + 1;
            if let Some(sep) = [';', '\t'].into_iter().find(|c| name.contains(*c)) {
                return Err(DataError::Separator {
                    path: p(),
                    sep: if sep == ';' { "semicolons" } else { "tabs" },
                });
            }
            let lower = name.to_ascii_lowercase();
            let name = lower.as_str();
            let slot = if name == "f_hz" {
                Slot::Freq
            } else if let Some(ch) = Channel::parse(name) {
                Slot::Value(ch)
            } else if let Some(ch) = name.strip_suffix("_sd").and_then(Channel::parse) {
                Slot::Sd(ch)
            } else {
                return Err(DataError::UnknownColumn {
                    path: p(),
                    col,
                    name: quote(header.get(i).unwrap_or_default()),
                });
            };
            if header.iter().take(i).any(|h| h.eq_ignore_ascii_case(name)) {
                return Err(DataError::Duplicate {
                    path: p(),
                    col,
                    name: quote(name),
                });
            }
            slots.push(slot);
        }
        let Some(f_col) = slots.iter().position(|s| matches!(s, Slot::Freq)) else {
            return Err(DataError::NoFrequency { path: p() });
        };
        for (i, s) in slots.iter().enumerate() {
            if let Slot::Sd(ch) = s
                && !slots.iter().any(|t| matches!(t, Slot::Value(c) if c == ch))
            {
                return Err(DataError::OrphanSd {
                    path: p(),
                    col: i + 1,
                    name: quote(header.get(i).unwrap_or_default()),
                    base: quote(&ch.key()),
                });
            }
        }

        let mut f_hz = Vec::new();
        // Cells of every column, by file position.
        let mut cells: Vec<Vec<Option<f64>>> = vec![Vec::new(); slots.len()];
        let mut lines = Vec::new();
        for record in reader.records() {
            let record = record.map_err(csv_err)?;
            let line = record.position().map_or(0, |q| q.line());
            for (i, text) in record.iter().enumerate() {
                let col = i + 1;
                let name = header.get(i).unwrap_or_default();
                let value = if text.is_empty() {
                    None
                } else {
                    match text.parse::<f64>() {
                        Ok(v) if v.is_finite() => Some(v),
                        _ => {
                            return Err(DataError::NotNumber {
                                path: p(),
                                line,
                                col,
                                name: quote(name),
                                text: quote(text),
                            });
                        }
                    }
                };
                match (&slots[i], value) {
                    (Slot::Freq, None) => {
                        return Err(DataError::MissingFrequency {
                            path: p(),
                            line,
                            col,
                        });
                    }
                    (Slot::Freq, Some(v)) if !(MIN_HZ..=MAX_HZ).contains(&v) => {
                        return Err(DataError::BadFrequency {
                            path: p(),
                            line,
                            col,
                            value: v,
                        });
                    }
                    (Slot::Freq, Some(v)) => {
                        if let Some(&previous) = f_hz.last()
                            && v <= previous
                        {
                            return Err(DataError::NotIncreasing {
                                path: p(),
                                line,
                                col,
                                value: v,
                                previous,
                            });
                        }
                        f_hz.push(v);
                    }
                    (Slot::Value(ch), Some(v)) if ch.quantity == Quantity::Mag && v <= 0.0 => {
                        return Err(DataError::BadMagnitude {
                            path: p(),
                            line,
                            col,
                            name: quote(name),
                            value: v,
                        });
                    }
                    (Slot::Sd(_), Some(v)) if v <= 0.0 => {
                        return Err(DataError::BadSd {
                            path: p(),
                            line,
                            col,
                            name: quote(name),
                            value: v,
                        });
                    }
                    _ => {}
                }
                cells[i].push(value);
            }
            lines.push(line);
        }
        if f_hz.is_empty() {
            return Err(DataError::NoRows { path: p() });
        }
        // Every weighted value needs its standard deviation.
        for (i, s) in slots.iter().enumerate() {
            let Slot::Sd(ch) = s else { continue };
            let Some(v) = slots
                .iter()
                .position(|t| matches!(t, Slot::Value(c) if c == ch))
            else {
                continue;
            };
            if let Some(row) =
                (0..f_hz.len()).find(|&r| cells[v][r].is_some() && cells[i][r].is_none())
            {
                return Err(DataError::MissingSd {
                    path: p(),
                    line: lines[row],
                    col: i + 1,
                    name: quote(header.get(i).unwrap_or_default()),
                    base: quote(&ch.key()),
                });
            }
        }
        let _ = f_col;
        let mut columns = Vec::new();
        for ch in Channel::ALL {
            let Some(v) = slots
                .iter()
                .position(|t| matches!(t, Slot::Value(c) if *c == ch))
            else {
                continue;
            };
            if cells[v].iter().all(Option::is_none) {
                continue;
            }
            let sd = slots
                .iter()
                .position(|t| matches!(t, Slot::Sd(c) if *c == ch))
                .map(|s| std::mem::take(&mut cells[s]));
            columns.push(Column {
                channel: ch,
                values: std::mem::take(&mut cells[v]),
                sd,
            });
        }
        if columns.is_empty() {
            return Err(DataError::NoColumn { path: p() });
        }
        Ok(Measured {
            path: path.to_string(),
            f_hz,
            columns,
        })
    }

    /// Number of measured values (non-empty cells of data columns).
    pub fn values(&self) -> usize {
        self.columns
            .iter()
            .map(|c| c.values.iter().flatten().count())
            .sum()
    }

    /// Names of the usable columns, in order.
    pub fn column_names(&self) -> Vec<String> {
        self.columns.iter().map(|c| c.channel.key()).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fit::error::KNOWN;

    fn parse(text: &str) -> Result<Measured, DataError> {
        Measured::parse(text, "d.csv")
    }

    /// Both follow from the response-function table; the texts are the
    /// ones the messages always printed.
    #[test]
    fn the_channels_and_known_columns_follow_the_function_table() {
        let keys: Vec<String> = Channel::ALL.iter().map(|c| c.key()).collect();
        assert_eq!(keys.join(", "), KNOWN);
        assert_eq!(
            KNOWN,
            "stht_mag, stht_phase_deg, dpmi_mag, dpmi_phase_deg, apms_mag, apms_phase_deg"
        );
        assert_eq!(Channel::ALL.len(), 2 * Function::ALL.len());
        for (i, c) in Channel::ALL.iter().enumerate() {
            assert_eq!(c.function, Function::ALL[i / 2]);
            assert_eq!(Channel::parse(&c.key()), Some(*c));
        }
    }

    #[test]
    fn columns_in_canonical_order_with_missing_cells() {
        let m = parse("apms_mag,f_hz,stht_mag,stht_mag_sd\n50,1,1.1,0.1\n,2,1.3,0.1\n").unwrap();
        assert_eq!(m.f_hz, vec![1.0, 2.0]);
        assert_eq!(m.column_names(), vec!["stht_mag", "apms_mag"]);
        assert_eq!(m.columns[1].values, vec![Some(50.0), None]);
        assert_eq!(m.columns[0].sd, Some(vec![Some(0.1), Some(0.1)]));
        assert_eq!(m.values(), 3);
    }

    #[test]
    fn a_byte_order_mark_and_upper_case_names_are_accepted() {
        let m = parse("\u{feff}F_Hz, APMS_mag\n1,50\n").unwrap();
        assert_eq!(m.column_names(), vec!["apms_mag"]);
        assert_eq!(m.f_hz, vec![1.0]);
    }

    #[test]
    fn errors_name_line_and_column() {
        let cases = [
            (
                "f_hz,apms_mag\n1,50\n2,abc\n",
                "line 3, column 2 (apms_mag): 'abc'",
            ),
            ("f_hz,apms_mag\n0,50\n", "line 2, column 1 (f_hz): 0 Hz"),
            // Outside the band's physical limits, the line named (it was
            // "an undamped resonance?" after the fit, with no line).
            (
                "f_hz,apms_mag\n1,50\n1e300,50\n",
                "line 3, column 1 (f_hz): 1e300 Hz; a frequency must be from 1e-3 to 1e5 Hz",
            ),
            (
                "f_hz,apms_mag\n1e-4,50\n",
                "line 2, column 1 (f_hz): 1e-4 Hz; a frequency must be from",
            ),
            (
                "f_hz,apms_mag\n1,50\n1,51\n",
                "line 3, column 1 (f_hz): 1 Hz does not exceed",
            ),
            (
                "f_hz,apms_mag\n1,-50\n",
                "line 2, column 2 (apms_mag): magnitude -50",
            ),
            ("f_hz,apms_mag\n1,0\n", "magnitude 0 is not > 0"),
            ("f_hz,apms_mag\n1,\n", "no usable column"),
            (
                "f_hz,apms_mg\n1,5\n",
                "line 1, column 2: unknown column 'apms_mg'",
            ),
            (
                "f_hz,apms_mag,apms_mag\n1,5,5\n",
                "column 3: column 'apms_mag' appears twice",
            ),
            ("f_hz,apms_mag_sd\n1,5\n", "weights a column 'apms_mag'"),
            ("apms_mag\n5\n", "no f_hz column"),
            ("f_hz,apms_mag\n", "no data rows"),
            ("", "the file is empty"),
            ("f_hz,apms_mag\n1,5,6\n", "line 2"),
            ("f_hz,apms_mag\n1,inf\n", "'inf' is not a finite number"),
            (
                "f_hz,apms_mag,apms_mag_sd\n1,5,\n",
                "line 2, column 3 (apms_mag_sd): empty",
            ),
            (
                "f_hz,apms_mag,apms_mag_sd\n1,5,-1\n",
                "standard deviation -1",
            ),
            (
                "f_hz,apms_mag\n,5\n",
                "line 2, column 1 (f_hz): the frequency is empty",
            ),
        ];
        for (text, want) in cases {
            let e = parse(text).unwrap_err().to_string();
            assert!(e.starts_with("d.csv"), "{text:?}: {e}");
            assert!(e.contains(want), "{text:?}: {e}");
        }
    }
}
