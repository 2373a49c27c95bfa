//! The header row: its fields (quotes, a byte-order mark), and the two
//! ways a first line is not one: numbers only (data, no header), or one
//! field another separator splits.

use super::RecordError;
use std::path::Path;

/// The header's fields, through the csv crate (quotes, a byte-order mark).
pub(super) fn header_fields(
    path: &Path,
    line: u64,
    bytes: &[u8],
) -> Result<Vec<String>, RecordError> {
    let bytes = bytes.strip_prefix("\u{feff}".as_bytes()).unwrap_or(bytes);
    let mut r = csv::ReaderBuilder::new()
        .has_headers(false)
        .from_reader(bytes);
    let mut rec = csv::StringRecord::new();
    match r.read_record(&mut rec) {
        Ok(_) => Ok(rec.iter().map(|h| h.trim().to_string()).collect()),
        Err(e) => Err(RecordError::Csv {
            path: path.to_path_buf(),
            line,
            msg: e.to_string(),
        }),
    }
}

/// Refuses a first line of numbers only: it is data, and reading it as
/// names would lose its sample.
pub(super) fn refuse_numbers(path: &Path, header: &[String]) -> Result<(), RecordError> {
    let number =
        |h: &String| super::decimal::parse(h.as_bytes()).is_some() || h.parse::<f64>().is_ok();
    if header.iter().all(number) {
        return Err(RecordError::NumericHeader {
            path: path.to_path_buf(),
            first: header.join(","),
        });
    }
    Ok(())
}

/// The separator a one-field header is really split by, if any: `;`
/// (spreadsheets in locales with a decimal comma), a tab, `|`, or spaces.
pub(super) fn other_separator(header: &str) -> Option<&'static str> {
    [(';', "';'"), ('\t', "tabs"), ('|', "'|'")]
        .into_iter()
        .find(|(c, _)| header.contains(*c))
        .map(|(_, name)| name)
        .or_else(|| (header.split_whitespace().count() > 1).then_some("spaces"))
}
