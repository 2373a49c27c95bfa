//! The working day's sheet as both fronts write it: the per-operation
//! headings of `biodyn day` and its report page, how an hour to a value
//! prints, and the CSV of `biodyn day --format csv`, which is the Day
//! tab's `.csv` export byte for byte.

pub mod verdicts;

use super::table::fx;
use biodyn::exposure::{Day, DayVdv, VdvHours};

/// The headings of the day's per-operation table, as text and in the
/// report's page.
pub const OPERATION_HEADINGS: [&str; 11] = [
    "operation",
    "hours",
    "axis",
    "k·a_w m/s²",
    "A(8) m/s²",
    "points",
    "to EAV h",
    "to ELV h",
    "VDV m/s^1.75",
    "to VDV EAV h",
    "to VDV ELV h",
];

/// Hours to a value in a table: two decimals however many (a value beyond
/// any day shows as the hours it takes, 122.40); "never" when it is never
/// reached (k·a_w or k·VDV 0); "<0.01" rather than a 0.00 that reads as
/// no time.
pub fn hours_cell(h: Option<f64>) -> String {
    match h {
        None => "never".into(),
        Some(h) if h < 0.005 => "<0.01".into(),
        Some(h) => fx(h, 2),
    }
}

/// The two VDV hour cells of an operation's axis: "-" (not judged: no
/// VDV measured, as its VDV cell) rather than a number.
pub fn vdv_hours_cells(h: Option<VdvHours>) -> [String; 2] {
    match h {
        Some(h) => [hours_cell(h.to_eav), hours_cell(h.to_elv)],
        None => ["-".into(), "-".into()],
    }
}

/// A name in a CSV cell: quoted when it holds a separator, a quote or a
/// line break.
fn cell(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// A number in a CSV cell, shortest round-trip; empty for none.
fn opt(v: Option<f64>) -> String {
    v.map_or(String::new(), |v| v.to_string())
}

/// The CSV header of the sheet.
pub const CSV_HEADER: &str = "operation,axis,hours,kaw_m_s2,a8_m_s2,points,hours_to_eav,hours_to_elv,vdv_exposure_m_s175,hours_to_vdv_eav,hours_to_vdv_elv,vdv_at_least_m_s175";

/// One row per operation and axis, then one per axis for the day (hours
/// empty), then the day's highest A(8) axis (`axis` "highest: z") and,
/// where any VDV is known, its highest VDV axis ("highest VDV: z"). An
/// empty hours cell is never reached (k·a_w or VDV 0) or, for the VDV's,
/// not judged (no VDV measured: its `vdv_exposure_m_s175` is empty too).
/// `vdv_at_least_m_s175` is the known part of a day's VDV when some
/// operation lacks one: a lower bound, never the day's VDV.
pub fn csv(day: &Day) -> String {
    let mut out = String::from(CSV_HEADER);
    out.push('\n');
    for o in &day.operations {
        for (a, e) in o.axes.iter() {
            let (to_eav, to_elv) = match e.hours_to_vdv {
                Some(h) => (h.to_eav, h.to_elv),
                None => (None, None),
            };
            out.push_str(&format!(
                "{},{},{},{},{},{},{},{},{},{},{},\n",
                cell(&o.name),
                a.name(),
                o.hours,
                e.kaw,
                e.a8,
                e.points,
                opt(e.hours_to_eav),
                opt(e.hours_to_elv),
                opt(e.vdv_exposure),
                opt(to_eav),
                opt(to_elv),
            ));
        }
    }
    for (a, d) in day.axes.iter() {
        let bound = d.vdv_known.filter(|_| d.vdv.is_none());
        out.push_str(&format!(
            "the day,{},,,{},{},,,{},,,{}\n",
            a.name(),
            d.a8,
            d.points,
            opt(d.vdv),
            opt(bound)
        ));
    }
    out.push_str(&format!(
        "the day,highest: {},,,{},{},,,,,,\n",
        day.a8_axis.name(),
        day.a8,
        day.points
    ));
    match day.vdv_verdict {
        DayVdv::Known { axis, vdv, .. } => {
            out.push_str(&format!(
                "the day,highest VDV: {},,,,,,,{vdv},,,\n",
                axis.name()
            ));
        }
        DayVdv::AtLeast { axis, vdv, .. } => {
            out.push_str(&format!(
                "the day,highest VDV: {},,,,,,,,,,{vdv}\n",
                axis.name()
            ));
        }
        DayVdv::Unknown => {}
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use biodyn::exposure::{Measured, Operation};
    use biodyn::time::{Axis, PerAxis};

    fn op(name: &str, hours: f64, z: (f64, Option<f64>)) -> Operation {
        let mut m = PerAxis::default();
        m.set(
            Axis::Z,
            Measured {
                aw: z.0,
                vdv: z.1,
                measured_s: z.1.map(|_| 600.0),
                dz: None,
            },
        );
        Operation::new(name, hours, &m)
    }

    #[test]
    fn hours_print_as_the_sheet_does() {
        assert_eq!(hours_cell(None), "never");
        assert_eq!(hours_cell(Some(122.4)), "122.40");
        assert_eq!(hours_cell(Some(0.004)), "<0.01");
        assert_eq!(hours_cell(Some(0.005)), "0.01");
        assert_eq!(vdv_hours_cells(None), ["-", "-"]);
    }

    /// z 0.8 m/s² for 2 h, VDV 9.0 over 600 s; a second operation without
    /// a VDV: the day's VDV is at least 9·12^¼ = 16.75 (a lower bound,
    /// in its own column), and its hours are empty, never 0.
    #[test]
    fn the_sheet_carries_the_vdvs_and_keeps_a_bound_apart() {
        let day = Day::of(vec![
            op("loading, hard", 2.0, (0.8, Some(9.0))),
            op("idle", 1.0, (0.2, None)),
        ])
        .expect("a day");
        let csv = csv(&day);
        let lines: Vec<&str> = csv.lines().collect();
        assert_eq!(lines[0], CSV_HEADER);
        let bound = 9.0 * 12f64.powf(0.25);
        let e = day.operations[0].axes.get(Axis::Z).expect("z");
        let h = e.hours_to_vdv.expect("hours");
        assert_eq!(
            lines[1],
            format!(
                "\"loading, hard\",z,2,0.8,{},{},{},{},{bound},{},{},",
                e.a8,
                e.points,
                e.hours_to_eav.expect("eav"),
                e.hours_to_elv.expect("elv"),
                h.to_eav.expect("vdv eav"),
                h.to_elv.expect("vdv elv")
            )
        );
        assert!(lines[2].starts_with("idle,z,1,"), "{}", lines[2]);
        assert!(lines[2].ends_with(",,,,"), "{}", lines[2]);
        let day_z = day.axes.get(Axis::Z).expect("z");
        assert_eq!(
            lines[3],
            format!("the day,z,,,{},{},,,,,,{bound}", day_z.a8, day_z.points)
        );
        assert_eq!(lines[5], format!("the day,highest VDV: z,,,,,,,,,,{bound}"));
        // Every row has the header's twelve cells (the quoted name is one).
        for l in &lines[2..] {
            assert_eq!(l.split(',').count(), 12, "{l}");
        }
    }
}
