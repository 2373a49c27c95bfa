//! The CSV writer: a header, then rows, every number in shortest
//! round-trip form. The response curve's row loop lives here once.

use biodyn::{Function, Response};
use std::fmt::Write;

/// The response curve's header: `f_hz`, then magnitude and phase of each
/// function in `Function::ALL` order.
pub fn curve_header() -> String {
    curve_header_of(&Function::ALL)
}

/// As `curve_header`, with the columns of `functions`.
pub fn curve_header_of(functions: &[Function]) -> String {
    let mut s = String::from("f_hz");
    for f in functions {
        let _ = write!(s, ",{},{}", f.mag_column(), f.phase_column());
    }
    s
}

/// Appends one row per frequency of `curve`, each starting with `prefix`
/// (cells already written, comma included: `"65 kg",65,`) — the one CSV row
/// loop of every response output.
pub fn curve_rows(out: &mut String, prefix: &str, curve: &[Response]) {
    curve_rows_of(out, prefix, curve, &Function::ALL);
}

/// As `curve_rows`, with the columns of `functions`.
pub fn curve_rows_of(out: &mut String, prefix: &str, curve: &[Response], functions: &[Function]) {
    for r in curve {
        let _ = write!(out, "{prefix}{}", r.f_hz);
        for &f in functions {
            let _ = write!(out, ",{},{}", r.mag(f), r.phase_deg(f));
        }
        out.push('\n');
    }
}

/// A whole response curve as CSV.
pub fn curve(curve: &[Response]) -> String {
    curve_of(curve, &Function::ALL)
}

/// A whole response curve as CSV, with the columns of `functions`.
pub fn curve_of(curve: &[Response], functions: &[Function]) -> String {
    let mut s = String::with_capacity(curve.len() * (20 + 40 * functions.len()));
    s.push_str(&curve_header_of(functions));
    s.push('\n');
    curve_rows_of(&mut s, "", curve, functions);
    s
}

/// A text cell: quoted, with inner double quotes made single.
pub fn text_cell(s: &str) -> String {
    format!("\"{}\"", s.replace('"', "'"))
}

/// A header and rows of numbers.
pub fn numbers(header: &[&str], rows: impl IntoIterator<Item = Vec<f64>>) -> String {
    let mut s = header.join(",");
    s.push('\n');
    for r in rows {
        let cells: Vec<String> = r.iter().map(|v| format!("{v}")).collect();
        s.push_str(&cells.join(","));
        s.push('\n');
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use biodyn::{Band, Body, Solver};

    #[test]
    fn header_and_rows_follow_function_all() {
        assert_eq!(
            curve_header(),
            "f_hz,stht_mag,stht_phase_deg,dpmi_mag,dpmi_phase_deg,apms_mag,apms_phase_deg"
        );
        let body = Body::paper(75.0).unwrap();
        let c = Solver::new(&body).sweep(&Band::new(1.0, 2.0, 0.5).unwrap());
        let mut out = String::new();
        curve_rows(&mut out, "\"a\",1,", &c);
        let rows: Vec<&str> = out.lines().collect();
        assert_eq!(rows.len(), 3);
        let cells: Vec<&str> = rows[1].split(',').collect();
        assert_eq!(cells.len(), 2 + 1 + 2 * Function::ALL.len());
        assert_eq!(cells[2], "1.5");
        assert_eq!(cells[3], format!("{}", c[1].mag(Function::Stht)));
        assert_eq!(text_cell("say \"hi\""), "\"say 'hi'\"");
    }
}
