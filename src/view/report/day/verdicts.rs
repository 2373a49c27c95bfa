//! The day's VDV verdict in words (exact, or the known part judged as the
//! lower bound it is) and the week (its A(8), the days whose VDV passes a
//! value) as `biodyn day` prints them, in text and JSON.

use crate::view::report::table::{fx, table};
use biodyn::exposure::{Day, DayFile, DayVdv, Week};
use biodyn::iso2631::{VDV_ACTION, VDV_LIMIT, Verdict};
use serde_json::{Map, Value, json};

/// The names of the operations at `lacking` (indices into the day's).
pub fn lacking_names(d: &Day, lacking: &[usize]) -> Vec<String> {
    lacking
        .iter()
        .filter_map(|&i| d.operations.get(i))
        .map(|o| o.name.clone())
        .collect()
}

pub fn week_json(w: &Week, days: &[(DayFile, Day)]) -> Value {
    let mut axes = Map::new();
    for (a, v) in w.axes.iter() {
        axes.insert(a.name().into(), json!({ "a8_m_s2": v }));
    }
    let passing: Vec<Value> = w
        .vdv_passing()
        .iter()
        .filter_map(|&(i, v)| {
            let (axis, vdv, at_least) = v.value()?;
            let mut m = Map::new();
            m.insert("day".into(), json!(i + 1));
            m.insert(
                "file".into(),
                json!(days.get(i).map(|(f, _)| f.origin.clone())),
            );
            m.insert("vdv_axis".into(), json!(axis.name()));
            match v {
                DayVdv::Known { .. } => m.insert("vdv_exposure_m_s175".into(), json!(vdv)),
                _ => m.insert("vdv_at_least_m_s175".into(), json!(vdv)),
            };
            m.insert("eu_vdv_at_least".into(), json!(at_least.words()));
            if let Some(eu) = v.decided() {
                m.insert("eu_vdv".into(), json!(eu.words()));
            }
            Some(Value::Object(m))
        })
        .collect();
    let open: Vec<usize> = w.vdv_open().iter().map(|i| i + 1).collect();
    json!({
        "axes": axes,
        "a8_m_s2": w.a8,
        "a8_axis": w.a8_axis.name(),
        "points": w.points,
        "eu_a8": w.eu_a8.words(),
        "vdv_days": passing,
        "vdv_open_days": open,
    })
}

/// The day's VDV verdict in words: exact; or the known part judged as
/// the lower bound it is (a missing VDV only raises (Σ VDV_i⁴)^¼), the
/// verdict open only below the limit; the operations without one named.
pub fn vdv_text(d: &Day) -> String {
    let values = format!("(action {VDV_ACTION}, limit {VDV_LIMIT})");
    let lacking: Vec<String> = d
        .axes
        .iter()
        .filter(|(_, x)| !x.lacking_vdv.is_empty())
        .map(|(a, x)| {
            let names: Vec<String> = lacking_names(d, &x.lacking_vdv)
                .iter()
                .map(|n| format!("'{}'", biodyn::io::short_quote(n)))
                .collect();
            format!("{a}: {}", names.join(", "))
        })
        .collect();
    let lacking = lacking.join("; ");
    let bound = format!(
        "    a lower bound: a missing VDV only raises the day's; without a measured VDV: {lacking}\n"
    );
    match d.vdv_verdict {
        DayVdv::Known { axis, vdv, verdict } => format!(
            "  VDV {vdv:.2} m/s^1.75 on {axis}: {} {values}\n",
            verdict.words()
        ),
        DayVdv::AtLeast {
            axis,
            vdv,
            at_least: Verdict::BelowAction,
        } => format!(
            "  VDV not judged: at least {vdv:.2} m/s^1.75 on {axis}, below the action value so far {values}\n{bound}"
        ),
        DayVdv::AtLeast {
            axis,
            vdv,
            at_least: Verdict::AboveAction,
        } => format!(
            "  VDV at least {vdv:.2} m/s^1.75 on {axis}: above action value; above limit value open {values}\n{bound}"
        ),
        DayVdv::AtLeast {
            axis,
            vdv,
            at_least: Verdict::AboveLimit,
        } => format!(
            "  VDV at least {vdv:.2} m/s^1.75 on {axis}: above limit value {values}\n{bound}"
        ),
        DayVdv::Unknown => {
            format!("  VDV not judged: operations without a measured VDV ({lacking})\n")
        }
    }
}

pub fn week_text(w: &Week, list: &[(DayFile, Day)]) -> String {
    let days = list.len();
    let rows: Vec<Vec<String>> = w
        .axes
        .iter()
        .map(|(a, v)| vec![format!("{a} ({})", a.direction()), fx(*v, 3)])
        .collect();
    format!(
        "The week ({days} day{}; A(8)week = √(⅕ Σ A(8)day²), UK SI 2005/1093 Schedule 2):\n{}\nWeekly exposure: {} ({}), A(8) {:.3} m/s², {:.0} points: {}\n",
        if days == 1 { "" } else { "s" },
        table(&["axis", "A(8)week m/s²"], &rows),
        w.a8_axis,
        w.a8_axis.direction(),
        w.a8,
        w.points,
        w.eu_a8.words()
    ) + &week_vdv_text(w, list)
}

/// The days whose VDV passes a value (the VDV is a day's; the week has
/// none), and those whose VDV verdict is open.
fn week_vdv_text(w: &Week, list: &[(DayFile, Day)]) -> String {
    let name = |i: usize| {
        list.get(i)
            .map_or(String::new(), |(f, _)| format!(" ({})", f.origin))
    };
    let mut s = String::new();
    for (i, v) in w.vdv_passing() {
        let Some((axis, vdv, at_least)) = v.value() else {
            continue;
        };
        let verdict = match (v, v.decided()) {
            (DayVdv::Known { .. }, Some(eu)) => {
                format!("{vdv:.2} m/s^1.75 on {axis}: {}", eu.words())
            }
            (_, Some(eu)) => format!("at least {vdv:.2} m/s^1.75 on {axis}: {}", eu.words()),
            _ => format!(
                "at least {vdv:.2} m/s^1.75 on {axis}: {}; above limit value open",
                at_least.words()
            ),
        };
        s.push_str(&format!("  day {}{}: VDV {verdict}\n", i + 1, name(i)));
    }
    let open: Vec<String> = w
        .vdv_open()
        .iter()
        .filter(|i| !w.vdv_passing().iter().any(|(p, _)| p == *i))
        .map(|i| format!("day {}", i + 1))
        .collect();
    if !open.is_empty() {
        s.push_str(&format!(
            "  VDV not judged on {}: operations without a measured VDV\n",
            open.join(", ")
        ));
    }
    if s.is_empty() {
        "Days over a VDV value: none\n".into()
    } else {
        format!(
            "Days over a VDV value (the VDV is a day's: the week has none; action {VDV_ACTION}, limit {VDV_LIMIT}):\n{s}"
        )
    }
}
