//! Line endings: LF, CRLF, and a last line that ends without a newline or
//! in a bare CR (a file saved by an old Mac tool, or cut mid-line): the
//! CR is never part of the last value.

use super::{Record, RecordOptions};

/// The z values read, on one thread (the line reader) and on two (the
/// chunks), which must agree.
fn values(text: &str) -> Result<Vec<f64>, String> {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("r.csv");
    std::fs::write(&p, text).unwrap();
    let read = |chunk: Option<usize>| -> Result<Vec<f64>, String> {
        let rec = Record::open_with(&p, &RecordOptions::default(), chunk, 2)
            .map_err(|e| e.to_string())?;
        rec.map(|r| r.map(|row| row[2]).map_err(|e| e.to_string()))
            .collect()
    };
    let (one, two) = (read(None), read(Some(16)));
    assert_eq!(one, two, "{text:?}");
    one
}

#[test]
fn the_last_lines_cr_is_not_part_of_its_value() {
    let want = vec![1.0, 2.0, 3.0];
    for text in [
        "t_s,az\n0,1\n0.01,2\n0.02,3\n",
        "t_s,az\r\n0,1\r\n0.01,2\r\n0.02,3\r\n",
        "t_s,az\r\n0,1\r\n0.01,2\r\n0.02,3",
        "t_s,az\r\n0,1\r\n0.01,2\r\n0.02,3\r",
        "t_s,az\n0,1\n0.01,2\n0.02,3",
    ] {
        assert_eq!(values(text), Ok(want.clone()), "{text:?}");
    }
}
